#pragma once
/// \file ParaView collection (`.pvd`) listing the `.vtu` file of each increment.

#include <filesystem>
#include <string>
#include <vector>

namespace tether {

/// Keeps the list of datasets of an analysis and rewrites the `.pvd` after
/// each addition, atomically (temporary file + rename): the collection on
/// disk is complete and valid XML at every moment, even if the analysis is
/// killed between increments.
class PvdWriter {
 public:
  /// One `<DataSet>` line.
  struct Entry {
    double time = 0;   ///< total time of the increment
    std::string file;  ///< dataset path relative to the `.pvd`'s directory
  };

  /// Nothing is written until the first add(); an existing file at `file` is
  /// replaced then.
  explicit PvdWriter(std::filesystem::path file);

  /// Appends a dataset (`relative_file` relative to the `.pvd`'s directory,
  /// e.g. "job_1_3.vtu") and rewrites the collection. Throws
  /// std::runtime_error on I/O errors.
  void add(double total_time, const std::string& relative_file);

  [[nodiscard]] const std::vector<Entry>& entries() const { return entries_; }
  [[nodiscard]] const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  std::vector<Entry> entries_;
};

}  // namespace tether
