#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/Error.h"
#include "io/Config.h"
#include "scenario/run/Checkpoint.h"

namespace wiggle {
namespace {

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A checkpoint of a two-grain world written with `storedToml` as its config text, read back
// against `config`.
Checkpoint roundTrip(const std::string& storedToml, const RunConfig& config) {
  // One directory per process: ctest runs this file's tests in parallel processes.
  const std::string dir =
      (std::filesystem::temp_directory_path() / ("wiggle_checkpoint_test-" + std::to_string(::getpid()))).string();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  WorldDef def;
  def.boxWidth = 10.0;
  World world(def);
  world.addGrain(2.0, 2.0, 0.5);
  world.addGrain(5.0, 2.0, 0.5);
  writeCheckpoint(dir, storedToml, world, RunState{}, FieldObserver(config.fields, config.box.width));
  const std::string bytes = readAll(checkpointPath(dir));
  std::filesystem::remove_all(dir);
  return parseCheckpoint(bytes, "checkpoint.bin", config, toToml(config));
}

std::string withoutLine(std::string text, const std::string& start) {
  const std::size_t at = text.find("\n" + start);
  EXPECT_NE(at, std::string::npos) << start;
  return text.erase(at + 1, text.find('\n', at + 1) - at);
}

TEST(Checkpoint, SameConfigIsAcceptedAndAnotherRefused) {
  RunConfig config;
  EXPECT_EQ(roundTrip(toToml(config), config).world.grainCount(), 2u);
  RunConfig longer = config;
  longer.run.duration = 200.0;
  EXPECT_THROW(roundTrip(toToml(longer), config), Error);
}

TEST(Checkpoint, WrittenBeforeAKeyExistedItHoldsTheKeysDefault) {
  // A checkpoint from a version without run.bed_history: its config text lacks the line. It
  // belongs to a run that leaves the key at its default, not to one that sets it.
  RunConfig config;
  const std::string older = withoutLine(toToml(config), "bed_history");
  EXPECT_NO_THROW(roundTrip(older, config));
  RunConfig setsIt = config;
  setsIt.run.keepBedHistory = false;
  EXPECT_THROW(roundTrip(older, setsIt), Error);
  // A key this version does not know makes it another config, not a parse error that escapes.
  EXPECT_THROW(roundTrip(toToml(config) + "\n[run]\nno_such_key = 1\n", config), Error);
}

}  // namespace
}  // namespace wiggle
