#pragma once
/// \file Helpers for Contribution::save_state / load_state: a state is a list
/// of doubles; integers are stored as exact doubles and read back checked.

#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

namespace tether::saved_state {

/// Takes the next value from the front of `in`; std::runtime_error when `in` is empty.
inline double take(std::span<const double>& in) {
  if (in.empty()) throw std::runtime_error("its saved state is too short");
  const double v = in.front();
  in = in.subspan(1);
  return v;
}

/// Takes an integer in [lo, hi]; std::runtime_error naming `what` otherwise.
inline int take_int(std::span<const double>& in, int lo, int hi, const char* what) {
  const double v = take(in);
  if (!(v >= lo && v <= hi) || std::floor(v) != v)
    throw std::runtime_error(std::string("bad ") + what + " in its saved state (" + std::to_string(v) +
                             ", expected " + std::to_string(lo) + ".." + std::to_string(hi) + ")");
  return static_cast<int>(v);
}

/// Takes a tag written by save_state and checks it (the record belongs to this kind of contribution).
inline void expect_tag(std::span<const double>& in, double tag, const char* kind) {
  if (take(in) != tag) throw std::runtime_error(std::string("the saved state is not that of a ") + kind);
}

}  // namespace tether::saved_state
