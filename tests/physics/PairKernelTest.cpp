// The contact law in SIMD lanes gives the scalar law's bits (ARCHITECTURE.md's claim, on which
// determinism across builds and the LAMMPS comparisons rest), on pairs chosen to take every branch:
// apart, grazing, deep, sticking, slipping past the Coulomb cap, a capped pair with no history,
// zero history, a frozen partner, a pair the damping pulls, and random pairs around contact; for every
// law (ContactLaws.h). And the laws against their formulas on a head-on pair.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "physics/ContactLaws.h"
#include "physics/PairKernel.h"

namespace wiggle {
namespace {

struct Case {
  PairInputs<double> in;
  double shearX, shearY;  // history before the step
};

std::vector<Case> adversarialPairs() {
  const double mi = 0.5, mj = 0.6;  // masses of grains of radius about 0.5
  auto pair = [&](double dx, double dy, double dvx, double dvy, double oi, double oj, double sx, double sy,
                  double invMassSum) {
    return Case{{dx, dy, dvx, dvy, 0.5, 0.45, oi, oj, invMassSum, 0.45}, sx, sy};
  };
  const double both = 1.0 / mi + 1.0 / mj, frozen = 1.0 / mi;
  std::vector<Case> cases = {
      pair(1.2, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, both),          // apart: no force, history dropped
      pair(0.95 - 1e-12, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, both),  // grazing: overlap 1e-12
      pair(0.5, 0.3, 3.0, -2.0, 1.0, -1.0, 0.0, 0.0, both),         // deep (0.37 d)
      pair(0.9, 0.1, 0.0, 1e-6, 0.0, 0.0, 1e-7, 1e-6, both),        // sticking: small shear, slow slip
      pair(0.9, 0.1, 0.0, 5.0, 3.0, 2.0, 0.0, 0.05, both),          // slipping: past the Coulomb cap
      pair(0.93, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, both),          // no relative motion, zero history
      pair(0.94, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.0, both),          // capped with zero history
      pair(0.0, 0.93, 0.2, -0.3, 0.5, 0.0, 0.01, 0.0, frozen),      // frozen partner below
      pair(-0.6, -0.6, 0.0, 0.0, 0.0, 0.0, -0.02, 0.02, both),      // oblique, loaded spring
      pair(0.949, 0.0, 5.0, 0.5, 1.0, 0.0, 0.0, 1e-3, both),        // separating fast: the damping pulls
  };
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  while (cases.size() % 8 != 0 || cases.size() < 64) {
    const double angle = 3.14159265358979 * u(rng), r = 0.9 + 0.08 * u(rng);
    cases.push_back(pair(r * std::cos(angle), r * std::sin(angle), 3 * u(rng), 3 * u(rng), 5 * u(rng), 5 * u(rng),
                         0.02 * u(rng), 0.02 * u(rng), u(rng) > 0 ? both : frozen));
  }
  return cases;
}

struct Slots {
  std::vector<double> shearX, shearY, forceX, forceY, torqueArm, excess;
  explicit Slots(const std::vector<Case>& cases)
      : forceX(cases.size()), forceY(cases.size()), torqueArm(cases.size()), excess(cases.size()) {
    for (const Case& c : cases) {
      shearX.push_back(c.shearX);
      shearY.push_back(c.shearY);
    }
  }
  PairSlots view() { return {shearX.data(), shearY.data(), forceX.data(), forceY.data(), torqueArm.data()}; }
};

void expectSameBits(const std::vector<double>& a, const std::vector<double>& b, const char* what) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k)
    EXPECT_EQ(std::bit_cast<std::uint64_t>(a[k]), std::bit_cast<std::uint64_t>(b[k]))
        << what << " of pair " << k << ": " << a[k] << " vs " << b[k];
}

template <class Law>
void expectLanesGiveScalarBits() {
#if !WIGGLE_SIMD_DOUBLE4
  GTEST_SKIP() << "this build has no SIMD lanes: only the scalar law runs";
#else
  const std::vector<Case> cases = adversarialPairs();
  const auto n = static_cast<std::uint32_t>(cases.size());
  PairChunk chunk;
  ASSERT_LE(n, kChunk);
  for (std::uint32_t k = 0; k < n; ++k) chunk.set(k, cases[k].in);
  for (const bool updateShear : {false, true})
    for (const double mu : {0.0, 0.1, 0.5}) {
      ContactParams params;
      params.mu = mu;
      Slots scalar(cases);
      for (std::uint32_t k = 0; k < n; ++k)
        scalar.excess[k] = evaluatePairs<Law>(cases[k].in, k, scalar.view(), params, 1e-4, updateShear, 1.0);
      auto compareLanes = [&](auto lane) {
        using V = decltype(lane);
        Slots lanes(cases);
        for (std::uint32_t m = 0; m < n; m += V::kLanes)
          simd::store(lanes.excess.data() + m,
                      evaluatePairs<Law>(chunk.inputs<V>(m), m, lanes.view(), params, 1e-4, updateShear, 1.0));
        SCOPED_TRACE(testing::Message() << V::kLanes << " lanes, updateShear " << updateShear << ", mu " << mu);
        expectSameBits(scalar.forceX, lanes.forceX, "forceX");
        expectSameBits(scalar.forceY, lanes.forceY, "forceY");
        expectSameBits(scalar.torqueArm, lanes.torqueArm, "torqueArm");
        expectSameBits(scalar.shearX, lanes.shearX, "shearX");
        expectSameBits(scalar.shearY, lanes.shearY, "shearY");
        expectSameBits(scalar.excess, lanes.excess, "overlap excess");
      };
      compareLanes(simd::Double4{});
#if WIGGLE_SIMD_DOUBLE8
      compareLanes(simd::Double8{});
#endif
    }
  // The cases do take the branches they are named for (the law is not trivially equal).
  Slots s(cases);
  for (std::uint32_t k = 0; k < n; ++k) evaluatePairs<Law>(cases[k].in, k, s.view(), ContactParams{}, 1e-4, true, 1.0);
  EXPECT_EQ(s.forceX[0], 0.0);  // apart
  EXPECT_EQ(s.shearX[0], 0.0);  // history dropped
  EXPECT_NE(s.forceX[2], 0.0);  // deep
#endif
}

