#pragma once
// An advisory lock on a file (flock), held for the object's lifetime: exclusive, or shared with
// other shared holders. The sweep directory's .sweep.lock (a whole sweep holds it alone; one-case
// runs share it) and the short lock around rewriting results.csv (sweep/SweepRunner).
#include <string>

namespace wiggle {

class FileLock {
 public:
  // Opens (making it if missing) and locks `path`. `wait`: block until the lock is free; else a
  // lock held elsewhere throws wiggle::Error "another wiggle sweep is running in DIR (...)".
  FileLock(const std::string& path, bool shared, bool wait);
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;
  ~FileLock();

  // Whether another process holds `path` locked exclusively (a whole sweep running in its
  // directory), probed without waiting and without taking the lock; false when the file is absent.
  static bool heldExclusivelyElsewhere(const std::string& path);

 private:
  int fd_ = -1;
};

}  // namespace wiggle
