#pragma once
// Verlet neighbour lists with contact history (SPEC 2: history lives as long as the pair touches and
// survives rebuilds, re-sorting and checkpoints).
//
// NeighbourList: a half list over the grains and the frozen base in CSR form: row i holds the
// partners j > i within radI + radJ + skin, sorted by j. Pair k is (owner[k], partner[k]); its
// history and its last force live at index k. revStart/revPair list, for every particle, the pairs
// in which it is the partner, so that each grain can sum its own forces in a fixed order (the
// gather), which is what makes the result independent of the thread count.
//
// IntruderPairs: (grain, intruder atom) pairs, with their history, built with a larger skin.
#include <cstdint>
#include <vector>

namespace wiggle {

struct ParticleStore;

struct NeighbourList {
  std::vector<std::uint32_t> rowStart;  // size grainCount + 1
  std::vector<std::uint32_t> owner;     // i of pair k
  std::vector<std::uint32_t> partner;   // j of pair k (j > i)
  std::vector<double> shearX, shearY;   // tangential history of pair k, in i's frame [d]
  std::vector<double> forceX, forceY;   // last contact force on i from pair k [m g]
  std::vector<double> torqueArm;        // last torque arm of pair k (see ContactLaw.h)
  std::vector<std::uint32_t> revStart;  // size particle count + 1
  std::vector<std::uint32_t> revPair;   // pairs in which the particle is the partner

  std::uint32_t pairCount() const { return static_cast<std::uint32_t>(partner.size()); }

  // Rebuilds from the store (x already wrapped into [0, W)). History is carried from `old` for every
  // pair present in both: newToOld maps a new particle index to its index in `old` (empty:
  // identity). A pair whose owner/partner order flipped gets its history negated (it is stored in
  // the owner's frame).
  void build(const ParticleStore& store, double boxWidth, double skin, const NeighbourList& old,
             const std::vector<std::uint32_t>& newToOld);
  // Derives owner and the reverse incidence from rowStart/partner.
  void deriveIndex(std::uint32_t particleCount);
};

struct IntruderPairs {
  std::vector<std::uint32_t> grain;     // particle index (grain or base)
  std::vector<std::uint32_t> atom;      // intruder atom index
  std::vector<double> shearX, shearY;   // history in the grain's frame
  std::vector<double> forceX, forceY;   // last contact force on the grain [m g]

  std::uint32_t size() const { return static_cast<std::uint32_t>(grain.size()); }
};

}  // namespace wiggle
