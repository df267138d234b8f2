#pragma once
// An advisory lock on a file (flock), held for the object's lifetime: exclusive, or shared with
// other shared holders. The sweep directory's .sweep.lock (a whole sweep holds it alone; one-case
// runs share it), the short lock around rewriting results.csv (sweep/SweepRunner), a run
// directory's .running.lock (held by the run writing it) and a bed's lock while it is made.
#include <string>
#include <utility>

namespace wiggle {

class FileLock {
 public:
  // Opens (making it if missing) and locks `path`. `wait`: block until the lock is free; else a
  // lock held elsewhere throws wiggle::Error `busy` (which says what holding it means).
  FileLock(const std::string& path, bool shared, bool wait, const std::string& busy);
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;
  FileLock(FileLock&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}
  FileLock& operator=(FileLock&&) = delete;
  ~FileLock();

  enum class Holders { None, Shared, Exclusive };
  // Who holds `path` locked now (any open file of it, in this process or another, but the probe's
  // own), probed without waiting and without keeping the lock; None when the file is absent.
  static Holders holders(const std::string& path);

 private:
  int fd_ = -1;
};

}  // namespace wiggle
