// One case end to end on a tiny bed: outputs, resume from a checkpoint bit for bit, bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "scenario/Experiment.h"

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

std::string scratch(const std::string& name) {
  const std::string dir = (fs::temp_directory_path() / ("wiggle-experiment-test-" + std::to_string(::getpid()))).string();
  fs::create_directories(dir);
  return dir + "/" + name;
}

RunOptions quiet(const std::string& dir) {
  RunOptions o;
  o.outDir = dir;
  o.progressLine = false;
  return o;
}

TEST(Experiment, ResumedRunIsBitwiseIdenticalToAnUninterruptedOne) {
  const RunConfig config = tinyConfig(scratch(""));
  const std::string straight = scratch("straight"), interrupted = scratch("interrupted");
  const RunOutcome reference = runExperiment(config, quiet(straight));
  ASSERT_EQ(reference.status, "ok");

  RunOptions stop = quiet(interrupted);
  stop.stopAfterSteps = 1700;  // mid-period, between samples and dump frames
  stop.checkpointAtStop = true;
  ASSERT_EQ(runExperiment(config, stop).status, "stopped");
  // Work done after the checkpoint and lost in a crash: the resumed run must not depend on it.
  RunOptions resume = quiet(interrupted);
  resume.resume = true;
  const RunOutcome resumed = runExperiment(config, resume);
  EXPECT_EQ(resumed.stateHash, reference.stateHash);
  for (const char* file : {"trajectory.csv", "phase_rates.csv", "fields.csv", "dumps/dump.lammpstrj", "model.json"})
    EXPECT_EQ(readFile(interrupted + "/" + file), readFile(straight + "/" + file)) << file;
  const auto summary = nlohmann::json::parse(readFile(straight + "/summary.json"));
  EXPECT_EQ(summary["status"], "ok");
  EXPECT_EQ(summary["steps"], 4000);
  EXPECT_EQ(summary["state_hash"], reference.stateHash);
  EXPECT_GT(summary["n_grains"].get<int>(), 100);
  // 20 phase rows, each bin filled over t > t_i = 0.04 (3600 steps, 180 per bin).
  std::ifstream rates(straight + "/phase_rates.csv");
  std::string line;
  int rows = -1;
  while (std::getline(rates, line)) ++rows;
  EXPECT_EQ(rows, 20);
}

TEST(Experiment, ThreadCountDoesNotChangeTheResult) {
  const RunConfig config = tinyConfig(scratch(""));
  RunOptions one = quiet(scratch("one-thread"));
  one.threads = 1;
  RunOptions three = quiet(scratch("three-threads"));
  three.threads = 3;
  const RunOutcome a = runExperiment(config, one);
  const RunOutcome b = runExperiment(config, three);
  EXPECT_EQ(a.stateHash, b.stateHash);
  EXPECT_EQ(readFile(one.outDir + "/fields.csv"), readFile(three.outDir + "/fields.csv"));
}

TEST(Experiment, RefusesToOverwriteARunAndKeepsItsFiles) {
  const RunConfig config = tinyConfig(scratch(""));
  const std::string dir = scratch("existing");
  runExperiment(config, quiet(dir));
  const std::string before = readFile(dir + "/summary.json");
  EXPECT_THROW(runExperiment(config, quiet(dir)), Error);
  EXPECT_EQ(readFile(dir + "/summary.json"), before);
  RunConfig other = config;
  other.drive.period = 1.0;
  RunOptions resume = quiet(dir);
  resume.resume = true;
  EXPECT_THROW(runExperiment(other, resume), Error);  // a different config cannot resume this run
  EXPECT_EQ(readFile(dir + "/summary.json"), before);
}

TEST(Experiment, GeometryErrorsNameTheKey) {
  RunConfig c = tinyConfig(scratch(""));
  auto message = [&](const RunConfig& config) {
    try {
      runExperiment(config, quiet(scratch("never")));
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
  const RunOutcome expected = runExperiment(config, quiet(reference));
  RunOptions stop = quiet(dir);
  stop.stopAfterSteps = 1000;
  stop.checkpointAtStop = true;
  runExperiment(config, stop);
  RunOptions more = quiet(dir);
  more.resume = true;
  more.stopAfterSteps = 1000;
  more.checkpointAtStop = true;
  runExperiment(config, more);  // now checkpoint.bin (step 2000) and checkpoint.prev.bin (step 1000)
  std::string bytes = readFile(dir + "/checkpoint.bin");
  bytes[bytes.size() / 2] ^= 0x10;
  writeFileAtomically(dir + "/checkpoint.bin", bytes);
  RunOptions resume = quiet(dir);
  resume.resume = true;
  EXPECT_EQ(runExperiment(config, resume).stateHash, expected.stateHash);
  EXPECT_NE(readFile(dir + "/log.txt").find("checksum"), std::string::npos);
}

}  // namespace
}  // namespace wiggle
