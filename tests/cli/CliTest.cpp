// The `wiggle` command line as a user meets it, by running the built binary (WIGGLE_BINARY): every
// command-line error is one line "wiggle: ..." naming the argument, with exit status 2, while
// --help and --version exit 0; a config or sweep file that is a directory, FIFO or device is
// refused before anything is written; --out creates at most its last component (issue 18).
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Result {
  int status = -1;  // exit status; -1 when killed or not run
  std::string out, err;
  // stderr's lines (without the final newline).
  std::vector<std::string> errLines() const {
    std::vector<std::string> lines;
    std::istringstream in(err);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
  }
};

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    char tmpl[] = "/tmp/wiggle-cli-test-XXXXXX";
    ASSERT_NE(mkdtemp(tmpl), nullptr);
    root_ = tmpl;
    work_ = root_ / "work";  // the commands' current directory: must stay empty on errors
    fs::create_directories(work_);
    logs_ = root_ / "logs";
    fs::create_directories(logs_);
  }
  void TearDown() override { fs::remove_all(root_); }

  // Runs `wiggle ARGS` (shell words, already quoted where needed) in work_, bounded by a timeout so
  // that a regression (a bad path accepted and a simulation started) fails instead of hanging.
  // `environment`: more VAR=value words for the command's environment.
  Result wiggle(const std::string& args, const std::string& environment = "") const {
    const std::string cmd = "cd " + quoted(work_.string()) + " && WIGGLE_CACHE=" + quoted((root_ / "cache").string()) +
                            " " + environment + " timeout 120 " + quoted(WIGGLE_BINARY) + " " + args + " >" +
                            quoted((logs_ / "out").string()) + " 2>" + quoted((logs_ / "err").string()) +
                            " </dev/null";
    const int raw = std::system(cmd.c_str());
    Result r;
    if (raw != -1 && WIFEXITED(raw)) r.status = WEXITSTATUS(raw);
    r.out = slurp(logs_ / "out");
    r.err = slurp(logs_ / "err");
    return r;
  }

  // A valid run config of a tiny case (about 230 grains), its bed cached under root_: should a
  // check below ever let it through, the command still ends in seconds.
  std::string tinyConfig() const {
    const fs::path path = root_ / "tiny.toml";
    std::ofstream(path) << "[box]\nwidth = 20.0\nbed_height = 12.0\nseed = 1\n"
                        << "[intruder]\nshape = \"polygon\"\nvertices = [[-1.5, -1.5], [1.5, -1.5], [1.5, 1.5], "
                           "[-1.5, 1.5]]\ny0 = 6.0\n"
                        << "[drive]\namplitude = 0.5\nperiod = 1.0\n"
                        << "[bed]\nrest_energy = 1e-4\nmax_time = 100.0\n"
                        << "[run]\ndt = 0.0001\nduration = 0.01\nsample_interval = 0.005\ndump_interval = 0.0\n"
                        << "plot = false\n[fields]\nenabled = false\n";
    return path.string();
  }

  // A sweep file whose only case fails its geometry check at once (a self-intersecting outline).
  std::string quickSweep() const {
    const fs::path path = root_ / "quick.toml";
    std::ofstream(path) << "[sweep]\nname = \"quick\"\n[base.intruder]\nshape = \"polygon\"\n"
                        << "vertices = [[0,0],[4,4],[4,0],[0,4]]\n";
    return path.string();
  }

  bool workIsEmpty() const { return fs::is_empty(work_); }

  // One line on stderr, starting "wiggle: " and holding every word of `words`; exit status 2.
  static void expectOneLineError(const Result& r, const std::vector<std::string>& words, const std::string& what) {
    EXPECT_EQ(r.status, 2) << what << ": " << r.err;
    const auto lines = r.errLines();
    ASSERT_EQ(lines.size(), 1u) << what << ": " << r.err;
    EXPECT_EQ(lines[0].rfind("wiggle: ", 0), 0u) << what << ": " << lines[0];
    for (const std::string& w : words)
      EXPECT_NE(lines[0].find(w), std::string::npos) << what << ": no '" << w << "' in " << lines[0];
  }

  fs::path root_, work_, logs_;
};

