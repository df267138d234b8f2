#pragma once
// The step's pair loops (the ContactForces stage of ARCHITECTURE.md's step), compiled once per
// instruction set and chosen when the program starts, so that one binary (the portable build
// included) runs the widest lanes the CPU offers: eight doubles with AVX-512, four with AVX2, one
// otherwise. Every width gives the scalar law's bits (core/Simd.h), so the choice never changes a
// result; it only changes the speed. Each contact law (ContactLaws.h) has its own loops, the law a
// compile-time policy of the pair kernels, so the default law pays nothing for the others' existence.
//
// The variants are physics/ForceKernelVariant.cpp built three times (CMakeLists.txt, one object
// library per instruction set); their inline functions live in per-instruction-set namespaces
// (core/Simd.h), which a test checks on the object files (tests/physics/kernel_symbols.py).
#include <cstdint>
#include <string>

#include "physics/ContactLaws.h"
#include "physics/Intruder.h"
#include "physics/NeighbourList.h"
#include "physics/PairKernel.h"
#include "physics/ParticleStore.h"

namespace wiggle {

enum class SimdLevel : std::uint8_t { Scalar, Avx2, Avx512 };

struct ForceKernels {
  SimdLevel level;
  int lanes;  // doubles per vector: 1, 4 or 8
  ContactLaw law;

  // Force block b of the grain list (NeighbourList.h): every pair of its rows is evaluated, and its
  // force added to the owner and, if the partner is a grain of this block, to the partner, in pair
  // order. The block's grains start from zero: they get no other contribution before this. Returns
  // the block's largest overlap excess (PairKernel.h, evaluatePairs).
  double (*forceBlock)(std::uint32_t b, ParticleStore& s, const Kinematics* kin, NeighbourList& list,
                       ContactParams params, double dt, double width, bool updateShear, double overlapRatio);

  // The contacts between grains and the clump's atoms: each pair's force, torque arm and new history
  // written into its slots (IntruderPairs), nothing summed yet (World adds them to the grains and
  // the clump, in list order), so that it can run beside the force blocks. Returns the largest
  // overlap excess. An atom enters meff with the clump's contact mass (ClumpDef::contactMass) and
  // moves with the clump, turning at `omega` about its centre (0: not turning).
  double (*intruderPairForces)(const ParticleStore& s, const ClumpDef& clump, const ClumpState& state, double omega,
                               IntruderPairs& pairs, ContactParams params, double dt, double width, bool updateShear,
                               double overlapRatio);
};

// "scalar", "avx2", "avx512".
std::string simdLevelName(SimdLevel level);

// The widest level this CPU runs, capped by the environment variable WIGGLE_SIMD (scalar | avx2 |
// avx512) when it is set, for comparisons and benchmarks. Throws wiggle::Error for an unknown value
// or a level the CPU does not have.
SimdLevel defaultSimdLevel();

// The kernels of one level and law; throws wiggle::Error if the CPU cannot run them.
const ForceKernels& forceKernels(SimdLevel level, ContactLaw law);

}  // namespace wiggle
