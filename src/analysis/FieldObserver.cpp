#include "analysis/FieldObserver.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>

#include <omp.h>

#include "core/Error.h"
#include "core/Format.h"
#include "io/AtomicFile.h"
#include "physics/World.h"

namespace wiggle {
namespace {

constexpr std::size_t kMaxPointsPerSide = 4001;
constexpr std::uint32_t kSaveVersion = 1;

// x into [-W/2, W/2]: the minimum image of a separation in the periodic direction.
double wrap(double dx, double width) { return dx - width * std::round(dx / width); }

// A segment prepared once for many grid points: length L, unit direction u, and the constant
// 1 / (2 sqrt(pi) w L) of the closed form (see segmentGaussianWeight in the header).
struct Segment {
  double bx, by, length, ux, uy, norm, invW;
  bool point;  // length negligible against w: the integral is W at the (single) point
};

Segment prepareSegment(double bx, double by, double w) {
  Segment s{};
  s.bx = bx;
  s.by = by;
  s.length = std::hypot(bx, by);
  s.invW = 1.0 / w;
  s.point = s.length < 1e-12 * w;
  if (s.point) {
    s.norm = 1.0 / (std::numbers::pi * w * w);
    return s;
  }
  s.ux = bx / s.length;
  s.uy = by / s.length;
  s.norm = 1.0 / (2.0 * std::sqrt(std::numbers::pi) * w * s.length);
  return s;
}

// integral_0^1 W(q - s b) ds, W(r) = exp(-r^2/w^2)/(pi w^2). With a = q.u (the projection of q on
// the segment) and h = |q x u| (the distance from the segment's line), |q - s b|^2 = (sL - a)^2 + h^2,
// so the integral is exp(-h^2/w^2)/(pi w^2 L) * int_{-a}^{L-a} exp(-t^2/w^2) dt
//   = exp(-h^2/w^2) / (2 sqrt(pi) w L) * [erf(a/w) + erf((L-a)/w)].
// When the projection falls outside the segment one erf is near -1 and the other near +1; the
// bracket is then written as a difference of erfc, which keeps its relative precision far away.
double segmentWeight(const Segment& s, double qx, double qy) {
  if (s.point) return s.norm * std::exp(-(qx * qx + qy * qy) * s.invW * s.invW);
  const double a = qx * s.ux + qy * s.uy;
  const double h = qx * s.uy - qy * s.ux;
  const double lo = a * s.invW, hi = (s.length - a) * s.invW;
  double bracket;
  if (lo < 0.0) bracket = std::erfc(-lo) - std::erfc(hi);       // before the start: hi > 0
  else if (hi < 0.0) bracket = std::erfc(-hi) - std::erfc(lo);  // past the end: lo > 0
  else bracket = std::erf(lo) + std::erf(hi);
  return s.norm * std::exp(-h * h * s.invW * s.invW) * bracket;
}

}  // namespace

double segmentGaussianWeight(double qx, double qy, double bx, double by, double w) {
  return segmentWeight(prepareSegment(bx, by, w), qx, qy);
}

void FieldObserver::Grid::resize(std::size_t points) {
  for (auto* v : {&phi, &momX, &momY, &sxx, &sxy, &syx, &syy}) v->assign(points, 0.0);
}

void FieldObserver::Grid::zero() {
  for (auto* v : {&phi, &momX, &momY, &sxx, &sxy, &syx, &syy}) std::fill(v->begin(), v->end(), 0.0);
}

FieldObserver::FieldObserver(const FieldsDef& def, double boxWidth) : def_(def), boxWidth_(boxWidth) {
  if (!(def.width > 0) || !std::isfinite(def.width))
    throw Error("fields.width must be > 0, got " + formatNumber(def.width, 10));
  if (!(def.spacing > 0) || !std::isfinite(def.spacing))
    throw Error("fields.spacing must be > 0, got " + formatNumber(def.spacing, 10));
  if (!(def.radius >= 0) || !std::isfinite(def.radius))
    throw Error("fields.radius must be >= 0, got " + formatNumber(def.radius, 10));
  if (!(boxWidth > 0) || !std::isfinite(boxWidth))
    throw Error("fields: box width must be > 0, got " + formatNumber(boxWidth, 10));
  const double steps = 2.0 * def.radius / def.spacing;
  if (steps + 1.0 > static_cast<double>(kMaxPointsPerSide))
    throw Error("fields.radius / fields.spacing gives more than " + std::to_string(kMaxPointsPerSide) +
                " grid points per side");
  // A grid from -radius to +radius; when 2 radius / spacing is not whole, the points that fit,
  // placed symmetrically about the centre.
  n_ = static_cast<std::size_t>(std::floor(steps + 1e-9)) + 1;
  cut_ = 3.0 * def.width;
  reach_ = gridCoordinate(n_ - 1) + cut_;
  invWidthSq_ = 1.0 / (def.width * def.width);
  pointNorm_ = 1.0 / (std::numbers::pi * def.width * def.width);
  frames_.assign(def.phases.size(), 0);
  sums_.resize(def.phases.size());
  for (auto& g : sums_) g.resize(n_ * n_);
  frame_.resize(n_ * n_);
}

double FieldObserver::gridCoordinate(std::size_t k) const {
  return (static_cast<double>(k) - 0.5 * static_cast<double>(n_ - 1)) * def_.spacing;
}

std::uint64_t FieldObserver::frames(std::size_t phaseIndex) const {
  if (phaseIndex >= frames_.size())
    throw Error("fields: phase index " + std::to_string(phaseIndex) + " out of range (" +
                std::to_string(frames_.size()) + " phases)");
  return frames_[phaseIndex];
}

void FieldObserver::addFrame(const World& world, std::size_t phaseIndex) {
  if (!world.hasIntruder()) throw Error("fields: the world has no intruder to centre the grid on");
  addFrameAt(world, phaseIndex, world.intruder().x, world.intruder().y);
}

void FieldObserver::addFrameAt(const World& world, std::size_t phaseIndex, double centreX, double centreY) {
  if (phaseIndex >= frames_.size())
    throw Error("fields: phase index " + std::to_string(phaseIndex) + " out of range (" +
                std::to_string(frames_.size()) + " phases)");
  if (world.def().boxWidth != boxWidth_)
    throw Error("fields: the world's box width " + formatNumber(world.def().boxWidth, 10) +
                " differs from the observer's " + formatNumber(boxWidth_, 10));
  const NeighbourList& list = world.neighbours();
  if (list.forceX.size() < list.pairCount() || list.forceY.size() < list.pairCount() ||
      list.owner.size() < list.pairCount())
    throw Error("fields: the neighbour list has no forces yet (take a step first)");
  if (world.hasIntruder()) {
    const IntruderPairs& ip = world.intruderPairs();
    if (ip.forceX.size() < ip.size() || ip.forceY.size() < ip.size())
      throw Error("fields: the intruder pairs have no forces yet (take a step first)");
  }

  // Threads split the grid into bands of rows; each thread visits every grain and contact but
  // deposits only into its own rows. Every grid point thus receives its terms in the same order
  // (grain index, then pair index) for any thread count: the fields are bitwise reproducible.
  frame_.zero();
#pragma omp parallel
  {
    const auto threads = static_cast<std::size_t>(omp_get_num_threads());
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    const Rows rows{n_ * t / threads, n_ * (t + 1) / threads};
    std::vector<double> ex(n_), ey(n_);
    depositGrains(world, centreX, centreY, rows, ex, ey);
    depositContacts(world, centreX, centreY, rows);
    if (def_.kinetic) depositKinetic(world, centreX, centreY, rows);
  }

  Grid& sum = sums_[phaseIndex];
  const std::size_t points = n_ * n_;
  for (std::size_t k = 0; k < points; ++k) {
    sum.phi[k] += frame_.phi[k];
    sum.momX[k] += frame_.momX[k];
    sum.momY[k] += frame_.momY[k];
    sum.sxx[k] += frame_.sxx[k];
    sum.sxy[k] += frame_.sxy[k];
    sum.syx[k] += frame_.syx[k];
    sum.syy[k] += frame_.syy[k];
  }
  ++frames_[phaseIndex];
}

namespace {

// Grid index range [first, last] of the points with coordinate in [lo, hi]; empty when first > last.
struct IndexRange {
  std::ptrdiff_t first, last;
};

IndexRange indexRange(double lo, double hi, double spacing, std::size_t n) {
  const double offset = 0.5 * static_cast<double>(n - 1);
  auto first = static_cast<std::ptrdiff_t>(std::ceil(lo / spacing + offset));
  auto last = static_cast<std::ptrdiff_t>(std::floor(hi / spacing + offset));
  first = std::max<std::ptrdiff_t>(first, 0);
  last = std::min<std::ptrdiff_t>(last, static_cast<std::ptrdiff_t>(n) - 1);
  return {first, last};
}

// The same, for rows, further restricted to the calling thread's band [begin, end).
IndexRange rowRange(double lo, double hi, double spacing, std::size_t n, std::size_t begin, std::size_t end) {
  IndexRange r = indexRange(lo, hi, spacing, n);
  r.first = std::max(r.first, static_cast<std::ptrdiff_t>(begin));
  r.last = std::min(r.last, static_cast<std::ptrdiff_t>(end) - 1);
  return r;
}

// Calls fn(i, gx, gy) for every grain i and every periodic image of it whose centre (gx, gy),
// relative to the grid centre, lies within `reach` of the grid's square in both directions.
template <class Fn>
void forEachGrainImage(const ParticleStore& s, double width, double cx, double cy, double reach, Fn&& fn) {
  for (std::uint32_t i = 0; i < s.grainCount; ++i) {
    const double gy = s.y[i] - cy;
    if (std::fabs(gy) > reach) continue;
    const double dx = wrap(s.x[i] - cx, width);
    const auto kFirst = static_cast<long>(std::ceil((-reach - dx) / width));
    const auto kLast = static_cast<long>(std::floor((reach - dx) / width));
    for (long k = kFirst; k <= kLast; ++k) fn(i, dx + static_cast<double>(k) * width, gy);
  }
}

}  // namespace

void FieldObserver::depositGrains(const World& world, double cx, double cy, Rows rows,
                                  std::vector<double>& ex, std::vector<double>& ey) {
  const ParticleStore& s = world.particles();
  const double spacing = def_.spacing, cut = cut_, cutSq = cut * cut;
  const double invWSq = invWidthSq_, norm = pointNorm_, reach = reach_;
  const std::size_t n = n_;
  forEachGrainImage(s, boxWidth_, cx, cy, reach, [&](std::uint32_t i, double gx, double gy) {
    const IndexRange rx = indexRange(gx - cut, gx + cut, spacing, n);
    const IndexRange ry = rowRange(gy - cut, gy + cut, spacing, n, rows.begin, rows.end);
    if (rx.first > rx.last || ry.first > ry.last) return;
    // exp(-(dx^2 + dy^2)/w^2) = exp(-dx^2/w^2) exp(-dy^2/w^2): 2 x 13 exponentials per grain
    // instead of ~113 at the default spacing.
    for (auto ix = rx.first; ix <= rx.last; ++ix) {
      const double d = gridCoordinate(ix) - gx;
      ex[ix] = std::exp(-d * d * invWSq);
    }
    for (auto iy = ry.first; iy <= ry.last; ++iy) {
      const double d = gridCoordinate(iy) - gy;
      ey[iy] = std::exp(-d * d * invWSq);
    }
    const double area = std::numbers::pi * s.radius[i] * s.radius[i];
    const double vx = s.vx[i], vy = s.vy[i];
    for (auto iy = ry.first; iy <= ry.last; ++iy) {
      const double dy = gridCoordinate(iy) - gy;
      const double aw = area * norm * ey[iy];
      std::size_t row = static_cast<std::size_t>(iy) * n;
      for (auto ix = rx.first; ix <= rx.last; ++ix) {
        const double dx = gridCoordinate(ix) - gx;
        if (dx * dx + dy * dy > cutSq) continue;
        const double weight = aw * ex[ix];
        const std::size_t k = row + static_cast<std::size_t>(ix);
        frame_.phi[k] += weight;
        frame_.momX[k] += weight * vx;
        frame_.momY[k] += weight * vy;
      }
    }
  });
}

void FieldObserver::depositSegment(double px, double py, double bx, double by, double fx, double fy,
                                   Rows rows) {
  const double spacing = def_.spacing, cut = cut_, cutSq = cut * cut, reach = reach_;
  const double ymin = std::min(py, py + by), ymax = std::max(py, py + by);
  if (ymax < -reach || ymin > reach) return;
  const IndexRange ry = rowRange(ymin - cut, ymax + cut, spacing, n_, rows.begin, rows.end);
  if (ry.first > ry.last) return;
  const double xmin0 = std::min(px, px + bx), xmax0 = std::max(px, px + bx);
  const auto kFirst = static_cast<long>(std::ceil((-reach - xmax0) / boxWidth_));
  const auto kLast = static_cast<long>(std::floor((reach - xmin0) / boxWidth_));
  const Segment seg = prepareSegment(bx, by, def_.width);
  const double lengthSq = bx * bx + by * by;
  const double fxbx = fx * bx, fxby = fx * by, fybx = fy * bx, fyby = fy * by;
  for (long k = kFirst; k <= kLast; ++k) {
    const double sx = px + static_cast<double>(k) * boxWidth_;
    const IndexRange rx = indexRange(std::min(sx, sx + bx) - cut, std::max(sx, sx + bx) + cut, spacing, n_);
    for (auto iy = ry.first; iy <= ry.last; ++iy) {
      const double qy = gridCoordinate(iy) - py;
      const std::size_t row = static_cast<std::size_t>(iy) * n_;
      for (auto ix = rx.first; ix <= rx.last; ++ix) {
        const double qx = gridCoordinate(ix) - sx;
        // Squared distance from the grid point to the closest point of the segment.
        const double along = qx * bx + qy * by;
        double distSq;
        if (along <= 0.0) {
          distSq = qx * qx + qy * qy;
        } else if (along >= lengthSq) {
          distSq = (qx - bx) * (qx - bx) + (qy - by) * (qy - by);
        } else {
          const double cross = qx * by - qy * bx;
          distSq = cross * cross / lengthSq;
        }
        if (distSq > cutSq) continue;
        const double weight = segmentWeight(seg, qx, qy);
        const std::size_t idx = row + static_cast<std::size_t>(ix);
        frame_.sxx[idx] += fxbx * weight;
        frame_.sxy[idx] += fxby * weight;
        frame_.syx[idx] += fybx * weight;
        frame_.syy[idx] += fyby * weight;
      }
    }
  }
}

void FieldObserver::depositContacts(const World& world, double cx, double cy, Rows rows) {
  const ParticleStore& s = world.particles();
  const double width = boxWidth_;
  const double reach = reach_;

  // Grain-grain and grain-base: force on the owner i from the partner j, branch i -> j.
  const NeighbourList& list = world.neighbours();
  const std::uint32_t pairs = list.pairCount();
  for (std::uint32_t k = 0; k < pairs; ++k) {
    const double fx = list.forceX[k], fy = list.forceY[k];
    if (fx == 0.0 && fy == 0.0) continue;  // in the list but not touching
    const std::uint32_t i = list.owner[k], j = list.partner[k];
    const double py = s.y[i] - cy;
    const double by = s.y[j] - s.y[i];
    // Cheap cull before the wrap: a contact branch is shorter than 2 radii.
    if (std::fabs(py) > reach + std::fabs(by)) continue;
    depositSegment(wrap(s.x[i] - cx, width), py, wrap(s.x[j] - s.x[i], width), by, fx, fy, rows);
  }

  // Grain-intruder: force on the grain, branch from the grain centre to the atom centre.
  if (!world.hasIntruder()) return;
  const IntruderPairs& ip = world.intruderPairs();
  const ClumpDef& clump = world.clump();
  const ClumpState& state = world.intruder();
  for (std::uint32_t p = 0; p < ip.size(); ++p) {
    const double fx = ip.forceX[p], fy = ip.forceY[p];
    if (fx == 0.0 && fy == 0.0) continue;
    const std::uint32_t g = ip.grain[p], a = ip.atom[p];
    const double ax = state.x + clump.offsetX[a], ay = state.y + clump.offsetY[a];
    depositSegment(wrap(s.x[g] - cx, width), s.y[g] - cy, wrap(ax - s.x[g], width), ay - s.y[g], fx, fy,
                   rows);
  }
}

void FieldObserver::depositKinetic(const World& world, double cx, double cy, Rows rows) {
  // Needs this frame's velocity field v(p) = momentum / Phi: depositGrains has run.
  const ParticleStore& s = world.particles();
  const double spacing = def_.spacing, cut = cut_, cutSq = cut * cut;
  const double invWSq = invWidthSq_, norm = pointNorm_, reach = reach_;
  const std::size_t n = n_;
  forEachGrainImage(s, boxWidth_, cx, cy, reach, [&](std::uint32_t i, double gx, double gy) {
    const IndexRange rx = indexRange(gx - cut, gx + cut, spacing, n);
    const IndexRange ry = rowRange(gy - cut, gy + cut, spacing, n, rows.begin, rows.end);
    const double mass = s.mass[i];
    for (auto iy = ry.first; iy <= ry.last; ++iy) {
      const double dy = gridCoordinate(iy) - gy;
      const std::size_t row = static_cast<std::size_t>(iy) * n;
      for (auto ix = rx.first; ix <= rx.last; ++ix) {
        const double dx = gridCoordinate(ix) - gx;
        const double rSq = dx * dx + dy * dy;
        if (rSq > cutSq) continue;
        const std::size_t k = row + static_cast<std::size_t>(ix);
        // phi > 0 here: this grain itself deposited a positive weight at k.
        const double ux = s.vx[i] - frame_.momX[k] / frame_.phi[k];
        const double uy = s.vy[i] - frame_.momY[k] / frame_.phi[k];
        const double mw = mass * norm * std::exp(-rSq * invWSq);
        frame_.sxx[k] -= mw * ux * ux;
        frame_.sxy[k] -= mw * ux * uy;
        frame_.syx[k] -= mw * uy * ux;
        frame_.syy[k] -= mw * uy * uy;
      }
    }
  });
}

FieldSample FieldObserver::sample(std::size_t phaseIndex, std::size_t ix, std::size_t iy) const {
  const std::uint64_t count = frames(phaseIndex);
  if (count == 0) throw Error("fields: phase " + std::to_string(phaseIndex) + " has no frames");
  if (ix >= n_ || iy >= n_) throw Error("fields: grid index out of range");
  const Grid& g = sums_[phaseIndex];
  const std::size_t k = iy * n_ + ix;
  const double inv = 1.0 / static_cast<double>(count);
  FieldSample out;
  out.phi = g.phi[k] * inv;
  if (g.phi[k] > 0.0) {
    out.vx = g.momX[k] / g.phi[k];
    out.vy = g.momY[k] / g.phi[k];
  } else {
    out.vx = out.vy = std::numeric_limits<double>::quiet_NaN();
  }
  out.sxx = g.sxx[k] * inv;
  out.sxy = g.sxy[k] * inv;
  out.syx = g.syx[k] * inv;
  out.syy = g.syy[k] * inv;
  out.pressure = -0.5 * (out.sxx + out.syy);
  return out;
}

void FieldObserver::forEachRow(const std::function<void(const Row&)>& visit) const {
  for (std::size_t p = 0; p < def_.phases.size(); ++p) {
    const std::uint64_t count = frames_[p];
    for (std::size_t iy = 0; iy < n_; ++iy)
      for (std::size_t ix = 0; ix < n_; ++ix) {
        std::optional<FieldSample> f;
        if (count != 0) f = sample(p, ix, iy);
        visit(Row{def_.phases[p], gridCoordinate(ix), gridCoordinate(iy), count, f ? &*f : nullptr});
      }
  }
}

void FieldObserver::writeCsv(const std::string& path) const {
  std::string out = "phase,x,y,phi,vx,vy,sxx,sxy,syy,pressure,frames\n";
  char line[512];
  forEachRow([&](const Row& row) {
    if (!row.sample) {
      std::snprintf(line, sizeof line, "%.10g,%.10g,%.10g,,,,,,,,0\n", row.phase, row.x, row.y);
    } else {
      const FieldSample& f = *row.sample;
      char vx[40] = "", vy[40] = "";
      if (!std::isnan(f.vx)) {
        std::snprintf(vx, sizeof vx, "%.10g", f.vx);
        std::snprintf(vy, sizeof vy, "%.10g", f.vy);
      }
      std::snprintf(line, sizeof line, "%.10g,%.10g,%.10g,%.10g,%s,%s,%.10g,%.10g,%.10g,%.10g,%llu\n", row.phase, row.x,
                    row.y, f.phi, vx, vy, f.sxx, f.symmetricShear(), f.syy, f.pressure,
                    static_cast<unsigned long long>(row.frames));
    }
    out += line;
  });
  writeFileAtomically(path, out);
}

void FieldObserver::save(BinaryWriter& out) const {
  out.value<std::uint32_t>(kSaveVersion);
  out.value<std::uint64_t>(n_);
  out.value<double>(def_.spacing);
  out.value<double>(def_.width);
  out.value<std::uint8_t>(def_.kinetic ? 1 : 0);
  out.array(def_.phases);
  out.array(frames_);
  for (const Grid& g : sums_)
    for (const auto* v : {&g.phi, &g.momX, &g.momY, &g.sxx, &g.sxy, &g.syx, &g.syy}) out.array(*v);
}

void FieldObserver::load(BinaryReader& in) {
  const std::string what = in.what() + " (fields)";
  if (in.value<std::uint32_t>() != kSaveVersion) throw Error(what + ": unknown fields format version");
  const auto n = in.value<std::uint64_t>();
  const double spacing = in.value<double>();
  const double width = in.value<double>();
  const bool kinetic = in.value<std::uint8_t>() != 0;
  const auto phases = in.array<double>();
  if (n != n_ || spacing != def_.spacing || width != def_.width || kinetic != def_.kinetic ||
      phases != def_.phases)
    throw Error(what + ": the saved field grid or phases differ from the run's [fields] settings");
  auto frames = in.array<std::uint64_t>();
  if (frames.size() != def_.phases.size()) throw Error(what + " is corrupt: wrong number of frame counts");
  std::vector<Grid> sums(def_.phases.size());
  for (Grid& g : sums)
    for (auto* v : {&g.phi, &g.momX, &g.momY, &g.sxx, &g.sxy, &g.syx, &g.syy}) {
      *v = in.array<double>();
      if (v->size() != n_ * n_) throw Error(what + " is corrupt: wrong grid size");
    }
  frames_ = std::move(frames);
  sums_ = std::move(sums);
}

}  // namespace wiggle
