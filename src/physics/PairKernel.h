#pragma once
// The pair loop's building blocks, shared by the grain pairs and the intruder pairs of World and by
// the micro-benchmarks: a pair's inputs (gathered for one pair or for four at once), and the
// contact law over them writing the pair's slots. Every vector path gives the scalar path's bits
// (core/Simd.h), so which one runs never changes a result.
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

#include "core/Simd.h"
#include "physics/ContactLaw.h"
#include "physics/ParticleStore.h"

namespace wiggle {

// A particle's position and velocity in one 32-byte record: a copy of the store's values that World
// refreshes whenever they change (the drift, a rebuild, a load), so that one vector subtraction
// gives a pair's dx, dy, dvx, dvy where the store's arrays need eight scalar loads.
struct alignas(32) Kinematics {
  double x, y, vx, vy;
};

// Where pairs' results go: history (read and written), force on i and torque arm, indexed by pair.
struct PairSlots {
  double *shearX, *shearY, *forceX, *forceY, *torqueArm;
};

inline namespace WIGGLE_ISA_NAMESPACE {

// A pair's inputs to the contact law, for one pair (V = double) or for lanes of pairs.
template <class V>
struct PairInputs {
  V dx, dy, dvx, dvy;     // i minus j, x minimum-imaged
  V radI, radJ, omegaI, omegaJ;
  V invMassSum;           // 1/mi + 1/mj
  V alarmRadius;          // the radius the overlap bound is relative to (World.h, WorldDef::maxOverlapRatio)
};

template <class V>
inline V minimumImage(V dx, double width) {
  using simd::select;
  const double halfWidth = 0.5 * width;
  return select(dx > V(halfWidth), dx - V(width), select(dx < V(-halfWidth), dx + V(width), dx));
}

// The contact law Law (a law of ContactLaws.h) for the pairs in `in` (one, or lanes of
// four), whose slots start at k: history read from and written to shearX/Y[k..], force and torque
// arm written to forceX/Y and torqueArm.
// Returns, per lane, (radI + radJ - allowed)^2 - r^2, allowed being `overlapRatio` x alarmRadius:
// positive when a pair overlaps more than that, which is how a blow-up shows between two health
// checks. Squared, so that it costs no sqrt.
template <class Law, class V>
inline V evaluatePairs(const PairInputs<V>& in, std::uint32_t k, PairSlots slots, const ContactParams params, double dt,
                       bool updateShear, double overlapRatio) {
  static_assert(Law::kHistoryValues == kPairHistoryValues, "the pair slots hold the shear displacement s alone");
  using simd::load;
  using simd::store;
  const ContactForceOf<V> c =
      historyContact<Law>(params, dt, in.dx, in.dy, in.dvx, in.dvy, in.radI, in.radJ, in.omegaI, in.omegaJ,
                          in.invMassSum, load<V>(slots.shearX + k), load<V>(slots.shearY + k), updateShear);
  store(slots.shearX + k, c.shearX);
  store(slots.shearY + k, c.shearY);
  store(slots.forceX + k, c.fx);
  store(slots.forceY + k, c.fy);
  store(slots.torqueArm + k, c.torqueArm);
  using simd::max;
  const V closest = max(V(0.0), in.radI + in.radJ - V(overlapRatio) * in.alarmRadius);
  return closest * closest - (in.dx * in.dx + in.dy * in.dy);
}

// Runs evaluate(m, V{}) over [m, n) in lanes of V while whole lanes fit, advancing m, and returns
// the largest value it returned over every lane. The new value first: max returns its second
// argument for a NaN, so a NaN lane (a blow-up, which the health check reports) never displaces an
// excess already seen.
template <class V, class Evaluate>
inline double maxOverLanesOf(std::uint32_t& m, std::uint32_t n, Evaluate& evaluate) {
  if constexpr (std::is_same_v<V, double>) {
    double excess = -std::numeric_limits<double>::infinity();
    for (; m < n; ++m) excess = simd::max(evaluate(m, 0.0), excess);
    return excess;
  } else {
    V excess(-std::numeric_limits<double>::infinity());
    for (; m + V::kLanes <= n; m += V::kLanes) excess = max(evaluate(m, V{}), excess);
    return horizontalMax(excess);  // found by argument-dependent lookup in simd
  }
}

// Calls evaluate(m, V{}) for every pair m in [0, n): in the widest lanes the instruction set has
// while they fit, then in four lanes, then one by one with V = double. Returns the largest value
// it returned over every lane.
template <class Evaluate>
inline double maxOverLanes(std::uint32_t n, Evaluate&& evaluate) {
  std::uint32_t m = 0;
  double excess = -std::numeric_limits<double>::infinity();
#if WIGGLE_SIMD_DOUBLE8
  excess = simd::max(maxOverLanesOf<simd::Double8>(m, n, evaluate), excess);
#endif
#if WIGGLE_SIMD_DOUBLE4
  excess = simd::max(maxOverLanesOf<simd::Double4>(m, n, evaluate), excess);
#endif
  return simd::max(maxOverLanesOf<double>(m, n, evaluate), excess);
}

// Inputs of up to kChunk pairs gathered one by one (the intruder's contacts, the benchmarks), to be
// read back as lanes.
constexpr std::uint32_t kChunk = 64;
struct PairChunk {
  alignas(64) double dx[kChunk], dy[kChunk], dvx[kChunk], dvy[kChunk], radI[kChunk], radJ[kChunk], omegaI[kChunk],
      omegaJ[kChunk], invMassSum[kChunk], alarmRadius[kChunk];

  void set(std::uint32_t m, const PairInputs<double>& in) {
    dx[m] = in.dx;
    dy[m] = in.dy;
    dvx[m] = in.dvx;
    dvy[m] = in.dvy;
    radI[m] = in.radI;
    radJ[m] = in.radJ;
    omegaI[m] = in.omegaI;
    omegaJ[m] = in.omegaJ;
    invMassSum[m] = in.invMassSum;
    alarmRadius[m] = in.alarmRadius;
  }
  template <class V>
  PairInputs<V> inputs(std::uint32_t m) const {
    using simd::load;
    return {load<V>(dx + m),     load<V>(dy + m),     load<V>(dvx + m),        load<V>(dvy + m),
            load<V>(radI + m),   load<V>(radJ + m),   load<V>(omegaI + m),     load<V>(omegaJ + m),
            load<V>(invMassSum + m), load<V>(alarmRadius + m)};
  }
};

// Evaluates pairs [0, n) of a chunk whose slots start at k0; returns the largest overlap excess.
template <class Law>
inline double evaluateChunk(const PairChunk& c, std::uint32_t n, std::uint32_t k0, PairSlots slots,
                            const ContactParams& params, double dt, bool updateShear, double overlapRatio) {
  return maxOverLanes(n, [&](std::uint32_t m, auto lane) {
    using V = decltype(lane);
    return evaluatePairs<Law>(c.inputs<V>(m), k0 + m, slots, params, dt, updateShear, overlapRatio);
  });
}

// Inputs of grain pair (i, j): positions and velocities from the Kinematics records (the same
// values as the store's), the rest from the store.
inline PairInputs<double> grainPairInputs(const Kinematics* kin, const ParticleStore& s, std::uint32_t i, std::uint32_t j,
                                   double width) {
  const Kinematics& a = kin[i];
  const Kinematics& b = kin[j];
  return {minimumImage(a.x - b.x, width), a.y - b.y, a.vx - b.vx, a.vy - b.vy, s.radius[i], s.radius[j],
          s.omega[i], s.omega[j], s.invMass[i] + s.invMass[j], simd::min(s.radius[i], s.radius[j])};
}

// The same for the lanes of V (owner[0..lanes) with partner[0..lanes)), with the same operations.
template <class V>
inline PairInputs<V> grainPairInputs(const Kinematics* kin, const ParticleStore& s, const std::uint32_t* owner,
                                     const std::uint32_t* partner, double width);

#if WIGGLE_SIMD_DOUBLE4
// Four pairs: one subtraction of two records gives a pair's (dx, dy, dvx, dvy) as a row, and a
// 4 x 4 transpose turns four pairs' rows into lanes.
template <>
inline PairInputs<simd::Double4> grainPairInputs(const Kinematics* kin, const ParticleStore& s,
                                                 const std::uint32_t* owner, const std::uint32_t* partner,
                                                 double width) {
  __m256d d[4];
  for (int m = 0; m < 4; ++m)
    d[m] = _mm256_sub_pd(_mm256_load_pd(&kin[owner[m]].x), _mm256_load_pd(&kin[partner[m]].x));
  const __m256d t0 = _mm256_unpacklo_pd(d[0], d[1]), t1 = _mm256_unpackhi_pd(d[0], d[1]);
  const __m256d t2 = _mm256_unpacklo_pd(d[2], d[3]), t3 = _mm256_unpackhi_pd(d[2], d[3]);
  using V = simd::Double4;
  auto lanes = [](const std::vector<double>& v, const std::uint32_t* index) {
    return V{_mm256_set_pd(v[index[3]], v[index[2]], v[index[1]], v[index[0]])};
  };
  const V radI = lanes(s.radius, owner), radJ = lanes(s.radius, partner);
  return {minimumImage(V{_mm256_permute2f128_pd(t0, t2, 0x20)}, width), V{_mm256_permute2f128_pd(t1, t3, 0x20)},
          V{_mm256_permute2f128_pd(t0, t2, 0x31)}, V{_mm256_permute2f128_pd(t1, t3, 0x31)}, radI, radJ,
          lanes(s.omega, owner), lanes(s.omega, partner), lanes(s.invMass, owner) + lanes(s.invMass, partner),
          min(radI, radJ)};
}
#endif

#if WIGGLE_SIMD_DOUBLE8
// Eight pairs: the four-pair gather twice, its lanes joined (the same values, so the same bits).
template <>
inline PairInputs<simd::Double8> grainPairInputs(const Kinematics* kin, const ParticleStore& s,
                                                 const std::uint32_t* owner, const std::uint32_t* partner,
                                                 double width) {
  const auto a = grainPairInputs<simd::Double4>(kin, s, owner, partner, width);
  const auto b = grainPairInputs<simd::Double4>(kin, s, owner + 4, partner + 4, width);
  using V = simd::Double8;
  return {V(a.dx, b.dx),         V(a.dy, b.dy),         V(a.dvx, b.dvx),         V(a.dvy, b.dvy),
          V(a.radI, b.radI),     V(a.radJ, b.radJ),     V(a.omegaI, b.omegaI),   V(a.omegaJ, b.omegaJ),
          V(a.invMassSum, b.invMassSum), V(a.alarmRadius, b.alarmRadius)};
}
#endif

}  // inline namespace WIGGLE_ISA_NAMESPACE
}  // namespace wiggle