TEST(PairKernel, LanesGiveTheScalarLawsBitsOnAdversarialPairs) { expectLanesGiveScalarBits<HertzLaw>(); }
TEST(PairKernel, LanesGiveTheScalarLawsBitsOnAdversarialPairsForHooke) { expectLanesGiveScalarBits<HookeLaw>(); }
TEST(PairKernel, LanesGiveTheScalarLawsBitsOnAdversarialPairsForHertzLimitDamping) {
  expectLanesGiveScalarBits<HertzLimitDampingLaw>();
}

// Head-on, i to the right of j, overlapping by delta and approaching at speed u, no spin, no
// history: the normal force on i is kn delta + meff gammaN u for Hooke and sqrt(delta Reff) times
// that for Hertz (LAMMPS's gran/hooke/history and gran/hertz/history), and the tangential force
// is zero. An independent reading of the formulas the kernels compose.
TEST(PairKernel, HeadOnForceIsEachLawsFormula) {
  const double ri = 0.5, rj = 0.45, delta = 2e-3, u = 0.7, mi = 0.5, mj = 0.6;
  const double r = ri + rj - delta, meff = mi * mj / (mi + mj), reff = ri * rj / (ri + rj);
  const ContactParams p;
  const double hooke = p.kn * delta + meff * p.gammaN * u;
  auto force = [&](auto law) {
    using Law = decltype(law);
    return historyContact<Law>(p, 1e-4, r, 0.0, -u, 0.0, ri, rj, 0.0, 0.0, 1 / mi + 1 / mj, 0.0, 0.0, true);
  };
  const ContactForce h = force(HookeLaw{}), z = force(HertzLaw{});
  EXPECT_NEAR(h.fx, hooke, 1e-12 * hooke);
  EXPECT_NEAR(z.fx, std::sqrt(delta * reff) * hooke, 1e-12 * hooke);
  for (const ContactForce& c : {h, z}) {
    EXPECT_EQ(c.fy, 0.0);
    EXPECT_EQ(c.torqueArm, 0.0);
  }
}

// Head-on, as above, but separating at speed u fast enough that the damping outweighs the spring:
// Hertz pulls (Fn < 0, LAMMPS without limit_damping), the limit_damping law gives exactly no force,
// and the history of a capped pair is rescaled to cancel the damping (s = -meff gammaT vt / kt, as
// LAMMPS does). While the pair approaches, the two laws give the same bits.
TEST(PairKernel, LimitDampingClampsAPullingNormalForceAtZero) {
  const double ri = 0.5, rj = 0.45, delta = 1e-3, u = 5.0, mi = 0.5, mj = 0.6;
  const double r = ri + rj - delta, meff = mi * mj / (mi + mj);
  const ContactParams p;
  auto force = [&](auto law, double dvx) {
    using Law = decltype(law);
    return historyContact<Law>(p, 1e-4, r, 0.0, dvx, 0.3, ri, rj, 0.0, 0.0, 1 / mi + 1 / mj, 0.0, 1e-3, true);
  };
  const ContactForce hertz = force(HertzLaw{}, u), clamped = force(HertzLimitDampingLaw{}, u);
  ASSERT_LT(hertz.fx, 0.0);  // the damping pulls
  EXPECT_EQ(clamped.fx, 0.0);
  EXPECT_EQ(clamped.fy, 0.0);
  EXPECT_EQ(clamped.torqueArm, 0.0);
  EXPECT_NEAR(clamped.shearY, -meff * p.gammaT * 0.3 / p.kt, 1e-12 * meff * p.gammaT * 0.3 / p.kt);
  const ContactForce hertzIn = force(HertzLaw{}, -u), clampedIn = force(HertzLimitDampingLaw{}, -u);
  EXPECT_GT(hertzIn.fx, 0.0);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(hertzIn.fx), std::bit_cast<std::uint64_t>(clampedIn.fx));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(hertzIn.fy), std::bit_cast<std::uint64_t>(clampedIn.fy));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(hertzIn.shearY), std::bit_cast<std::uint64_t>(clampedIn.shearY));
}

}  // namespace
}  // namespace wiggle
