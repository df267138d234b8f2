// The coordinator on its own (sweep/Coordinator.h), with a stand-in for the wiggle binary: a shell
// script that behaves as a case task would, so that what is tested is the coordinator's side:
// every case handed out once, never more at once than the jobs, results.csv and sweep.log written
// from the outcomes, a failure recorded with its message, and a second sweep over the same
// directory running only what did not finish. (The same loops with real runs, kills and resumes:
// SweepRunnerTest; under MPI: tests/sweep/mpi_test.sh.)
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "io/AtomicFile.h"
#include "io/SweepSpec.h"
#include "scenario/run/RunSummary.h"
#include "sweep/Coordinator.h"
#include "sweep/ResultsTable.h"
#include "support/TestSupport.h"

namespace wiggle {
namespace {

namespace fs = std::filesystem;
using testing_support::ScratchDir;

// A case task (`sweep --run-case CONFIG --out DIR --threads N`): notes its start and end in
// $FAKE_LOG, fails as a blown-up run would when its directory names period 2, else writes the
// summary $FAKE_SUMMARY holds.
constexpr const char* kFakeWiggle = R"(#!/bin/sh
out="$5"
echo "start $out" >> "$FAKE_LOG"
sleep 0.2
echo "end $out" >> "$FAKE_LOG"
case "$out" in
  *period=2*) echo "wiggle: the run blew up at t = 3"; exit 1 ;;
esac
cp "$FAKE_SUMMARY" "$out/summary.json"
)";

class CoordinatorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    fake_ = dir_ / "fake-wiggle";
    std::ofstream(fake_) << kFakeWiggle;
    fs::permissions(fake_, fs::perms::owner_all);
    writeFileAtomically(dir_ / "pinned.bed", "never read: a pinned bed is not made, and the stand-in reads nothing");
    RunSummary summary;
    summary.status = RunStatus::Ok;
    summary.vy = 0.25;
    writeFileAtomically(dir_ / "summary.json", toJson(summary).dump());
    ::setenv("FAKE_SUMMARY", (dir_ / "summary.json").c_str(), 1);
    ::setenv("FAKE_LOG", (dir_ / "fake.log").c_str(), 1);
    // Five cases on a pinned bed (no bed task): one of them, period 2, fails.
    writeFileAtomically(dir_ / "sweep.toml", "[sweep]\nname = \"coordinator\"\n[base.bed]\nfile = \"" +
                                                 (dir_ / "pinned.bed") +
                                                 "\"\n[grid.drive]\nperiod = [1.0, 2.0, 3.0, 4.0, 5.0]\n");
  }
  void TearDown() override {
    ::unsetenv("FAKE_SUMMARY");
    ::unsetenv("FAKE_LOG");
  }

  // The whole sweep, or with `only` one case of it as `sweep --case` runs it.
  SweepOutcome sweep(std::optional<std::size_t> only = std::nullopt) {
    SweepPlan plan = makeSweepPlan(loadSweepSpec(dir_ / "sweep.toml"), dir_ / "out");
    SweepOptions options;
    options.outDir = dir_ / "out";
    options.progress = false;
    options.logToStderr = false;
    options.handleSignals = false;
    fs::create_directories(dir_ / "out/cases");
    return coordinateSweep(plan, SweepRunSettings{2, 1, fake_}, options, nullptr, only);
  }

  // results.csv's status and error of each case, by case name.
  std::map<std::string, std::pair<std::string, std::string>> tableRows() {
    const auto rows = parseCsv(readFile(dir_ / "out/results.csv"));
    const auto& header = rows.at(0);
    const auto column = [&](const char* name) { return std::find(header.begin(), header.end(), name) - header.begin(); };
    std::map<std::string, std::pair<std::string, std::string>> byCase;
    for (std::size_t r = 1; r < rows.size(); ++r)
      byCase[rows[r][column("case")]] = {rows[r][column("status")], rows[r][column("error")]};
    return byCase;
  }

  // The stand-in's log: how many times each case started, and the most that ran at once.
  std::pair<std::map<std::string, int>, int> starts() {
    std::map<std::string, int> count;
    int running = 0, most = 0;
    std::istringstream log(readFile(dir_ / "fake.log"));
    for (std::string word, out; log >> word >> out;) {
      if (word == "start") ++count[fs::path(out).filename().string()];
      running += word == "start" ? 1 : -1;
      most = std::max(most, running);
    }
    return {count, most};
  }

  ScratchDir dir_{"coordinator"};
  std::string fake_;
};

TEST_F(CoordinatorTest, EveryCaseOnceAtMostTheJobsAtOnceAndTheFailureRecorded) {
  const SweepOutcome outcome = sweep();
  EXPECT_EQ(outcome.cases, 5u);
  EXPECT_EQ(outcome.ok, 4u);
  EXPECT_EQ(outcome.failed, 1u);
  EXPECT_FALSE(outcome.interrupted);
  const auto [count, most] = starts();
  EXPECT_EQ(count.size(), 5u);
  for (const auto& [name, n] : count) EXPECT_EQ(n, 1) << name;
  EXPECT_LE(most, 2);  // the jobs
  const auto rows = parseCsv(readFile(dir_ / "out/results.csv"));
  ASSERT_EQ(rows.size(), 6u);
  const auto& header = rows[0];
  const auto column = [&](const char* name) { return std::find(header.begin(), header.end(), name) - header.begin(); };
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const bool bad = rows[r][column("case")] == "period=2";
    EXPECT_EQ(rows[r][column("status")], bad ? "failed" : "ok") << rows[r][column("case")];
    EXPECT_EQ(rows[r][column("error")], bad ? "the run blew up at t = 3" : "");
    if (!bad) {
      EXPECT_EQ(std::stod(rows[r][column("vy")]), 0.25);
    }
  }
  const std::string log = readFile(dir_ / "out/sweep.log");
  EXPECT_NE(log.find("failed period=2: the run blew up at t = 3"), std::string::npos) << log;
}

TEST_F(CoordinatorTest, ASecondSweepRunsOnlyWhatDidNotFinish) {
  sweep();
  fs::remove(dir_ / "fake.log");
  const SweepOutcome again = sweep();
  EXPECT_EQ(again.ok, 4u);
  EXPECT_EQ(again.failed, 1u);
  EXPECT_EQ(starts().first, (std::map<std::string, int>{{"period=2", 1}}));
}

// Two array tasks in one directory, one after the other: the second started after the first's
// case failed, and rewrites the table; the failure, which only the first task's row records, stays.
TEST_F(CoordinatorTest, ACaseTaskKeepsTheFailureAnotherTaskWroteOfItsCase) {
  EXPECT_EQ(sweep(1).failed, 1u);  // period=2
  EXPECT_EQ(tableRows().at("period=2"), std::make_pair(std::string("failed"), std::string("the run blew up at t = 3")));
  EXPECT_EQ(sweep(0).ok, 1u);  // period=1
  const auto rows = tableRows();
  EXPECT_EQ(rows.at("period=1").first, "ok");
  EXPECT_EQ(rows.at("period=2"), std::make_pair(std::string("failed"), std::string("the run blew up at t = 3")));
  EXPECT_EQ(rows.at("period=3"), std::make_pair(std::string("pending"), std::string()));
}

}  // namespace
}  // namespace wiggle
