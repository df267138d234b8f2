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
  writeSweepStart(path, {"an array's", 0, 1});     // an array task's start, with no file yet: written
  ASSERT_TRUE(readSweepStart(path).has_value());
  EXPECT_EQ(readSweepStart(path)->jobs, 0);
  writeSweepStart(path, {"fig5", 2, 1});  // a whole sweep's start replaces it
  writeSweepStart(path, {"fig5", 0, 1});  // and an array task of it after that leaves it be
  const std::optional<SweepStart> start = readSweepStart(path);
  ASSERT_TRUE(start.has_value());
  EXPECT_EQ(start->name, "fig5");
  EXPECT_EQ(start->jobs, 2);
  EXPECT_EQ(start->threads, 1);
  std::ofstream(dir / "sweep.json") << "{\"name\": 3";  // damaged: nothing known, no error
  EXPECT_FALSE(readSweepStart(path).has_value());
}

}  // namespace
}  // namespace wiggle
