#pragma once
/// \file A shared library loaded at run time (dlopen), for user plug-ins.

#include <array>
#include <memory>
#include <string>

namespace tether {

/// One dlopen handle (RTLD_NOW | RTLD_LOCAL), closed when the last owner lets
/// go. open() returns the same object for the same library while anyone holds
/// it, so constraints naming one library share one handle.
class SharedLibrary {
 public:
  /// Loads `path` (or returns the already loaded instance). A path containing
  /// '/' is used as is (relative to the working directory); a bare file name is
  /// searched by the dynamic loader (LD_LIBRARY_PATH, ...). Throws ModelError
  /// naming the path and dlerror() when the library cannot be loaded.
  static std::shared_ptr<SharedLibrary> open(const std::string& path);

  ~SharedLibrary();
  SharedLibrary(const SharedLibrary&) = delete;
  SharedLibrary& operator=(const SharedLibrary&) = delete;

  /// Address of `name`, or nullptr with `error` set to dlerror()'s text.
  [[nodiscard]] void* symbol(const std::string& name, std::string& error) const;

  /// The path as given to open().
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  SharedLibrary(std::string path, void* handle) : path_(std::move(path)), handle_(handle) {}

  std::string path_;
  void* handle_ = nullptr;
};

/// Message buffer handed to a user routine (C interfaces take char*, size).
using RoutineMessage = std::array<char, 512>;

/// Throws ModelError "`who` reported failure (status N): message" when a user
/// routine returned a nonzero status. Terminates `message` first.
void check_routine_status(int status, RoutineMessage& message, const std::string& who);

}  // namespace tether
