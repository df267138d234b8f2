// NeighbourList on its own (physics/NeighbourList.h): the list against every pair found by brute
// force (periodic in x), its order, the contact history carried through a re-sort, the cross-pair
// index of the force blocks, the threads' strips of blocks, and the same list for any thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include <omp.h>

#include "core/Error.h"
#include "physics/NeighbourList.h"
#include "physics/ParticleStore.h"

namespace wiggle {
namespace {

constexpr double kWidth = 20.0;
constexpr double kSkin = 0.2;

// `grains` random grains over [0, W) x [1, 1 + height] (overlaps allowed: the list does not care),
// two of them straddling the periodic boundary, then a base row of unit spheres at y = 0.
ParticleStore randomStore(std::uint32_t grains, double height, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(0.0, kWidth), uy(1.0, 1.0 + height), ur(0.45, 0.55);
  ParticleStore s;
  for (std::uint32_t i = 0; i < grains; ++i) {
    double x = ux(rng), y = uy(rng);
    if (i == 0) x = 0.05, y = 3.0;            // touches grain 1 only across x = 0 / x = W
    if (i == 1) x = kWidth - 0.05, y = 3.2;
    s.append(x, y, 0, 0, 0, ur(rng), 1.0, 1.0, 1.0, i);
  }
  s.grainCount = grains;
  for (std::uint32_t k = 0; k < static_cast<std::uint32_t>(kWidth); ++k)
    s.append(k + 0.5, 0.0, 0, 0, 0, 0.5, 1.0, 0.0, 0.0, grains + k);
  return s;
}

// The partners j > i of every grain i within r_i + r_j + skin, nearest periodic image in x.
std::vector<std::vector<std::uint32_t>> bruteForcePartners(const ParticleStore& s) {
  std::vector<std::vector<std::uint32_t>> rows(s.grainCount);
  for (std::uint32_t i = 0; i < s.grainCount; ++i) {
    for (std::uint32_t j = i + 1; j < s.size(); ++j) {
      double dx = std::fabs(s.x[i] - s.x[j]);
      dx = std::min(dx, kWidth - dx);
      const double dy = s.y[i] - s.y[j];
      const double reach = s.radius[i] + s.radius[j] + kSkin;
      if (dx * dx + dy * dy < reach * reach) rows[i].push_back(j);
    }
  }
  return rows;
}

NeighbourList built(const ParticleStore& s, const NeighbourList& old = {},
                    const std::vector<std::uint32_t>& newToOld = {}) {
  NeighbourList list;
  list.build(s, kWidth, kSkin, old, newToOld);
  return list;
}

TEST(NeighbourList, HoldsExactlyThePairsWithinReachInAscendingRows) {
  const ParticleStore s = randomStore(300, 12.0, 1);
  const NeighbourList list = built(s);
  const auto expected = bruteForcePartners(s);
  ASSERT_EQ(list.rowCount(), s.grainCount);
  ASSERT_EQ(list.rowStart.front(), 0u);
  std::size_t pairs = 0;
  for (std::uint32_t i = 0; i < s.grainCount; ++i) {
    const std::vector<std::uint32_t> row(list.partner.begin() + list.rowStart[i],
                                         list.partner.begin() + list.rowStart[i + 1]);
    EXPECT_EQ(row, expected[i]) << "row " << i;  // same partners, ascending
    for (std::uint32_t k = list.rowStart[i]; k < list.rowStart[i + 1]; ++k) EXPECT_EQ(list.owner[k], i);
    pairs += expected[i].size();
  }
  EXPECT_EQ(list.pairCount(), pairs);
  EXPECT_GT(pairs, 300u);  // a dense enough cloud for the comparison to mean something
  // The pair across the periodic boundary, and grains reaching the base, are there.
  EXPECT_TRUE(std::count(expected[0].begin(), expected[0].end(), 1u));
  EXPECT_TRUE(std::any_of(list.partner.begin(), list.partner.end(), [&](std::uint32_t j) { return j >= s.grainCount; }));
  // A fresh list has no history and no forces.
  for (std::uint32_t k = 0; k < list.pairCount(); ++k) {
    EXPECT_EQ(list.shearX[k], 0.0);
    EXPECT_EQ(list.forceX[k], 0.0);
  }
}

TEST(NeighbourList, HistoryFollowsEachPairThroughAReSort) {
  const ParticleStore before = randomStore(200, 10.0, 2);
  NeighbourList old = built(before);
  // A value per unordered pair of tags, stored in the owner's (lower index's) frame.
  auto historyOf = [](std::uint32_t tagA, std::uint32_t tagB) {
    return 1000.0 * std::min(tagA, tagB) + std::max(tagA, tagB) + 0.5;
  };
  for (std::uint32_t k = 0; k < old.pairCount(); ++k) {
    old.shearX[k] = historyOf(before.tag[old.owner[k]], before.tag[old.partner[k]]);
    old.shearY[k] = -2.0 * old.shearX[k];
  }
  // Shuffle the grains (the base stays behind them, in place): new index k holds old order[k].
  std::vector<std::uint32_t> order(before.size());
  std::iota(order.begin(), order.end(), 0u);
  std::shuffle(order.begin(), order.begin() + before.grainCount, std::mt19937_64(3));
  ParticleStore after = before;
  after.permute(order);
  const NeighbourList list = built(after, old, order);
  ASSERT_EQ(list.pairCount(), old.pairCount());  // the same pairs: nobody moved
  int flipped = 0;
  for (std::uint32_t k = 0; k < list.pairCount(); ++k) {
    const std::uint32_t i = list.owner[k], j = list.partner[k];
    // The old owner was the lower old index; if the shuffle swapped the order, the frame flips.
    const double sign = order[i] < order[j] ? 1.0 : -1.0;
    flipped += sign < 0;
    const double h = historyOf(after.tag[i], after.tag[j]);
    EXPECT_EQ(list.shearX[k], sign * h) << "pair " << k;
    EXPECT_EQ(list.shearY[k], -2.0 * sign * h) << "pair " << k;
  }
  EXPECT_GT(flipped, 0);  // the test covers both frames
}

TEST(NeighbourList, PairsNewSinceTheLastBuildStartWithoutHistory) {
  ParticleStore s = randomStore(150, 8.0, 4);
  NeighbourList old = built(s);
  for (double& h : old.shearX) h = 1.0;
  // Grain 5 jumps far from where it was: every pair it has now is new.
  s.x[5] = std::fmod(s.x[5] + 0.5 * kWidth, kWidth);
  const NeighbourList list = built(s, old);
  int fresh = 0;
  for (std::uint32_t k = 0; k < list.pairCount(); ++k) {
    const bool wasThere = [&] {
      for (std::uint32_t m = old.rowStart[list.owner[k]]; m < old.rowStart[list.owner[k] + 1]; ++m)
        if (old.partner[m] == list.partner[k]) return true;
      return false;
    }();
    EXPECT_EQ(list.shearX[k], wasThere ? 1.0 : 0.0) << "pair " << k;
    fresh += !wasThere;
  }
  EXPECT_GT(fresh, 0);  // grain 5's new neighbours
}

TEST(NeighbourList, CrossIndexListsThePairsReachingALaterBlock) {
  const ParticleStore s = randomStore(300, 12.0, 5);
  NeighbourList list = built(s);
  list.deriveIndex(7);  // small blocks: many cross pairs
  ASSERT_EQ(list.crossStart.size(), s.grainCount + 1u);
  std::size_t crossing = 0;
  for (std::uint32_t k = 0; k < list.pairCount(); ++k) {
    const std::uint32_t j = list.partner[k];
    const bool cross = j < s.grainCount && j / 7 != list.owner[k] / 7;
    const auto first = list.crossPair.begin() + list.crossStart[cross ? j : 0];
    const auto last = list.crossPair.begin() + list.crossStart[cross ? j + 1 : 0];
    EXPECT_EQ(std::count(first, last, k), cross ? 1 : 0) << "pair " << k;
    crossing += cross;
  }
  EXPECT_EQ(list.crossPair.size(), crossing);
  EXPECT_GT(crossing, 10u);
  for (std::uint32_t j = 0; j < s.grainCount; ++j)  // each partner's cross pairs in pair order
    EXPECT_TRUE(std::is_sorted(list.crossPair.begin() + list.crossStart[j], list.crossPair.begin() + list.crossStart[j + 1]));
}

TEST(NeighbourList, SameListForAnyThreadCount) {
  const ParticleStore s = randomStore(400, 15.0, 6);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const NeighbourList one = built(s);
  omp_set_num_threads(3);
  const NeighbourList three = built(s);
  omp_set_num_threads(threads);
  EXPECT_EQ(one.rowStart, three.rowStart);
  EXPECT_EQ(one.partner, three.partner);
  EXPECT_EQ(one.owner, three.owner);
  EXPECT_EQ(one.crossStart, three.crossStart);
  EXPECT_EQ(one.crossPair, three.crossPair);
}

// The strips tile the blocks in order, and share the work: the list's pairs and the pairs the first
// thread evaluates besides its strip (the intruder's), which shorten its strip.
TEST(NeighbourList, StripsTileTheBlocksAndShareThePairs) {
  const ParticleStore s = randomStore(600, 20.0, 8);
  NeighbourList list = built(s);
  list.deriveIndex(7);  // 86 blocks, so that the shares can be even
  const std::uint32_t blocks = list.blockCount(), rows = list.rowCount();
  std::uint32_t largestBlock = 0;
  for (std::uint32_t b = 0; b < blocks; ++b)
    largestBlock = std::max(largestBlock, list.rowStart[std::min((b + 1) * 7, rows)] - list.rowStart[b * 7]);
  for (std::uint32_t extra : {0u, 40u, 400u})
    for (std::uint32_t threads : {1u, 2u, 3u, 5u, 200u}) {
      std::uint32_t nextBlock = 0, nextRow = 0, heaviest = 0;
      for (std::uint32_t t = 0; t < threads; ++t) {
        const NeighbourList::Strip strip = list.strip(t, threads, extra);
        EXPECT_EQ(strip.firstBlock, nextBlock) << threads << " threads, strip " << t;  // consecutive, no gap
        EXPECT_EQ(strip.firstRow, nextRow);
        EXPECT_LE(strip.firstBlock, strip.lastBlock);
        EXPECT_EQ(strip.lastRow, std::min(strip.lastBlock * 7, rows));  // a strip's rows are its blocks'
        nextBlock = strip.lastBlock;
        nextRow = strip.lastRow;
        const std::uint32_t work = list.rowStart[strip.lastRow] - list.rowStart[strip.firstRow] + (t == 0 ? extra : 0);
        heaviest = std::max(heaviest, work);
      }
      EXPECT_EQ(nextBlock, blocks) << threads << " threads";  // every block, and every row, once
      EXPECT_EQ(nextRow, rows);
      // No strip holds more than its share of the work and one block (the first thread's extra pairs
      // are not divisible: past a share, they are its whole work).
      const std::uint32_t work = list.pairCount() + extra, share = (work + threads - 1) / threads;
      EXPECT_LE(heaviest, std::max(share, extra) + largestBlock) << threads << " threads, extra " << extra;
      EXPECT_DOUBLE_EQ(list.stripImbalance(threads, extra), static_cast<double>(heaviest) * threads / work);
      EXPECT_GE(list.stripImbalance(threads, extra), 1.0);
    }
  EXPECT_DOUBLE_EQ(list.stripImbalance(1, 40), 1.0);
  // The first thread's strip shrinks by about its extra pairs.
  const auto firstStripPairs = [&](std::uint32_t extra) {
    const NeighbourList::Strip strip = list.strip(0, 2, extra);
    return list.rowStart[strip.lastRow] - list.rowStart[strip.firstRow];
  };
  EXPECT_LE(firstStripPairs(400), firstStripPairs(0) - 200 + largestBlock);
}

TEST(NeighbourList, RefusesABoxNarrowerThanThreeCells) {
  ParticleStore s;
  s.append(0.5, 1.0, 0, 0, 0, 0.5, 1.0, 1.0, 1.0, 0);
  s.grainCount = 1;
  NeighbourList list;
  EXPECT_THROW(list.build(s, 3.0, kSkin, {}, {}), Error);  // cells of 1.2 d: only 2 fit
  EXPECT_NO_THROW(list.build(s, 4.0, kSkin, {}, {}));
}

TEST(NeighbourList, ForceBlocksAreAboutFourRowsOfGrains) {
  EXPECT_EQ(forceBlockRows(60.0), 240u);
  EXPECT_EQ(forceBlockRows(300.0), 1200u);
  EXPECT_EQ(forceBlockRows(5.0), 64u);  // never fewer than 64 grains a block
}

}  // namespace
}  // namespace wiggle
