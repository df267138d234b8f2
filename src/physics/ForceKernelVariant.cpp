// The step's pair loops for one instruction set (physics/ForceKernels.h). CMakeLists.txt compiles
// this file once per instruction set, with -march for it and WIGGLE_KERNEL_VARIANT naming it
// (scalar, avx2, avx512) and WIGGLE_KERNEL_LANES the lanes it must have; everything here has
// internal linkage but the one function that hands out the variant's table.
#include <algorithm>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "physics/ForceKernels.h"

#if !defined(WIGGLE_KERNEL_VARIANT) || !defined(WIGGLE_KERNEL_LANES)
#error "built by CMakeLists.txt once per instruction set, with WIGGLE_KERNEL_VARIANT and WIGGLE_KERNEL_LANES"
#endif

namespace wiggle {

namespace {

static_assert(simd::kLaneCount<simd::WidestLanes> == WIGGLE_KERNEL_LANES,
              "the compiler flags of this variant do not give the lanes it is named for");

// Pairs go in chunks of kChunk: evaluated (PairKernel.h), then added while their slots are in L1.
template <class Law>
double forceBlock(std::uint32_t b, ParticleStore& s, const Kinematics* kin, NeighbourList& list,
                  const ContactParams params, double dt, double width, bool updateShear, double overlapRatio) {
  // Raw pointers and the rows' count read here, not the containers' inline members: an unoptimised
  // build (the sanitizers' -O1) would otherwise emit those members out of line in this object, under
  // this instruction set, where the linker could pick them for every caller (kernel_symbols.py).
  const auto rows = static_cast<std::uint32_t>(list.rowStart.size() - 1);
  const std::uint32_t r0 = b * list.blockRows;
  const std::uint32_t r1 = std::min(r0 + list.blockRows, rows);
  std::fill(s.fx.data() + r0, s.fx.data() + r1, 0.0);
  std::fill(s.fy.data() + r0, s.fy.data() + r1, 0.0);
  std::fill(s.torque.data() + r0, s.torque.data() + r1, 0.0);
  const PairSlots slots{list.shearX.data(), list.shearY.data(), list.forceX.data(), list.forceY.data(),
                        list.torqueArm.data()};
  const std::uint32_t* owner = list.owner.data();
  const std::uint32_t* partner = list.partner.data();
  double excess = -std::numeric_limits<double>::infinity();
  // The owner's sums stay in registers along its row: its partner contributions all come from
  // earlier rows, so loading them at the row's start adds the same terms in the same order.
  std::uint32_t current = r0;
  double ownFx = 0.0, ownFy = 0.0, ownTorque = 0.0;
  const std::uint32_t end = list.rowStart[r1];
  for (std::uint32_t first = list.rowStart[r0]; first < end; first += kChunk) {
    const std::uint32_t last = std::min(first + kChunk, end);
    // Gathered straight into registers, a lane's worth of pairs at a time.
    excess = std::max(excess, maxOverLanes(last - first, [&](std::uint32_t m, auto lane) {
      using V = decltype(lane);
      const std::uint32_t k = first + m;
      if constexpr (std::is_same_v<V, double>)
        return evaluatePairs<Law>(grainPairInputs(kin, s, owner[k], partner[k], width), k, slots, params, dt,
                                  updateShear, overlapRatio);
      else
        return evaluatePairs<Law>(grainPairInputs<V>(kin, s, owner + k, partner + k, width), k, slots, params, dt,
                                  updateShear, overlapRatio);
    }));
    for (std::uint32_t k = first; k < last; ++k) {
      const std::uint32_t i = owner[k], j = partner[k];
      if (i != current) {
        s.fx[current] = ownFx;
        s.fy[current] = ownFy;
        s.torque[current] = ownTorque;
        current = i;
        ownFx = s.fx[i];
        ownFy = s.fy[i];
        ownTorque = s.torque[i];
      }
      ownFx += slots.forceX[k];
      ownFy += slots.forceY[k];
      ownTorque -= s.radius[i] * slots.torqueArm[k];
      if (j < r1) {  // a grain of this block (j > i >= r0); frozen and later-block partners are not
        s.fx[j] -= slots.forceX[k];
        s.fy[j] -= slots.forceY[k];
        s.torque[j] -= s.radius[j] * slots.torqueArm[k];
      }
    }
  }
  if (end > list.rowStart[r0]) {
    s.fx[current] = ownFx;
    s.fy[current] = ownFy;
    s.torque[current] = ownTorque;
  }
  return excess;
}

template <class Law>
double intruderPairForces(const ParticleStore& s, const ClumpDef& clump, const ClumpState& state, double omega,
                          IntruderPairs& ip, const ContactParams params, double dt, double width, bool updateShear,
                          double overlapRatio) {
  double worstExcess = -std::numeric_limits<double>::infinity();
  const double invClumpMass = 1.0 / clump.contactMass();
  const PairSlots slots{ip.shearX.data(), ip.shearY.data(), ip.forceX.data(), ip.forceY.data(),
                        ip.torqueArm.data()};
  // A turning clump's atom moves at v + omega x r and spins at omega (as a rigid body's atoms do in
  // LAMMPS's fix rigid); a clump that does not turn keeps the plain expressions, and their bits.
  const bool turning = omega != 0.0;
  auto inputs = [&](std::uint32_t p) {
    const std::uint32_t g = ip.grain[p], a = ip.atom[p];
    const double atomVx = turning ? state.vx - omega * clump.offsetY[a] : state.vx;
    const double atomVy = turning ? state.vy + omega * clump.offsetX[a] : state.vy;
    return PairInputs<double>{minimumImage(s.x[g] - (state.x + clump.offsetX[a]), width),
                              s.y[g] - (state.y + clump.offsetY[a]),
                              s.vx[g] - atomVx,
                              s.vy[g] - atomVy,
                              s.radius[g],
                              clump.atomRadius,
                              s.omega[g],
                              turning ? omega : 0.0,
                              s.invMass[g] + invClumpMass,
                              s.radius[g]};
  };
  PairChunk chunk;
  for (std::uint32_t first = 0; first < ip.size(); first += kChunk) {
    const std::uint32_t count = std::min(kChunk, ip.size() - first);
    for (std::uint32_t m = 0; m < count; ++m) chunk.set(m, inputs(first + m));
    worstExcess =
        std::max(worstExcess, evaluateChunk<Law>(chunk, count, first, slots, params, dt, updateShear, overlapRatio));
  }
  return worstExcess;
}

}  // namespace

#define WIGGLE_KERNEL_TABLE_NAME(variant) WIGGLE_KERNEL_TABLE_NAME_(variant)
#define WIGGLE_KERNEL_TABLE_NAME_(variant) forceKernels_##variant

namespace {

constexpr SimdLevel kLevel = WIGGLE_KERNEL_LANES == 8   ? SimdLevel::Avx512
                             : WIGGLE_KERNEL_LANES == 4 ? SimdLevel::Avx2
                                                        : SimdLevel::Scalar;

template <class Law>
constexpr ForceKernels kKernels{kLevel, WIGGLE_KERNEL_LANES, contactLaw<Law>, &forceBlock<Law>,
                                &intruderPairForces<Law>};

// Every law's kernels (ContactLaws.h), indexed by its ContactLaw value (a built-in array: see
// forceBlock on containers' members).
template <class List>
struct KernelTable;
template <class... Laws>
struct KernelTable<LawList<Laws...>> {
  static constexpr const ForceKernels* byLaw[] = {&kKernels<Laws>...};
};

}  // namespace

// Declared (and called only on a CPU that has the instruction set, for a law that exists) in
// ForceKernels.cpp.
const ForceKernels& WIGGLE_KERNEL_TABLE_NAME(WIGGLE_KERNEL_VARIANT)(ContactLaw law) {
  return *KernelTable<ContactLaws>::byLaw[static_cast<std::size_t>(law)];
}

}  // namespace wiggle
