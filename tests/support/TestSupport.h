#pragma once
// What several test files need: a source file's text, the message of an expected error, and a scratch directory of the
// test's own. ctest runs every test in a process of its own and several at once (-j), so a test
// that writes files writes them only under a ScratchDir: named by the process and a counter, made
// empty, removed at the end (WIGGLE_KEEP_TEST_DIRS=1 keeps it to look at).
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "core/Error.h"

namespace wiggle::testing_support {

// A file of the source tree (a document, a schema) as text; empty when missing.
inline std::string sourceFile(const std::string& relative) {
  std::ifstream in(std::string(WIGGLE_SOURCE_DIR) + "/" + relative);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The message of the wiggle::Error that f throws, or "(no error)".
inline std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name) {
    static std::atomic<int> count{0};
    path_ = std::filesystem::temp_directory_path() /
            ("wiggle-" + name + "-" + std::to_string(::getpid()) + "-" + std::to_string(count++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    const char* keep = std::getenv("WIGGLE_KEEP_TEST_DIRS");
    std::error_code ignored;
    if (keep == nullptr || std::string(keep) != "1") std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace wiggle::testing_support
