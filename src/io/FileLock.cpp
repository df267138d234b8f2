#include "io/FileLock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/Error.h"

namespace wiggle {

FileLock::FileLock(const std::string& path, bool shared, bool wait, const std::string& busy) {
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw Error("cannot open " + path + ": " + std::strerror(errno));
  if (::flock(fd_, (shared ? LOCK_SH : LOCK_EX) | (wait ? 0 : LOCK_NB)) != 0) {
    const int error = errno;
    ::close(fd_);
    if (error == EWOULDBLOCK) throw Error(busy + " (" + path + " is locked)");
    throw Error("cannot lock " + path + ": " + std::strerror(error));
  }
}

FileLock::~FileLock() {
  if (fd_ >= 0) ::close(fd_);
}

FileLock::Holders FileLock::holders(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return Holders::None;
  Holders held = Holders::None;
  if (::flock(fd, LOCK_SH | LOCK_NB) != 0)
    held = Holders::Exclusive;  // a shared lock is refused only by an exclusive one
  else if (::flock(fd, LOCK_EX | LOCK_NB) != 0)
    held = Holders::Shared;  // ours converts to exclusive unless another shared holder is there
  ::close(fd);               // and with it whatever lock the probe took
  return held;
}

}  // namespace wiggle
