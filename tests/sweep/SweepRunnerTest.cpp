// `wiggle sweep` end to end on a tiny bed (20 d x 12 d, about 230 grains, a 3 d square polygon):
// the cases run as child processes of the real wiggle binary (WIGGLE_BINARY). The bed is made once
// per test binary run (about 5 s) into a private cache and shared by every test here.
#include <gtest/gtest.h>

#include <cctype>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include "io/AtomicFile.h"
#include "io/SweepSpec.h"
#include "sweep/BoundaryStudy.h"
#include "sweep/ResultsTable.h"
#include "sweep/SweepPlan.h"
#include "sweep/SweepRunner.h"
#include "sweep/SweepStart.h"

namespace wiggle {
namespace {

namespace fs = std::filesystem;

// A minimal RFC 4180 reader: the test must not trust the writer's own quoting code.
std::vector<std::vector<std::string>> parseCsv(const std::string& text) {
  std::vector<std::vector<std::string>> rows(1);
  std::string cell;
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char ch = text[i];
    if (quoted) {
      if (ch == '"' && i + 1 < text.size() && text[i + 1] == '"') cell += '"', ++i;
      else if (ch == '"') quoted = false;
      else cell += ch;
    } else if (ch == '"') {
      quoted = true;
    } else if (ch == ',') {
      rows.back().push_back(cell), cell.clear();
    } else if (ch == '\n') {
      rows.back().push_back(cell), cell.clear();
      rows.emplace_back();
    } else {
      cell += ch;
    }
  }
  if (rows.back().empty()) rows.pop_back();
  return rows;
}

// results.csv as one map per row (column -> cell), keyed by case name.
std::map<std::string, std::map<std::string, std::string>> readResults(const std::string& dir) {
  const auto rows = parseCsv(readFile(dir + "/results.csv"));
  std::map<std::string, std::map<std::string, std::string>> out;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    std::map<std::string, std::string> row;
    for (std::size_t c = 0; c < rows[0].size() && c < rows[r].size(); ++c) row[rows[0][c]] = rows[r][c];
    out[row["case"]] = row;
  }
  return out;
}

class SweepRunnerTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = new std::string(fs::temp_directory_path().string() + "/wiggle-sweep-test-" + std::to_string(::getpid()));
    fs::remove_all(*root_);
    fs::create_directories(*root_ + "/cache");
  }
  static void TearDownTestSuite() {
    fs::remove_all(*root_);
    delete root_;
  }

  // The sweep file: `grid` is the [grid] part, `duration` the run length.
  static std::string sweepFile(const std::string& name, const std::string& grid, double duration = 0.2) {
    std::ostringstream s;
    s << "[sweep]\nname = \"" << name << "\"\n"
      << "[base.box]\nwidth = 20.0\nbed_height = 12.0\nseed = 1\n"
      << "[base.intruder]\nshape = \"polygon\"\nvertices = [[-1.5, -1.5], [1.5, -1.5], [1.5, 1.5], [-1.5, 1.5]]\n"
      << "y0 = 6.0\n"
      << "[base.drive]\namplitude = 0.5\nperiod = 1.0\n"
      << "[base.bed]\nrest_energy = 1e-4\nmax_time = 100.0\ncache_dir = \"" << *root_ << "/cache\"\n"
      << "[base.run]\ndt = 0.0001\nduration = " << duration << "\nsample_interval = 0.01\ndump_interval = 0.0\n"
      << "checkpoint_interval = 0.02\nplot = false\n"
      << "[base.fields]\nenabled = false\n"
      << grid;
    const std::string path = *root_ + "/" + name + ".toml";
    std::ofstream(path) << s.str();
    return path;
  }

  static SweepOptions quietOptions(const std::string& out) {
    SweepOptions o;
    o.outDir = out;
    o.jobs = 2;
    o.threads = 1;
    o.executable = WIGGLE_BINARY;
    o.allowMpi = false;
    o.progress = false;
    o.logToStderr = false;
    o.handleSignals = false;
    return o;
  }

  static std::string* root_;
};
std::string* SweepRunnerTest::root_ = nullptr;

