#include "tether/core/shared_library.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <map>
#include <mutex>

#include "tether/core/error.hpp"

namespace tether {

namespace {

// dlerror() reports through global state: all dl* calls go through this lock.
std::mutex& loader_mutex() {
  static std::mutex m;
  return m;
}

// Loaded libraries by canonical key; weak, so a library closes with its last user.
std::map<std::string, std::weak_ptr<SharedLibrary>>& loaded() {
  static std::map<std::string, std::weak_ptr<SharedLibrary>> libraries;
  return libraries;
}

std::string key_of(const std::string& path) {
  if (path.find('/') == std::string::npos) return path;  // resolved by the loader's search
  std::error_code ec;
  const auto canonical = std::filesystem::weakly_canonical(path, ec);
  return ec ? path : canonical.string();
}

std::string last_dl_error() {
  const char* e = dlerror();
  return e ? e : "unknown error";
}

}  // namespace

std::shared_ptr<SharedLibrary> SharedLibrary::open(const std::string& path) {
  const std::lock_guard lock(loader_mutex());
  const std::string key = key_of(path);
  auto& libraries = loaded();
  if (auto it = libraries.find(key); it != libraries.end())
    if (auto existing = it->second.lock()) return existing;
  dlerror();
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw ModelError("cannot load shared library '" + path + "': " + last_dl_error());
  std::shared_ptr<SharedLibrary> library(new SharedLibrary(path, handle));
  libraries[key] = library;
  return library;
}

SharedLibrary::~SharedLibrary() {
  const std::lock_guard lock(loader_mutex());
  if (handle_) dlclose(handle_);
}

void* SharedLibrary::symbol(const std::string& name, std::string& error) const {
  const std::lock_guard lock(loader_mutex());
  dlerror();
  void* address = dlsym(handle_, name.c_str());
  if (!address) error = last_dl_error();
  return address;
}

void check_routine_status(int status, RoutineMessage& message, const std::string& who) {
  message.back() = '\0';
  if (status != 0)
    throw ModelError(who + " reported failure (status " + std::to_string(status) + ")" +
                     (message[0] ? ": " + std::string(message.data()) : std::string()));
}

}  // namespace tether
