#include "io/FileLock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "core/Error.h"

namespace wiggle {

FileLock::FileLock(const std::string& path, bool shared, bool wait) {
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw Error("cannot open " + path + ": " + std::strerror(errno));
  if (::flock(fd_, (shared ? LOCK_SH : LOCK_EX) | (wait ? 0 : LOCK_NB)) != 0) {
    ::close(fd_);
    throw Error("another wiggle sweep is running in " + std::filesystem::path(path).parent_path().string() + " (" +
                path + " is locked)");
  }
}

FileLock::~FileLock() { ::close(fd_); }

bool FileLock::heldExclusivelyElsewhere(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool held = ::flock(fd, LOCK_SH | LOCK_NB) != 0;  // a shared lock is refused only by an exclusive one
  if (!held) ::flock(fd, LOCK_UN);
  ::close(fd);
  return held;
}

}  // namespace wiggle
