// TaskRunner on its own (sweep/TaskRunner.h), with a stand-in for the wiggle binary: a shell script
// that behaves as a case task would (writes a summary and exits 0, prints an error and exits 1, or
// hangs until killed). What is tested is the runner's side: the child's arguments and files, how an
// outcome is read (summary, last error line, signal), and the task codes that travel over MPI.
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/SweepSpec.h"
#include "scenario/run/RunSummary.h"
#include "sweep/TaskRunner.h"

namespace wiggle {
namespace {

namespace fs = std::filesystem;

// FAKE_MODE picks what the stand-in does; it records its arguments in DIR/args.txt.
constexpr const char* kFakeWiggle = R"(#!/bin/sh
out="$5"
echo "$@" > "$out/args.txt"
case "$FAKE_MODE" in
  ok)   cp "$FAKE_SUMMARY" "$out/summary.json"; echo "wiggle: warning: a warning is not a failure"; exit 0 ;;
  fail) echo "[run] 40%"; echo "wiggle: the run blew up at t = 3"; echo "wiggle: warning: not this one" >&2; exit 1 ;;
  hang) exec sleep 60 ;;
esac
)";

class TaskRunnerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("wiggle-task-runner-" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
    fake_ = (root_ / "fake-wiggle").string();
    std::ofstream(fake_) << kFakeWiggle;
    fs::permissions(fake_, fs::perms::owner_all);
    RunSummary summary;
    summary.status = RunStatus::Ok;
    summary.vy = 0.5;
    summary.stateHash = "0123456789abcdef";
    writeFileAtomically((root_ / "summary.json").string(), toJson(summary).dump());
    ::setenv("FAKE_SUMMARY", (root_ / "summary.json").c_str(), 1);
    spec_ = parseSweepSpec("[sweep]\nname = \"t\"\n[grid.drive]\nperiod = [1.0, 2.0]\n", "t.toml");
  }
  void TearDown() override {
    ::unsetenv("FAKE_MODE");
    fs::remove_all(root_);
  }

  // Starts case `index` in `mode` and waits for its outcome.
  TaskOutcome runCase(std::size_t index, const char* mode, TaskRunner& runner, bool kill = false) {
    ::setenv("FAKE_MODE", mode, 1);
    const pid_t pid = runner.start({SweepTask::Kind::Case, index});
    EXPECT_GT(pid, 0);
    EXPECT_EQ(runner.running(), 1u);
    if (kill) runner.signalAll(SIGKILL);
    for (int i = 0; i < 1000; ++i) {
      std::vector<TaskOutcome> done = runner.poll();
      if (!done.empty()) {
        EXPECT_EQ(done.size(), 1u);
        EXPECT_EQ(done[0].pid, pid);
        return done[0];
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ADD_FAILURE() << "the child did not finish";
    return {};
  }

  fs::path root_;
  std::string fake_;
  SweepSpec spec_;
};

TEST_F(TaskRunnerTest, ACaseThatEndsWellIsReadFromItsSummary) {
  TaskRunner runner(spec_, root_.string(), fake_, 3);
  const TaskOutcome o = runCase(1, "ok", runner);
  EXPECT_TRUE(o.ok) << o.error;
  EXPECT_EQ(o.result.status, CaseStatus::Ok);
  EXPECT_EQ(o.result.summary.vy, 0.5);
  EXPECT_EQ(o.result.summary.stateHash, "0123456789abcdef");
  EXPECT_EQ(o.task, (SweepTask{SweepTask::Kind::Case, 1}));
  // The child was given the case's own config and directory, through the one internal entry.
  const std::string dir = (root_ / "cases" / spec_.cases[1].name).string();
  EXPECT_EQ(readFile(dir + "/args.txt"),
            "sweep " + std::string(kCaseTaskFlag) + " " + dir + "/config.toml --out " + dir + " --threads 3\n");
  EXPECT_NE(readFile(dir + "/config.toml").find("period = 2.0"), std::string::npos);
  EXPECT_NE(readFile(dir + "/sweep-child.log").find("a warning is not a failure"), std::string::npos);
  EXPECT_EQ(runner.running(), 0u);
}

TEST_F(TaskRunnerTest, AFailureIsItsLastErrorLineNotAWarning) {
  TaskRunner runner(spec_, root_.string(), fake_, 1);
  const TaskOutcome o = runCase(0, "fail", runner);
  EXPECT_FALSE(o.ok);
  EXPECT_EQ(o.error, "the run blew up at t = 3");
  EXPECT_EQ(o.result.status, CaseStatus::Failed);
  EXPECT_EQ(o.result.error, o.error);
}

TEST_F(TaskRunnerTest, AKilledChildIsReportedWithItsSignal) {
  TaskRunner runner(spec_, root_.string(), fake_, 1);
  const TaskOutcome o = runCase(0, "hang", runner, true);
  EXPECT_FALSE(o.ok);
  EXPECT_NE(o.error.find("killed by signal 9"), std::string::npos) << o.error;
}

TEST_F(TaskRunnerTest, ACaseOutsideThePlanIsRefused) {
  TaskRunner runner(spec_, root_.string(), fake_, 1);
  EXPECT_THROW(runner.start({SweepTask::Kind::Case, 2}), Error);
  EXPECT_EQ(runner.running(), 0u);
}

TEST(SweepTask, CodesRoundTripAndKeepBedsApartFromCases) {
  for (std::size_t i : {0u, 1u, 7u, 123456u}) {
    for (SweepTask::Kind kind : {SweepTask::Kind::Bed, SweepTask::Kind::Case}) {
      const SweepTask t{kind, i};
      EXPECT_EQ(SweepTask::decode(t.encode()), t);
    }
    EXPECT_NE(SweepTask({SweepTask::Kind::Bed, i}).encode(), SweepTask({SweepTask::Kind::Case, i}).encode());
  }
}

TEST(SweepTask, OutcomesSurviveTheTripBetweenRanks) {
  TaskOutcome o;
  o.task = {SweepTask::Kind::Bed, 4};
  o.ok = false;
  o.error = "making its bed failed: \"quoted\", and a comma";
  o.wallSeconds = 12.5;
  o.pid = 4242;
  o.result.status = CaseStatus::Failed;
  o.result.error = o.error;
  const TaskOutcome back = TaskOutcome::fromJson(o.toJson());
  EXPECT_EQ(back.task, o.task);
  EXPECT_EQ(back.ok, o.ok);
  EXPECT_EQ(back.error, o.error);
  EXPECT_EQ(back.wallSeconds, o.wallSeconds);
  EXPECT_EQ(back.pid, o.pid);
  EXPECT_EQ(back.result.status, o.result.status);
}

TEST(TaskRunner, FailureLineIsTheLastErrorWithoutPrefix) {
  EXPECT_EQ(failureLine("wiggle: warning: cached bed refused\nwiggle: box.width = 5 is too narrow\n"),
            "box.width = 5 is too narrow");
  EXPECT_EQ(failureLine("wiggle: a\nwiggle: warning: b\n\n"), "a");
  EXPECT_EQ(failureLine("[run] 10%\r[run] 20%\rSegmentation fault\n"), "Segmentation fault");
  EXPECT_EQ(failureLine(""), "");
}

}  // namespace
}  // namespace wiggle
