// What one bed's V_y is worth (scenario/run/BedScatter.h): the measured between-bed scatter for a
// bed of the size and window a committed replicate study measured, else "scatter unknown" and how
// to measure it.
#include "scenario/run/BedScatter.h"

#include <gtest/gtest.h>

#include <string>

#include "io/Config.h"
#include "support/TestSupport.h"

namespace wiggle {
namespace {

using testing_support::sourceFile;

RunConfig preset(const std::string& name) { return parseRunConfig(sourceFile("configs/" + name), name); }

TEST(BedScatter, ThePresetsWindowsHaveTheirMeasuredFigure) {
  const RunConfig small = preset("small.toml");
  const std::string note = oneBedScatterNote(small, 10, 100);
  EXPECT_EQ(note.rfind("one bed; beds of this size scatter by about +-0.018 over this window (t = 10-100", 0), 0u)
      << note;
  EXPECT_NE(note.find("results/pour_protocol_small"), std::string::npos) << note;

  RunConfig depth = preset("paper_depth.toml");
  EXPECT_EQ(measuredScatterFor(depth, 10, 100)->sigma, 0.045);
  // By the paper's clock each shape has its own, pooled over its cells.
  depth.intruder.shape = ShapeName::Square;
  EXPECT_EQ(measuredScatterFor(depth, 100, 1000)->sigma, 0.0024);
  depth.intruder.shape = ShapeName::Triangle;
  EXPECT_EQ(measuredScatterFor(depth, 100, 1000)->sigma, 0.0108);
  const std::string clock = oneBedScatterNote(depth, 100, 1000);
  EXPECT_NE(clock.find("+-0.0108"), std::string::npos) << clock;
  EXPECT_NE(clock.find("the triangle's"), std::string::npos) << clock;
}

TEST(BedScatter, ElsewhereTheScatterIsUnknownAndTheNoteSaysHowToMeasureIt) {
  RunConfig small = preset("small.toml");
  const std::string other = oneBedScatterNote(small, 10, 50);  // another window
  EXPECT_EQ(other.rfind("one bed: scatter unknown", 0), 0u) << other;
  EXPECT_NE(other.find("run `beds = N`"), std::string::npos) << other;
  EXPECT_FALSE(measuredScatterFor(small, 100, 1000));  // the clock's figures are the deeper bed's
  small.intruder.y0 = 30;                              // another depth
  EXPECT_FALSE(measuredScatterFor(small, 10, 100));
  RunConfig depth = preset("paper_depth.toml");
  depth.intruder.shape = ShapeName::Polygon;  // a shape no study measured by the paper's clock
  EXPECT_FALSE(measuredScatterFor(depth, 100, 1000));
  EXPECT_TRUE(measuredScatterFor(depth, 10, 100));  // the t = 100 figure is taken for every shape
}

}  // namespace
}  // namespace wiggle