TEST_F(Cli, HelpAndVersionExitZero) {
  Result r = wiggle("--help");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("Subcommands:"), std::string::npos) << r.out;
  r = wiggle("--version");
  EXPECT_EQ(r.status, 0) << r.err;
  // The release and the git revision the binary was built from (unknown outside a checkout).
  EXPECT_EQ(r.out.rfind(std::string("wiggle ") + WIGGLE_VERSION + " (git ", 0), 0u) << r.out;
  EXPECT_EQ(r.out.substr(r.out.size() - 2), ")\n") << r.out;
  // Every subcommand has a help of its own and is offered by the bash completion.
  std::ifstream completionFile(std::string(WIGGLE_SOURCE_DIR) + "/tools/completion/wiggle.bash");
  std::stringstream completion;
  completion << completionFile.rdbuf();
  const std::string text = completion.str();
  const auto listStart = text.find("local commands=\"");
  ASSERT_NE(listStart, std::string::npos);
  const std::string offered = " " + text.substr(listStart + 16, text.find('"', listStart + 16) - listStart - 16) + " ";
  // The subcommands the main help lists (the indented names under "Subcommands:").
  std::vector<std::string> subcommands;
  {
    std::istringstream help(wiggle("--help").out);
    bool listing = false;
    for (std::string line; std::getline(help, line);) {
      if (line == "Subcommands:")
        listing = true;
      else if (listing && line.rfind("  ", 0) == 0 && line.size() > 2 && line[2] != ' ')
        subcommands.push_back(line.substr(2, line.find(' ', 2) - 2));
      else if (listing && line.empty())
        break;
    }
  }
  EXPECT_GE(subcommands.size(), 9u);
  for (const std::string& sub : subcommands) {
    r = wiggle(sub + " --help");
    EXPECT_EQ(r.status, 0) << sub << ": " << r.err;
    EXPECT_NE(r.out.find("wiggle " + sub), std::string::npos) << r.out;
    EXPECT_EQ(r.err, "") << sub;
    EXPECT_NE(offered.find(" " + sub + " "), std::string::npos) << sub << " is not in the completion's list";
    // Each option its help lists is offered after it: the completion's "SUB) options=..." line.
    const auto line = text.find("    " + sub + ") options=\"");
    ASSERT_NE(line, std::string::npos) << sub << " has no options line in the completion";
    const auto open = text.find('"', line) + 1;
    const std::string options = " " + text.substr(open, text.find('"', open) - open) + " ";
    std::istringstream help(r.out);
    bool listing = false;
    for (std::string helpLine; std::getline(help, helpLine);) {
      if (helpLine == "Options:") listing = true;
      const auto dash = helpLine.find("--");
      if (!listing || helpLine.rfind("  -", 0) != 0 || dash == std::string::npos) continue;
      const std::string option = helpLine.substr(dash, helpLine.find_first_of(" ,", dash) - dash);
      EXPECT_NE(options.find(" " + option + " "), std::string::npos) << sub << " " << option << " is not offered";
    }
  }
}

TEST_F(Cli, ParseErrorsAreOneLineNamingTheArgumentWithStatus2) {
  // CLI11 exits 105/106/109/114 by itself; every one of these is bad input.
  struct Case {
    const char* args;
    std::vector<std::string> words;
  };
  const std::vector<Case> cases = {
      {"", {"no command given", "run, sweep, model, plot, export-lammps"}},
      {"rn", {"unknown command 'rn'", "run, sweep"}},
      {"--bogus", {"no command given; not expected: --bogus"}},
      {"--bogus run", {"wiggle: The following argument was not expected: --bogus (see wiggle --help)"}},
      {"run --threads abc", {"run: ", "--threads", "abc", "wiggle run --help"}},
      {"run --threads 0", {"--threads", "0", "not in range"}},
      {"run --bogus", {"run: ", "--bogus", "not expected"}},
      {"run a b c", {"The following arguments were not expected: b c"}},
      {"run --out", {"--out", "missing"}},
      {"sweep --jobs 0", {"sweep: ", "--jobs", "0"}},
      {"model --angle x", {"model: ", "--angle", "x"}},
      {"plot --format", {"plot: ", "--format"}},
      {"export-lammps", {"export-lammps: ", "--out", "required"}},
      {"report", {"report: ", "dir", "required"}},
      {"report . --out", {"report: ", "--out", "missing"}},
  };
  for (const Case& c : cases) {
    const Result r = wiggle(c.args);
    expectOneLineError(r, c.words, std::string("wiggle ") + c.args);
    EXPECT_EQ(r.out, "") << c.args;
  }
  EXPECT_TRUE(workIsEmpty());
}

TEST_F(Cli, BoundaryRefusesBadInputInOneLineBeforeAnythingIsWritten) {
  struct Case {
    const char* args;
    std::vector<std::string> words;
  };
  const std::vector<Case> cases = {
      {"boundary --resolution 0.1 --out o", {"--range LO:HI is required"}},
      {"boundary --range 1-5 --resolution 0.1 --out o", {"--range 1-5", "LO:HI"}},
      {"boundary --range 1:x --resolution 0.1 --out o", {"--range", "'x' is not a number"}},
      {"boundary --range 1:5 --out o", {"--resolution", "required"}},
      {"boundary --range 1:5 --resolution 0 --out o", {"--resolution 0", "must be positive"}},
      {"boundary --range 1:5 --resolution 0.1 --scatter -0.1 --out o", {"--scatter -0.1", "zero or positive"}},
      {"boundary --range 1:5 --resolution 0.1 --out no/such/dir --dry-run",
       {"--out no/such/dir", "parent directory", "does not exist"}},
      {"boundary --range 5:1 --resolution 0.1 --out o", {"range", "LO < HI"}},
      {"boundary --range 1:5 --resolution 0.1", {"--out DIR is required"}},
      {"boundary --range 1:5 --resolution 0.1 --vary box.seed --out o", {"--vary box.seed", "not a real-valued key"}},
      {"boundary --range 1:5 --resolution 0.1 --vary drive.perod --out o",
       {"--vary drive.perod", "no such config key"}},
      {"boundary --range 1:5 --resolution 0.00015 --out o", {"drive.period = 1.00015", "whole number of run.dt"}},
      {"boundary --range 1:5 --resolution 0.1 --over drive.amplitude --out o", {"--over", "KEY=V1,V2"}},
      {"boundary --range 1:5 --resolution 0.1 --over drive.amplitude=1,1 --out o", {"given twice"}},
      {"boundary --range 1:5 --resolution 0.1 --rate fast --out o", {"--rate fast", "paper or settled"}},
      {"boundary --range 1:5 --resolution 0.1 --beds 1:3 --out o", {"2 beds"}},
      {"boundary --range 1:5 --resolution 0.1 --beds 2.5:4 --out o", {"--beds", "'2.5' is not a whole number"}},
      {"boundary --range 1:5 --resolution 0.1 --points 1 --out o", {"--points"}},
  };
  for (const Case& c : cases) {
    const Result r = wiggle(c.args);
    expectOneLineError(r, c.words, std::string("wiggle ") + c.args);
    EXPECT_EQ(r.out, "") << c.args;
  }
  EXPECT_TRUE(workIsEmpty());
  // --dry-run lists the first round (5 values x 2 beds) and writes nothing.
  const Result r = wiggle("boundary --range 1:5 --resolution 0.25 --dry-run");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("first round: 10 runs"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("drive.period = 3, box.seed = 2"), std::string::npos) << r.out;
  EXPECT_TRUE(workIsEmpty());
}