TEST(SweepPlan, GrainEstimateIsAreaTimesPackingOverMeanGrainArea) {
  RunConfig c;
  c.box.width = 300;
  c.box.bedHeight = 195;
  c.grains.dMin = 0.9;
  c.grains.dMax = 1.1;
  // Mean of pi d^2 / 4 for d uniform in [0.9, 1.1]: (pi/4) (E[d]^2 + Var d) = (pi/4)(1 + 0.04/12).
  const double meanArea = 3.14159265358979 / 4.0 * (1.0 + 0.04 / 12.0);
  c.bed.pour = BedPour::Lattice;
  EXPECT_NEAR(estimatedGrains(c), 300.0 * 195.0 * 0.83 / meanArea, 1e-6);
  c.bed.pour = BedPour::Random;
  EXPECT_NEAR(estimatedGrains(c), 300.0 * 195.0 * 0.85 / meanArea, 1e-6);
  // The paper's bed made by its own protocol (random pour; study results/paper_box/t1000) holds
  // 63,049 and 63,073 grains: the estimate within 0.1 %.
  EXPECT_NEAR(estimatedGrains(c), 63061.0, 63.0);
}

// Carved beds of one seed share their base bed: the plan counts its pour once, in the first of
// them, and the carving alone in the others.
TEST(SweepPlan, CarvedBedsOfOneSeedCountTheirBasePourOnce) {
  const std::string cache = (fs::temp_directory_path() / ("wiggle-plan-carved-" + std::to_string(::getpid()))).string();
  const SweepSpec spec = parseSweepSpec("[base.bed]\ncavity = \"carved\"\ncache_dir = \"" + cache +
                                            "\"\n[grid.intruder]\nshape = [\"disk\", \"square\", \"triangle\"]\n",
                                        "carved.toml");
  const SweepPlan plan = makeSweepPlan(spec, cache + "/out");
  ASSERT_EQ(plan.beds.size(), 3u);
  const RunConfig& c = spec.cases[0].config;
  // Each carved bed (the three beds are the same size): the cut's relaxation at the plan's speed
  // over the bed's particles; the first one also pours the base.
  const double secondsPerTime = 1e-9 * plan.speed.ns * (estimatedGrains(c) + c.box.width) / c.run.dt;
  const double pour = estimatedBedTime(c, true) - estimatedBedTime(c, false);
  EXPECT_GT(pour, 0.0);
  EXPECT_EQ(estimatedBedTime(c, false), CostModel::carvedRelaxTime);
  EXPECT_NEAR(plan.beds[0].estimatedSeconds, secondsPerTime * (CostModel::carvedRelaxTime + pour), 1e-9);
  for (std::size_t b = 1; b < 3; ++b)
    EXPECT_NEAR(plan.beds[b].estimatedSeconds, secondsPerTime * CostModel::carvedRelaxTime, 1e-9) << b;
  EXPECT_FALSE(fs::exists(cache));  // planning makes nothing
}

// A --case task (one Slurm array task, one core of a local study) makes at most its own case's bed:
// its ETA and bed count must not hold the beds of cases that other tasks run.
TEST(SweepPlan, ACaseTaskMakesOnlyTheBedItsCaseWaitsFor) {
  const std::string cache = (fs::temp_directory_path() / ("wiggle-plan-own-" + std::to_string(::getpid()))).string();
  const SweepSpec spec = parseSweepSpec("[base.bed]\ncache_dir = \"" + cache +
                                            "\"\n[grid.intruder]\nshape = [\"disk\", \"square\", \"triangle\"]\n"
                                            "[grid.drive]\nperiod = [3.0, 4.0]\n",
                                        "own.toml");
  const SweepPlan plan = makeSweepPlan(spec, cache + "/out");
  ASSERT_EQ(plan.cases.size(), 6u);
  ASSERT_EQ(plan.beds.size(), 3u);  // one a shape, shared by its two periods
  EXPECT_EQ(bedsMadeBy(plan, std::nullopt), (std::vector<std::size_t>{0, 1, 2}));
  for (std::size_t c = 0; c < plan.cases.size(); ++c) {
    const std::vector<std::size_t> own = bedsMadeBy(plan, c);
    ASSERT_EQ(own.size(), 1u) << c;
    EXPECT_EQ(plan.beds[own[0]].key, plan.cases[c].bedKey) << c;
  }
  EXPECT_FALSE(fs::exists(cache));  // planning makes nothing
}

