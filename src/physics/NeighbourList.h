#pragma once
// Verlet neighbour lists with contact history (history lives as long as the pair touches and survives
// rebuilds, re-sorting and checkpoints: docs/PHYSICS.md §4).
//
// NeighbourList: a half list over the grains and the frozen base in CSR form: row i holds the
// partners j > i within radI + radJ + skin, sorted by j. Pair k is (owner[k], partner[k]); its
// history and its last force live at index k.
//
// Force blocks: the rows are cut into blocks of `blockRows` consecutive grains (a number fixed by
// the box width, never by the thread count). A block's pairs are evaluated by one thread, which adds
// each force straight to the owner and, when the partner is a grain of the same block, to the
// partner. The few pairs whose partner is a grain of a later block ("cross" pairs) reach their
// partner afterwards, through crossStart/crossPair, in pair order. Every sum therefore has an order
// that depends only on the list, which is what makes the result independent of the thread count.
//
// IntruderPairs: (grain, intruder atom) pairs, with their history, built with a larger skin.
#include <cstdint>
#include <vector>

namespace wiggle {

struct ParticleStore;

// In a map from new particle indices to old ones (NeighbourList::build's newToOld, World's pending
// map): a particle that is new, with no old index and no history.
inline constexpr std::uint32_t kNoOldIndex = 0xffffffffu;

// Rows per force block for a box of this width: about four rows of grains, so that cross pairs
// (those reaching into the next block) are around a tenth of all pairs.
std::uint32_t forceBlockRows(double boxWidth);

struct NeighbourList {
  std::uint32_t blockRows = 1;          // grains per force block
  std::vector<std::uint32_t> rowStart;  // size grainCount + 1
  std::vector<std::uint32_t> owner;     // i of pair k
  std::vector<std::uint32_t> partner;   // j of pair k (j > i)
  std::vector<double> shearX, shearY;   // tangential history of pair k, in i's frame [d]
  std::vector<double> forceX, forceY;   // last contact force on i from pair k [m g]
  std::vector<double> torqueArm;        // last torque arm of pair k (see ContactLaw.h)
  std::vector<std::uint32_t> crossStart;  // size grainCount + 1
  std::vector<std::uint32_t> crossPair;   // cross pairs of each partner grain, ascending

  std::uint32_t pairCount() const { return static_cast<std::uint32_t>(partner.size()); }
  std::uint32_t rowCount() const { return rowStart.empty() ? 0 : static_cast<std::uint32_t>(rowStart.size() - 1); }
  std::uint32_t blockCount() const { return (rowCount() + blockRows - 1) / blockRows; }

  // Thread t's strip of `threads`: the consecutive blocks [first, last) holding about a 1/threads share
  // of the pairs, and their rows. As the grains are sorted by height, a strip is a layer of the box;
  // a thread evaluates its strip's blocks and then passes over the strip's grains, so the sums it
  // writes are the ones it reads, on its own core, and only the strips' edges (cross pairs,
  // partners' positions) cross between cores. Which thread evaluates a block never changes a sum.
  // `firstThreadPairs`: pairs the first thread evaluates besides its strip (the intruder's), counted
  // into its share, so that its strip is that much shorter.
  struct Strip {
    std::uint32_t firstBlock, lastBlock;  // blocks [firstBlock, lastBlock)
    std::uint32_t firstRow, lastRow;      // their grains [firstRow, lastRow)
  };
  Strip strip(std::uint32_t t, std::uint32_t threads, std::uint32_t firstThreadPairs = 0) const;
  // The heaviest of `threads` strips' pairs (the first thread's with its firstThreadPairs) over the
  // mean: the force stage at that thread count takes at least this times a perfect share. It is
  // fixed by the blocks (a strip holds whole blocks), so a list of few blocks bounds the speed-up.
  double stripImbalance(std::uint32_t threads, std::uint32_t firstThreadPairs = 0) const;

  // Rebuilds from the store (x already wrapped into [0, W)). History is carried from `old` for every
  // pair present in both: newToOld maps a new particle index to its index in `old` (empty:
  // identity). A pair whose owner/partner order flipped gets its history negated (it is stored in
  // the owner's frame).
  void build(const ParticleStore& store, double boxWidth, double skin, const NeighbourList& old,
             const std::vector<std::uint32_t>& newToOld);
  // Derives owner and the cross-pair index from rowStart/partner, with blocks of `rows` grains.
  void deriveIndex(std::uint32_t rows);
};

struct IntruderPairs {
  std::vector<std::uint32_t> grain;     // particle index (grain or base)
  std::vector<std::uint32_t> atom;      // intruder atom index
  std::vector<double> shearX, shearY;   // history in the grain's frame
  std::vector<double> forceX, forceY;   // last contact force on the grain [m g]
  std::vector<double> torqueArm;        // last torque arm (ContactLaw.h); torque_grain -= r * arm

  std::uint32_t size() const { return static_cast<std::uint32_t>(grain.size()); }
};

}  // namespace wiggle
