// The random pour's batches (scenario/bed/RandomPour.h, bed.pour = "random", docs/PHYSICS.md §8): one
// batch's geometry and area fraction, what it does when the room runs out, and its determinism.
#include "scenario/bed/RandomPour.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "io/Config.h"
#include "scenario/case/Case.h"

namespace wiggle {
namespace {

bool sameBits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

// The default case's box and disk (60 wide, the disk at y0 = 25), random pour.
RunConfig randomConfig(std::vector<std::string> extra = {}) {
  std::vector<std::string> sets = {"bed.pour=random"};
  sets.insert(sets.end(), extra.begin(), extra.end());
  return loadRunConfig(std::nullopt, sets);
}

// Every pair of grains of a batch, every grain against every clump atom, every centre in the region.
void expectNoOverlaps(const RunConfig& c, const ClumpDef& clump, const RandomBatch& b) {
  const double width = c.box.width;
  const double cx = 0.5 * width, cy = c.intruder.y0;
  int bad = 0;
  for (std::size_t i = 0; i < b.grains.size(); ++i) {
    const PouredGrain& g = b.grains[i];
    if (!(g.x >= 0.0 && g.x < width && g.y >= b.yLow && g.y <= b.yHigh)) ++bad;
    if (!(g.radius >= 0.5 * c.grains.dMin && g.radius <= 0.5 * c.grains.dMax)) ++bad;
    for (std::size_t j = i + 1; j < b.grains.size(); ++j) {
      double dx = g.x - b.grains[j].x;
      dx -= width * std::round(dx / width);
      const double dy = g.y - b.grains[j].y;
      if (std::hypot(dx, dy) < g.radius + b.grains[j].radius) ++bad;
    }
    for (std::size_t a = 0; a < clump.offsetX.size(); ++a) {
      if (std::hypot(g.x - (cx + clump.offsetX[a]), g.y - (cy + clump.offsetY[a])) < g.radius + clump.atomRadius) ++bad;
    }
  }
  EXPECT_EQ(bad, 0);
}

TEST(RandomPour, RandomBatchHasNoOverlapsAndFillsItsAreaFraction) {
  const RunConfig c = randomConfig();
  const ClumpDef clump = prepareCase(c).clump;
  // The region [16.1, 36.1] holds the whole disk (y0 = 25): grains must avoid it.
  const RandomBatch b = randomPourBatch(c, clump, 15.0, 0);
  EXPECT_DOUBLE_EQ(b.yLow, 15.0 + c.grains.dMax);
  EXPECT_DOUBLE_EQ(b.yHigh, b.yLow + c.bed.batchHeight);
  const double regionArea = c.box.width * c.bed.batchHeight;
  double area = 0.0;
  for (const PouredGrain& g : b.grains) area += std::numbers::pi * g.radius * g.radius;
  EXPECT_DOUBLE_EQ(area, b.area);
  EXPECT_LT(b.attempts, b.maxAttempts);  // attempts sufficed: the target was reached
  EXPECT_NEAR(area / regionArea, c.bed.pourFraction, 0.02 * c.bed.pourFraction);
  EXPECT_GT(b.grains.size(), 400u);
  expectNoOverlaps(c, clump, b);
  std::printf("random batch: %zu grains, area fraction %.4f, %llu attempts\n", b.grains.size(), area / regionArea,
              static_cast<unsigned long long>(b.attempts));

  // Above the jamming limit of random sequential addition (about 0.55): the attempts run out and
  // the batch keeps what it has, still without overlaps.
  const RunConfig dense = randomConfig({"bed.pour_fraction=0.6"});
  const RandomBatch d = randomPourBatch(dense, clump, 15.0, 0);
  EXPECT_EQ(d.attempts, d.maxAttempts);
  EXPECT_LT(d.area, d.targetArea);
  EXPECT_GT(d.area / regionArea, 0.4);
  expectNoOverlaps(dense, clump, d);
}

TEST(RandomPour, AFullBatchStopsWhenItsAttemptsRunOut) {
  // The paper's width, a 40 d batch at the largest fraction, 0.6: random sequential placement jams
  // near 0.55, so the batch ends on its bound of 100 attempts per target grain with about 8,000
  // grains, none overlapping (checked on smaller batches above). Not timed: speed belongs to the
  // benchmarks.
  const RunConfig c = randomConfig(
      {"box.width=300", "box.bed_height=195", "intruder.y0=90", "bed.batch_height=40", "bed.pour_fraction=0.6"});
  const ClumpDef clump = prepareCase(c).clump;
  const RandomBatch b = randomPourBatch(c, clump, 70.0, 0);
  EXPECT_EQ(b.attempts, b.maxAttempts);
  EXPECT_LT(b.area, b.targetArea);
  EXPECT_GT(b.grains.size(), 6000u);
  const double fraction = b.area / (c.box.width * c.bed.batchHeight);
  EXPECT_GT(fraction, 0.45);
  EXPECT_LT(fraction, 0.56);
}

TEST(RandomPour, RandomBatchIsAPureFunctionOfSeedAndSerial) {
  const RunConfig c = randomConfig();
  const ClumpDef clump = prepareCase(c).clump;
  const RandomBatch a = randomPourBatch(c, clump, 15.0, 1000);
  const RandomBatch again = randomPourBatch(c, clump, 15.0, 1000);
  ASSERT_EQ(a.grains.size(), again.grains.size());
  EXPECT_EQ(a.attempts, again.attempts);
  EXPECT_TRUE(sameBits(a.area, again.area));
  for (std::size_t i = 0; i < a.grains.size(); ++i) {
    ASSERT_TRUE(sameBits(a.grains[i].x, again.grains[i].x) && sameBits(a.grains[i].y, again.grains[i].y) &&
                sameBits(a.grains[i].radius, again.grains[i].radius))
        << i;
  }
  auto differs = [&](const RandomBatch& other) {
    if (other.grains.size() != a.grains.size()) return true;
    for (std::size_t i = 0; i < a.grains.size(); ++i)
      if (!sameBits(other.grains[i].x, a.grains[i].x)) return true;
    return false;
  };
  EXPECT_TRUE(differs(randomPourBatch(randomConfig({"box.seed=2"}), clump, 15.0, 1000)));  // another seed
  EXPECT_TRUE(differs(randomPourBatch(c, clump, 15.0, 1001)));  // the next batch's serial numbers
}

}  // namespace
}  // namespace wiggle