TEST_F(Cli, ConfigThatIsNotARegularFileIsRefusedBeforeAnythingIsWritten) {
  const fs::path dir = root_ / "configs";
  fs::create_directories(dir);
  const fs::path fifo = root_ / "fifo.toml";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  const std::string out = (root_ / "out").string();
  const std::string quick = " --set run.duration=0.01 --set run.plot=false --out " + quoted(out);
  struct Case {
    std::string args;
    std::vector<std::string> words;
  };
  const std::vector<Case> cases = {
      {"run " + quoted(dir.string()) + quick, {"config file '" + dir.string() + "' is a directory, not a file"}},
      {"run " + quoted(fifo.string()) + quick, {"config file '" + fifo.string() + "' is not a regular file"}},
      {"run /dev/null" + quick, {"config file '/dev/null' is not a regular file"}},
      {"run " + quoted((root_ / "missing.toml").string()) + quick, {"missing.toml' does not exist"}},
      {"export-lammps " + quoted(dir.string()) + " --out " + quoted(out), {"config file '" + dir.string() + "' is a directory"}},
      {"export-lammps " + quoted(fifo.string()) + " --out " + quoted(out), {"is not a regular file"}},
      {"sweep " + quoted(dir.string()), {"sweep file '" + dir.string() + "' is a directory, not a file"}},
      {"sweep " + quoted(dir.string()) + " --dry-run", {"sweep file '" + dir.string() + "' is a directory"}},
      {"sweep " + quoted(fifo.string()) + " --out " + quoted(out), {"sweep file '" + fifo.string() + "' is not a regular file"}},
      {"sweep --make-bed " + quoted(dir.string()), {"config file '" + dir.string() + "' is a directory"}},
  };
  for (const Case& c : cases) {
    const Result r = wiggle(c.args);
    expectOneLineError(r, c.words, c.args);
    EXPECT_FALSE(fs::exists(out)) << c.args;
    EXPECT_TRUE(workIsEmpty()) << c.args;  // e.g. no wiggle-out/ nor sweep-configs/
  }
  EXPECT_TRUE(fs::is_empty(dir));
  EXPECT_FALSE(fs::exists(root_ / "cache"));  // no bed made either
}

// WIGGLE_SIMD (ForceKernels.h) is checked before a command writes anything.
TEST_F(Cli, BadSimdLevelInTheEnvironmentIsRefusedBeforeAnythingIsWritten) {
  const std::string out = (root_ / "out").string();
  for (const std::string& args : {"run " + tinyConfig() + " --out " + quoted(out),
                                  "run " + tinyConfig() + " --check --out " + quoted(out),
                                  "export-lammps " + tinyConfig() + " --out " + quoted(out),
                                  "sweep " + quickSweep() + " --out " + quoted(out)}) {
    expectOneLineError(wiggle(args, "WIGGLE_SIMD=avx9"), {"WIGGLE_SIMD=avx9", "scalar, avx2, avx512"}, args);
    EXPECT_FALSE(fs::exists(out)) << args;
  }
  EXPECT_FALSE(fs::exists(root_ / "cache"));
  EXPECT_EQ(wiggle("run " + tinyConfig() + " --check --out " + quoted(out), "WIGGLE_SIMD=scalar").status, 0);
}

