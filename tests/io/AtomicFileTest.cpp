// Files never seen half-written (io/AtomicFile.h): replacement, the old file kept when a write
// fails, appending, clearing a killed writer's temporaries, and reading.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <string>

#include "core/Error.h"
#include "io/AtomicFile.h"

namespace wiggle {
namespace {

namespace fs = std::filesystem;

std::string scratchDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("wiggle_atomic_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

int filesIn(const std::string& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicFile, WritesAndReplacesWholeFilesLeavingNothingElse) {
  const std::string dir = scratchDir("write");
  const std::string path = dir + "/a.bin";
  const std::string binary("x\0y\n\xff", 5);
  writeFileAtomically(path, binary);
  EXPECT_EQ(readFile(path), binary);
  writeFileAtomically(path, "shorter");
  EXPECT_EQ(readFile(path), "shorter");
  writeFileAtomically(path, "");
  EXPECT_EQ(readFile(path), "");
  EXPECT_EQ(filesIn(dir), 1);  // no temporaries left behind
  fs::remove_all(dir);
}

TEST(AtomicFile, AFailedWriteKeepsTheOldFileAndNamesTheTarget) {
  const std::string dir = scratchDir("fail");
  const std::string path = dir + "/results.csv";
  writeFileAtomically(path, "old");
  // A child process with a 16-byte file-size limit tries to replace it with 100 bytes.
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    std::signal(SIGXFSZ, SIG_IGN);  // the write then fails with EFBIG instead of killing us
    const rlimit limit{16, 16};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    try {
      writeFileAtomically(path, std::string(100, 'n'));
    } catch (const Error& e) {
      _exit(std::string(e.what()).find("cannot write " + path) == 0 ? 0 : 3);
    }
    _exit(4);  // no error: the test fails
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "3: the error does not name the file; 4: no error";
  EXPECT_EQ(readFile(path), "old");
  EXPECT_EQ(filesIn(dir), 1);  // the temporary was removed
  // A directory that does not exist.
  EXPECT_THROW(writeFileAtomically(dir + "/missing/x", "y"), Error);
  fs::remove_all(dir);
}

TEST(AtomicFile, AppendsAndCreates) {
  const std::string dir = scratchDir("append");
  const std::string path = dir + "/log.txt";
  appendToFile(path, "one\n");
  appendToFile(path, "two\n");
  EXPECT_EQ(readFile(path), "one\ntwo\n");
  EXPECT_THROW(appendToFile(dir + "/missing/log.txt", "x"), Error);
  fs::remove_all(dir);
}

TEST(AtomicFile, RemovesOnlyTheTemporariesOfTheDirectoryItself) {
  const std::string dir = scratchDir("leftovers");
  for (const char* name : {"summary.json", "summary.json.tmp.123", "trajectory.csv.tmp.9", "notes.tmp"})
    writeFileAtomically(dir + "/" + name, "x");
  fs::create_directories(dir + "/sub");
  writeFileAtomically(dir + "/sub/a.tmp.5", "x");
  removeLeftoverTemporaries(dir);
  EXPECT_TRUE(fs::exists(dir + "/summary.json"));
  EXPECT_TRUE(fs::exists(dir + "/notes.tmp"));
  EXPECT_FALSE(fs::exists(dir + "/summary.json.tmp.123"));
  EXPECT_FALSE(fs::exists(dir + "/trajectory.csv.tmp.9"));
  EXPECT_TRUE(fs::exists(dir + "/sub/a.tmp.5"));  // not recursive
  fs::remove_all(dir);
}

TEST(AtomicFile, ReadingAMissingFileNamesIt) {
  try {
    readFile("/nonexistent/wiggle/file.toml");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/wiggle/file.toml"), std::string::npos);
  }
}

}  // namespace
}  // namespace wiggle
