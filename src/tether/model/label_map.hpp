#pragma once
/// \file Map from user labels (node or element numbers) to 0-based indices.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace tether {

/// Label -> index, with the part of std::unordered_map<int, int>'s interface
/// that the model's users need (find, end, count, at, emplace, operator[]).
/// Labels in [0, kDenseLimit) and not far beyond the number of labels stored
/// (at most 2 n + 1024) are kept in a dense array, 4 bytes per slot;
/// others (negative, or sparse) in a hash map. A mesh numbered 1..n thus
/// costs 4 bytes per label instead of a hash node and bucket (about 40
/// bytes): 8 MiB less for the 230k-dof Hertz deck's nodes and elements.
/// Indices must be >= 0.
class LabelMap {
 public:
  /// What find() returns: ->first is the label, ->second the index; equal to
  /// end() when the label is not stored. Not an iterator over the map (the
  /// map is not iterated).
  class Found {
   public:
    Found() = default;
    Found(int label, int index) : pair_(label, index), found_(true) {}
    const std::pair<int, int>* operator->() const { return &pair_; }
    const std::pair<int, int>& operator*() const { return pair_; }
    bool operator==(const Found& other) const {
      return found_ == other.found_ && (!found_ || pair_ == other.pair_);
    }

   private:
    std::pair<int, int> pair_{0, -1};
    bool found_ = false;
  };

  [[nodiscard]] Found find(int label) const {
    const int i = lookup(label);
    return i < 0 ? Found{} : Found{label, i};
  }
  [[nodiscard]] Found end() const { return {}; }
  [[nodiscard]] std::size_t count(int label) const { return lookup(label) < 0 ? 0 : 1; }
  [[nodiscard]] std::size_t size() const { return size_; }
  [[nodiscard]] bool empty() const { return size_ == 0; }
  /// The index of `label`; throws std::out_of_range when it is not stored.
  [[nodiscard]] int at(int label) const {
    const int i = lookup(label);
    if (i < 0) throw std::out_of_range("LabelMap::at: no label " + std::to_string(label));
    return i;
  }
  /// Stores label -> index unless the label is stored; true when stored now.
  bool emplace(int label, int index) {
    if (lookup(label) >= 0) return false;
    slot(label) = index;
    ++size_;
    return true;
  }
  /// The index of `label`, inserted as -1 first when absent (assign it).
  int& operator[](int label) {
    if (lookup(label) < 0) ++size_;
    return slot(label);
  }

 private:
  static constexpr int kDenseLimit = 1 << 30;
  [[nodiscard]] int lookup(int label) const {
    if (label >= 0 && static_cast<std::size_t>(label) < dense_.size()) return dense_[static_cast<std::size_t>(label)];
    const auto it = sparse_.find(label);
    return it == sparse_.end() ? -1 : it->second;
  }
  /// The slot of `label`, created (-1) when absent: dense when it keeps the
  /// array at most 2 size_ + 1024 long (moving sparse labels it now covers).
  int& slot(int label) {
    if (label >= 0 && static_cast<std::size_t>(label) < dense_.size()) return dense_[static_cast<std::size_t>(label)];
    if (label >= 0 && label < kDenseLimit && static_cast<std::size_t>(label) < 2 * size_ + 1024) {
      dense_.resize(static_cast<std::size_t>(label) + 1, -1);  // the capacity grows geometrically
      for (auto it = sparse_.begin(); it != sparse_.end();) {
        if (it->first >= 0 && static_cast<std::size_t>(it->first) < dense_.size()) {
          dense_[static_cast<std::size_t>(it->first)] = it->second;
          it = sparse_.erase(it);
        } else {
          ++it;
        }
      }
      return dense_[static_cast<std::size_t>(label)];
    }
    return sparse_.try_emplace(label, -1).first->second;
  }

  std::vector<int> dense_;  ///< dense_[label] = index, -1: none
  std::unordered_map<int, int> sparse_;
  std::size_t size_ = 0;
};

}  // namespace tether