TEST_F(SweepRunnerTest, RunsEveryCaseRecordsFailuresAndResumes) {
  // amplitude 7 fails the geometry check (box too narrow); period 0.0003 (3 steps: the intruder jumps 0.4 d a step)
  // drives the intruder so
  // hard that the run stops with "the simulation blew up"; the other two must finish.
  const std::string file = sweepFile("mixed", "[grid.drive]\namplitude = [0.5, 7.0]\nperiod = [0.0003, 1.0, 2.0]\n");
  const std::string out = *root_ + "/mixed";

  // A reader polls results.csv during the sweep: every version it sees must be whole.
  std::atomic<bool> done{false};
  std::atomic<int> reads{0}, torn{0};
  std::thread reader([&] {
    while (!done) {
      std::error_code ec;
      if (fs::exists(out + "/results.csv", ec)) {
        const std::string text = readFile(out + "/results.csv");
        const auto rows = parseCsv(text);
        const bool whole = !text.empty() && text.back() == '\n' && rows.size() == 7 &&
                           std::all_of(rows.begin(), rows.end(), [&](const auto& r) { return r.size() == rows[0].size(); });
        ++reads;
        if (!whole) ++torn;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  });
  std::vector<std::string> started;
  SweepOptions options = quietOptions(out);
  options.onTaskStarted = [&](const SweepTask& t, pid_t) {
    if (t.kind == SweepTask::Kind::Case) started.push_back(std::to_string(t.caseIndex));
  };
  const SweepOutcome first = runSweep(file, options);
  done = true;
  reader.join();
  EXPECT_GT(reads.load(), 0);
  EXPECT_EQ(torn.load(), 0);

  EXPECT_EQ(first.cases, 6u);
  EXPECT_EQ(first.ok, 2u);
  EXPECT_EQ(first.failed, 4u);
  EXPECT_NE(first.summary.find("2 cases have warnings"), std::string::npos) << first.summary;
  EXPECT_EQ(started.size(), 3u);  // the three amplitude-7 cases never start a process

  auto rows = readResults(out);
  ASSERT_EQ(rows.size(), 6u);
  // Columns: the fixed ones, the grid keys, the always-present parameters, bookkeeping, error.
  const auto header = parseCsv(readFile(out + "/results.csv"))[0];
  const std::vector<std::string> expected = {"case",
                                             "run_dir",
                                             "status",
                                             "vy",
                                             "vy_slope",
                                             "vy_settled",
                                             "t_settled",
                                             "wall_s",
                                             "drive.amplitude",
                                             "drive.period",
                                             "intruder.shape",
                                             "contact.mu",
                                             "box.seed",
                                             "n_grains",
                                             "steps",
                                             "ns_per_particle_step",
                                             "state_hash",
                                             "error",
                                             "warnings"};
  EXPECT_EQ(header, expected);
  // Case order is the sweep's: the last grid key varies fastest.
  const auto all = parseCsv(readFile(out + "/results.csv"));
  EXPECT_EQ(all[1][0], "amplitude=0.5_period=0.0003");
  EXPECT_EQ(all[2][0], "amplitude=0.5_period=1");
  EXPECT_EQ(all[6][0], "amplitude=7_period=2");

  for (const char* ok : {"amplitude=0.5_period=1", "amplitude=0.5_period=2"}) {
    const auto& r = rows[ok];
    EXPECT_EQ(r.at("status"), "ok") << ok << ": " << r.at("error");
    EXPECT_EQ(r.at("run_dir"), std::string("cases/") + ok);
    EXPECT_EQ(r.at("error"), "");
    // The row repeats the case's summary.json.
    const std::string summary = readFile(out + "/cases/" + ok + "/summary.json");
    EXPECT_NE(summary.find("\"state_hash\": \"" + r.at("state_hash") + "\""), std::string::npos);
    EXPECT_EQ(r.at("steps"), "2000");
    EXPECT_FALSE(r.at("vy").empty());
    // Its warnings too (these runs are short: within the drive's start-up transient).
    EXPECT_NE(r.at("warnings").find("start-up transient"), std::string::npos) << r.at("warnings");
    // ... which the sweep's console (here its log, which gets the same lines) says as the case ends.
    EXPECT_NE(readFile(out + "/sweep.log").find(std::string("warning ") + ok + ": V_y is measured"), std::string::npos);
  }
  // How it was started, for `wiggle status` (sweep.json): its name and 2 jobs x 1 thread.
  const std::optional<SweepStart> start = readSweepStart(out);
  ASSERT_TRUE(start.has_value());
  EXPECT_EQ(start->jobs, 2);
  EXPECT_EQ(start->threads, 1);
  EXPECT_FALSE(start->name.empty());
  // ... and the beds it had to make, with their estimates: all made now.
  ASSERT_TRUE(start->beds.has_value());
  for (const BedToMake& bed : *start->beds) {
    EXPECT_TRUE(fs::exists(bed.cachePath)) << bed.key;
    EXPECT_GT(bed.estimatedSeconds, 0.0) << bed.key;
  }
  EXPECT_EQ(rows["amplitude=0.5_period=0.0003"].at("status"), "failed");
  EXPECT_NE(rows["amplitude=0.5_period=0.0003"].at("error").find("blew up"), std::string::npos)
      << rows["amplitude=0.5_period=0.0003"].at("error");
  EXPECT_EQ(rows["amplitude=0.5_period=0.0003"].at("vy"), "");
  // Guard rail end to end: the blow-up passed the up-front time-step check (the drive's speed is
  // in it, and 1e-4 is below its limit) and was stopped by the health check; no NaN or inf
  // reached results.csv, and the case left no summary.json to be mistaken for a result.
  {
    std::string lower = readFile(out + "/results.csv");
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char ch) { return std::tolower(ch); });
    for (const auto& row : parseCsv(lower))
      for (const auto& cell : row) EXPECT_TRUE(cell != "nan" && cell != "inf" && cell != "-inf") << cell;
    EXPECT_FALSE(fs::exists(out + "/cases/amplitude=0.5_period=0.0003/summary.json"));
  }
  EXPECT_EQ(rows["amplitude=7_period=1"].at("status"), "failed");
  EXPECT_NE(rows["amplitude=7_period=1"].at("error").find("box.width = 20 is too narrow"), std::string::npos);
  EXPECT_EQ(rows["amplitude=7_period=1"].at("drive.amplitude"), "7");
  EXPECT_EQ(rows["amplitude=7_period=1"].at("intruder.shape"), "polygon");
  // No temporary file of the atomic writes is left behind.
  for (const auto& e : fs::directory_iterator(out)) EXPECT_EQ(e.path().string().find(".tmp."), std::string::npos);

  // A rerun starts only the case that failed at run time (and fails it again); the finished ones
  // are skipped and keep their rows.
  started.clear();
  const std::string before = readFile(out + "/cases/amplitude=0.5_period=1/summary.json");
  const SweepOutcome second = runSweep(file, options);
  EXPECT_EQ(second.ok, 2u);
  EXPECT_EQ(second.failed, 4u);
  EXPECT_EQ(started, std::vector<std::string>{"0"});
  EXPECT_EQ(readFile(out + "/cases/amplitude=0.5_period=1/summary.json"), before);
  const auto again = readResults(out);
  for (const char* ok : {"amplitude=0.5_period=1", "amplitude=0.5_period=2"})
    EXPECT_EQ(again.at(ok).at("state_hash"), rows.at(ok).at("state_hash"));
}