TEST_F(Cli, OutCreatesAtMostItsLastComponent) {
  const fs::path missing = root_ / "nonexistent";
  const std::string deep = (missing / "deep" / "dir").string();
  const std::string parent = (missing / "deep").string();
  const std::string config = tinyConfig();
  const std::string sweep = quickSweep();
  const fs::path runDir = root_ / "rundir";  // looks like a run directory to the plotter
  fs::create_directories(runDir);
  std::ofstream(runDir / "summary.json") << "{}\n";
  const fs::path aFile = root_ / "a_file";
  std::ofstream(aFile) << "x\n";
  for (const std::string& command : {"run " + quoted(config), "sweep " + quoted(sweep), "export-lammps " + quoted(config),
                                     "plot " + quoted(runDir.string())}) {
    Result r = wiggle(command + " --out " + quoted(deep));
    EXPECT_EQ(r.err, "wiggle: --out " + deep + ": parent directory " + parent + " does not exist\n") << command;
    EXPECT_EQ(r.status, 2) << command;
    EXPECT_FALSE(fs::exists(missing)) << command << " created " << missing;
    // A trailing slash names the same directory.
    r = wiggle(command + " --out " + quoted(deep + "/"));
    EXPECT_EQ(r.status, 2) << command;
    EXPECT_NE(r.err.find("parent directory " + parent + " does not exist"), std::string::npos) << r.err;
    // A file where the output directory should be, or under it.
    r = wiggle(command + " --out " + quoted(aFile.string()));
    expectOneLineError(r, {"--out " + aFile.string() + ": exists and is not a directory"}, command);
    r = wiggle(command + " --out " + quoted((aFile / "x").string()));
    expectOneLineError(r, {"--out " + (aFile / "x").string() + ": parent " + aFile.string() + " is not a directory"},
                       command);
    EXPECT_FALSE(fs::exists(missing)) << command;
    EXPECT_TRUE(workIsEmpty()) << command;
  }
  EXPECT_FALSE(fs::exists(root_ / "cache"));  // refused before the bed was made
  // The last component alone is created: the sweep makes its directory and records the case failed.
  const std::string fresh = (root_ / "fresh").string();
  const Result r = wiggle("sweep " + quoted(sweep) + " --out " + quoted(fresh));
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_TRUE(fs::is_regular_file(fresh + "/results.csv")) << r.err;
}

TEST_F(Cli, PlotOutThatCannotBeCreatedIsOneLineWithStatus2) {
  if (access("/usr/bin/python3", X_OK) != 0) GTEST_SKIP() << "no /usr/bin/python3";
  const fs::path runDir = root_ / "rundir";
  fs::create_directories(runDir);
  std::ofstream(runDir / "summary.json") << "{}\n";
  const Result r = wiggle("plot " + quoted(runDir.string()) + " --out /proc/nope");
  EXPECT_EQ(r.status, 2) << r.err;
  const auto lines = r.errLines();
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_EQ(lines[0].rfind("wiggleplot: --out /proc/nope: cannot create the directory", 0), 0u) << lines[0];
  EXPECT_EQ(lines[0].find("Errno"), std::string::npos) << lines[0];
  EXPECT_FALSE(fs::exists(runDir / "figures"));
}

}  // namespace

namespace {

TEST_F(Cli, RunCheckPrintsWhatTheRunWouldBeAndWritesNothing) {
  const std::string config = tinyConfig();
  Result r = wiggle("run " + quoted(config) + " --check --out checked");
  EXPECT_EQ(r.status, 0) << r.err;
  for (const char* what : {"config ok: polygon intruder", "about", "grains", "bed ", "not cached", "run: 100 steps",
                           "out: checked (new)"})
    EXPECT_NE(r.out.find(what), std::string::npos) << "no '" << what << "' in\n" << r.out;
  EXPECT_TRUE(workIsEmpty());                     // no output directory, no wiggle-out/
  EXPECT_FALSE(fs::exists(root_ / "cache"));      // no bed made
  // A config the run would refuse is refused the same way: one line, exit 2, nothing written.
  r = wiggle("run " + quoted(config) + " --check --set drive.amplitude=40");
  expectOneLineError(r, {"box.width", "too narrow"}, "--check, amplitude 40");
  EXPECT_TRUE(workIsEmpty());
  // An --out the run could not make or write is what --check is for: one line, exit 2 (/proc
  // refuses a new directory even to root; a read-only directory refuses another user).
  r = wiggle("run " + quoted(config) + " --check --out /proc/nope");
  expectOneLineError(r, {"--out /proc/nope", "cannot create the directory"}, "--check, --out /proc/nope");
  EXPECT_FALSE(fs::exists("/proc/nope"));
  fs::create_directories(work_ / "existing");
  r = wiggle("run " + quoted(config) + " --check --out existing");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::is_empty(work_ / "existing"));  // the probe is gone
  fs::remove(work_ / "existing");
}

