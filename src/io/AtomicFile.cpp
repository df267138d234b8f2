#include "io/AtomicFile.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "core/Error.h"

namespace wiggle {

namespace {
std::string systemError() { return std::strerror(errno); }

// Writes all of `content` to fd; false, with errno set, when a write fails (a full disk, a file-size
// limit: a short write is retried, and the retry reports why).
bool writeAll(int fd, const std::string& content) {
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}
}  // namespace

void writeFileAtomically(const std::string& path, const std::string& content) {
  const std::string temp = path + ".tmp." + std::to_string(::getpid());
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw Error("cannot write " + path + ": " + systemError());
  if (!writeAll(fd, content)) {
    const std::string why = systemError();
    ::close(fd);
    ::unlink(temp.c_str());
    throw Error("cannot write " + path + ": " + why);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    const std::string why = systemError();
    ::unlink(temp.c_str());
    throw Error("cannot write " + path + ": " + why);
  }
  if (::rename(temp.c_str(), path.c_str()) != 0) {
    const std::string why = systemError();
    ::unlink(temp.c_str());
    throw Error("cannot write " + path + ": " + why);
  }
  // Make the rename itself durable.
  const std::string dir = std::filesystem::path(path).parent_path().string();
  const int dirFd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dirFd >= 0) {
    ::fsync(dirFd);
    ::close(dirFd);
  }
}

void appendToFile(const std::string& path, const std::string& content) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) throw Error("cannot write " + path + ": " + systemError());
  if (!writeAll(fd, content)) {
    const std::string why = systemError();
    ::close(fd);
    throw Error("cannot write " + path + ": " + why);
  }
  if (::close(fd) != 0) throw Error("cannot write " + path + ": " + systemError());
}

void removeLeftoverTemporaries(const std::string& dir) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    if (entry.path().filename().string().find(".tmp.") != std::string::npos) std::filesystem::remove(entry.path(), ec);
  }
}

namespace {

// open(2) and read(2) rather than a stream: a stream opens a directory without complaint and reads
// it as empty, and says nothing of why a read failed; read(2) sets errno (EISDIR, EACCES, EIO).
std::string readWholeFile(const std::string& path, const std::string& name) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw Error("cannot read " + name + ": " + systemError());
  std::string content;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n > 0) {
      content.append(buffer, static_cast<std::size_t>(n));
    } else if (n == 0) {
      break;
    } else if (errno != EINTR) {
      const std::string why = systemError();
      ::close(fd);
      throw Error("cannot read " + name + ": " + why);
    }
  }
  ::close(fd);
  return content;
}

}  // namespace

std::string readFile(const std::string& path) { return readWholeFile(path, path); }

std::string readInputFile(const std::string& path, const std::string& what) {
  return readWholeFile(path, what + " '" + path + "'");
}

}  // namespace wiggle