TEST_F(SweepRunnerTest, KilledCaseResumesToTheUninterruptedState) {
  // Two identical cases in two sweeps: one runs through, the other's process is killed with
  // SIGKILL after its first checkpoint and then resumed by a rerun. The final states must agree
  // bit for bit (summary.json state_hash).
  const std::string grid = "[grid.drive]\nperiod = [1.0]\n";
  const double duration = 2.0;  // 20,000 steps: long enough to be killed half way
  const std::string file = sweepFile("kill", grid, duration);
  const std::string reference = *root_ + "/kill-reference", killed = *root_ + "/kill-killed";
  const SweepOutcome ref = runSweep(file, quietOptions(reference));
  ASSERT_EQ(ref.ok, 1u);
  const std::string caseDir = killed + "/cases/period=1";

  SweepOptions options = quietOptions(killed);
  std::thread killer;
  std::atomic<bool> killedMidRun{false};
  options.onTaskStarted = [&](const SweepTask& t, pid_t pid) {
    if (t.kind != SweepTask::Kind::Case) return;
    killer = std::thread([&, pid] {
      // Wait for the first checkpoint, then kill before the run can finish.
      for (int i = 0; i < 20000 && !fs::exists(caseDir + "/checkpoint.bin"); ++i)
        std::this_thread::sleep_for(std::chrono::microseconds(500));
      killedMidRun = !fs::exists(caseDir + "/summary.json");
      ::kill(pid, SIGKILL);
    });
  };
  const SweepOutcome first = runSweep(file, options);
  killer.join();
  ASSERT_TRUE(killedMidRun.load()) << "the case finished before it could be killed: make it longer";
  EXPECT_EQ(first.failed, 1u);
  EXPECT_EQ(readResults(killed)["period=1"].at("status"), "failed");
  EXPECT_NE(readResults(killed)["period=1"].at("error").find("killed by signal 9"), std::string::npos);
  EXPECT_FALSE(fs::exists(caseDir + "/summary.json"));

  options.onTaskStarted = {};
  const SweepOutcome second = runSweep(file, options);
  EXPECT_EQ(second.ok, 1u);
  const auto refRow = readResults(reference)["period=1"];
  const auto resumedRow = readResults(killed)["period=1"];
  EXPECT_EQ(resumedRow.at("status"), "ok");
  EXPECT_EQ(resumedRow.at("state_hash"), refRow.at("state_hash"));
  EXPECT_EQ(resumedRow.at("vy"), refRow.at("vy"));
  // The resumed run really continued from a checkpoint rather than starting over.
  EXPECT_NE(readFile(caseDir + "/log.txt").find("resumed from"), std::string::npos);
}

