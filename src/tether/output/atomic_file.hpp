#pragma once
/// \file Crash-safe file replacement: write a temporary file, then rename it.

#include <filesystem>
#include <fstream>

namespace tether {

/// A file written under a temporary name (`<target>.tmp`, in the same
/// directory) and moved onto its target by commit() with
/// std::filesystem::rename, which replaces the target atomically on POSIX
/// file systems. Readers therefore see either the old or the new complete
/// file, never a partial one. If commit() is not reached (an exception, a
/// crash) the target is untouched; the destructor removes the temporary file.
///
/// Not thread-safe; one AtomicFile per target at a time.
class AtomicFile {
 public:
  /// Opens `<target>.tmp` for binary writing. Throws std::runtime_error when
  /// it cannot be created (the message names the path).
  explicit AtomicFile(std::filesystem::path target);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicFile();

  /// The stream to write the content to.
  [[nodiscard]] std::ostream& stream() { return stream_; }

  /// Flushes and closes the temporary file and renames it onto the target.
  /// Throws std::runtime_error (naming the path) on any write or rename error;
  /// the target is then left as it was.
  void commit();

  [[nodiscard]] const std::filesystem::path& target() const { return target_; }
  [[nodiscard]] const std::filesystem::path& temporary() const { return temporary_; }

 private:
  std::filesystem::path target_;
  std::filesystem::path temporary_;
  std::ofstream stream_;
  bool committed_ = false;
};

}  // namespace tether
