#include "scenario/bed/RandomPour.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/Rng.h"

namespace wiggle {

bool touchesClump(const ClumpDef& clump, double cx, double cy, double x, double y, double r) {
  const double reach = r + clump.atomRadius + 0.01;
  for (std::size_t a = 0; a < clump.offsetX.size(); ++a) {
    const double dx = x - (cx + clump.offsetX[a]);
    const double dy = y - (cy + clump.offsetY[a]);
    if (dx * dx + dy * dy < reach * reach) return true;
  }
  return false;
}

RandomBatch randomPourBatch(const RunConfig& config, const ClumpDef& clump, double highest, std::uint64_t firstSerial) {
  const double width = config.box.width, height = config.bed.batchHeight;
  const double cx = 0.5 * width, cy = config.intruder.y0;
  const double dMin = config.grains.dMin, dMax = config.grains.dMax;
  const std::uint64_t seed = config.box.seed;
  RandomBatch b;
  b.yLow = highest + dMax;  // a grain's bottom stays above every grain already there
  b.yHigh = b.yLow + height;
  b.targetArea = config.bed.pourFraction * width * height;
  // fix pour's count: the target area over a mean grain's area (E[d^2] of the uniform diameters).
  const double meanArea = std::numbers::pi / 4.0 * (dMin * dMin + dMin * dMax + dMax * dMax) / 3.0;
  const auto targetCount = static_cast<std::uint64_t>(std::ceil(b.targetArea / meanArea));
  b.maxAttempts = 100 * std::max<std::uint64_t>(1, targetCount);

  // Cells at least d_max wide and tall: a candidate can only overlap grains of its own and the
  // eight neighbouring cells (columns periodic). head/next: a linked list of grains per cell.
  const int nx = std::max(1, static_cast<int>(std::floor(width / dMax)));
  const int ny = std::max(1, static_cast<int>(std::floor(height / dMax)));
  const double cellW = width / nx, cellH = height / ny;
  std::vector<std::int32_t> head(static_cast<std::size_t>(nx) * ny, -1), next;
  std::vector<int> columns;  // the columns to search around a candidate's (each once)
  // A bounding circle of the clump: most candidates are far from it and skip its atoms.
  double clumpReach = 0.0;
  for (std::size_t a = 0; a < clump.offsetX.size(); ++a)
    clumpReach = std::max(clumpReach, std::hypot(clump.offsetX[a], clump.offsetY[a]));
  clumpReach += clump.atomRadius + 0.5 * dMax + 0.02;  // (touchesClump's reach, and a margin for round-off)

  for (; b.attempts < b.maxAttempts && b.area < b.targetArea; ++b.attempts) {
    const std::uint64_t serial = firstSerial + b.attempts;
    const double r = 0.5 * (dMin + (dMax - dMin) * uniform01(seed, RngStream::RandomPourDiameter, serial));
    double x = width * uniform01(seed, RngStream::RandomPourPosition, serial, 0);
    if (x >= width) x -= width;  // (a product that rounds up to W)
    const double y = b.yLow + height * uniform01(seed, RngStream::RandomPourPosition, serial, 1);
    const int col = std::min(nx - 1, static_cast<int>(x / cellW));
    const int row = std::min(ny - 1, static_cast<int>((y - b.yLow) / cellH));
    columns.clear();
    if (nx < 3) {
      for (int c = 0; c < nx; ++c) columns.push_back(c);
    } else {
      for (int c : {col - 1, col, col + 1}) columns.push_back((c + nx) % nx);
    }
    bool fits = true;
    for (int rr = std::max(0, row - 1); fits && rr <= std::min(ny - 1, row + 1); ++rr) {
      for (int c : columns) {
        for (std::int32_t j = head[static_cast<std::size_t>(rr) * nx + c]; j >= 0; j = next[j]) {
          const PouredGrain& g = b.grains[j];
          double dx = x - g.x;
          dx -= width * std::round(dx / width);
          const double dy = y - g.y, reach = r + g.radius;
          if (dx * dx + dy * dy < reach * reach) {
            fits = false;
            break;
          }
        }
        if (!fits) break;
      }
    }
    if (!fits) continue;
    if (std::hypot(x - cx, y - cy) < clumpReach && touchesClump(clump, cx, cy, x, y, r)) continue;
    const std::size_t cell = static_cast<std::size_t>(row) * nx + col;
    next.push_back(head[cell]);
    head[cell] = static_cast<std::int32_t>(b.grains.size());
    b.grains.push_back({x, y, r});
    b.area += std::numbers::pi * r * r;
  }
  return b;
}

}  // namespace wiggle
