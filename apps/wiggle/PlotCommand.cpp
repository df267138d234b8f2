// `wiggle plot DIR [--format png,pdf] [--movie] [--times ...] [--out OUT] [--geometry F.json...]`:
// draws a run or sweep directory by running the plotting package (python/wiggleplot) under
// Debian's /usr/bin/python3. Python draws, C++ computes: the package only reads the files the
// other commands wrote (docs/OUTPUT-FORMATS.md), so this command just finds it and runs it.
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "Commands.h"
#include "PathChecks.h"
#include "core/Error.h"

extern char** environ;

namespace wiggle::cli {

namespace {

namespace fs = std::filesystem;

// The interpreter is Debian's, which carries python3-matplotlib and python3-numpy; a pyenv or
// venv python3 earlier on PATH usually lacks them.
// Debian's python3, which has Debian's matplotlib, numpy and pandas; WIGGLE_PYTHON chooses another
// interpreter (a virtual environment, a conda python) that has them.
std::string pythonInterpreter() {
  const char* env = std::getenv("WIGGLE_PYTHON");
  return env != nullptr && *env != '\0' ? env : "/usr/bin/python3";
}

bool holdsPackage(const fs::path& dir) {
  std::error_code ec;
  return fs::is_regular_file(dir / "wiggleplot" / "__main__.py", ec);
}

fs::path executableDir() {
  std::error_code ec;
  fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : self.parent_path();
}

// Where the package lives, first match wins: $WIGGLE_PYTHONPATH (must hold it), an installed
// tree (<prefix>/bin/wiggle next to <prefix>/share/wiggle/python), then the source tree this
// binary was built from.
fs::path packageDir() {
  if (const char* env = std::getenv("WIGGLE_PYTHONPATH"); env != nullptr && *env != '\0') {
    if (!holdsPackage(env)) {
      throw Error(std::string("WIGGLE_PYTHONPATH=") + env + " holds no wiggleplot/__main__.py");
    }
    return fs::path(env);
  }
  std::vector<fs::path> tried;
  if (fs::path exe = executableDir(); !exe.empty()) {
    tried.push_back((exe / ".." / "share" / "wiggle" / "python").lexically_normal());
  }
  tried.push_back(fs::path(WIGGLE_SOURCE_DIR) / "python");
  for (const auto& dir : tried) {
    if (holdsPackage(dir)) return dir;
  }
  std::string where;
  for (const auto& dir : tried) where += (where.empty() ? "" : ", ") + dir.string();
  throw Error("plotting package wiggleplot not found (looked in " + where +
              "; set WIGGLE_PYTHONPATH to the directory holding wiggleplot/)");
}

// The child's environment: ours, with the package directory first on PYTHONPATH and a
// non-interactive matplotlib backend unless the user chose one.
std::vector<std::string> childEnvironment(const fs::path& package) {
  std::vector<std::string> env;
  std::string pythonPath = "PYTHONPATH=" + package.string();
  bool haveBackend = false;
  for (char** e = environ; *e != nullptr; ++e) {
    std::string entry(*e);
    if (entry.rfind("PYTHONPATH=", 0) == 0) {
      if (entry.size() > 11) pythonPath += ":" + entry.substr(11);
      continue;
    }
    if (entry.rfind("MPLBACKEND=", 0) == 0) haveBackend = true;
    env.push_back(std::move(entry));
  }
  env.push_back(pythonPath);
  if (!haveBackend) env.emplace_back("MPLBACKEND=Agg");
  return env;
}

std::vector<char*> pointers(std::vector<std::string>& strings) {
  std::vector<char*> out;
  for (auto& s : strings) out.push_back(s.data());
  out.push_back(nullptr);
  return out;
}

}  // namespace

// Runs `PYTHON -m wiggleplot ARGS...` (pythonInterpreter()) and returns its exit status (128 + signal when it
// was killed). Other commands (e.g. `wiggle run` drawing its figures at the end) may declare and
// call it. Throws Error when python3 or the package is missing; the package itself reports a
// missing matplotlib or numpy in one line and exits with status 3.
int runPlotter(const std::vector<std::string>& args) {
  const std::string python = pythonInterpreter();
  if (access(python.c_str(), X_OK) != 0) {
    throw Error(
        "python3 not found at " + python +
        " (install Debian's python3 and python3-matplotlib, or set WIGGLE_PYTHON to a python3 that has matplotlib)");
  }
  std::vector<std::string> argv = {python, "-m", "wiggleplot"};
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<std::string> env = childEnvironment(packageDir());
  auto argvPtr = pointers(argv);
  auto envPtr = pointers(env);
  pid_t pid = 0;
  if (int rc = posix_spawn(&pid, python.c_str(), nullptr, nullptr, argvPtr.data(), envPtr.data()); rc != 0) {
    throw Error("cannot start " + python + ": " + std::strerror(rc));
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw Error(std::string("waiting for the plotter failed: ") + std::strerror(errno));
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return 1;
}

void addPlotCommand(CLI::App& app) {
  struct Options {
    std::string dir;
    std::string format = "png,pdf";
    bool movie = false;
    std::string times;
    std::string out;
    std::vector<std::string> geometry;
  };
  auto opts = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "plot",
      "Draw the figures of a run or sweep directory into DIR/figures (python3 + matplotlib)");
  cmd->add_option("dir", opts->dir, "run directory (summary.json, trajectory.csv, ...) or sweep "
                                    "directory (results.csv); the kind is detected from the files");
  cmd->add_option("--format", opts->format, "comma-separated figure formats")->capture_default_str();
  cmd->add_flag("--movie", opts->movie, "also write figures/movie.mp4 from the dump frames (ffmpeg)");
  cmd->add_option("--times", opts->times,
                  "snapshot times, comma-separated [sqrt(d/g)] (default: up to 6 spread over the run)");
  cmd->add_option("--out", opts->out, "output directory (default DIR/figures; made if missing, its parent must exist)");
  cmd->add_option("--geometry", opts->geometry,
                  "intruder geometry files from `wiggle model --geometry` to draw (paper fig. 13)");
  cmd->callback([opts] {
    if (opts->dir.empty() && opts->geometry.empty()) {
      throw Error("plot: give a run or sweep directory, or --geometry FILE.json ...");
    }
    requireOutputDirectory("--out", opts->out);  // the plotter creates it (python/wiggleplot/cli.py)
    std::vector<std::string> args;
    if (!opts->dir.empty()) args.push_back(opts->dir);
    args.insert(args.end(), {"--format", opts->format});
    if (opts->movie) args.emplace_back("--movie");
    if (!opts->times.empty()) args.insert(args.end(), {"--times", opts->times});
    if (!opts->out.empty()) args.insert(args.end(), {"--out", opts->out});
    if (!opts->geometry.empty()) {
      args.emplace_back("--geometry");
      args.insert(args.end(), opts->geometry.begin(), opts->geometry.end());
    }
    if (int rc = runPlotter(args); rc != 0) {
      // The plotter already printed its one-line reason; pass its status through silently.
      throw CLI::RuntimeError(rc);
    }
  });
}

}  // namespace wiggle::cli
