// `wiggle status` read from a sweep directory laid out by hand (sweep/SweepStatus.h): each state a
// case can be in, the rule that a case results.csv calls ok is done only when its summary says so,
// whether a process runs a case now (the directory's lock and each run's), and the time-to-go
// estimate, computed here from the numbers written into the directory.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "io/AtomicFile.h"
#include "io/Config.h"
#include "io/FileLock.h"
#include "scenario/bed/BedMaker.h"
#include "scenario/run/Experiment.h"
#include "scenario/run/RunProgress.h"
#include "scenario/run/RunSummary.h"
#include "support/TestSupport.h"
#include "sweep/SweepStart.h"
#include "sweep/SweepStatus.h"
#include "sweep/TaskRunner.h"

namespace wiggle {
namespace {

namespace fs = std::filesystem;
using testing_support::errorOf;
using testing_support::ScratchDir;

// A sweep of seven cases: three done (wall 100 s, 300 s, and 5000 s for one paused for most of its
// run), one failed, one running a quarter through its steps, one pending, and one that results.csv
// calls ok but whose summary.json is missing.
class SweepStatusTest : public ::testing::Test {
 protected:
  void SetUp() override {
    writeFileAtomically(dir_ / "results.csv",
                        "case,run_dir,status,vy,wall_s,error,warnings\n"
                        "a,cases/a,ok,0.25,100,,\n"
                        "b,cases/b,ok,-0.5,300,,\"short window\"\n"
                        "c,cases/c,failed,,,the run blew up at t = 3,\n"
                        "d,cases/d,running,,,,\n"
                        "e,cases/e,pending,,,,\n"
                        "f,cases/f,ok,0.1,50,,\n"
                        "g,cases/g,ok,0.2,5000,,\n");
    for (const char* name : {"a", "b", "c", "d", "e", "f", "g"})
      fs::create_directories(dir_ / (std::string("cases/") + name));
    RunSummary ok;
    ok.status = RunStatus::Ok;
    writeFileAtomically(dir_ / "cases/a/summary.json", toJson(ok).dump());
    writeFileAtomically(dir_ / "cases/g/summary.json", toJson(ok).dump());
    ok.warnings = {"short window"};
    writeFileAtomically(dir_ / "cases/b/summary.json", toJson(ok).dump());
    writeRunProgress(dir_ / "cases/d", RunProgress{RunPhase::Running, "running", 0.25, 25.0, 100.0, 60.0});
    writeSweepStart(dir_.path().string(), SweepStart{"demo", 2, 1, {}});
  }
  ScratchDir dir_{"sweep-status"};
};

TEST_F(SweepStatusTest, EachCaseIsInTheStateItsFilesShow) {
  const SweepStatus s = readSweepStatus(dir_.path().string());
  EXPECT_EQ(s.name, "demo");
  EXPECT_EQ(s.jobs, 2);
  EXPECT_FALSE(s.sweepRunning());  // nothing holds the directory's lock
  ASSERT_EQ(s.cases.size(), 7u);
  EXPECT_EQ(s.cases[0].status, CaseStatus::Ok);
  EXPECT_EQ(s.cases[0].vy, 0.25);
  EXPECT_EQ(s.cases[1].warnings, std::vector<std::string>{"short window"});
  EXPECT_EQ(s.cases[2].status, CaseStatus::Failed);
  EXPECT_EQ(s.cases[2].error, "the run blew up at t = 3");
  EXPECT_EQ(s.cases[3].status, CaseStatus::Running);
  EXPECT_EQ(s.cases[3].fraction, 0.25);
  EXPECT_EQ(s.cases[4].status, CaseStatus::Pending);
  // Called ok, but without a summary the sweep would run it again: pending, saying why.
  EXPECT_EQ(s.cases[5].status, CaseStatus::Pending);
  EXPECT_EQ(s.cases[5].error.rfind("results.csv says ok, but", 0), 0u) << s.cases[5].error;
}

TEST_F(SweepStatusTest, TimeToGoIsTheMedianFinishedWallTimesWhatIsLeftOverTheJobs) {
  const SweepStatus s = readSweepStatus(dir_.path().string());
  // Finished: a, b and g, median 300 s (the paused g does not set it; the mean would be 1800 s).
  // Left: d's three quarters, e and f whole = 2.75 cases, over 2 jobs.
  EXPECT_DOUBLE_EQ(s.etaSeconds, 300.0 * 2.75 / 2.0);
  const std::string text = formatSweepStatus(s);
  EXPECT_NE(text.find("7 cases: 3 done, 1 running, 1 failed, 2 pending"), std::string::npos) << text;
  EXPECT_NE(text.find("running  d (25 % of its run)  [stale: interrupted]"), std::string::npos) << text;
  EXPECT_NE(text.find("failed   c: the run blew up at t = 3"), std::string::npos) << text;
  EXPECT_NE(text.find("warning  b: short window"), std::string::npos) << text;
  const auto json = nlohmann::json::parse(sweepStatusJson(s));
  EXPECT_DOUBLE_EQ(json["eta_s"].get<double>(), 412.5);
  EXPECT_TRUE(json["cases"][2]["vy"].is_null());  // a value only for a finished case
  EXPECT_EQ(json["cases"][3]["fraction"].get<double>(), 0.25);
}

// Slurm array tasks: they share the directory's lock and write results.csv only when their case
// ends, so a case runs when its run holds its own directory's lock, whatever the table says.
TEST_F(SweepStatusTest, ArrayTasksCasesRunWhereTheirRunsHoldTheirDirectories) {
  writeSweepStart(dir_.path().string(), SweepStart{"demo", 0, 1, {}});  // jobs unknown: tasks say none
  writeRunProgress(dir_ / "cases/e", RunProgress{RunPhase::Running, "running", 0.5, 50.0, 100.0, 60.0});
  const FileLock tasks(sweepLockPath(dir_.path().string()), /*shared=*/true, false, "");
  const FileLock e(runLockPath(dir_ / "cases/e"), false, false, ""), f(runLockPath(dir_ / "cases/f"), false, false, "");
  const SweepStatus s = readSweepStatus(dir_.path().string());
  EXPECT_EQ(s.sweepLock, FileLock::Holders::Shared);
  EXPECT_TRUE(s.sweepRunning());
  EXPECT_EQ(s.cases[3].status, CaseStatus::Running);  // d: results.csv's word, but no process runs it
  EXPECT_TRUE(s.cases[3].interrupted);
  EXPECT_EQ(s.cases[4].status, CaseStatus::Running);  // e: pending in the table, its run holds it
  EXPECT_FALSE(s.cases[4].interrupted);
  EXPECT_EQ(s.cases[4].fraction, 0.5);
  EXPECT_EQ(s.cases[5].status, CaseStatus::Running);  // f: "ok" without a summary, being run again
  EXPECT_EQ(s.cases[5].error, "");
  // Two cases run at once: e's own 60 s left, plus d's three quarters and f whole (it has no
  // estimate yet) = 1.75 cases of 300 s, over 2.
  EXPECT_EQ(s.casesAtOnce, 2);
  EXPECT_DOUBLE_EQ(s.etaSeconds, (60.0 + 300.0 * 1.75) / 2.0);
  const std::string text = formatSweepStatus(s);
  EXPECT_NE(text.find("one-case `wiggle sweep --case` tasks are running in it"), std::string::npos) << text;
  EXPECT_NE(text.find("running  e (50 % of its run, about 1m00s to go)\n"), std::string::npos) << text;
  EXPECT_NE(text.find("running  d (25 % of its run)  [stale: interrupted]"), std::string::npos) << text;
  const auto json = nlohmann::json::parse(sweepStatusJson(s));
  EXPECT_TRUE(json["sweep_running"].get<bool>());
  EXPECT_TRUE(json["cases"][3]["interrupted"].get<bool>());
  EXPECT_FALSE(json["cases"][4]["interrupted"].get<bool>());
}

TEST_F(SweepStatusTest, UnderAWholeSweepItsRunningCasesRun) {
  const FileLock whole(sweepLockPath(dir_.path().string()), /*shared=*/false, false, "");
  const SweepStatus s = readSweepStatus(dir_.path().string());
  EXPECT_EQ(s.sweepLock, FileLock::Holders::Exclusive);
  EXPECT_FALSE(s.cases[3].interrupted);  // d: the sweep says running and holds the directory
  const std::string text = formatSweepStatus(s);
  EXPECT_NE(text.find("a wiggle sweep is running in it"), std::string::npos) << text;
  EXPECT_EQ(text.find("[stale"), std::string::npos) << text;
}

// A bed takes hours in which no case runs: the status names each bed not made yet, whether a
// process makes it now (its lock in the cache), and the maker's last report from its log.
TEST_F(SweepStatusTest, BedsNotMadeYetAreNamedWithTheirLastReport) {
  RunConfig config;
  config.bed.cacheDir = dir_ / "cache";
  fs::create_directories(config.bed.cacheDir);
  fs::create_directories(dir_ / "beds");
  for (const char* key : {"k1", "k2", "k3", "k4", "k5"})
    writeFileAtomically(dir_ / (std::string("beds/bed-") + key + ".toml"), toToml(config));
  writeFileAtomically(dir_ / "beds/bed-k1.log", "[bed] pouring batch 2, 40 grains\n[bed] relaxing batch 3, 60 grains\n");
  writeFileAtomically(dir_ / "beds/bed-k2.log", "[bed] pouring batch 1, 20 grains\nwiggle: interrupted by signal 15\n");
  writeFileAtomically(bedPartialPath(config, "k2"), "part");
  writeFileAtomically(dir_ / "beds/bed-k3.log", "[bed] relaxing batch 3, 60 grains\n" + bedTaskDoneLine("k3", false, 60) + "\n");
  writeFileAtomically(bedCachePath(config, "k4"), "bed");
  const FileLock making(bedLockPath(config, "k1"), false, false, "");
  const SweepStatus s = readSweepStatus(dir_.path().string());
  ASSERT_EQ(s.beds.size(), 3u);  // k3's log says it was made, k4 is in the cache
  EXPECT_EQ(s.beds[0].key, "k1");
  EXPECT_EQ(s.beds[0].state, BedAtAGlance::State::Making);
  EXPECT_EQ(s.beds[0].report, "[bed] relaxing batch 3, 60 grains");
  EXPECT_EQ(s.beds[1].state, BedAtAGlance::State::PartMade);
  EXPECT_EQ(s.beds[2].key, "k5");
  EXPECT_EQ(s.beds[2].state, BedAtAGlance::State::NotMade);
  EXPECT_EQ(s.beds[2].report, "");
  const std::string text = formatSweepStatus(s);
  EXPECT_NE(text.find("  bed      k1: being made: [bed] relaxing batch 3, 60 grains\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  bed      k2: part-made, not being made (the same `wiggle sweep` command continues it): [bed] "
                      "pouring batch 1, 20 grains\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("  bed      k5: not being made, nothing of it saved\n"), std::string::npos) << text;
}

// A bed takes hours in which no case runs: the beds the sweep had to make at its start (sweep.json)
// count in the time to go, at the plan's estimate over the sweep's threads, until the cache holds them.
TEST_F(SweepStatusTest, BedsStillToMakeCountInTheTimeToGo) {
  const std::string made = dir_ / "bed-made.bin";
  writeFileAtomically(made, "bed");
  writeSweepStart(dir_.path().string(),
                  SweepStart{"demo", 2, 2,
                             std::vector<BedToMake>{{"made", made, 1000.0},
                                                    {"k1", dir_ / "bed-k1.bin", 600.0},
                                                    {"k2", dir_ / "bed-k2.bin", 200.0}}});
  const SweepStatus s = readSweepStatus(dir_.path().string());
  EXPECT_TRUE(s.bedsCounted);
  EXPECT_EQ(s.bedsToMake, 2);                 // the cache holds the first
  EXPECT_DOUBLE_EQ(s.bedSeconds, 800.0 / 2);  // seconds of one core, over 2 threads
  // The cases as in TimeToGoIsTheMedianFinishedWallTimesWhatIsLeftOverTheJobs, plus the beds, over 2 jobs.
  EXPECT_DOUBLE_EQ(s.etaSeconds, (300.0 * 2.75 + 400.0) / 2.0);
  const std::string text = formatSweepStatus(s);
  EXPECT_NE(text.find("x the cases left, plus the 2 beds to make, about 6m40s by the sweep's plan, over 2 jobs)"),
            std::string::npos)
      << text;
  // A sweep.json without the beds (an older wiggle's): they are not counted, and the status says so.
  writeSweepStart(dir_.path().string(), SweepStart{"demo", 2, 1, {}});
  const SweepStatus old = readSweepStatus(dir_.path().string());
  EXPECT_FALSE(old.bedsCounted);
  EXPECT_DOUBLE_EQ(old.etaSeconds, 300.0 * 2.75 / 2.0);
  EXPECT_NE(formatSweepStatus(old).find("beds still to make are not counted"), std::string::npos);
  // Before any case knows its pace, the beds' share is said on its own.
  writeSweepStart(dir_.path().string(),
                  SweepStart{"demo", 2, 2, std::vector<BedToMake>{{"k1", dir_ / "bed-k1.bin", 800.0}}});
  writeFileAtomically(dir_ / "results.csv", "case,run_dir,status,vy,wall_s,error\ne,cases/e,pending,,,\n");
  EXPECT_NE(formatSweepStatus(readSweepStatus(dir_.path().string()))
                .find("time to go: unknown until a case has finished or a running one knows its pace; the 1 bed to "
                      "make, about 6m40s by the sweep's plan first\n"),
            std::string::npos);
}

TEST_F(SweepStatusTest, WithNothingFinishedTheTimeToGoIsUnknown) {
  writeFileAtomically(dir_ / "results.csv", "case,run_dir,status,vy,wall_s,error\ne,cases/e,pending,,,\n");
  const SweepStatus s = readSweepStatus(dir_.path().string());
  EXPECT_EQ(s.caseTime, SweepStatus::CaseTime::Unknown);
  EXPECT_LT(s.etaSeconds, 0.0);
  EXPECT_NE(formatSweepStatus(s).find("time to go: unknown"), std::string::npos);
}

// A paper-scale case runs for many hours before any finishes: until then a running case's own
// estimate of its time left, over the fraction it has left, is the wall time of a case.
TEST_F(SweepStatusTest, WithNothingFinishedTheRunningCasesPaceGivesTheTimeToGo) {
  writeFileAtomically(dir_ / "results.csv",
                      "case,run_dir,status,vy,wall_s,error\nd,cases/d,running,,,\ne,cases/e,pending,,,\n");
  const FileLock whole(sweepLockPath(dir_.path().string()), /*shared=*/false, false, "");
  const SweepStatus s = readSweepStatus(dir_.path().string());
  EXPECT_EQ(s.caseTime, SweepStatus::CaseTime::RunningPace);
  // d: a quarter done, 60 s left: 80 s whole. Left: d's own 60 s and e's 80 s, over 2 jobs.
  EXPECT_DOUBLE_EQ(s.etaSeconds, (60.0 + 80.0) / 2.0);
  const std::string text = formatSweepStatus(s);
  EXPECT_NE(text.find("running  d (25 % of its run, about 1m00s to go)\n"), std::string::npos) << text;
  EXPECT_NE(text.find("time to go: about 1m10s (estimate: the running cases' own times to go, plus a case's wall time "
                      "at the running cases' present pace, nothing having finished yet, x the other cases left, over 2 "
                      "jobs, and no less than the longest running case's"),
            std::string::npos)
      << text;
}

// The finished cases may have run faster than the running one (another shape, a quieter machine): a
// running case's own estimate is its time left, and the sweep cannot end before its longest.
TEST_F(SweepStatusTest, ARunningCaseCountsItsOwnTimeLeft) {
  writeFileAtomically(dir_ / "results.csv",
                      "case,run_dir,status,vy,wall_s,error\na,cases/a,ok,0.25,100,\nd,cases/d,running,,,\n");
  writeRunProgress(dir_ / "cases/d", RunProgress{RunPhase::Running, "running", 0.25, 25.0, 100.0, 900.0});
  const FileLock whole(sweepLockPath(dir_.path().string()), /*shared=*/false, false, "");
  const SweepStatus s = readSweepStatus(dir_.path().string());
  EXPECT_EQ(s.caseTime, SweepStatus::CaseTime::FinishedCases);
  // Not 100 s x three quarters over 2 jobs: d's 900 s, which the second job does not shorten.
  EXPECT_DOUBLE_EQ(s.etaSeconds, 900.0);
  const std::string text = formatSweepStatus(s);
  EXPECT_NE(text.find("running  d (25 % of its run, about 15m00s to go)\ntime to go: about 15m00s (estimate: the "
                      "running cases' own times to go, plus the finished cases' median wall time x the other cases "
                      "left, over 2 jobs, and no less than the longest running case's"),
            std::string::npos)
      << text;
}

// An interrupted case's estimate is of a run that no longer runs: it sets no pace.
TEST_F(SweepStatusTest, AnInterruptedCaseSetsNoPace) {
  writeFileAtomically(dir_ / "results.csv",
                      "case,run_dir,status,vy,wall_s,error\nd,cases/d,running,,,\ne,cases/e,pending,,,\n");
  const SweepStatus s = readSweepStatus(dir_.path().string());
  EXPECT_TRUE(s.cases[0].interrupted);
  EXPECT_EQ(s.caseTime, SweepStatus::CaseTime::Unknown);
  EXPECT_EQ(formatSweepStatus(s).find("to go)"), std::string::npos);
}

TEST_F(SweepStatusTest, WhatIsNotASweepDirectoryIsNamed) {
  EXPECT_NE(errorOf([&] { readSweepStatus(dir_ / "cases/a"); }).find("no results.csv: not a sweep directory"),
            std::string::npos);
  writeFileAtomically(dir_ / "results.csv", "case,status\na,ok\n");
  EXPECT_NE(errorOf([&] { readSweepStatus(dir_.path().string()); }).find("no column 'run_dir'"), std::string::npos);
  // A status word that is none of the table's (a hand-edited file) is named, not taken for pending.
  writeFileAtomically(dir_ / "results.csv", "case,run_dir,status,vy,wall_s,error\na,cases/a,done,,,\n");
  EXPECT_NE(errorOf([&] { readSweepStatus(dir_.path().string()); })
                .find("row 2: status 'done' is none of ok, failed, running, pending"),
            std::string::npos);
}

}  // namespace
}  // namespace wiggle
