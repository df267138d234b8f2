// One case end to end on a tiny bed: outputs, resume from a checkpoint bit for bit, bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <thread>
#include <vector>

#include "analysis/Trajectory.h"
#include "core/Error.h"
#include "core/StopSignal.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "io/FileLock.h"
#include "io/StateFile.h"
#include "scenario/bed/BedMaker.h"
#include "scenario/lammps/LammpsDump.h"
#include "scenario/lammps/LammpsExport.h"
#include "scenario/run/Checkpoint.h"
#include "scenario/run/Experiment.h"
#include "scenario/run/Remeasure.h"
#include "scenario/run/RunProgress.h"
#include "scenario/run/RunSummary.h"
#include "support/TestSupport.h"

namespace wiggle {
namespace {

namespace fs = std::filesystem;

// A 20 x 12 bed (about 200 grains) around a 3 x 3 square, A = 1, T = 0.5, run for 0.4 (4000 steps),
// with fields, dumps and several phase bins filled; the bed is cached once per test process.
RunConfig tinyConfig(const std::string& root) {
  RunConfig c = loadRunConfig(std::nullopt,
                              {"box.width=20", "box.bed_height=12", "intruder.shape=polygon",
                               "intruder.vertices=[[-1.5,-1.5],[1.5,-1.5],[1.5,1.5],[-1.5,1.5]]", "intruder.y0=6",
                               "drive.amplitude=1", "drive.period=0.5", "bed.rest_energy=1e-4", "bed.max_time=100",
                               "run.duration=0.4", "run.sample_interval=0.01", "run.dump_interval=0.1",
                               "run.plot=false", "fields.radius=4"});
  c.bed.cacheDir = root + "/cache";
  return c;
}

// The process's own scratch directory, emptied when first used and removed at exit: a directory
// left by an earlier process of the same id (ids are reused) must not look like an earlier run.
std::string scratch(const std::string& name) {
  static const testing_support::ScratchDir dir("experiment-test");
  fs::create_directories(dir.path());  // (some tests remove it to start over)
  return dir / name;
}

RunOptions quiet(const std::string& dir) {
  RunOptions o;
  o.outDir = dir;
  o.progressLine = false;
  return o;
}

TEST(Experiment, ResumedRunIsBitwiseIdenticalToAnUninterruptedOne) {
  // Its own empty bed cache: the uninterrupted run makes the bed and runs on it as made, the
  // interrupted one loads it from the cache (where the pairs' forces are not held), so the dump
  // frames' forces are compared across both ways of starting as well as across the resume.
  RunConfig config = tinyConfig(scratch(""));
  config.bed.cacheDir = scratch("resume-cache");
  fs::remove_all(config.bed.cacheDir);
  const std::string straight = scratch("straight"), interrupted = scratch("interrupted");
  const RunOutcome reference = runExperiment(prepareCase(config), quiet(straight));
  ASSERT_EQ(reference.summary.status, RunStatus::Ok);
  ASSERT_NE(readFile(straight + "/log.txt").find("bed made"), std::string::npos);
  const std::optional<RunProgress> done = readRunProgress(straight);  // what `wiggle status` reads
  ASSERT_TRUE(done.has_value());
  EXPECT_EQ(done->phase, RunPhase::Finished);
  EXPECT_EQ(done->stage, "finished");
  EXPECT_EQ(done->fraction, 1.0);
  EXPECT_DOUBLE_EQ(done->t, config.run.duration);

  RunOptions stop = quiet(interrupted);
  stop.stopAfterSteps = 1700;  // mid-period, between samples and dump frames
  stop.checkpointAtStop = true;
  ASSERT_EQ(runExperiment(prepareCase(config), stop).summary.status, RunStatus::Stopped);
  // Beside its checkpoint, the trajectory so far: the uninterrupted run's first rows, to step 1700.
  const std::string soFar = readFile(interrupted + "/trajectory.csv");
  const std::string whole = readFile(straight + "/trajectory.csv");
  EXPECT_EQ(whole.rfind(soFar, 0), 0u) << "not the start of the whole run's trajectory";
  const double lastSample = readTrajectoryCsv(interrupted + "/trajectory.csv").back().t;
  EXPECT_GT(lastSample, 0.16 - 1e-9);  // samples every 0.01, the stop at t = 0.17
  EXPECT_LT(lastSample, 0.17 + 1e-9);
  EXPECT_LT(soFar.size(), whole.size());
  // Work done after the checkpoint and lost in a crash: the resumed run must not depend on it.
  RunOptions resume = quiet(interrupted);
  resume.resume = true;
  const RunOutcome resumed = runExperiment(prepareCase(config), resume);
  EXPECT_EQ(resumed.summary.stateHash, reference.summary.stateHash);
  ASSERT_NE(readFile(interrupted + "/log.txt").find("bed loaded"), std::string::npos);
  for (const char* file : {"trajectory.csv", "phase_rates.csv", "fields.csv", "dumps/dump.lammpstrj", "model.json"})
    EXPECT_EQ(readFile(interrupted + "/" + file), readFile(straight + "/" + file)) << file;
  const std::string dump = readFile(straight + "/dumps/dump.lammpstrj");
  // Five frames (t = 0, 0.1, ..., 0.4), each with the force and torque columns.
  std::size_t frames = 0;
  for (std::size_t at = 0; (at = dump.find("ITEM: ATOMS id type x y z radius vx vy fx fy tqz\n", at)) != std::string::npos; ++at)
    ++frames;
  EXPECT_EQ(frames, 5u);
  const auto summary = nlohmann::json::parse(readFile(straight + "/summary.json"));
  EXPECT_EQ(summary["status"], "ok");
  EXPECT_EQ(summary["steps"], 4000);
  EXPECT_EQ(summary["state_hash"], reference.summary.stateHash);
  EXPECT_GT(summary["n_grains"].get<int>(), 100);
  // The file holds exactly the schema's keys (step_profile only with run.profile), and reads back into
  // the struct that wrote it.
  std::vector<std::string> keys, schema;
  for (const auto& [key, value] : summary.items()) keys.push_back(key);
  for (const SummaryField& f : summaryFields())
    if (std::string(f.name) != "step_profile") schema.push_back(f.name);
  std::sort(schema.begin(), schema.end());
  EXPECT_EQ(keys, schema);
  EXPECT_EQ(toJson(summaryFromJson(summary)), summary);
  // 20 phase rows, each bin filled over t > t_i = 0.04 (3600 steps, 180 per bin).
  std::ifstream rates(straight + "/phase_rates.csv");
  std::string line;
  int rows = -1;
  while (std::getline(rates, line)) ++rows;
  EXPECT_EQ(rows, 20);
}

// An intruder that may turn writes its turn beside each sample (trajectory.csv's angle and omega, the
// last angle summary.json's angle_end), and a resumed run writes it bit for bit as an uninterrupted one.
TEST(Experiment, ATurningIntruderRecordsItsTurnAndResumesBitwise) {
  RunConfig config = tinyConfig(scratch(""));
  config.intruder.rotation = IntruderRotation::Free;
  config.run.dumpInterval = 0.0;
  config.fields.enabled = false;
  const std::string straight = scratch("turning-straight"), interrupted = scratch("turning-interrupted");
  const RunOutcome reference = runExperiment(prepareCase(config), quiet(straight));
  ASSERT_EQ(reference.summary.status, RunStatus::Ok);
  const std::string whole = readFile(straight + "/trajectory.csv");
  EXPECT_EQ(whole.substr(0, whole.find('\n')), "t,x,y,vx,vy,fy,angle,omega");
  std::istringstream lastRow(whole.substr(whole.rfind('\n', whole.size() - 2) + 1));
  std::vector<double> cells;
  for (std::string cell; std::getline(lastRow, cell, ',');) cells.push_back(std::stod(cell));
  ASSERT_EQ(cells.size(), 8u);
  const double lastAngle = cells[6];
  EXPECT_NEAR(lastAngle, reference.summary.angleEnd, 1e-9 * (1.0 + std::fabs(lastAngle)));
  EXPECT_NE(reference.summary.angleEnd, 0.0);  // it turned

  RunOptions stop = quiet(interrupted);
  stop.stopAfterSteps = 1700;
  stop.checkpointAtStop = true;
  ASSERT_EQ(runExperiment(prepareCase(config), stop).summary.status, RunStatus::Stopped);
  RunOptions resume = quiet(interrupted);
  resume.resume = true;
  const RunOutcome resumed = runExperiment(prepareCase(config), resume);
  EXPECT_EQ(resumed.summary.stateHash, reference.summary.stateHash);
  EXPECT_EQ(readFile(interrupted + "/trajectory.csv"), whole);
}

// run.profile: summary.json's step_profile, whose stages sum to its step_s, within the run's wall
// time; the same bits as without it, and no step_profile without it.
TEST(Experiment, StepProfileOnlyWhenAskedWithTheSameBits) {
  RunConfig plain = tinyConfig(scratch(""));
  RunConfig profiled = plain;
  profiled.run.profile = true;
  const std::string without = scratch("profile-off"), with = scratch("profile-on");
  const RunOutcome a = runExperiment(prepareCase(plain), quiet(without));
  const RunOutcome b = runExperiment(prepareCase(profiled), quiet(with));
  ASSERT_EQ(b.summary.status, RunStatus::Ok);
  EXPECT_EQ(b.summary.stateHash, a.summary.stateHash);
  EXPECT_FALSE(nlohmann::json::parse(readFile(without + "/summary.json")).contains("step_profile"));
  const auto summary = nlohmann::json::parse(readFile(with + "/summary.json"));
  ASSERT_TRUE(summary.contains("step_profile"));
  const nlohmann::json& p = summary["step_profile"];
  EXPECT_EQ(p["steps"], summary["steps"]);
  const double step = p["step_s"].get<double>();
  EXPECT_GT(step, 0.0);
  EXPECT_LE(step, summary["run_wall_s"].get<double>());
  double seconds = 0.0, shares = 0.0;
  for (const auto& [name, stage] : p["stages"].items()) {
    seconds += stage["s"].get<double>();
    shares += stage["share"].get<double>();
  }
  EXPECT_NEAR(seconds, step, 1e-9 * step + 1e-12);
  EXPECT_NEAR(shares, 1.0, 1e-9);
  EXPECT_EQ(p["stages"]["contact_forces"]["calls"], summary["steps"]);
  EXPECT_EQ(p["stages"].size(), 10u);
  for (const char* share : {"serial_share", "wait_share"}) {
    EXPECT_GE(p[share].get<double>(), 0.0) << share;
    EXPECT_LE(p[share].get<double>(), 1.0) << share;
  }
  EXPECT_EQ(toJson(summaryFromJson(summary)), summary);
}

TEST(Experiment, FinishedRunExtendedIsTheLongerRunFromTheStart) {
  // A run of t = 0.4, finished, then resumed with run.duration = 0.8: the same final state, trajectory
  // and V_y as a run of 0.8 from the start. Its phase rates and fields average from t = 0.04 (0.1 of
  // its first duration) instead of 0.08, which summary.json says.
  RunConfig shorter = tinyConfig(scratch(""));
  RunConfig longer = shorter;
  longer.run.duration = 0.8;
  const std::string straight = scratch("long-straight"), extended = scratch("extended");
  const RunOutcome reference = runExperiment(prepareCase(longer), quiet(straight));
  ASSERT_EQ(runExperiment(prepareCase(shorter), quiet(extended)).summary.status, RunStatus::Ok);
  RunOptions resume = quiet(extended);
  resume.resume = true;
  const RunOutcome grown = runExperiment(prepareCase(longer), resume);
  EXPECT_EQ(grown.summary.stateHash, reference.summary.stateHash);
  EXPECT_EQ(grown.summary.vy, reference.summary.vy);
  EXPECT_EQ(readFile(extended + "/trajectory.csv"), readFile(straight + "/trajectory.csv"));
  const auto summary = nlohmann::json::parse(readFile(extended + "/summary.json"));
  EXPECT_NEAR(summary["averaged_from_t"].get<double>(), 0.04, 1e-9);
  bool saysExtended = false;  // (beside the short-window warning: 1.44 periods here)
  for (const auto& w : summary["warnings"]) saysExtended |= w.get<std::string>().find("extended") != std::string::npos;
  EXPECT_TRUE(saysExtended) << summary["warnings"];
  EXPECT_NEAR(nlohmann::json::parse(readFile(straight + "/summary.json"))["averaged_from_t"].get<double>(), 0.08, 1e-9);

  // What cannot continue a run is refused, naming the key: a shorter run, or any other key.
  auto refusal = [&](RunConfig changed) {
    try {
      runExperiment(prepareCase(changed), resume);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  RunConfig cut = longer;
  cut.run.duration = 0.6;
  EXPECT_NE(refusal(cut).find("run.duration = 0.6 is shorter"), std::string::npos) << refusal(cut);
  RunConfig other = longer;
  other.drive.amplitude = 0.5;
  EXPECT_NE(refusal(other).find("drive.amplitude is 0.5 here but 1 in the run"), std::string::npos) << refusal(other);
}

TEST(Experiment, ThreadCountDoesNotChangeTheResult) {
  const RunConfig config = tinyConfig(scratch(""));
  RunOptions one = quiet(scratch("one-thread"));
  one.threads = 1;
  RunOptions three = quiet(scratch("three-threads"));
  three.threads = 3;
  const RunOutcome a = runExperiment(prepareCase(config), one);
  const RunOutcome b = runExperiment(prepareCase(config), three);
  EXPECT_EQ(a.summary.stateHash, b.summary.stateHash);
  EXPECT_EQ(readFile(one.outDir + "/fields.csv"), readFile(three.outDir + "/fields.csv"));
  // The seconds at each thread count (physics/ThreadGovernor.h): none at one thread; at three, every
  // count used is one to three, and they add up to no more than the run's own wall time.
  EXPECT_TRUE(a.summary.threadsUsed.is_null());
  ASSERT_TRUE(b.summary.threadsUsed.is_object());
  double seconds = 0.0;
  for (const auto& [count, s] : b.summary.threadsUsed.items()) {
    EXPECT_GE(std::stoi(count), 1);
    EXPECT_LE(std::stoi(count), 3);
    seconds += s.get<double>();
  }
  EXPECT_GT(seconds, 0.0);
  EXPECT_LE(seconds, b.summary.runWallSeconds);
}

// The lines of a bed cache's speed.log (scenario/cost/SpeedRecord.h), each split at its tabs.
std::vector<std::vector<std::string>> speedLogLines(const RunConfig& config) {
  std::ifstream log(config.bed.cacheDir + "/speed.log");
  std::vector<std::vector<std::string>> lines;
  for (std::string line; std::getline(log, line);) {
    std::vector<std::string> fields;
    std::istringstream in(line);
    for (std::string f; std::getline(in, f, '\t');) fields.push_back(f);
    lines.push_back(fields);
  }
  return lines;
}

// A run of 10^4 steps or more leaves its speed for the cost estimates (scenario/cost/SpeedRecord.h): one
// line in its bed cache's speed.log with the wall figure of its summary, its CPU figure, which is
// what the estimates take, and its particle count, by which they pick runs of beds of their size.
// One thread's CPU time cannot exceed its wall time.
TEST(Experiment, ARunRecordsItsWallAndCpuSpeedForTheEstimates) {
  const std::string root = scratch("speed");
  fs::remove_all(root);
  RunConfig config = tinyConfig(root);
  config.run.duration = 1.2;  // 12,000 steps
  RunOptions options = quiet(root + "/run");
  options.threads = 1;
  ASSERT_EQ(runExperiment(prepareCase(config), options).summary.status, RunStatus::Ok);
  const nlohmann::json summary = nlohmann::json::parse(readFile(options.outDir + "/summary.json"));
  const auto lines = speedLogLines(config);
  ASSERT_EQ(lines.size(), 1u);
  ASSERT_EQ(lines[0].size(), 7u);
  EXPECT_EQ(lines[0][1], "1");
  const double wall = std::stod(lines[0][2]), cpu = std::stod(lines[0][5]);
  EXPECT_NEAR(wall, summary.at("ns_per_particle_step").get<double>(), 1e-5 * wall);
  EXPECT_GT(cpu, 0.0);
  EXPECT_LE(cpu, 1.02 * wall);
  EXPECT_EQ(lines[0][6], std::to_string(summary.at("n_particles").get<std::uint64_t>()));
}

// A run stopped by a signal leaves the speed of its stretch too: a case of hours mostly runs in
// stretches that end so, and a machine that has only run such cases needs a speed of its own for
// the estimates. The signal comes once a checkpoint's trajectory (one every 0.2 s of wall time)
// has passed t = 1.2 (10^4 steps and more) of the run's 50, which on any machine is long before
// the run's end; the test's own guard keeps a signal that came late from killing the process.
TEST(Experiment, ARunStoppedBySignalRecordsTheSpeedOfItsStretch) {
  const std::string root = scratch("speed-signal");
  fs::remove_all(root);
  RunConfig config = tinyConfig(root);
  config.run.duration = 50.0;
  config.run.checkpointInterval = 0.2;
  RunOptions options = quiet(root + "/run");
  options.threads = 1;
  const Case run = prepareCase(config);
  const std::uint64_t particles = obtainBed(config, run.clump).world.particles().size();  // cached before the run
  const std::string trajectory = options.outDir + "/trajectory.csv";
  const auto passed = [&](double t) {
    try {
      const std::vector<TrajectorySample> samples = readTrajectoryCsv(trajectory);
      return !samples.empty() && samples.back().t >= t;
    } catch (const Error&) {  // not written yet
      return false;
    }
  };
  const StopSignalGuard late;
  std::atomic<bool> ended{false};
  std::thread signaller([&] {
    for (; !ended; std::this_thread::sleep_for(std::chrono::milliseconds(20)))
      if (passed(1.2)) {
        std::raise(SIGTERM);
        return;
      }
  });
  try {
    runExperiment(run, options);
    ADD_FAILURE() << "not interrupted";
  } catch (const Interrupted& e) {
    EXPECT_EQ(e.exitStatus(), 143);
  } catch (const std::exception& e) {  // failed: the signaller is still to be joined
    ADD_FAILURE() << e.what();
  }
  ended = true;
  signaller.join();
  const auto lines = speedLogLines(config);
  ASSERT_EQ(lines.size(), 1u);
  ASSERT_EQ(lines[0].size(), 7u);
  EXPECT_EQ(lines[0][1], "1");
  EXPECT_GT(std::stod(lines[0][2]), 0.0);  // wall
  EXPECT_GT(std::stod(lines[0][5]), 0.0);  // CPU (with the checkpoints' own, here not small beside the stepping)
  EXPECT_EQ(lines[0][6], std::to_string(particles));
}

TEST(Experiment, RefusesToOverwriteARunAndKeepsItsFiles) {
  const RunConfig config = tinyConfig(scratch(""));
  const std::string dir = scratch("existing");
  runExperiment(prepareCase(config), quiet(dir));
  const std::string before = readFile(dir + "/summary.json");
  EXPECT_THROW(runExperiment(prepareCase(config), quiet(dir)), Error);
  EXPECT_EQ(readFile(dir + "/summary.json"), before);
  RunConfig other = config;
  other.drive.period = 1.0;
  RunOptions resume = quiet(dir);
  resume.resume = true;
  EXPECT_THROW(runExperiment(prepareCase(other), resume), Error);  // a different config cannot resume this run
  EXPECT_EQ(readFile(dir + "/summary.json"), before);
}

// Two processes given one directory (two array tasks with the same case, a resume while the run
// goes on): the second stops before it writes anything, naming the directory.
TEST(Experiment, ARunningRunsDirectoryIsRefusedToAnother) {
  const RunConfig config = tinyConfig(scratch(""));
  const std::string dir = scratch("held");
  fs::create_directories(dir);
  RunOptions resume = quiet(dir);
  resume.resume = true;
  {
    const FileLock running(runLockPath(dir), false, false, "");  // as the run writing there holds it
    const std::string refused = testing_support::errorOf([&] { runExperiment(prepareCase(config), resume); });
    EXPECT_NE(refused.find("another wiggle process is running the case in " + dir), std::string::npos) << refused;
    EXPECT_FALSE(fs::exists(dir + "/config.toml"));
  }
  EXPECT_EQ(runExperiment(prepareCase(config), resume).summary.status, RunStatus::Ok);       // released: it runs
  EXPECT_EQ(FileLock::holders(runLockPath(dir)), FileLock::Holders::None);  // and lets go when it ends
}

TEST(Experiment, GeometryErrorsNameTheKey) {
  RunConfig c = tinyConfig(scratch(""));
  auto message = [&](const RunConfig& config) {
    try {
      runExperiment(prepareCase(config), quiet(scratch("never")));
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  RunConfig narrow = c;
  narrow.drive.amplitude = 8;
  EXPECT_NE(message(narrow).find("box.width"), std::string::npos);
  RunConfig high = c;
  high.intruder.y0 = 10.5;
  EXPECT_NE(message(high).find("intruder.y0"), std::string::npos);
  RunConfig low = c;
  low.intruder.y0 = 2.0;
  EXPECT_NE(message(low).find("intruder.y0"), std::string::npos);
  EXPECT_FALSE(fs::exists(scratch("never") + "/summary.json"));
}

TEST(Experiment, CorruptCheckpointFallsBackToThePreviousOne) {
  const RunConfig config = tinyConfig(scratch(""));
  const std::string reference = scratch("ref-corrupt"), dir = scratch("corrupt");
  const RunOutcome expected = runExperiment(prepareCase(config), quiet(reference));
  RunOptions stop = quiet(dir);
  stop.stopAfterSteps = 1000;
  stop.checkpointAtStop = true;
  runExperiment(prepareCase(config), stop);
  RunOptions more = quiet(dir);
  more.resume = true;
  more.stopAfterSteps = 1000;
  more.checkpointAtStop = true;
  runExperiment(prepareCase(config), more);  // now checkpoint.bin (step 2000) and checkpoint.prev.bin (step 1000)
  std::string bytes = readFile(dir + "/checkpoint.bin");
  bytes[bytes.size() / 2] ^= 0x10;
  writeFileAtomically(dir + "/checkpoint.bin", bytes);
  RunOptions resume = quiet(dir);
  resume.resume = true;
  EXPECT_EQ(runExperiment(prepareCase(config), resume).summary.stateHash, expected.summary.stateHash);
  EXPECT_NE(readFile(dir + "/log.txt").find("checksum"), std::string::npos);
}

TEST(Experiment, ResumingAFinishedRunRewritesTheSameSummary) {
  // --resume on a finished run rewrites its results from the last checkpoint, where the pairs'
  // forces are not held: the summary must still count the contacts of the last step.
  const RunConfig config = tinyConfig(scratch(""));
  const std::string dir = scratch("finished-resumed");
  fs::remove_all(dir);
  ASSERT_EQ(runExperiment(prepareCase(config), quiet(dir)).summary.status, RunStatus::Ok);
  const auto before = nlohmann::json::parse(readFile(dir + "/summary.json"));
  RunOptions resume = quiet(dir);
  resume.resume = true;
  ASSERT_EQ(runExperiment(prepareCase(config), resume).summary.status, RunStatus::Ok);
  const auto after = nlohmann::json::parse(readFile(dir + "/summary.json"));
  EXPECT_GT(before["contacts"].get<int>(), 0);
  for (const char* key : {"contacts", "neighbour_pairs", "intruder_pairs", "state_hash", "vy", "warnings"})
    EXPECT_EQ(after[key], before[key]) << key;
}

TEST(Experiment, NoDumpsLeaveNoDumpFile) {
  RunConfig config = tinyConfig(scratch(""));
  config.run.dumpInterval = 0;
  const std::string dir = scratch("no-dumps");
  fs::remove_all(dir);
  ASSERT_EQ(runExperiment(prepareCase(config), quiet(dir)).summary.status, RunStatus::Ok);
  EXPECT_FALSE(fs::exists(dir + "/dumps/dump.lammpstrj"));
  EXPECT_FALSE(fs::exists(dir + "/dumps"));
}

TEST(Experiment, UnreadableCheckpointsRestartFromTheBedWithAWarning) {
  // Both checkpoints damaged: the run starts again from the bed, which must be said in the
  // outcome (the console) and in summary.json, not only in log.txt; and it is kept when that
  // restarted run is itself interrupted and resumed.
  const RunConfig config = tinyConfig(scratch(""));
  const std::string dir = scratch("both-corrupt");
  fs::remove_all(dir);
  RunOptions stop = quiet(dir);
  stop.stopAfterSteps = 1000;
  stop.checkpointAtStop = true;
  runExperiment(prepareCase(config), stop);
  RunOptions more = stop;
  more.resume = true;
  runExperiment(prepareCase(config), more);
  for (const std::string& path : {checkpointPath(dir), previousCheckpointPath(dir)}) {
    std::string bytes = readFile(path);
    bytes[bytes.size() / 2] ^= 0x10;
    writeFileAtomically(path, bytes);
  }
  runExperiment(prepareCase(config), more);  // restarts from the bed, stops again at step 1000
  RunOptions resume = quiet(dir);
  resume.resume = true;
  const RunOutcome outcome = runExperiment(prepareCase(config), resume);
  auto saysRestarted = [](const auto& warnings) {
    int n = 0;
    for (const auto& w : warnings) n += std::string(w).find("restarted from the bed") != std::string::npos;
    return n;
  };
  EXPECT_EQ(saysRestarted(outcome.summary.warnings), 1);
  const auto summary = nlohmann::json::parse(readFile(dir + "/summary.json"));
  EXPECT_EQ(saysRestarted(summary["warnings"].get<std::vector<std::string>>()), 1) << summary["warnings"];
  // A new run in a fresh directory has no such history.
  EXPECT_EQ(readRunWarnings(scratch("no-such-run")).size(), 0u);
}

TEST(Experiment, DamagedCheckpointsAndBedsAreNeverLoaded) {
  // A real checkpoint and a real cached bed, each damaged 100 ways (50 truncations at random
  // lengths, 50 random runs of 1-16 bytes overwritten): every version is refused by the readers
  // `--resume` and the bed cache use, with a one-line error naming the file.
  const RunConfig config = tinyConfig(scratch(""));
  const std::string dir = scratch("damaged");
  RunOptions stop = quiet(dir);
  stop.stopAfterSteps = 300;
  stop.checkpointAtStop = true;
  runExperiment(prepareCase(config), stop);
  const std::string configToml = toToml(config);
  const std::string checkpoint = readFile(checkpointPath(dir));
  const std::string key = bedKey(config, prepareCase(config).clump);
  const std::string bed = readFile(bedCachePath(config, key));
  ASSERT_NO_THROW(parseCheckpoint(checkpoint, "c.bin", config, configToml));
  ASSERT_NO_THROW(parseCachedBed(bed, "b.bin", key));
  std::mt19937_64 rng(7);
  int refused = 0;
  for (const bool isBed : {false, true}) {
    const std::string& good = isBed ? bed : checkpoint;
    for (int trial = 0; trial < 100; ++trial) {
      std::string bad = good;
      if (trial < 50) {
        bad.resize(rng() % good.size());
      } else {
        const std::size_t at = rng() % good.size(), n = 1 + rng() % 16;
        for (std::size_t i = at; i < std::min(good.size(), at + n); ++i) bad[i] = static_cast<char>(rng());
        if (bad == good) continue;
      }
      try {
        if (isBed) parseCachedBed(bad, "b.bin", key);
        else parseCheckpoint(bad, "c.bin", config, configToml);
        ADD_FAILURE() << (isBed ? "bed" : "checkpoint") << " damage " << trial << " was loaded";
      } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
        EXPECT_EQ(std::string(e.what()).rfind(isBed ? "b.bin" : "c.bin", 0), 0u) << e.what();
        ++refused;
      }
    }
  }
  EXPECT_GE(refused, 195);  // (a random overwrite may leave the bytes as they were: skipped)
  // A checkpoint of another config is refused too.
  RunConfig other = config;
  other.drive.period = 1.0;
  EXPECT_THROW(parseCheckpoint(checkpoint, "c.bin", other, toToml(other)), Error);
}

TEST(Experiment, CorruptOrForeignCachedBedIsRebuiltIdentically) {
  const RunConfig config = tinyConfig(scratch("bed-rebuild"));
  const ClumpDef clump = prepareCase(config).clump;
  const std::string path = bedCachePath(config, bedKey(config, clump));
  const CachedBed first = obtainBed(config, clump);
  const std::string good = readFile(path);
  const std::string hash = first.world.stateHash();
  std::string flipped = good;
  flipped[good.size() / 3] ^= 0x01;
  std::string foreign;  // a bed file of the right kind holding another key
  {
    BinaryWriter out;
    out.string("0123456789abcdef");
    first.world.save(out);
    writeStateFile(path + ".foreign", "bed", out.bytes());
    foreign = readFile(path + ".foreign");
  }
  const std::pair<std::string, std::string> damages[] = {{flipped, "checksum"},
                                                         {good.substr(0, good.size() / 2), "truncated"},
                                                         {foreign, "other parameters"},
                                                         {readFile(path + ".foreign").substr(0, 8) + "junk", "truncated"}};
  for (const auto& [bytes, why] : damages) {
    writeFileAtomically(path, bytes);
    const CachedBed bed = obtainBed(config, clump);
    EXPECT_FALSE(bed.fromCache) << why;
    EXPECT_NE(bed.note.find(why), std::string::npos) << bed.note;
    EXPECT_EQ(bed.world.stateHash(), hash) << "the rebuilt bed differs (" << why << ")";
    EXPECT_EQ(readFile(path), good) << "the cache file was not rewritten whole (" << why << ")";
  }
}

// The state hash of tinyConfig's bed made in one go (made once per test process).
const std::string& tinyBedHash() {
  static const std::string hash = [] {
    const RunConfig config = tinyConfig(scratch("bed-reference"));
    return makeBed(config, prepareCase(config).clump).stateHash();
  }();
  return hash;
}

TEST(Experiment, BedMakingStoppedBySignalContinuesToTheSameBits) {
  // SIGTERM while pouring and while relaxing: the bed so far is saved and obtainBed throws; the
  // same call then continues it to the bits of a bed made in one go. A damaged partial file is
  // refused and the bed made afresh, to the same bits.
  const RunConfig base = tinyConfig(scratch("bed-signal-reference"));
  const ClumpDef clump = prepareCase(base).clump;
  const std::string hash = tinyBedHash();
  for (const BedStage stage : {BedStage::Pouring, BedStage::Relaxing}) {
    RunConfig config = base;
    config.bed.cacheDir = scratch("bed-signal-" + std::string(choiceName(stage)));
    const std::string key = bedKey(config, clump);
    int reports = 0;
    {
      const StopSignalGuard guard;
      try {
        obtainBed(config, clump, [&](const BedStatus& s) {
          if (s.stage == stage && ++reports == 3) std::raise(SIGTERM);
        });
        ADD_FAILURE() << "not interrupted while " << choiceName(stage);
      } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("interrupted by signal 15"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(bedPartialPath(config, key)), std::string::npos) << e.what();
      }
    }
    ASSERT_TRUE(fs::exists(bedPartialPath(config, key))) << choiceName(stage);
    EXPECT_FALSE(fs::exists(bedCachePath(config, key))) << choiceName(stage);
    int reportsAfter = 0;
    const CachedBed continued = obtainBed(config, clump, [&](const BedStatus&) { ++reportsAfter; });
    EXPECT_FALSE(continued.fromCache);
    EXPECT_TRUE(continued.note.empty()) << continued.note;
    EXPECT_EQ(continued.world.stateHash(), hash) << "continued while " << choiceName(stage);
    EXPECT_FALSE(fs::exists(bedPartialPath(config, key))) << "the partial file outlived the bed";
    if (stage == BedStage::Relaxing) {  // it continued rather than started again: only the relaxing was left
      EXPECT_GT(reportsAfter, 0);
      writeFileAtomically(bedPartialPath(config, key), "WIGGLE\x1a\njunk");
      fs::remove(bedCachePath(config, key));
      const CachedBed afresh = obtainBed(config, clump);
      EXPECT_NE(afresh.note.find("unfinished bed refused"), std::string::npos) << afresh.note;
      EXPECT_EQ(afresh.world.stateHash(), hash);
    }
  }
}

TEST(Experiment, BedSavedPeriodicallyContinuesAfterAKill) {
  // With run.checkpoint_interval = 0 the bed in the making is saved at every chance. A copy of
  // the file taken at the 4th progress report stands for what a SIGKILL leaves behind (the making
  // is then stopped at the 6th, to keep the test short): continuing from the copy gives the bits
  // of the bed made in one go.
  RunConfig config = tinyConfig(scratch("bed-periodic"));
  config.run.checkpointInterval = 0.0;
  const ClumpDef clump = prepareCase(config).clump;
  const std::string key = bedKey(config, clump);
  const std::string partial = bedPartialPath(config, key), aside = partial + ".aside";
  {
    const StopSignalGuard guard;
    int reports = 0;
    EXPECT_THROW(obtainBed(config, clump,
                           [&](const BedStatus&) {
                             if (++reports == 4) fs::copy_file(partial, aside);
                             if (reports == 6) std::raise(SIGTERM);
                           }),
                 Error);
  }
  ASSERT_TRUE(fs::exists(aside));
  fs::rename(aside, partial);
  config.run.checkpointInterval = 600.0;  // (saving at every chance costs an fsync each)
  const CachedBed continued = obtainBed(config, clump);
  EXPECT_EQ(continued.world.stateHash(), tinyBedHash());
}

// bed.file: a friction study on one bed. The run starts from the pinned bed's very particles but
// with its own friction, which changes the run; a bed of another geometry is refused by name.
TEST(Experiment, PinnedBedServesAnotherFrictionAndRefusesAnotherGeometry) {
  const std::string root = scratch("pinned");
  const RunConfig own = tinyConfig(root);
  const CachedBed made = obtainBed(own, prepareCase(own).clump);
  const RunOutcome reference = runExperiment(prepareCase(own), quiet(root + "/own"));

  RunConfig other = own;
  other.contact.mu = 0.5;
  other.bed.file = made.path;
  other.bed.cacheDir = root + "/empty-cache";  // nothing to be found or made there
  const CachedBed pinned = obtainBed(other, prepareCase(other).clump);
  EXPECT_EQ(pinned.world.def().contact.mu, 0.5);
  EXPECT_EQ(pinned.key, made.key);
  EXPECT_NE(pinned.note.find("made for other parameters"), std::string::npos) << pinned.note;
  const RunOutcome run = runExperiment(prepareCase(other), quiet(root + "/pinned"));
  EXPECT_NE(run.summary.stateHash, reference.summary.stateHash);  // the friction took effect
  EXPECT_FALSE(fs::exists(root + "/empty-cache"));  // no bed was made
  const auto summary = nlohmann::json::parse(readFile(root + "/pinned/summary.json"));
  EXPECT_EQ(summary["bed_key"], made.key);
  // The same t = 0 row up to its last cell, fy: the start's contact force, evaluated with each
  // run's own friction.
  auto startWithoutFy = [](const std::string& csv) {
    const std::string rows = csv.substr(0, csv.find('\n', csv.find('\n') + 1));
    return rows.substr(0, rows.rfind(','));
  };
  EXPECT_EQ(startWithoutFy(readFile(root + "/own/trajectory.csv")), startWithoutFy(readFile(root + "/pinned/trajectory.csv")));

  auto refusal = [&](const std::vector<std::string>& sets) {
    RunConfig bad = loadRunConfig(std::nullopt, sets);
    bad.bed.cacheDir = root + "/cache";
    bad.bed.file = made.path;
    try {
      obtainBed(bad, prepareCase(bad).clump);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  std::vector<std::string> base = {"box.width=20", "box.bed_height=12", "intruder.shape=polygon",
                                   "intruder.vertices=[[-1.5,-1.5],[1.5,-1.5],[1.5,1.5],[-1.5,1.5]]", "intruder.y0=6",
                                   "drive.amplitude=1"};
  auto with = [&](const std::string& set) {
    std::vector<std::string> v = base;
    v.push_back(set);
    return v;
  };
  EXPECT_NE(refusal(with("box.width=24")).find("box.width = 24"), std::string::npos);
  EXPECT_NE(refusal(with("intruder.y0=7")).find("intruder.y0 = 7"), std::string::npos);
  EXPECT_NE(refusal(with("intruder.mass=3")).find("mass"), std::string::npos);
  EXPECT_NE(refusal(with("grains.mass_model=disc")).find("grains.mass_model"), std::string::npos);
  RunConfig missing = own;
  missing.bed.file = root + "/nope.bin";
  EXPECT_THROW(obtainBed(missing, prepareCase(missing).clump), Error);
  fs::remove_all(root);
}

// bed.swap_intruder: another surface of the same outline on the same bed (the coupling screen's
// lattice body on the glued shell's beds). The bed's grains stay; the intruder's atoms are the
// config's, held where the file's were. Refused without the key, and for an outline the grains
// overlap (another shape), naming the overlap.
TEST(Experiment, PinnedBedTakesAnotherSurfaceOfItsOutlineWithSwapIntruder) {
  const std::string root = scratch("swap");
  const RunConfig own = tinyConfig(root);
  const CachedBed made = obtainBed(own, prepareCase(own).clump);

  RunConfig lattice = own;
  lattice.intruder.surface = IntruderSurface::Lattice;
  lattice.bed.file = made.path;
  lattice.bed.cacheDir = root + "/empty-cache";
  auto refusal = [](const RunConfig& c) {
    try {
      obtainBed(c, prepareCase(c).clump);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(refusal(lattice).find("bed.swap_intruder = true"), std::string::npos) << refusal(lattice);

  lattice.bed.swapIntruder = true;
  const ClumpDef latticeClump = prepareCase(lattice).clump;
  const CachedBed swapped = obtainBed(lattice, latticeClump);
  EXPECT_EQ(swapped.world.clump().offsetX, latticeClump.offsetX);
  EXPECT_NE(swapped.world.clump().offsetX, made.world.clump().offsetX);
  EXPECT_EQ(swapped.world.grainCount(), made.world.grainCount());
  EXPECT_EQ(swapped.world.intruder().x, made.world.intruder().x);
  EXPECT_EQ(swapped.world.intruder().y, made.world.intruder().y);
  EXPECT_EQ(swapped.key, made.key);
  EXPECT_NE(swapped.note.find("bed.swap_intruder"), std::string::npos) << swapped.note;
  const RunOutcome run = runExperiment(prepareCase(lattice), quiet(root + "/lattice"));
  EXPECT_EQ(run.summary.status, RunStatus::Ok);
  EXPECT_FALSE(fs::exists(root + "/empty-cache"));  // no bed was made

  RunConfig bigger = lattice;  // a 4 d square where the bed holds a 3 d one: grains inside its outline
  bigger.intruder.vertices = {{-2.0, -2.0}, {2.0, -2.0}, {2.0, 2.0}, {-2.0, 2.0}};
  EXPECT_NE(refusal(bigger).find("overlaps this config's intruder by"), std::string::npos) << refusal(bigger);

  RunConfig alone = own;  // the key means nothing without a bed file: refused, not ignored
  alone.bed.swapIntruder = true;
  EXPECT_THROW(validateRunConfig(alone), Error);
  fs::remove_all(root);
}

// bed.file = a LAMMPS data file. The case exported by export-lammps and read back runs to the very
// state (hash, trajectory) that the original run reaches from its bed with run.bed_history = false:
// the data file carries every particle's bits and id, and nothing of the contact history.
TEST(Experiment, ExportedBedReadBackRunsAsTheBedWithoutHistory) {
  const std::string root = scratch("lammps-round-trip");
  RunConfig own = tinyConfig(scratch(""));  // the bed shared with the other tests
  own.run.keepBedHistory = false;
  const RunOutcome reference = runExperiment(prepareCase(own), quiet(root + "/own"));
  ASSERT_EQ(reference.summary.status, RunStatus::Ok);
  const Case ownCase = prepareCase(own);
  exportLammps(startRun(ownCase).world, ownCase, root + "/deck");  // as `wiggle export-lammps` does
  // The case beside the deck, so that `wiggle rate` reads the LAMMPS run's trajectory (here the
  // wiggle run's own stands in for it) by wiggle's rules.
  EXPECT_EQ(readFile(root + "/deck/config.toml"), toToml(own));
  fs::copy_file(root + "/own/trajectory.csv", root + "/deck/trajectory.csv");
  EXPECT_NEAR(remeasureRun(root + "/deck", RemeasureRequest{}).rate.vy, reference.summary.vy, 1e-8);

  RunConfig imported = own;
  imported.run.keepBedHistory = true;  // there is none to keep
  imported.bed.file = root + "/deck/data.lammps";
  imported.bed.cacheDir = root + "/empty-cache";  // nothing to be found or made there
  const RunOutcome run = runExperiment(prepareCase(imported), quiet(root + "/imported"));
  EXPECT_EQ(run.summary.stateHash, reference.summary.stateHash);
  EXPECT_EQ(readFile(root + "/imported/trajectory.csv"), readFile(root + "/own/trajectory.csv"));
  EXPECT_FALSE(fs::exists(root + "/empty-cache"));  // no bed was made
  EXPECT_NE(readFile(root + "/imported/log.txt").find("every contact starts with zero shear"), std::string::npos);
  fs::remove_all(root);
}

// A LAMMPS data file wiggle cannot map is refused in one line that says why.
TEST(Experiment, LammpsBedFileRefusedInOneLine) {
  const std::string root = scratch("lammps-refusals");
  RunConfig config = tinyConfig(scratch(""));
  const Case exported = prepareCase(config);
  exportLammps(startRun(exported).world, exported, root + "/deck");
  const std::string data = readFile(root + "/deck/data.lammps");
  auto refusal = [&](const std::string& text, const std::vector<std::string>& sets = {}) {
    const std::string path = root + "/bad.lammps";
    writeFileAtomically(path, text);
    RunConfig bad = config;
    for (const std::string& set : sets) applyOverride(bad, set);
    bad.bed.file = path;
    try {
      obtainBed(bad, prepareCase(bad).clump);
    } catch (const Error& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
      EXPECT_EQ(what.rfind("bed.file = " + path, 0), 0u) << what;
      return what;
    }
    return std::string("no error");
  };
  auto replaced = [&](const std::string& from, const std::string& to) {
    const std::size_t at = data.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return data.substr(0, at) + to + data.substr(at + from.size());
  };
  // The data file as it is, then with the types' roles moved: it maps, or names what it cannot.
  EXPECT_EQ(refusal(data), "no error");
  EXPECT_NE(refusal(replaced("Atoms # sphere", "Atoms # atomic")).find("atom_style atomic"), std::string::npos);
  EXPECT_NE(refusal(replaced("-0.5 0.5 zlo zhi\n", "-0.5 0.5 zlo zhi\n0 0 0 xy xz yz\n")).find("triclinic"),
            std::string::npos);
  EXPECT_NE(refusal(replaced("0 20 xlo xhi", "0 24 xlo xhi")).find("box.width = 20"), std::string::npos);
  EXPECT_NE(refusal(data, {"bed.lammps_types=1=grain 2=base"}).find("type 3"), std::string::npos);
  EXPECT_NE(refusal(data, {"intruder.y0=8"}).find("intruder"), std::string::npos);
  const std::size_t firstAtom = data.find('\n', data.find("Atoms # sphere") + 16) + 1;
  const std::string firstLine = data.substr(firstAtom, data.find('\n', firstAtom) - firstAtom);
  std::istringstream words(firstLine);
  std::string id, type, diameter;
  words >> id >> type >> diameter;
  const std::string denser = id + " " + type + " " + diameter + " 2.5" +
                             firstLine.substr(firstLine.find(' ', id.size() + type.size() + diameter.size() + 3));
  EXPECT_NE(refusal(replaced(firstLine, denser)).find("density 2.5"), std::string::npos);
  std::string badNumber = firstLine;
  badNumber.replace(badNumber.rfind(' '), std::string::npos, " 0.5x");  // z
  EXPECT_NE(refusal(replaced(firstLine, badNumber)).find("\"0.5x\" is not a finite number"), std::string::npos);
  EXPECT_NE(refusal(replaced(firstLine, firstLine.substr(0, firstLine.rfind(' ')) + " 0.25")).find("z = 0"),
            std::string::npos);
  EXPECT_NE(refusal(data.substr(0, data.find("Velocities") / 2)).find("truncated"), std::string::npos);
  EXPECT_NE(refusal(data.substr(0, data.size() - 40)).find("truncated"), std::string::npos);
  EXPECT_NE(refusal("not a data file\n\n12 atoms\n").find("not a LAMMPS data file"), std::string::npos);
  fs::remove_all(root);
}

// One dump frame's rows: type and the force columns, in the frame's order (the store's, then the
// intruder's atoms).
struct DumpRow {
  int type = 0;
  double vx = 0, vy = 0, fx = 0, fy = 0, tqz = 0;
};

std::vector<DumpRow> dumpRows(const std::string& frame) {
  std::istringstream in(frame);
  std::string line;
  while (std::getline(in, line) && line.rfind("ITEM: ATOMS", 0) != 0) {
  }
  EXPECT_EQ(line, "ITEM: ATOMS id type x y z radius vx vy fx fy tqz");
  std::vector<DumpRow> rows;
  while (std::getline(in, line)) {
    std::istringstream cells(line);
    DumpRow r;
    double id, x, y, z, radius;
    cells >> id >> r.type >> x >> y >> z >> radius >> r.vx >> r.vy >> r.fx >> r.fy >> r.tqz;
    EXPECT_TRUE(cells) << line;
    rows.push_back(r);
  }
  return rows;
}

TEST(Experiment, DumpedForcesOfASettledBedBalanceItsWeight) {
  // The tiny bed (made to bed.rest_energy = 1e-4) with the intruder held in it, left to settle for
  // t = 5 more (its grains still ring a little as made); the frame is written after a step, so every
  // pair's force is that step's (a bed loaded from the cache holds only the grains' totals).
  const RunConfig config = tinyConfig(scratch(""));
  World world = obtainBed(config, prepareCase(config).clump).world;
  world.run(50000);
  const std::vector<DumpRow> rows = dumpRows(lammpsDumpFrame(world));
  const ParticleStore& s = world.particles();
  ASSERT_EQ(rows.size(), s.size() + world.clump().offsetX.size());
  const double g = world.def().gravity;
  // Each grain at rest carries its weight on its contacts: its dumped total force (contacts plus
  // gravity) is within 5 % of m g, and within 1 % for the median grain, where a dump that left out
  // gravity or a contact would be off by m g or by a contact's share of it. (Measured here: 3 %
  // at most, 0.5 % median; the rest is the bed's ringing.)
  double grainWeight = 0.0;
  std::vector<double> imbalance;
  for (std::uint32_t i = 0; i < s.grainCount; ++i) {
    ASSERT_EQ(rows[i].type, 1);
    const double weight = s.mass[i] * g;
    grainWeight += weight;
    if (std::hypot(rows[i].vx, rows[i].vy) > 1e-3) continue;  // not at rest
    imbalance.push_back(std::hypot(rows[i].fx, rows[i].fy) / weight);
    EXPECT_LT(imbalance.back(), 0.05) << "grain " << i << ": force " << rows[i].fx << ", " << rows[i].fy
                                      << " against a weight of " << weight;
  }
  ASSERT_GT(imbalance.size(), s.grainCount * 9 / 10);
  std::nth_element(imbalance.begin(), imbalance.begin() + imbalance.size() / 2, imbalance.end());
  EXPECT_LT(imbalance[imbalance.size() / 2], 0.01);
  // The grains' weight rests on the base and the intruder's atoms: the contact forces dumped for
  // them add up to the grains' total weight, pointing down, within 1 %.
  double onBaseAndIntruder = 0.0;
  for (std::size_t r = s.grainCount; r < rows.size(); ++r) onBaseAndIntruder += rows[r].fy;
  EXPECT_NEAR(onBaseAndIntruder, -grainWeight, 0.01 * grainWeight);
  // The atoms' forces add up to the intruder's contact force (to the dump's six digits per atom).
  double atomsFx = 0.0, atomsFy = 0.0, largest = 0.0;
  for (std::size_t r = s.size(); r < rows.size(); ++r) {
    atomsFx += rows[r].fx;
    atomsFy += rows[r].fy;
    largest = std::max({largest, std::fabs(rows[r].fx), std::fabs(rows[r].fy)});
  }
  EXPECT_GT(std::fabs(world.intruder().contactFy), 1.0);  // grains rest on it: a sum worth comparing
  const double digits = 5e-6 * largest * static_cast<double>(rows.size() - s.size());
  EXPECT_NEAR(atomsFx, world.intruder().contactFx, digits);
  EXPECT_NEAR(atomsFy, world.intruder().contactFy, digits);
}

}  // namespace
}  // namespace wiggle
