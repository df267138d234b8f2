// `wiggle report DIR [--out FILE]`: one self-contained HTML page of a sweep directory (its status,
// a table of its cases, its figures embedded), for a browser or an e-mail. C++ computes, Python
// draws (as for `wiggle plot`): the status is `wiggle status`'s (sweep/SweepStatus.h), handed to the
// plotting package as JSON, which reads results.csv, draws the figures if DIR/figures lacks them and
// writes the page (python/wiggleplot/htmlreport.py).
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "Commands.h"
#include "PathChecks.h"
#include "core/Error.h"
#include "sweep/SweepStatus.h"

namespace wiggle::cli {

namespace {

// A file in the temporary directory holding `content`, removed when this goes out of scope.
class TemporaryFile {
 public:
  explicit TemporaryFile(const std::string& content) {
    std::string pattern = (std::filesystem::temp_directory_path() / "wiggle-report-XXXXXX").string();
    const int fd = ::mkstemp(pattern.data());
    if (fd < 0) throw Error("cannot create a temporary file " + pattern + ": " + std::strerror(errno));
    path_ = pattern;
    const bool written = ::write(fd, content.data(), content.size()) == static_cast<ssize_t>(content.size());
    const int writeErrno = errno;
    ::close(fd);
    if (!written) {
      std::remove(path_.c_str());
      throw Error("cannot write the temporary file " + path_ + ": " + std::strerror(writeErrno));
    }
  }
  ~TemporaryFile() { std::remove(path_.c_str()); }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace

void addReportCommand(CLI::App& app) {
  struct Options {
    std::string dir;
    std::string out;
  };
  auto opts = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "report",
      "One self-contained HTML page of a sweep directory: status, a table of the cases, the figures "
      "(drawn first if DIR/figures lacks them; python3 + matplotlib)");
  cmd->add_option("dir", opts->dir, "Sweep directory (wiggle sweep --out DIR)")->required();
  cmd->add_option("--out", opts->out,
                  "the HTML file to write (default DIR/report.html; its directory must exist; replaced whole)");
  cmd->callback([opts] {
    const SweepStatus status = readSweepStatus(opts->dir);  // Error: not a sweep directory
    const std::string out = opts->out.empty() ? opts->dir + "/report.html" : opts->out;
    requireOutputFile(opts->out.empty() ? out : "--out " + out, out);
    const TemporaryFile statusFile(sweepStatusJson(status));
    if (int rc = runPlotter({opts->dir, "--html", out, "--status", statusFile.path()}); rc != 0) {
      // The plotter already printed its one-line reason; pass its status through silently.
      throw CLI::RuntimeError(rc);
    }
  });
}

}  // namespace wiggle::cli
