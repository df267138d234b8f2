#pragma once
// Files that are never seen half-written: content goes to a temporary file in the same directory,
// is flushed to disk, and is renamed over the target (rename is atomic on POSIX file systems).
// A failure (full disk, no permission) throws wiggle::Error naming the file; the old file, if any,
// is left as it was.
#include <string>

namespace wiggle {

void writeFileAtomically(const std::string& path, const std::string& content);
// Appends `content` to the file (made if missing). Not atomic: a failure (named with its reason,
// e.g. "File too large") can leave part of it, which the caller must be able to cut off (the run's
// dump file is truncated to its checkpointed length on resume).
void appendToFile(const std::string& path, const std::string& content);
// Removes what writeFileAtomically leaves behind when its process is killed mid-write (the
// temporary NAME.tmp.PID files) from `dir`, not recursively. Only for a directory that no other
// process is writing to (a run directory being resumed), never for a shared one like the bed cache.
void removeLeftoverTemporaries(const std::string& dir);

// Whole file as bytes; throws wiggle::Error naming the file and why it cannot be read (it does not
// exist, permission denied, it is a directory): "cannot read PATH: Permission denied".
std::string readFile(const std::string& path);
// The same for a file the user named, called `what` in the message: "cannot read config file 'X':
// Is a directory".
std::string readInputFile(const std::string& path, const std::string& what);

}  // namespace wiggle