// `wiggle rate` on a run just made: the run's own window gives the summary's vy again (from
// trajectory.csv's 10 digits), as a CSV row; --write records vy_settled; bad options and paths are
// one line with status 2, and write nothing.
TEST_F(Cli, RateMeasuresAFinishedRunAgainAndRecordsTheSettledRate) {
  Result r = wiggle("run " + quoted(tinyConfig()) + " --set run.duration=0.2 --out run --threads 1");
  ASSERT_EQ(r.status, 0) << r.err;
  // Issue 80: a single run says what its number is worth; no study measured this bed's scatter.
  EXPECT_NE(r.out.find("\none bed: scatter unknown for a "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("run `beds = N`"), std::string::npos) << r.out;
  const std::string summaryBefore = slurp(work_ / "run" / "summary.json");
  r = wiggle("rate run");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("wiggle rate: one bed: scatter unknown for a "), std::string::npos) << r.err;
  std::istringstream table(r.out);
  std::string header, row;
  std::getline(table, header);
  std::getline(table, row);
  EXPECT_EQ(header, "run,period,t_i,t_f,vy,plateau,t_settled,vy_settled,settled");
  std::vector<std::string> cells;
  std::istringstream cellsIn(row);
  for (std::string cell; std::getline(cellsIn, cell, ',');) cells.push_back(cell);
  ASSERT_EQ(cells.size(), 9u) << row;
  EXPECT_EQ(cells[0], "run");
  const std::string summary = slurp(work_ / "run" / "summary.json");
  const std::size_t at = summary.find("\"vy\": ");
  ASSERT_NE(at, std::string::npos);
  EXPECT_NEAR(std::stod(cells[4]), std::stod(summary.substr(at + 6)), 1e-8);
  EXPECT_EQ(summary, summaryBefore);  // without --write nothing is written

  expectOneLineError(wiggle("rate run --band 0"), {"--band", "positive"}, "band 0");
  expectOneLineError(wiggle("rate run --write --to 0.1"), {"--write", "--to"}, "write with a window");
  expectOneLineError(wiggle("rate run --to 5"), {"--to 5", "past the end"}, "window past the end");
  expectOneLineError(wiggle("rate nowhere"), {"nowhere", "no such directory"}, "missing directory");
  EXPECT_EQ(slurp(work_ / "run" / "summary.json"), summaryBefore);

  r = wiggle("rate run --write");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(slurp(work_ / "run" / "summary.json").find("\"vy_settled\""), std::string::npos);

  // A run pinned to a bed file by a relative path is measured again from anywhere: the rates read
  // the trajectory, not the bed (a sweep of such cases read from another directory).
  std::string config = slurp(work_ / "run" / "config.toml");
  const std::size_t file = config.find("file = \"\"");
  ASSERT_NE(file, std::string::npos);
  config.replace(file, 9, "file = \"beds/elsewhere.bin\"");
  std::ofstream(work_ / "run" / "config.toml") << config;
  r = wiggle("rate run");
  EXPECT_EQ(r.status, 0) << r.err;
}

