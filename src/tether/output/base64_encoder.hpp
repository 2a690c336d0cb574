#pragma once
/// \file Streaming base64 encoder (RFC 4648, with '=' padding), used for the
/// binary DataArrays of VTK XML files.

#include <array>
#include <cstddef>
#include <string>

namespace tether {

/// Appends the base64 encoding of a byte stream to a string, in pieces.
///
/// Bytes may be fed in any number of add() calls; the result is the encoding
/// of their concatenation (up to two bytes are held back between calls).
/// finish() encodes the held-back bytes with padding. The target string may be
/// emptied by the caller between calls (to flush it to a file).
class Base64Encoder {
 public:
  /// `out` must outlive the encoder.
  explicit Base64Encoder(std::string& out) : out_(out) {}

  /// Encodes `n` bytes starting at `bytes`.
  void add(const void* bytes, std::size_t n);

  /// Writes the held-back bytes (0, 1 or 2) with padding; the encoder can be
  /// reused afterwards for a new, independent stream.
  void finish();

 private:
  std::string& out_;
  std::array<unsigned char, 3> pending_{};
  int n_pending_ = 0;
};

/// The base64 encoding of `n` bytes at `bytes`.
std::string base64_encode(const void* bytes, std::size_t n);

}  // namespace tether