TEST_F(SweepRunnerTest, DryRunListsCasesAndCostWithoutRunning) {
  const std::string file = sweepFile("dry", "[grid.drive]\nperiod = [1.0, 2.0]\n[grid.box]\nseed = [7, 8]\n");
  const std::string out = *root_ + "/dry";
  std::ostringstream listing;
  SweepOptions options = quietOptions(out);
  options.dryRun = true;
  options.listing = &listing;
  const SweepOutcome o = runSweep(file, options);
  EXPECT_EQ(o.cases, 4u);
  EXPECT_FALSE(fs::exists(out));
  const std::string text = listing.str();
  EXPECT_NE(text.find("period=1_seed=7"), std::string::npos) << text;
  EXPECT_NE(text.find("4 cases: 4 to run"), std::string::npos) << text;
  // Two seeds: two distinct beds, neither cached.
  EXPECT_NE(text.find("2 of 2 distinct beds to make"), std::string::npos) << text;
  EXPECT_NE(text.find("estimated cost"), std::string::npos);
}

TEST_F(SweepRunnerTest, ArrayTasksRunOneCaseEachAndTheTableMergesThem) {
  const std::string file = sweepFile("array", "[grid.drive]\nperiod = [1.0, 2.0, 0.5]\n");
  const std::string out = *root_ + "/array";
  // One task by its number in the --dry-run listing (from 1): only that case runs; the table lists
  // the others as pending.
  SweepOptions one = quietOptions(out);
  one.onlyCase = "2";
  const SweepOutcome o = runSweep(file, one);
  EXPECT_EQ(o.cases, 1u);
  EXPECT_EQ(o.ok, 1u);
  EXPECT_EQ(o.pending, 0u);
  auto results = readResults(out);
  EXPECT_EQ(results["period=2"]["status"], "ok");
  EXPECT_EQ(results["period=1"]["status"], "pending");
  EXPECT_FALSE(fs::exists(out + "/cases/period=1"));
  // Two tasks at once, as array tasks start, one by name: the table ends with all three.
  const std::string task = std::string(WIGGLE_BINARY) + " sweep " + file + " --out " + out + " --threads 1 --case ";
  ASSERT_EQ(std::system(("(" + task + "1 & " + task + "period=0.5 & wait) > /dev/null 2>&1").c_str()), 0);
  results = readResults(out);
  for (const char* name : {"period=1", "period=2", "period=0.5"}) EXPECT_EQ(results[name]["status"], "ok") << name;
  // A whole sweep afterwards finds every case done and runs nothing.
  const SweepOutcome all = runSweep(file, quietOptions(out));
  EXPECT_EQ(all.ok, 3u);
  EXPECT_EQ(readResults(out)["period=1"]["state_hash"], results["period=1"]["state_hash"]);
  // A case that is not there: the error says what there is.
  for (const char* bad : {"4", "0", "period=7", "-1"}) {
    SweepOptions wrong = quietOptions(out);
    wrong.onlyCase = bad;
    try {
      runSweep(file, wrong);
      ADD_FAILURE() << "--case " << bad << " accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("no such case"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("from 1 to 3"), std::string::npos) << e.what();
    }
  }
}

