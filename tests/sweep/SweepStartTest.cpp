// sweep.json (sweep/SweepStart.h): what `wiggle status` knows of how a sweep was started.
#include "sweep/SweepStart.h"

#include <gtest/gtest.h>

#include <fstream>

#include "support/TestSupport.h"

namespace wiggle {
namespace {

using testing_support::ScratchDir;

TEST(SweepStart, ReadsBackWhatItWroteAndAnArrayTaskLeavesTheSweepsFigures) {
  ScratchDir dir("sweep-start");
  const std::string path = dir.path().string();
  EXPECT_FALSE(readSweepStart(path).has_value());  // none yet
  writeSweepStart(path, {"an array's", 0, 1, {}});  // an array task's start, with no file yet: written
  ASSERT_TRUE(readSweepStart(path).has_value());
  EXPECT_EQ(readSweepStart(path)->jobs, 0);
  writeSweepStart(path, {"fig5", 2, 1, {}});  // a whole sweep's start replaces it
  writeSweepStart(path, {"fig5", 0, 1, {}});  // and an array task of it after that leaves it be
  const std::optional<SweepStart> start = readSweepStart(path);
  ASSERT_TRUE(start.has_value());
  EXPECT_EQ(start->name, "fig5");
  EXPECT_EQ(start->jobs, 2);
  EXPECT_EQ(start->threads, 1);
  EXPECT_FALSE(start->beds.has_value());  // not recorded: not known, which is not "none"
  writeSweepStart(path, {"fig5", 2, 1, std::vector<BedToMake>{{"k1", "/cache/bed-k1.bin", 3600.0}}});
  const std::optional<SweepStart> withBeds = readSweepStart(path);
  ASSERT_TRUE(withBeds.has_value() && withBeds->beds.has_value());
  ASSERT_EQ(withBeds->beds->size(), 1u);
  EXPECT_EQ(withBeds->beds->front().key, "k1");
  EXPECT_EQ(withBeds->beds->front().cachePath, "/cache/bed-k1.bin");
  EXPECT_EQ(withBeds->beds->front().estimatedSeconds, 3600.0);
  writeSweepStart(path, {"fig5", 2, 1, std::vector<BedToMake>{}});  // none to make: known, and empty
  ASSERT_TRUE(readSweepStart(path)->beds.has_value());
  EXPECT_TRUE(readSweepStart(path)->beds->empty());
  std::ofstream(dir / "sweep.json") << "{\"name\": 3";  // damaged: nothing known, no error
  EXPECT_FALSE(readSweepStart(path).has_value());
}

}  // namespace
}  // namespace wiggle
