#pragma once
// Checks of the paths a command is given, made in its callback before anything is read or written:
// a bad path gets a one-line wiggle::Error naming it (main() prints it, exit status 2) and leaves
// nothing behind. Shared by every command that takes a config file or an output directory.
#include <string>

namespace wiggle::cli {

// A file the command reads (`what`: "config file", "sweep file"): it must exist and be a regular
// file or a symbolic link to one. A directory, FIFO, socket or device is refused, e.g.
// "config file 'configs' is a directory, not a file".
void requireInputFile(const std::string& path, const std::string& what);

// An output directory given with `flag` (e.g. "--out"): an existing directory, or a new one whose
// parent directory exists. The commands create at most the last component, never a whole path:
// "--out /nonexistent/deep/dir: parent directory /nonexistent/deep does not exist". An empty path
// (the command's default) is not checked.
void requireOutputDirectory(const std::string& flag, const std::string& path);

// requireOutputDirectory, then that the directory can really be written or made: a scratch
// directory is made in it (or, for a new one, beside it, in its parent) and removed at once, so
// nothing stays behind. For `run --check`, which must find what the run would stumble on; access()
// alone would not do (root passes it in /proc, where nothing can be made).
void requireWritableOutputDirectory(const std::string& flag, const std::string& path);

// An output file (`name`: "--out report.html", or the default path the command names): not a
// directory, and its directory exists and is writable (the file is written to a temporary name
// there and renamed), e.g. "--out /nonexistent/r.html: directory /nonexistent does not exist".
void requireOutputFile(const std::string& name, const std::string& path);

}  // namespace wiggle::cli