// `wiggle rate SWEEP_DIR` measures the finished cases (summary.json says ok) and leaves out a case
// still running, though it has the trajectory.csv of its steps so far; with --write it records the
// finished ones and writes nothing into the running one.
TEST_F(Cli, RateOfASweepLeavesOutACaseStillRunning) {
  Result r = wiggle("run " + quoted(tinyConfig()) + " --set run.duration=0.2 --out run --threads 1");
  ASSERT_EQ(r.status, 0) << r.err;
  const fs::path sweep = work_ / "sweep";
  fs::create_directories(sweep / "cases");
  fs::copy(work_ / "run", sweep / "cases" / "done", fs::copy_options::recursive);
  fs::create_directories(sweep / "cases" / "running");
  for (const char* file : {"config.toml", "trajectory.csv"})
    fs::copy_file(work_ / "run" / file, sweep / "cases" / "running" / file);
  r = wiggle("rate sweep");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 2) << r.out;  // the header and the finished case
  EXPECT_NE(r.out.find("\ndone,"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("running,"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("1 case not finished left out"), std::string::npos) << r.err;
  r = wiggle("rate sweep --write");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(fs::exists(sweep / "cases" / "running" / "summary.json"));
  fs::remove_all(sweep);
  fs::remove_all(work_ / "run");
}

// A run or sweep stopped by SIGINT or SIGTERM saves its work and exits 128 + the signal (130, 143),
// not 2 (bad input), and not by dying of the signal: scripts and Slurm tell "resume me" from "fix
// your input". The process is started directly (fork/exec: no shell in between to translate a
// death by signal into 128 + N) and signalled once it has started work (its log or results exist).
struct Stopped {
  bool started = false;  // the file it waited for appeared before the signal
  bool exited = false;
  int status = -1;
  std::string err;
};

Stopped startAndSignal(const std::vector<std::string>& args, const fs::path& startedWhen, int signal,
                       const fs::path& errPath, const fs::path& cache) {
  const pid_t pid = fork();
  if (pid == 0) {
    setenv("WIGGLE_CACHE", cache.c_str(), 1);
    const int fd = ::open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, 2);
    const int null = ::open("/dev/null", O_WRONLY);
    dup2(null, 1);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  // Waits by event, not by a clock: a bed made under the sanitizers can take minutes, and a signal
  // sent before `startedWhen` appears would land in another stage than the test means.
  int raw = 0;
  bool ended = false;
  for (int i = 0; i < 6000 && !fs::exists(startedWhen) && !ended; ++i) {
    usleep(100000);
    ended = waitpid(pid, &raw, WNOHANG) == pid;
  }
  Stopped s;
  s.started = fs::exists(startedWhen);
  if (!ended) {
    if (s.started) usleep(1500000);  // past the start: the signal handlers are in place, a bed or the run is under way
    kill(pid, signal);
    waitpid(pid, &raw, 0);
  }
  s.exited = WIFEXITED(raw);
  s.status = s.exited ? WEXITSTATUS(raw) : -1;
  s.err = slurp(errPath);
  return s;
}

// `wiggle plot` runs the python3 that WIGGLE_PYTHON names (a virtual environment's, say), not
// always /usr/bin/python3; one that is not there is one line naming it.
TEST_F(Cli, PlotRunsThePythonThatWigglePythonNames) {
  const fs::path fake = root_ / "python3";
  std::ofstream(fake) << "#!/bin/sh\necho \"$@\" > " << quoted((root_ / "args").string()) << "\n";
  fs::permissions(fake, fs::perms::owner_all);
  fs::create_directories(work_ / "run");
  Result r = wiggle("plot run", "WIGGLE_PYTHON=" + quoted(fake.string()));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(slurp(root_ / "args"), "-m wiggleplot run --format png,pdf\n");
  r = wiggle("plot run", "WIGGLE_PYTHON=/nonexistent/python3");
  expectOneLineError(r, {"/nonexistent/python3", "WIGGLE_PYTHON"}, "WIGGLE_PYTHON missing");
  fs::remove_all(work_ / "run");
}

TEST_F(Cli, InterruptedRunsAndSweepsExit128PlusTheSignal) {
  // A bed of about 1,500 grains in its own cache: making it takes longer than the wait above.
  const fs::path config = root_ / "slow.toml";
  std::ofstream(config) << "[box]\nwidth = 40.0\nbed_height = 40.0\nseed = 3\n"
                        << "[run]\nduration = 50.0\nplot = false\ndump_interval = 0.0\n[fields]\nenabled = false\n";
  for (const auto& [signal, expected] : {std::pair{SIGINT, 130}, std::pair{SIGTERM, 143}}) {
    const fs::path out = work_ / ("run" + std::to_string(signal));
    const Stopped s =
        startAndSignal({WIGGLE_BINARY, "run", config.string(), "--out", out.string(), "--threads", "1"},
                       out / "log.txt", signal, logs_ / "err", root_ / ("cache" + std::to_string(signal)));
    EXPECT_TRUE(s.started) << "no log.txt: " << s.err;
    EXPECT_TRUE(s.exited) << "killed by the signal instead of stopping: " << s.err;
    EXPECT_EQ(s.status, expected) << s.err;
    EXPECT_NE(s.err.find("interrupted"), std::string::npos) << s.err;
  }
  const fs::path sweep = root_ / "slow-sweep.toml";
  std::ofstream(sweep) << "[sweep]\nname = \"slow\"\n[base.box]\nwidth = 40.0\nbed_height = 40.0\nseed = 4\n"
                       << "[base.run]\nduration = 50.0\nplot = false\ndump_interval = 0.0\n"
                       << "[base.fields]\nenabled = false\n[grid.drive]\nperiod = [1.0, 2.0]\n";
  const fs::path out = work_ / "sweep";
  const Stopped s = startAndSignal(
      {WIGGLE_BINARY, "sweep", sweep.string(), "--out", out.string(), "--jobs", "1", "--threads", "1", "--local"},
      out / "results.csv", SIGTERM, logs_ / "err", root_ / "cache-sweep");
  EXPECT_TRUE(s.started) << "no results.csv: " << s.err;
  EXPECT_TRUE(s.exited) << s.err;
  EXPECT_EQ(s.status, 143) << s.err;
  EXPECT_NE(s.err.find("rerun the same command to resume"), std::string::npos) << s.err;
  // Stopped while its bed was made: the bed is saved, not failed, and says so as a stopped case does.
  EXPECT_NE(s.err.find(" stopped: interrupted by signal 15 while making the bed"), std::string::npos) << s.err;
  EXPECT_EQ(s.err.find("failed"), std::string::npos) << s.err;
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Issue 53: a run stopped by Ctrl-C says where in its progress.json, and `wiggle status RUN_DIR`
// reports a single run (stopped, killed without a word, done) as it does a sweep.
TEST_F(Cli, StatusOfARunDirectorySaysWhereItStopped) {
  const fs::path out = work_ / "run";
  const Stopped s = startAndSignal({WIGGLE_BINARY, "run", tinyConfig(), "--set", "run.duration=50", "--set",
                                    "run.checkpoint_interval=0.2", "--out", out.string(), "--threads", "1"},
                                   out / "checkpoint.bin", SIGINT, logs_ / "err", root_ / "cache");
  ASSERT_TRUE(s.started) << "no checkpoint within 10 minutes: " << s.err;
  ASSERT_EQ(s.status, 130) << s.err;
  const std::string progress = slurp(out / "progress.json");
  EXPECT_NE(progress.find("\"stage\": \"interrupted at t = "), std::string::npos) << progress;
  EXPECT_NE(progress.find("\"phase\": \"interrupted\""), std::string::npos) << progress;
  Result r = wiggle("status run");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("run run: interrupted at t = ", 0), 0u) << r.out;
  EXPECT_NE(r.out.find(" of 50 ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("continue with: wiggle run --out run --resume"), std::string::npos) << r.out;

  // Killed outright, a run cannot say so: its last stage stays, and no process holds its lock.
  std::ofstream(out / "progress.json")
      << R"({"phase": "running", "stage": "running", "fraction": 0.25, "t": 12.5, "duration": 50, "eta_s": 60})";
  r = wiggle("status run");
  EXPECT_NE(r.out.find("run run: interrupted (its process ended without saying why: killed?) after t = 12.5 of 50 "
                       "(25 % of its steps)"),
            std::string::npos)
      << r.out;

  // Finished; a fresh run shorter than 0.25 (0.1 t_total off the sample grid) is not "extended".
  r = wiggle("run " + quoted(tinyConfig()) +
             " --set run.duration=0.12 --set run.sample_interval=0.04 --out done "
             "--threads 1");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("extended"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(work_ / "done" / "summary.json").find("extended"), std::string::npos);
  r = wiggle("status done");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("run done: done (t = 0.12): V_y = ", 0), 0u) << r.out;
}

// Issue 53: `--resume` on a directory that holds no run (a mistyped --out) is refused in one line
// before anything is written, instead of starting a new run there; a finished run is still rewritten.
TEST_F(Cli, ResumeWhereNoRunIsIsRefusedBeforeAnythingIsWritten) {
  expectOneLineError(wiggle("run " + quoted(tinyConfig()) + " --out nothere --resume --threads 1"),
                     {"--resume", "nothere", "holds no run"}, "resume of a missing directory");
  expectOneLineError(wiggle("run --out nothere --resume --check"), {"--resume", "nothere", "holds no run"},
                     "resume --check of a missing directory");
  EXPECT_TRUE(workIsEmpty());
  fs::create_directories(work_ / "empty");
  expectOneLineError(wiggle("run --out empty --resume --set run.duration=1"), {"--resume", "empty", "holds no run"},
                     "resume of an empty directory");
  EXPECT_TRUE(fs::is_empty(work_ / "empty"));
  EXPECT_FALSE(fs::exists(root_ / "cache"));

  ASSERT_EQ(wiggle("run " + quoted(tinyConfig()) + " --out done --threads 1").status, 0);
  const Result r = wiggle("run --out done --resume --threads 1");
  EXPECT_EQ(r.status, 0) << r.err;
}

// Issue 53: the sweep's final line is said once (it was printed as an event and again by the
// command), for a whole sweep and for one case.
TEST_F(Cli, SweepSaysItsSummaryOnce) {
  for (const std::string& only : {std::string(), std::string(" --case 1")}) {
    const Result r = wiggle("sweep " + quoted(quickSweep()) + " --out sweep --jobs 1 --threads 1" + only);
    EXPECT_EQ(r.status, 1) << r.err;  // its case fails its geometry check
    EXPECT_EQ(occurrences(r.out + r.err, "sweep sweep: "), 1u) << only << ": " << r.out << r.err;
  }
}

// Issue 53: a trajectory shorter than its config's run.duration (a LAMMPS run of the exported deck
// for fewer steps, `lmp -var nsteps N`) is measured to its end, and said so; --to past it is refused.
TEST_F(Cli, RateMeasuresAShorterTrajectoryToItsEnd) {
  ASSERT_EQ(wiggle("run " + quoted(tinyConfig()) + " --set run.duration=0.2 --out run --threads 1").status, 0);
  std::string config = slurp(work_ / "run" / "config.toml");
  const std::size_t at = config.find("\nduration = 0.2 ");  // [run]'s (a comment follows the value)
  ASSERT_NE(at, std::string::npos) << config;
  config.replace(at, 15, "\nduration = 100 ");
  std::ofstream(work_ / "run" / "config.toml") << config;
  const Result r = wiggle("rate run");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\nrun,1,0.02,0.2,"), std::string::npos) << r.out;  // t_i = 0.1 x 0.2, t_f = 0.2
  EXPECT_NE(r.err.find("trajectory.csv ends at t = 0.2, before the config's run.duration"), std::string::npos) << r.err;
  expectOneLineError(wiggle("rate run --to 5"), {"--to 5", "past the end"}, "--to past the end");
}
}  // namespace

namespace wiggle {
namespace {

// `wiggle status DIR` on a sweep directory as a stopped sweep leaves it: every state counted, the
// running case's progress from its progress.json, the failure's error (a quoted CSV cell with a comma), the
// estimate from the finished cases over the sweep's jobs, and no sweep holding the directory.
TEST_F(Cli, StatusSummarisesASweepDirectory) {
  const fs::path dir = root_ / "sweep";
  fs::create_directories(dir / "cases" / "b");
  fs::create_directories(dir / "cases" / "a");
  std::ofstream(dir / "cases" / "a" / "summary.json")
      << R"({"status": "ok", "vy": 0.1, "warnings": ["V_y is measured over 1.5 drive periods"]})";
  std::ofstream(dir / "results.csv")
      << "case,run_dir,status,vy,vy_slope,wall_s,drive.period,n_grains,steps,ns_per_particle_step,state_hash,error,"
         "warnings\n"
      << "a,cases/a,ok,0.1,0.1,600,5,100,1000,50,abc,,V_y is measured over 1.5 drive periods\n"
      << "b,cases/b,running,,,,3,,,,,,\n"
      << "c,cases/c,failed,,,,1,,,,,\"box.width = 5 is too narrow, really\",\n"
      << "d,cases/d,pending,,,,2,,,,,,\n";
  // An earlier wiggle's progress.json, without "phase": read by its words.
  std::ofstream(dir / "cases" / "b" / "progress.json")
      << R"({"stage": "running", "fraction": 0.25, "t": 25, "duration": 100, "eta_s": 60})";
  std::ofstream(dir / "sweep.json") << R"({"name": "s", "jobs": 2, "threads": 1})";
  const Result r = wiggle("status " + quoted(dir.string()));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("4 cases: 1 done, 1 running, 1 failed, 1 pending"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("no wiggle sweep is running"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("running  b (25 % of its run)  [stale: interrupted]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("failed   c: box.width = 5 is too narrow, really"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("warning  a: V_y is measured over 1.5 drive periods"), std::string::npos) << r.out;
  // 600 s per case x (0.75 + 1) cases left / 2 jobs = 525 s.
  EXPECT_NE(r.out.find("about 8m45s"), std::string::npos) << r.out;

  expectOneLineError(wiggle("status " + quoted(root_.string())),
                     {"neither a sweep directory (no results.csv) nor a run directory"},
                     "status of a directory that is neither a sweep's nor a run's");
  expectOneLineError(wiggle("status " + quoted((root_ / "nowhere").string())), {"nowhere", "not a directory"},
                     "status of a missing directory");
}

// Issue 80: a sweep's cells (cells.csv) in `wiggle status`: each cell's mean +- se over its beds and
// its verdict, a cell of one bed so far said as one bed and part-run; a sweep without cells.csv (an
// older wiggle's) or with one bed a cell shows no cells. `--dry-run` counts the cells and beds.
TEST_F(Cli, StatusListsTheCellsOfASweepWithBeds) {
  const fs::path dir = root_ / "sweep";
  for (const char* c : {"a1", "a2", "b1", "b2"}) fs::create_directories(dir / "cases" / c);
  for (const char* c : {"a1", "a2", "b1"})
    std::ofstream(dir / "cases" / c / "summary.json") << R"({"status": "ok", "vy": 0.1})";
  std::ofstream(dir / "results.csv") << "case,run_dir,status,vy,vy_slope,wall_s,drive.period,box.seed,error\n"
                                     << "a1,cases/a1,ok,-0.02,0,600,1,1,\n"
                                     << "a2,cases/a2,ok,-0.03,0,600,1,2,\n"
                                     << "b1,cases/b1,ok,0.09,0,600,5,1,\n"
                                     << "b2,cases/b2,pending,,,,5,2,\n";
  Result r = wiggle("status " + quoted(dir.string()));
  EXPECT_EQ(r.out.find("cell "), std::string::npos) << r.out;  // no cells.csv: as before
  std::ofstream(dir / "cells.csv") << "cell,drive.period,state,beds,n,vy_mean,vy_sd,vy_se,verdict,verdict_rule\n"
                                   << "period=1,1,done,2,2,-0.025,0.007071067812,0.005,sinks,rule\n"
                                   << "period=5,5,part-run,2,1,0.09,,,not resolved,rule\n";
  r = wiggle("status " + quoted(dir.string()));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("rises / sinks when |vy_mean| >= 2 vy_se with n >= 2, else not resolved"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("cell     period=1: -0.025 +- 0.005 (2 beds): sinks\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("cell     period=5: +0.09 (one bed: its sign is not a verdict; part-run: 1 of its 2 beds)\n"),
            std::string::npos)
      << r.out;

  const fs::path sweepFile = root_ / "beds.toml";
  std::ofstream(sweepFile) << "[sweep]\nbeds = 3\n[grid.drive]\nperiod = [1, 5]\n[base.run]\nduration = 1\n";
  r = wiggle("sweep " + quoted(sweepFile.string()) + " --out planned --dry-run");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("6 cases: 6 to run"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("2 cells x 3 beds (box.seed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("period=5_seed=3"), std::string::npos) << r.out;
  std::ofstream(sweepFile) << "[sweep]\nbeds = 0\n";
  expectOneLineError(wiggle("sweep " + quoted(sweepFile.string()) + " --out planned --dry-run"), {"sweep.beds = 0"},
                     "beds = 0");
}

// One truth for a case's state: results.csv says ok but the case's summary.json is garbage, so the
// sweep would run it again (its --dry-run says so): `wiggle status` must not call it done. When
// only failed cases are left, a rerun retries them: not "nothing left to run". A running case
// whose progress.json says its bed was loaded is not "making its bed".
TEST_F(Cli, StatusAgreesWithTheSweepOnWhatIsLeft) {
  const fs::path dir = root_ / "sweep";
  for (const char* c : {"a", "b", "c"}) fs::create_directories(dir / "cases" / c);
  std::ofstream(dir / "cases" / "a" / "summary.json") << "{garbage";
  std::ofstream(dir / "cases" / "c" / "progress.json")
      << R"({"stage": "bed loaded from the cache, run started", "fraction": -1, "t": 0, "duration": 100, "eta_s": -1})";
  std::ofstream(dir / "results.csv") << "case,run_dir,status,vy,vy_slope,wall_s,drive.period,error\n"
                                     << "a,cases/a,ok,0.1,0.1,600,5,\n"
                                     << "b,cases/b,failed,,,,3,blew up\n"
                                     << "c,cases/c,running,,,,2,\n";
  Result r = wiggle("status " + quoted(dir.string()));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("3 cases: 0 done, 1 running, 1 failed, 1 pending"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("pending  a: results.csv says ok, but"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("running  c (bed loaded from the cache, run started"), std::string::npos) << r.out;
  std::ofstream(dir / "results.csv") << "case,run_dir,status,vy,vy_slope,wall_s,drive.period,error\n"
                                     << "b,cases/b,failed,,,,3,blew up\n";
  r = wiggle("status " + quoted(dir.string()));
  EXPECT_EQ(r.out.find("nothing left to run\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("nothing left to run but the 1 failed case: the same `wiggle sweep` command retries it"),
            std::string::npos)
      << r.out;
}

}  // namespace
}  // namespace wiggle
