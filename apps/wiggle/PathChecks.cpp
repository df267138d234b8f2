#include "PathChecks.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "core/Error.h"

namespace wiggle::cli {

namespace fs = std::filesystem;

void requireInputFile(const std::string& path, const std::string& what) {
  const std::string name = what + " '" + path + "'";
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);  // follows symbolic links
  if (st.type() == fs::file_type::not_found) throw Error(name + " does not exist");
  if (ec) throw Error("cannot read " + name + ": " + ec.message());
  if (st.type() == fs::file_type::directory) throw Error(name + " is a directory, not a file");
  if (st.type() != fs::file_type::regular)
    throw Error(name + " is not a regular file (a FIFO, socket or device cannot be read as one)");
}

void requireOutputDirectory(const std::string& flag, const std::string& path) {
  if (path.empty()) return;
  const std::string name = flag + " " + path;
  fs::path dir(path);
  if (dir.has_relative_path() && !dir.has_filename()) dir = dir.parent_path();  // "a/b/" -> "a/b"
  std::error_code ec;
  const fs::file_status st = fs::status(dir, ec);
  if (st.type() == fs::file_type::directory) return;
  if (st.type() != fs::file_type::not_found) {
    if (ec) throw Error(name + ": " + ec.message());
    throw Error(name + ": exists and is not a directory");
  }
  const fs::path parent = dir.has_parent_path() ? dir.parent_path() : fs::path(".");
  const fs::file_status pst = fs::status(parent, ec);
  if (pst.type() == fs::file_type::directory) return;
  if (pst.type() == fs::file_type::not_found)
    throw Error(name + ": parent directory " + parent.string() + " does not exist");
  if (ec) throw Error(name + ": parent directory " + parent.string() + ": " + ec.message());
  throw Error(name + ": parent " + parent.string() + " is not a directory");
}

void requireWritableOutputDirectory(const std::string& flag, const std::string& path) {
  requireOutputDirectory(flag, path);
  fs::path dir(path);
  if (dir.has_relative_path() && !dir.has_filename()) dir = dir.parent_path();
  const bool exists = fs::is_directory(dir);
  const fs::path where = exists ? dir : dir.has_parent_path() ? dir.parent_path() : fs::path(".");
  std::string probe = (where / ".wiggle-check-XXXXXX").string();
  if (::mkdtemp(probe.data()) == nullptr)
    throw Error(flag + " " + path + ": cannot " + (exists ? "write in the directory" : "create the directory") + ": " +
                std::strerror(errno));
  std::error_code ec;
  fs::remove(probe, ec);
}

void requireOutputFile(const std::string& name, const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw Error(name + ": is a directory, not a file");
  const fs::path parent = fs::path(path).has_parent_path() ? fs::path(path).parent_path() : fs::path(".");
  const fs::file_status st = fs::status(parent, ec);
  if (st.type() == fs::file_type::not_found) throw Error(name + ": directory " + parent.string() + " does not exist");
  if (st.type() != fs::file_type::directory) throw Error(name + ": " + parent.string() + " is not a directory");
  if (::access(parent.c_str(), W_OK) != 0)
    throw Error(name + ": directory " + parent.string() + " is not writable (" + std::strerror(errno) + ")");
}

}  // namespace wiggle::cli