TEST_F(SweepRunnerTest, ArrayTaskEndsWhenItsCaseIsDoneThoughOtherCasesBedsAreNotMade) {
  // Two seeds, two beds: the task for case 1 makes its own bed only, runs its case and exits; the
  // other case's bed is someone else's work (an earlier version waited for it for ever). The
  // timeout turns such a wait into a failure instead of a stuck test.
  const std::string file = sweepFile("array_beds", "[grid.box]\nseed = [1, 2]\n");
  const std::string out = *root_ + "/array_beds";
  const std::string task = "timeout 300 " + std::string(WIGGLE_BINARY) + " sweep " + file + " --out " + out +
                           " --threads 1 --case 1 > /dev/null 2>&1";
  const int status = std::system(task.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);  // 124: timed out
  auto results = readResults(out);
  EXPECT_EQ(results["seed=1"]["status"], "ok");
  EXPECT_EQ(results["seed=2"]["status"], "pending");
  EXPECT_FALSE(fs::exists(out + "/cases/seed=2"));
}

// `wiggle boundary` on real runs (its decisions on a stand-in: BoundaryStudyTest): every run is a
// case of the sweep in its directory, and running it again finds them all finished and reaches the
// same probes and verdicts without starting a process.
TEST_F(SweepRunnerTest, BoundaryRunsAsASweepAndResumesWithTheSameDecisions) {
  const std::string out = *root_ + "/boundary";
  BoundarySpec spec;
  spec.base = loadSweepSpec(sweepFile("boundary_base", "")).cases[0].config;
  spec.options.lo = 1.0;
  spec.options.hi = 2.0;
  spec.options.points = 2;
  spec.options.resolution = 0.5;
  spec.options.minBeds = spec.options.maxBeds = 2;
  int started = 0;
  SweepOptions options = quietOptions(out);
  options.onTaskStarted = [&](const SweepTask& t, pid_t) { started += t.kind == SweepTask::Kind::Case; };
  SweepBoundaryRunner runner(options);
  const BoundaryResult first = runBoundary(spec, runner, out);
  ASSERT_GE(first.outcomes.size(), 4u);
  EXPECT_EQ(static_cast<std::size_t>(started), first.outcomes.size());
  const SweepSpec sweep = loadSweepSpec(out + "/boundary.toml");
  ASSERT_EQ(sweep.cases.size(), first.cases.size());
  const auto rows = readResults(out);
  for (std::size_t i = 0; i < first.cases.size(); ++i) {
    const auto& row = rows.at(sweep.cases[i].name);
    EXPECT_EQ(row.at("status"), "ok") << sweep.cases[i].name << ": " << row.at("error");
    EXPECT_TRUE(first.outcomes[i].ok);
    EXPECT_NEAR(std::stod(row.at("vy")), first.outcomes[i].vy, 1e-9 * (1 + std::fabs(first.outcomes[i].vy)));
    EXPECT_EQ(row.at("box.seed"), std::to_string(first.cases[i].run.seed));
  }
  EXPECT_TRUE(fs::exists(out + "/boundary.json"));
  EXPECT_TRUE(fs::exists(out + "/boundary.csv"));

  started = 0;
  SweepBoundaryRunner again(options);
  const BoundaryResult second = runBoundary(spec, again, out);
  EXPECT_EQ(started, 0);
  ASSERT_EQ(second.searches[0].probes().size(), first.searches[0].probes().size());
  for (std::size_t k = 0; k < first.searches[0].probes().size(); ++k) {
    const Probe &a = first.searches[0].probes()[k], &b = second.searches[0].probes()[k];
    EXPECT_EQ(a.value, b.value);
    EXPECT_EQ(a.vy, b.vy);
    EXPECT_EQ(a.verdict, b.verdict);
  }
}

}  // namespace
}  // namespace wiggle
