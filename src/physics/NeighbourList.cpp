#include "physics/NeighbourList.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <omp.h>

#include "core/Assert.h"
#include "core/Error.h"
#include "physics/ParticleStore.h"

namespace wiggle {

namespace {


// Particles binned into square-ish cells at least `cutoff` wide, periodic in x.
struct CellGrid {
  int nx = 0, ny = 0;
  double cellWidth = 0, cellHeight = 0, yMin = 0;
  std::vector<std::uint32_t> cellStart;  // nx * ny + 1
  std::vector<std::uint32_t> items;      // particle indices, by cell, ascending within a cell

  int cellX(double x) const { return std::clamp(static_cast<int>(x / cellWidth), 0, nx - 1); }
  int cellY(double y) const { return std::clamp(static_cast<int>((y - yMin) / cellHeight), 0, ny - 1); }
};

CellGrid binParticles(const ParticleStore& s, double boxWidth, double cutoff) {
  CellGrid grid;
  grid.nx = static_cast<int>(std::floor(boxWidth / cutoff));
  if (grid.nx < 3)
    throw Error("box width " + std::to_string(boxWidth) + " is too small for the neighbour grid: need at least 3 x " +
                std::to_string(cutoff));
  grid.cellWidth = boxWidth / grid.nx;
  double yMin = std::numeric_limits<double>::infinity(), yMax = -yMin;
  for (std::uint32_t i = 0; i < s.size(); ++i) {
    yMin = std::min(yMin, s.y[i]);
    yMax = std::max(yMax, s.y[i]);
  }
  if (s.size() == 0) yMin = yMax = 0.0;
  const double rows = (yMax - yMin) / cutoff;
  if (!(rows < 1e7))
    throw Error("particles spread over a height of " + std::to_string(yMax - yMin) +
                " d: the simulation has blown up or the input is wrong");
  grid.yMin = yMin;
  grid.cellHeight = cutoff;
  grid.ny = static_cast<int>(rows) + 1;
  const std::size_t cells = static_cast<std::size_t>(grid.nx) * grid.ny;
  grid.cellStart.assign(cells + 1, 0);
  std::vector<std::uint32_t> cellOf(s.size());
  for (std::uint32_t i = 0; i < s.size(); ++i) {
    cellOf[i] = static_cast<std::uint32_t>(grid.cellY(s.y[i]) * grid.nx + grid.cellX(s.x[i]));
    ++grid.cellStart[cellOf[i] + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) grid.cellStart[c + 1] += grid.cellStart[c];
  grid.items.resize(s.size());
  std::vector<std::uint32_t> fill(grid.cellStart.begin(), grid.cellStart.end() - 1);
  for (std::uint32_t i = 0; i < s.size(); ++i) grid.items[fill[cellOf[i]]++] = i;
  return grid;
}

// Partners j > i of grain i within radI + radJ + skin, appended to `out` in ascending order.
void findPartners(const ParticleStore& s, const CellGrid& grid, double boxWidth, double skin,
                  std::uint32_t i, std::vector<std::uint32_t>& out) {
  const double halfWidth = 0.5 * boxWidth;
  const std::size_t first = out.size();
  const int cx = grid.cellX(s.x[i]);
  const int cy = grid.cellY(s.y[i]);
  for (int oy = -1; oy <= 1; ++oy) {
    const int ny = cy + oy;
    if (ny < 0 || ny >= grid.ny) continue;
    for (int ox = -1; ox <= 1; ++ox) {
      const int nx = (cx + ox + grid.nx) % grid.nx;  // nx >= 3: the three columns are distinct
      const std::size_t cell = static_cast<std::size_t>(ny) * grid.nx + nx;
      for (std::uint32_t c = grid.cellStart[cell]; c < grid.cellStart[cell + 1]; ++c) {
        const std::uint32_t j = grid.items[c];
        if (j <= i) continue;
        double dx = s.x[i] - s.x[j];
        if (dx > halfWidth) dx -= boxWidth;
        else if (dx < -halfWidth) dx += boxWidth;
        const double dy = s.y[i] - s.y[j];
        const double reach = s.radius[i] + s.radius[j] + skin;
        if (dx * dx + dy * dy < reach * reach) out.push_back(j);
      }
    }
  }
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
}

}  // namespace

void NeighbourList::build(const ParticleStore& s, double boxWidth, double skin,
                          const NeighbourList& old, const std::vector<std::uint32_t>& newToOld) {
  WIGGLE_ASSERT(newToOld.empty() || newToOld.size() == s.size());
  double rMax = 0.0;
  for (double r : s.radius) rMax = std::max(rMax, r);
  const CellGrid grid = binParticles(s, boxWidth, 2.0 * rMax + skin);

  // Rows are found per thread over contiguous grain ranges and concatenated in range order, so the
  // list is the same for any thread count.
  const std::uint32_t rows = s.grainCount;
  std::vector<std::vector<std::uint32_t>> partnersOf;
  std::vector<std::vector<std::uint32_t>> rowSizesOf;
#pragma omp parallel
  {
#pragma omp single
    {
      partnersOf.resize(omp_get_num_threads());
      rowSizesOf.resize(omp_get_num_threads());
    }
    const int t = omp_get_thread_num();
    auto& local = partnersOf[t];
    auto& sizes = rowSizesOf[t];
#pragma omp for schedule(static)
    for (std::uint32_t i = 0; i < rows; ++i) {
      const std::size_t before = local.size();
      findPartners(s, grid, boxWidth, skin, i, local);
      sizes.push_back(static_cast<std::uint32_t>(local.size() - before));
    }
  }
  // Each thread's rows go to their place, found from the sizes of the threads before it.
  const std::size_t parts = partnersOf.size();
  std::vector<std::uint32_t> firstPair(parts + 1, 0), firstRow(parts + 1, 0);
  for (std::size_t t = 0; t < parts; ++t) {
    firstPair[t + 1] = firstPair[t] + static_cast<std::uint32_t>(partnersOf[t].size());
    firstRow[t + 1] = firstRow[t] + static_cast<std::uint32_t>(rowSizesOf[t].size());
  }
  WIGGLE_ASSERT(firstRow[parts] == rows);
  rowStart.resize(rows + 1);
  rowStart[0] = 0;
  partner.resize(firstPair[parts]);
#pragma omp parallel for schedule(static)
  for (std::int64_t t = 0; t < static_cast<std::int64_t>(parts); ++t) {
    std::copy(partnersOf[t].begin(), partnersOf[t].end(), partner.begin() + firstPair[t]);
    std::uint32_t row = firstRow[t], start = firstPair[t];
    for (std::uint32_t count : rowSizesOf[t]) rowStart[++row] = start += count;
  }

  // Carry the history of pairs that existed before, matching them by their old indices.
  const std::uint32_t pairs = pairCount();
  shearX.assign(pairs, 0.0);
  shearY.assign(pairs, 0.0);
  const std::uint32_t oldRows = old.rowStart.empty() ? 0 : static_cast<std::uint32_t>(old.rowStart.size() - 1);
#pragma omp parallel for schedule(static)
  for (std::uint32_t i = 0; i < rows; ++i) {
    for (std::uint32_t k = rowStart[i]; k < rowStart[i + 1]; ++k) {
      const std::uint32_t j = partner[k];
      const std::uint32_t oi = newToOld.empty() ? i : newToOld[i];
      const std::uint32_t oj = newToOld.empty() ? j : newToOld[j];
      if (oi == kNoOldIndex || oj == kNoOldIndex) continue;
      const std::uint32_t a = std::min(oi, oj), b = std::max(oi, oj);
      if (a >= oldRows) continue;
      for (std::uint32_t m = old.rowStart[a]; m < old.rowStart[a + 1]; ++m) {
        if (old.partner[m] != b) continue;
        // History is stored in the owner's frame: swapping owner and partner flips its sign.
        const double sign = oi < oj ? 1.0 : -1.0;
        shearX[k] = sign * old.shearX[m];
        shearY[k] = sign * old.shearY[m];
        break;
      }
    }
  }
  forceX.assign(pairs, 0.0);
  forceY.assign(pairs, 0.0);
  torqueArm.assign(pairs, 0.0);
  deriveIndex(forceBlockRows(boxWidth));
}

NeighbourList::Strip NeighbourList::strip(std::uint32_t t, std::uint32_t threads, std::uint32_t firstThreadPairs) const {
  WIGGLE_ASSERT(t < threads);
  const std::uint32_t blocks = blockCount(), rows = rowCount();
  const std::uint64_t extra = firstThreadPairs, work = pairCount() + extra;
  // The first block whose first pair is at or past the share's start (the last strip ends at the
  // last block, so that blocks without pairs at the end still belong to one). The shares are of the
  // work, the first thread's extra pairs ahead of the list's.
  auto boundary = [&](std::uint32_t share) -> std::uint32_t {
    if (share == threads) return blocks;
    const std::uint64_t workStart = work * share / threads;
    const std::uint64_t start = workStart > extra ? workStart - extra : 0;
    std::uint32_t lo = 0, hi = blocks;
    while (lo < hi) {
      const std::uint32_t mid = lo + (hi - lo) / 2;
      if (rowStart[mid * blockRows] < start)
        lo = mid + 1;
      else
        hi = mid;
    }
    return lo;
  };
  const std::uint32_t first = boundary(t), last = boundary(t + 1);
  return {first, last, std::min(first * blockRows, rows), std::min(last * blockRows, rows)};
}

double NeighbourList::stripImbalance(std::uint32_t threads, std::uint32_t firstThreadPairs) const {
  const std::uint64_t work = pairCount() + std::uint64_t{firstThreadPairs};
  if (rowCount() == 0 || work == 0) return 1.0;
  std::uint64_t heaviest = 0;
  for (std::uint32_t t = 0; t < threads; ++t) {
    const Strip s = strip(t, threads, firstThreadPairs);
    heaviest = std::max<std::uint64_t>(heaviest, rowStart[s.lastRow] - rowStart[s.firstRow] + (t == 0 ? firstThreadPairs : 0));
  }
  return static_cast<double>(heaviest) * threads / static_cast<double>(work);
}

std::uint32_t forceBlockRows(double boxWidth) {
  return static_cast<std::uint32_t>(std::clamp(4.0 * std::ceil(boxWidth), 64.0, 1e6));
}

void NeighbourList::deriveIndex(std::uint32_t rows) {
  WIGGLE_ASSERT(rows > 0);
  blockRows = rows;
  const std::uint32_t grains = rowCount();
  const std::uint32_t pairs = pairCount();
  const auto blocks = static_cast<std::int64_t>(blockCount());
  owner.resize(pairs);
  crossStart.assign(grains + 1, 0);
  // A grain's cross pairs come from owners in earlier blocks, at most `reach` rows before it (the
  // list's largest partner - owner among grains). So each block of partners finds its cross pairs
  // by scanning only the owners within reach before it, in ascending pair order, and writes only
  // its own grains' entries: the blocks go in parallel, and the index is the serial one's. (The
  // grains are sorted by height, so the reach is about a row; before the first sort of a bed kept in
  // its imported order it can be the whole list, and the scans cost blocks x pairs until then.)
  std::uint32_t reach = 0;
#pragma omp parallel for schedule(static) reduction(max : reach)
  for (std::uint32_t i = 0; i < grains; ++i)
    for (std::uint32_t k = rowStart[i]; k < rowStart[i + 1]; ++k) {
      owner[k] = i;
      if (partner[k] < grains) reach = std::max(reach, partner[k] - i);
    }
  // Calls f(k, p) for each cross pair k into block b's grain p, in ascending k.
  auto forCrossPairsInto = [&](std::uint32_t b, auto&& f) {
    const std::uint32_t first = b * blockRows, end = std::min(first + blockRows, grains);
    for (std::uint32_t i = first > reach ? first - reach : 0; i < first; ++i)
      for (std::uint32_t k = rowStart[i]; k < rowStart[i + 1]; ++k)
        if (partner[k] >= first && partner[k] < end) f(k, partner[k]);
  };
#pragma omp parallel for schedule(static)
  for (std::int64_t b = 0; b < blocks; ++b)
    forCrossPairsInto(static_cast<std::uint32_t>(b), [&](std::uint32_t, std::uint32_t p) { ++crossStart[p + 1]; });
  for (std::uint32_t p = 0; p < grains; ++p) crossStart[p + 1] += crossStart[p];
  crossPair.resize(crossStart[grains]);
#pragma omp parallel for schedule(static)
  for (std::int64_t b = 0; b < blocks; ++b) {
    const std::uint32_t first = static_cast<std::uint32_t>(b) * blockRows;
    const std::uint32_t end = std::min(first + blockRows, grains);
    std::vector<std::uint32_t> fill(crossStart.begin() + first, crossStart.begin() + end);
    forCrossPairsInto(static_cast<std::uint32_t>(b),
                      [&](std::uint32_t k, std::uint32_t p) { crossPair[fill[p - first]++] = k; });
  }
}

}  // namespace wiggle
