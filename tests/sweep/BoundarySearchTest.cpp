// The boundary search's decisions (sweep/BoundarySearch.h) on a stand-in for the runs: a known
// V_y(value) plus bed-to-bed noise that is a fixed function of (value, seed), so each test is
// deterministic and fast.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>

#include "core/Error.h"
#include "sweep/BoundarySearch.h"

namespace wiggle {
namespace {

// Noise in [-amplitude, amplitude], a hash of (value, seed): the same run always gives the same V_y.
double noise(double value, int seed, double amplitude) {
  std::uint64_t h = static_cast<std::uint64_t>(std::llround(value * 1e6)) * 0x9E3779B97F4A7C15ull ^
                    static_cast<std::uint64_t>(seed) * 0xC2B2AE3D27D4EB4Full;
  h ^= h >> 31;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 29;
  return amplitude * (2.0 * static_cast<double>(h % 1000001) / 1000000.0 - 1.0);
}

// Runs the search to the end, recording each batch of runs in the given order (or reversed).
// `fails`: the value whose runs fail.
BoundarySearch search(const BoundaryOptions& options, const std::function<double(double, int)>& vy,
                      bool reversed = false, std::optional<double> fails = {}) {
  BoundarySearch s(options);
  for (int guard = 0; !s.finished(); ++guard) {
    EXPECT_LT(guard, 1000) << "the search does not end";
    if (guard >= 1000) break;
    std::vector<BoundaryRun> runs = s.next();
    if (reversed) std::reverse(runs.begin(), runs.end());
    for (const BoundaryRun& run : runs) {
      if (fails && std::fabs(run.value - *fails) < 1e-9)
        s.recordFailure(run);
      else
        s.record(run, vy(run.value, run.seed));
    }
  }
  return s;
}

BoundaryOptions range(double lo, double hi, int points, double resolution) {
  BoundaryOptions o;
  o.lo = lo;
  o.hi = hi;
  o.points = points;
  o.resolution = resolution;
  return o;
}

// Each edge of a crossing (signed to neutral, neutral to signed, or signed to signed) is bracketed
// to the resolution.
void expectEdgesWithin(const BoundarySearch& s, double resolution) {
  const Probe* previous = nullptr;
  for (const Probe& p : s.probes()) {
    if (p.failed) continue;
    if (previous && previous->verdict != p.verdict) {
      EXPECT_LE(p.value - previous->value, resolution + 1e-12);
    }
    previous = &p;
  }
}

TEST(BoundarySearch, OneCrossingIsBracketedToTheResolution) {
  const auto vy = [](double T, int seed) { return 0.05 * (T - 2.7) + noise(T, seed, 0.004); };
  const BoundarySearch s = search(range(1, 5, 5, 0.1), vy);
  const auto crossings = s.crossings();
  ASSERT_EQ(crossings.size(), 1u);
  EXPECT_EQ(crossings[0].from, Verdict::Sinking);
  EXPECT_EQ(crossings[0].to, Verdict::Rising);
  EXPECT_LT(crossings[0].below, 2.7);
  EXPECT_GT(crossings[0].above, 2.7);
  EXPECT_LE(crossings[0].above - crossings[0].below, 0.5);  // the neutral band the noise leaves, and its edges
  expectEdgesWithin(s, 0.1);
  // Far from the crossing (|V_y| >= 0.065, 16 times the noise) two beds decide.
  for (const Probe& p : s.probes())
    if (std::fabs(p.value - 2.7) > 1.0) {
      EXPECT_EQ(p.vy.size(), 2u) << p.value;
    }
}

TEST(BoundarySearch, TwoCrossingsAreBothFound) {
  // Rises between 2 and 4 only (a maximum, as V_y(T) has).
  const auto vy = [](double T, int seed) { return 0.05 * (T - 2) * (4 - T) + noise(T, seed, 0.002); };
  const BoundarySearch s = search(range(0.5, 8, 6, 0.2), vy);
  const auto crossings = s.crossings();
  ASSERT_EQ(crossings.size(), 2u);
  EXPECT_EQ(crossings[0].from, Verdict::Sinking);
  EXPECT_EQ(crossings[1].from, Verdict::Rising);
  EXPECT_LT(crossings[0].below, 2.0);
  EXPECT_GT(crossings[0].above, 2.0);
  EXPECT_LT(crossings[1].below, 4.0);
  EXPECT_GT(crossings[1].above, 4.0);
  expectEdgesWithin(s, 0.2);
}

TEST(BoundarySearch, AFlatStretchIsANeutralBandNotAFailure) {
  // V_y is zero (within the beds' scatter) over [2.5, 3.5]: probes there run to the bed cap and
  // are neutral; the band's edges are bracketed to the resolution.
  const auto vy = [](double T, int seed) {
    const double drift = T < 2.5 ? -0.1 * (2.5 - T) : T > 3.5 ? 0.1 * (T - 3.5) : 0.0;
    return drift + noise(T, seed, 0.05);
  };
  BoundaryOptions o = range(1, 5, 5, 0.25);
  o.maxBeds = 3;
  const BoundarySearch s = search(o, vy);
  const auto crossings = s.crossings();
  ASSERT_EQ(crossings.size(), 1u);
  ASSERT_TRUE(crossings[0].neutralLo && crossings[0].neutralHi);
  EXPECT_LE(*crossings[0].neutralLo, 3.0);
  EXPECT_GE(*crossings[0].neutralHi, 3.0);
  const auto bands = s.neutralBands();
  ASSERT_EQ(bands.size(), 1u);
  EXPECT_EQ(bands[0].first, *crossings[0].neutralLo);
  EXPECT_EQ(bands[0].below, crossings[0].below);
  EXPECT_EQ(bands[0].above, crossings[0].above);
  // The band holds the flat stretch and reaches no further than where the drift is twice the noise.
  EXPECT_GE(bands[0].first, 1.5);
  EXPECT_LE(bands[0].first, 2.75);
  EXPECT_GE(bands[0].last, 3.25);
  EXPECT_LE(bands[0].last, 4.5);
  expectEdgesWithin(s, 0.25);
  for (const Probe& p : s.probes())
    if (p.verdict == Verdict::Neutral) {
      EXPECT_EQ(p.vy.size(), 3u);
    }
}

TEST(BoundarySearch, ATouchOfZeroWithoutASignChangeIsABandButNoCrossing) {
  const auto vy = [](double T, int seed) { return -0.1 * std::fabs(T - 3) + noise(T, seed, 0.01); };
  BoundaryOptions o = range(1, 5, 5, 0.25);
  o.maxBeds = 3;
  const BoundarySearch s = search(o, vy);
  EXPECT_TRUE(s.crossings().empty());
  ASSERT_EQ(s.neutralBands().size(), 1u);
  EXPECT_LE(s.neutralBands()[0].first, 3.0);
  EXPECT_GE(s.neutralBands()[0].last, 3.0);
}

TEST(BoundarySearch, ARangeWithoutACrossingSaysSo) {
  const auto vy = [](double T, int seed) { return 0.1 + 0.01 * T + noise(T, seed, 0.01); };
  const BoundarySearch s = search(range(1, 5, 5, 0.1), vy);
  EXPECT_TRUE(s.crossings().empty());
  EXPECT_TRUE(s.neutralBands().empty());
  EXPECT_EQ(s.probes().size(), 5u);
  for (const Probe& p : s.probes()) EXPECT_EQ(p.verdict, Verdict::Rising);
}

TEST(BoundarySearch, AFailedProbeIsSetAsideAndTheSearchGoesAroundIt) {
  const auto vy = [](double T, int seed) { return 0.05 * (T - 2.7) + noise(T, seed, 0.004); };
  const BoundarySearch s = search(range(1, 5, 5, 0.1), vy, false, 3.0);  // the probe at 3 fails
  const auto failed = std::count_if(s.probes().begin(), s.probes().end(), [](const Probe& p) { return p.failed; });
  EXPECT_EQ(failed, 1);
  ASSERT_EQ(s.crossings().size(), 1u);
  EXPECT_LT(s.crossings()[0].below, 2.7);
  EXPECT_GT(s.crossings()[0].above, 2.7);
  expectEdgesWithin(s, 0.1);  // the bisection went around the failed midpoint of [2, 4]
}

TEST(BoundarySearch, TheDecisionsDoNotDependOnTheOrderResultsArriveIn) {
  const auto vy = [](double T, int seed) { return 0.05 * (T - 2) * (4 - T) + noise(T, seed, 0.03); };
  const BoundarySearch a = search(range(0.5, 8, 6, 0.2), vy, false), b = search(range(0.5, 8, 6, 0.2), vy, true);
  ASSERT_EQ(a.probes().size(), b.probes().size());
  for (std::size_t k = 0; k < a.probes().size(); ++k) {
    EXPECT_EQ(a.probes()[k].value, b.probes()[k].value);
    EXPECT_EQ(a.probes()[k].vy, b.probes()[k].vy);
    EXPECT_EQ(a.probes()[k].verdict, b.probes()[k].verdict);
  }
}

TEST(BoundarySearch, TheRuleIsStudentsTestAt95PerCent) {
  // Two beds at +0.10 and +0.02: mean 0.06, standard error 0.04: 1.5 standard errors, far below
  // t(1) = 12.7: a third bed is asked for. Two beds at +0.060 and +0.062: 60 standard errors: rising.
  BoundarySearch wide(range(1, 2, 2, 0.5));
  wide.record({1, 1}, 0.10);
  wide.record({1, 2}, 0.02);
  EXPECT_EQ(wide.probes()[0].verdict, Verdict::Undecided);
  EXPECT_NEAR(wide.probes()[0].standardError, 0.04, 1e-12);
  EXPECT_EQ(wide.next()[0], (BoundaryRun{1, 3}));
  BoundarySearch narrow(range(1, 2, 2, 0.5));
  narrow.record({1, 1}, 0.060);
  narrow.record({1, 2}, 0.062);
  EXPECT_EQ(narrow.probes()[0].verdict, Verdict::Rising);
  EXPECT_THROW(narrow.record({1, 3}, 0.0), Error);    // not asked for
  EXPECT_THROW(narrow.record({1.5, 1}, 0.0), Error);  // not a probe
  // With a known scatter of one bed (0.045 at the paper-depth preset), 2 beds at +0.10 and +0.02
  // have a standard error of 0.032 and a mean of 1.9 of them: below 1.96, a third bed; at +0.10
  // and +0.04, 2.2: rising.
  BoundaryOptions o = range(1, 2, 2, 0.5);
  o.knownScatter = 0.045;
  BoundarySearch known(o);
  known.record({1, 1}, 0.10);
  known.record({1, 2}, 0.02);
  EXPECT_EQ(known.probes()[0].verdict, Verdict::Undecided);
  BoundarySearch known2(o);
  known2.record({1, 1}, 0.10);
  known2.record({1, 2}, 0.04);
  EXPECT_EQ(known2.probes()[0].verdict, Verdict::Rising);
  EXPECT_DOUBLE_EQ(studentT975(2), 4.303);
  EXPECT_DOUBLE_EQ(studentT975(100), 1.960);
}

TEST(BoundarySearch, BadOptionsAreNamed) {
  auto message = [](BoundaryOptions o) {
    try {
      checkBoundaryOptions(o);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message(range(3, 1, 5, 0.1)).find("range"), std::string::npos);
  EXPECT_NE(message(range(1, 3, 1, 0.1)).find("2 points"), std::string::npos);
  EXPECT_NE(message(range(1, 3, 5, 0)).find("resolution"), std::string::npos);
  BoundaryOptions o = range(1, 3, 5, 0.1);
  o.minBeds = 1;
  EXPECT_NE(message(o).find("2 beds"), std::string::npos);
  o.minBeds = 3;
  o.maxBeds = 2;
  EXPECT_NE(message(o).find("bed cap"), std::string::npos);
  EXPECT_EQ(message(range(1, 3, 5, 0.1)), "");
}

}  // namespace
}  // namespace wiggle
