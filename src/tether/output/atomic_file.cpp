#include "tether/output/atomic_file.hpp"

#include <stdexcept>
#include <system_error>

namespace tether {

AtomicFile::AtomicFile(std::filesystem::path target)
    : target_(std::move(target)), temporary_(target_.string() + ".tmp") {
  stream_.open(temporary_, std::ios::binary | std::ios::trunc);
  if (!stream_) throw std::runtime_error("cannot create output file '" + temporary_.string() + "'");
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  stream_.close();
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
}

void AtomicFile::commit() {
  stream_.flush();
  const bool written = static_cast<bool>(stream_);
  stream_.close();
  if (!written || stream_.fail())
    throw std::runtime_error("error while writing '" + temporary_.string() + "' (disk full?)");
  std::error_code error;
  std::filesystem::rename(temporary_, target_, error);
  if (error)
    throw std::runtime_error("cannot rename '" + temporary_.string() + "' to '" +
                             target_.string() + "': " + error.message());
  committed_ = true;
}

}  // namespace tether
