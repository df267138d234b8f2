// Tests of the coarse-grained fields against independent references: numerical quadrature of the
// line integral, F (x) r of a single contact, the weight of a settled pile (momentum balance), the
// directly counted area fraction, a uniform translation, and a symmetric kinetic-stress closed form.
#include "analysis/FieldObserver.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <sstream>
#include <unistd.h>

#include "core/Rng.h"
#include "physics/World.h"

namespace wiggle {
namespace {

constexpr double kPi = std::numbers::pi;
const double kCutLoss = std::exp(-9.0);  // weight of W beyond 3w: 1.234e-4

// Direct quadrature of integral_0^1 W(q - s b) ds, W = exp(-r^2/w^2)/(pi w^2): composite Simpson
// with 20000 intervals (error ~ (L/w)^4 h^4 / 180 relative, far below the tolerance used).
double quadratureWeight(double qx, double qy, double bx, double by, double w) {
  const int n = 20000;
  double sum = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double s = static_cast<double>(k) / n;
    const double rx = qx - s * bx, ry = qy - s * by;
    const double f = std::exp(-(rx * rx + ry * ry) / (w * w)) / (kPi * w * w);
    sum += f * (k == 0 || k == n ? 1.0 : (k % 2 ? 4.0 : 2.0));
  }
  return sum / (3.0 * n);
}

TEST(FieldObserver, SegmentWeightClosedFormMatchesQuadrature) {
  struct Case {
    double qx, qy, bx, by, w;
  };
  const Case cases[] = {
      {0.3, 0.2, 1.0, 0.0, 1.0},     // projection inside the segment
      {-0.7, 0.4, 0.9, 0.3, 1.0},    // before the start
      {2.1, -0.5, 0.6, -0.8, 1.0},   // past the end
      {0.0, 0.0, 1.05, 0.0, 1.0},    // at the start point
      {4.0, 3.0, 1.0, 0.5, 1.0},     // far: value ~ 1e-10, erfc branch
      {-4.5, 1.0, 0.8, 0.2, 1.0},    // far before the start
      {0.2, 0.1, 1e-3, 2e-3, 1.0},   // a very short segment
      {0.5, -0.3, 0.95, 0.1, 0.5},   // narrower kernel
      {1.5, 2.5, -0.9, 0.4, 2.0},    // wider kernel
      {0.4, 0.05, 0.0, 0.0, 1.0},    // zero-length segment: W itself
  };
  for (const Case& c : cases) {
    const double exact = segmentGaussianWeight(c.qx, c.qy, c.bx, c.by, c.w);
    const double numeric = quadratureWeight(c.qx, c.qy, c.bx, c.by, c.w);
    EXPECT_NEAR(exact, numeric, 1e-10 * numeric)
        << "q = (" << c.qx << ", " << c.qy << "), b = (" << c.bx << ", " << c.by << "), w = " << c.w;
  }
}

// A world with no gravity and a base far below, for contact tests.
WorldDef quietBox(double width) {
  WorldDef def;
  def.boxWidth = width;
  def.gravity = 0.0;
  return def;
}

FieldsDef fineGrid(double radius, double spacing = 0.1) {
  FieldsDef def;
  def.phases = {0.0};
  def.radius = radius;
  def.spacing = spacing;
  def.width = 1.0;
  return def;
}

struct Integrated {
  double sxx = 0, sxy = 0, syx = 0, syy = 0, phi = 0;
};

// Sum over the grid times the cell area: the integral over the plane (spectrally accurate for a
// Gaussian of width 1 sampled every 0.1; the 3w cut adds a lattice error of order 1e-6).
Integrated integrate(const FieldObserver& obs, double spacing) {
  Integrated out;
  const double cell = spacing * spacing;
  for (std::size_t iy = 0; iy < obs.pointsPerSide(); ++iy)
    for (std::size_t ix = 0; ix < obs.pointsPerSide(); ++ix) {
      const FieldSample f = obs.sample(0, ix, iy);
      out.sxx += f.sxx * cell;
      out.sxy += f.sxy * cell;
      out.syx += f.syx * cell;
      out.syy += f.syy * cell;
      out.phi += f.phi * cell;
    }
  return out;
}

// The integral of a contact's stress over the plane is f (x) b times (1 - loss), where the loss from
// the 3w cut is between 0 and exp(-9) (every point of the segment keeps at least its 3w disc).
void expectIntegralIsForceTimesBranch(const Integrated& got, double fx, double fy, double bx, double by) {
  const double scale = std::hypot(fx, fy) * std::hypot(bx, by);
  const double expect[4] = {fx * bx, fx * by, fy * bx, fy * by};
  const double have[4] = {got.sxx, got.sxy, got.syx, got.syy};
  for (int c = 0; c < 4; ++c) {
    // have = expect (1 - loss), 0 <= loss <= exp(-9), plus 1e-5 of the scale for lattice effects.
    const double lo = std::min(expect[c], expect[c] * (1 - kCutLoss)) - 1e-5 * scale;
    const double hi = std::max(expect[c], expect[c] * (1 - kCutLoss)) + 1e-5 * scale;
    EXPECT_GE(have[c], lo) << "component " << c;
    EXPECT_LE(have[c], hi) << "component " << c;
    std::printf("  component %d: integral %.9g, F(x)b %.9g, relative deficit %.3g\n", c, have[c], expect[c],
                expect[c] != 0 ? 1 - have[c] / expect[c] : 0.0);
  }
}

TEST(FieldObserver, SingleContactStressIntegratesToForceTimesBranch) {
  // Two grains pressed together with a sliding velocity: the force has a tangential part, so
  // f (x) b is not symmetric and all four components are checked.
  World w(quietBox(20.0));
  w.addGrain(10.0, 10.0, 0.5, 0.2, 0.0);
  w.addGrain(10.9, 10.3, 0.45, -0.2, 0.1);
  w.step();
  const auto& list = w.neighbours();
  const auto& s = w.particles();
  ASSERT_EQ(list.pairCount(), 1u);
  const double fx = list.forceX[0], fy = list.forceY[0];
  const std::uint32_t i = list.owner[0], j = list.partner[0];
  const double bx = s.x[j] - s.x[i], by = s.y[j] - s.y[i];
  ASSERT_GT(std::hypot(fx, fy), 1.0);
  ASSERT_GT(std::fabs(fx * by - fy * bx), 1e-3 * std::hypot(fx, fy) * std::hypot(bx, by));  // tangential part

  FieldObserver obs(fineGrid(6.0), 20.0);
  obs.addFrameAt(w, 0, 10.45, 10.15);
  const Integrated got = integrate(obs, 0.1);
  expectIntegralIsForceTimesBranch(got, fx, fy, bx, by);
  EXPECT_GT(-(got.sxx + got.syy) / 2, 0.0);  // repulsion: positive pressure
  // Area fraction: each grain's full area less exactly the cut's share exp(-9).
  const double areas = kPi * (0.5 * 0.5 + 0.45 * 0.45);
  EXPECT_NEAR(got.phi, areas * (1 - kCutLoss), 1e-5 * areas);
}

TEST(FieldObserver, ContactAcrossThePeriodicEdgeUsesTheMinimumImage) {
  World w(quietBox(20.0));
  w.addGrain(0.2, 10.0, 0.5);
  w.addGrain(19.21, 10.1, 0.5);  // 0.995 away through the edge
  w.step();
  const auto& list = w.neighbours();
  const auto& s = w.particles();
  ASSERT_EQ(list.pairCount(), 1u);
  const std::uint32_t i = list.owner[0], j = list.partner[0];
  double bx = s.x[j] - s.x[i];
  bx -= 20.0 * std::round(bx / 20.0);
  const double by = s.y[j] - s.y[i];
  ASSERT_NEAR(std::fabs(bx), 0.99, 1e-3);
  FieldObserver obs(fineGrid(6.0), 20.0);
  obs.addFrameAt(w, 0, 19.8, 10.0);  // centre near the edge: the grid straddles it
  expectIntegralIsForceTimesBranch(integrate(obs, 0.1), list.forceX[0], list.forceY[0], bx, by);
}

TEST(FieldObserver, IntruderContactsCarryStressAndCentreTheGrid) {
  // A one-atom intruder held in place, a grain pressed on it: the contact counts, with its branch
  // from the grain centre to the atom centre; the grid is centred on the intruder.
  World w(quietBox(20.0));
  ClumpDef clump{{0.0}, {0.0}, 0.25, 5.0};
  w.setIntruder(clump, 10.0, 10.0);
  w.addGrain(10.3, 10.6, 0.45);  // distance 0.671 < 0.7
  w.step();
  const auto& ip = w.intruderPairs();
  ASSERT_EQ(ip.size(), 1u);
  const double fx = ip.forceX[0], fy = ip.forceY[0];
  ASSERT_GT(std::hypot(fx, fy), 0.1);
  const auto& s = w.particles();
  const double bx = w.intruder().x - s.x[0], by = w.intruder().y - s.y[0];
  FieldObserver obs(fineGrid(6.0), 20.0);
  obs.addFrame(w, 0);
  const Integrated got = integrate(obs, 0.1);
  expectIntegralIsForceTimesBranch(got, fx, fy, bx, by);
  EXPECT_GT(-(got.sxx + got.syy) / 2, 0.0);
  // The grain sits at (+0.3, +0.6) from the intruder: the area-fraction peak is the grid point there.
  std::size_t best = 0;
  double bestPhi = -1;
  for (std::size_t k = 0; k < obs.pointsPerSide() * obs.pointsPerSide(); ++k) {
    const double phi = obs.sample(0, k % obs.pointsPerSide(), k / obs.pointsPerSide()).phi;
    if (phi > bestPhi) bestPhi = phi, best = k;
  }
  EXPECT_NEAR(obs.gridCoordinate(best % obs.pointsPerSide()), 0.3, 1e-9);
  EXPECT_NEAR(obs.gridCoordinate(best / obs.pointsPerSide()), 0.6, 1e-9);
  // Phi excludes the intruder: at the intruder centre only the grain's Gaussian tail remains.
  const std::size_t mid = obs.pointsPerSide() / 2;
  const double r2 = std::pow(s.x[0] - w.intruder().x, 2) + std::pow(s.y[0] - w.intruder().y, 2);
  EXPECT_NEAR(obs.sample(0, mid, mid).phi, 0.45 * 0.45 * std::exp(-r2), 1e-14);

  World none(quietBox(20.0));
  none.addGrain(5.0, 5.0, 0.5);
  EXPECT_THROW(obs.addFrame(none, 0), Error);
  EXPECT_THROW(obs.addFrameAt(w, 1, 0.0, 0.0), Error);
}

// ---------------------------------------------------------------- a settled pile

// 30 columns x 30 rows of grains on a jittered lattice (as tests/physics/WorldTest.cpp's makePile),
// dropped on the base and run until the kinetic energy per grain is below 1e-9 m g d.
// dt = 5e-4 is well inside the Hertz limit (about 1.5e-3 for these grains). One thread: on a
// shared machine that is the fastest (about 5 s of CPU).
const World& settledPile() {
  static const World pile = [] {
    const int savedThreads = omp_get_max_threads();
    omp_set_num_threads(1);
    const int columns = 30, rows = 30;
    const std::uint64_t seed = 5;
    WorldDef def;
    def.boxWidth = 1.2 * columns;
    def.dt = 5e-4;
    World w(def);
    for (int i = 0; i < static_cast<int>(def.boxWidth); ++i) w.addFrozen(i + 0.5, 0.0, 0.5);
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < columns; ++c) {
        const auto n = static_cast<std::uint64_t>(r * columns + c);
        const double d = 0.9 + 0.2 * uniform01(seed, RngStream::GrainDiameter, n);
        const double x = (c + 0.5) * 1.2 + 0.05 * (uniform01(seed, RngStream::PourPosition, n) - 0.5);
        w.addGrain(x, 1.2 + 1.2 * r, 0.5 * d, 0.2 * (uniform01(seed, RngStream::PourVelocity, n) - 0.5));
      }
    for (int block = 0; block < 400; ++block) {
      w.run(500);
      if (w.kineticEnergy() / w.grainCount() < 1e-9) break;
    }
    omp_set_num_threads(savedThreads);
    return w;
  }();
  return pile;
}

constexpr double kPileWidth = 36.0;

// Observer whose grid spans exactly one period in x: radius W/2, spacing 0.5, so the 72 columns
// ix = 0..71 sample the period uniformly (ix = 72 repeats ix = 0), and y from 0 to 36.
struct PileFields {
  FieldObserver obs;
  double centreY = 18.0;
  // One frame of `w`, or `frames` frames of a copy of it taken every `stepsBetween` steps.
  explicit PileFields(const World& w, bool kinetic = false, int frames = 1, int stepsBetween = 0)
      : obs(makeDef(kinetic), kPileWidth) {
    const auto t0 = std::chrono::steady_clock::now();
    obs.addFrameAt(w, 0, kPileWidth / 2, centreY);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    std::printf("  one frame on %u grains, %zu x %zu grid: %.1f ms\n", w.grainCount(), obs.pointsPerSide(),
                obs.pointsPerSide(), ms);
    if (frames > 1) {
      const int saved = omp_get_max_threads();
      omp_set_num_threads(1);
      World copy = w;
      for (int k = 1; k < frames; ++k) {
        copy.run(static_cast<std::uint64_t>(stepsBetween));
        obs.addFrameAt(copy, 0, kPileWidth / 2, centreY);
      }
      omp_set_num_threads(saved);
    }
  }
  static FieldsDef makeDef(bool kinetic) {
    FieldsDef def;
    def.phases = {0.0};
    def.radius = kPileWidth / 2;
    def.spacing = 0.5;
    def.kinetic = kinetic;
    return def;
  }
  // Lateral mean over one period of a row.
  FieldSample rowMean(std::size_t iy) const {
    FieldSample m;
    const std::size_t columns = obs.pointsPerSide() - 1;
    for (std::size_t ix = 0; ix < columns; ++ix) {
      const FieldSample f = obs.sample(0, ix, iy);
      m.phi += f.phi / columns;
      m.sxx += f.sxx / columns;
      m.sxy += f.sxy / columns;
      m.syx += f.syx / columns;
      m.syy += f.syy / columns;
    }
    m.pressure = -0.5 * (m.sxx + m.syy);
    return m;
  }
  double rowY(std::size_t iy) const { return centreY + obs.gridCoordinate(iy); }
};

double surfaceHeight(const World& w) {
  // Mean over the box of the highest grain top in each unit-wide column.
  const auto& s = w.particles();
  std::vector<double> top(static_cast<std::size_t>(kPileWidth), 0.0);
  for (std::uint32_t i = 0; i < s.grainCount; ++i) {
    auto c = static_cast<std::size_t>(std::fmod(s.x[i] + kPileWidth, kPileWidth));
    c = std::min(c, top.size() - 1);
    top[c] = std::max(top[c], s.y[i] + s.radius[i]);
  }
  double sum = 0;
  for (double t : top) sum += t;
  return sum / static_cast<double>(top.size());
}

TEST(FieldObserver, SettledPileVerticalStressIsTheWeightAbove) {
  const World& w = settledPile();
  ASSERT_LT(w.kineticEnergy() / w.grainCount(), 1e-9) << "the pile did not settle";
  const auto& s = w.particles();
  const double g = w.def().gravity;
  const double surface = surfaceHeight(w);
  // 40 frames 100 steps apart (t = 2 in all): a single frame of a bed that is
  // "at rest" (kinetic energy 1e-9 per grain) still carries the inertia of its slowly decaying
  // vertical breathing mode, which shows as a 0.5-1% excess of the contact forces over the weight
  // (measured directly on the contact forces crossing a horizontal line). Over a window the mean
  // of sum m a is the change of momentum over the window's length, ~1e-5 of the weight.
  PileFields f(w, false, 40, 100);

  // (1) Exact reference. Averaged over a period in x, the static momentum balance of the
  // coarse-grained fields reads d(sigma_yy)/dy = g rho(y), rho the coarse-grained mass density,
  // so -sigma_yy(y) = (g / W) sum_i m_i (1/2) erfc((y - y_i) / w): the weight of the grains above y
  // with each grain's mass smeared by the kernel's marginal. Valid above the frozen base's reach
  // (its contact forces are external), i.e. y > 0.5 + 3w; the residual error is the 3w cut (~1e-4)
  // and the grains' residual accelerations.
  double worstRel = 0, sumRatio = 0;
  int rowsChecked = 0;
  for (std::size_t iy = 0; iy < f.obs.pointsPerSide(); ++iy) {
    const double y = f.rowY(iy);
    if (y < 4.0 || y > surface - 2.0) continue;
    double weightAbove = 0, sharpAbove = 0;
    for (std::uint32_t i = 0; i < s.grainCount; ++i) {
      weightAbove += s.mass[i] * g * 0.5 * std::erfc((y - s.y[i]) / 1.0);
      if (s.y[i] > y) sharpAbove += s.mass[i] * g;
    }
    weightAbove /= kPileWidth;
    sharpAbove /= kPileWidth;
    const FieldSample m = f.rowMean(iy);
    const double rel = std::fabs(-m.syy - weightAbove) / weightAbove;
    worstRel = std::max(worstRel, rel);
    sumRatio += m.pressure / -m.syy;
    ++rowsChecked;
    EXPECT_NEAR(-m.syy, weightAbove, 1e-3 * weightAbove) << "y = " << y;
    // The sharp weight above differs by the smearing of the grain layer at y: within ~ a third of
    // a layer's weight (rho g d ~ 0.45 per unit width) at any depth.
    EXPECT_NEAR(-m.syy, sharpAbove, 0.15) << "y = " << y;
    if (iy % 8 == 0)
      std::printf("  y %5.1f  -syy %8.4f  smeared weight %8.4f  sharp weight %8.4f  P %8.4f  P/(-syy) %.3f\n", y,
                  -m.syy, weightAbove, sharpAbove, m.pressure, m.pressure / -m.syy);
  }
  ASSERT_GT(rowsChecked, 30);
  std::printf("  surface %.2f; rows %d; worst |(-syy) - smeared weight| / weight = %.2e; mean P/(-syy) = %.3f\n",
              surface, rowsChecked, worstRel, sumRatio / rowsChecked);

  // (2) rho_bulk g z: in the bulk, -sigma_yy grows linearly with depth at the rate rho_bulk g, with
  // rho_bulk the mass of the grains in the band over the band's area.
  const double y1 = 6.0, y2 = surface - 6.0;
  double bandMass = 0;
  for (std::uint32_t i = 0; i < s.grainCount; ++i)
    if (s.y[i] >= y1 && s.y[i] < y2) bandMass += s.mass[i];
  const double rhoBulk = bandMass / (kPileWidth * (y2 - y1));
  double sy = 0, syy = 0, sYY = 0, sYS = 0;
  int count = 0;
  for (std::size_t iy = 0; iy < f.obs.pointsPerSide(); ++iy) {
    const double y = f.rowY(iy);
    if (y < y1 || y > y2) continue;
    const double v = -f.rowMean(iy).syy;
    sy += y, sYY += y * y, syy += v, sYS += y * v;
    ++count;
  }
  const double slope = (count * sYS - sy * syy) / (count * sYY - sy * sy);
  std::printf("  band [%.1f, %.1f]: rho_bulk %.4f, d(-syy)/dy %.4f, -rho_bulk g %.4f, ratio %.4f\n", y1, y2,
              rhoBulk, slope, -rhoBulk * g, slope / (-rhoBulk * g));
  EXPECT_NEAR(slope, -rhoBulk * g, 0.03 * rhoBulk * g);
}

TEST(FieldObserver, SettledPileAreaFractionMatchesDirectCount) {
  const World& w = settledPile();
  const auto& s = w.particles();
  const double surface = surfaceHeight(w);
  PileFields f(w);
  // Direct count: sum of pi r^2 of the grains whose centre lies in a band, over the band's area.
  const double y1 = 4.0, y2 = surface - 4.0;
  double area = 0;
  for (std::uint32_t i = 0; i < s.grainCount; ++i)
    if (s.y[i] >= y1 && s.y[i] < y2) area += kPi * s.radius[i] * s.radius[i];
  const double counted = area / (kPileWidth * (y2 - y1));
  // Field: mean Phi over the grid points in the band (rows at y1 + 0.25, y1 + 0.75, ...: each row
  // stands for the 0.5-tall strip around it). Also the exact lateral mean of each row,
  // (1/W) sum_i a_i exp(-(y - y_i)^2/w^2) / (sqrt(pi) w).
  double phiSum = 0, worst = 0;
  int rows = 0;
  for (std::size_t iy = 0; iy < f.obs.pointsPerSide(); ++iy) {
    const double y = f.rowY(iy);
    const FieldSample m = f.rowMean(iy);
    double exact = 0;
    for (std::uint32_t i = 0; i < s.grainCount; ++i) {
      const double dy = y - s.y[i];
      exact += kPi * s.radius[i] * s.radius[i] * std::exp(-dy * dy) / std::sqrt(kPi);
    }
    exact /= kPileWidth;
    if (exact > 0.05) {
      worst = std::max(worst, std::fabs(m.phi - exact) / exact);
      EXPECT_NEAR(m.phi, exact, 1e-3 * exact) << "y = " << y;
    }
    if (y > y1 && y < y2) phiSum += m.phi, ++rows;
  }
  const double field = phiSum / rows;
  std::printf("  band [%.1f, %.1f]: Phi field %.4f, counted %.4f, ratio %.4f; row means vs exact: worst %.2e\n", y1,
              y2, field, counted, field / counted, worst);
  EXPECT_NEAR(field, counted, 0.02 * counted);
}

TEST(FieldObserver, UniformTranslationGivesThatVelocityAndNoKineticStress) {
  // The settled pile's grains, all moving with the same velocity, one frame (no step: no contacts).
  const World& pile = settledPile();
  const auto& s = pile.particles();
  WorldDef def = pile.def();
  World w(def);
  const double ux = 0.37, uy = -1.21;
  for (std::uint32_t i = 0; i < s.grainCount; ++i)
    w.addGrain(std::fmod(s.x[i] + kPileWidth, kPileWidth), s.y[i], s.radius[i], ux, uy);
  PileFields f(w, /*kinetic=*/true);
  int withGrains = 0;
  for (std::size_t iy = 0; iy < f.obs.pointsPerSide(); ++iy)
    for (std::size_t ix = 0; ix < f.obs.pointsPerSide(); ++ix) {
      const FieldSample v = f.obs.sample(0, ix, iy);
      if (v.phi == 0.0) {
        EXPECT_TRUE(std::isnan(v.vx));
        continue;
      }
      ++withGrains;
      ASSERT_NEAR(v.vx, ux, 1e-13);
      ASSERT_NEAR(v.vy, uy, 1e-13);
      ASSERT_LT(std::fabs(v.sxx) + std::fabs(v.sxy) + std::fabs(v.syy), 1e-24);
    }
  EXPECT_GT(withGrains, 1500);
}

TEST(FieldObserver, BitwiseIdenticalForAnyThreadCount) {
  const World& pile = settledPile();
  auto fieldsWith = [&](int threads) {
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
    FieldsDef def = PileFields::makeDef(true);
    FieldObserver obs(def, kPileWidth);
    obs.addFrameAt(pile, 0, 7.0, 15.0);
    omp_set_num_threads(saved);
    BinaryWriter out;
    obs.save(out);
    return out.bytes();
  };
  const std::string one = fieldsWith(1);
  EXPECT_EQ(fieldsWith(2), one);
  EXPECT_EQ(fieldsWith(3), one);
}

TEST(FieldObserver, KineticStressOfTwoOpposedGrains) {
  // Two equal grains at (+-a, 0) moving at (+-u, 0). At the midpoint v = 0 by symmetry and the
  // kinetic stress is -2 m u^2 W(a) in xx, 0 elsewhere; W(a) = exp(-a^2/w^2) / (pi w^2).
  World w(quietBox(20.0));
  const double a = 0.6, u = 0.8;
  w.addGrain(10.0 - a, 10.0, 0.3, u, 0.0);
  w.addGrain(10.0 + a, 10.0, 0.3, -u, 0.0);
  FieldsDef def = fineGrid(2.0, 0.5);
  def.kinetic = true;
  FieldObserver obs(def, 20.0);
  obs.addFrameAt(w, 0, 10.0, 10.0);
  const std::size_t mid = obs.pointsPerSide() / 2;
  const FieldSample f = obs.sample(0, mid, mid);
  const double m = w.particles().mass[0];
  EXPECT_NEAR(f.vx, 0.0, 1e-15);
  EXPECT_NEAR(f.sxx, -2 * m * u * u * std::exp(-a * a) / kPi, 1e-14);
  EXPECT_NEAR(f.syy, 0.0, 1e-15);
  EXPECT_NEAR(f.sxy, 0.0, 1e-15);
  // Galilean invariance: adding (0.5, -0.3) to both shifts v and leaves the kinetic stress.
  World moved(quietBox(20.0));
  moved.addGrain(10.0 - a, 10.0, 0.3, u + 0.5, -0.3);
  moved.addGrain(10.0 + a, 10.0, 0.3, -u + 0.5, -0.3);
  FieldObserver obs2(def, 20.0);
  obs2.addFrameAt(moved, 0, 10.0, 10.0);
  for (std::size_t iy = 0; iy < obs.pointsPerSide(); ++iy)
    for (std::size_t ix = 0; ix < obs.pointsPerSide(); ++ix) {
      const FieldSample p = obs.sample(0, ix, iy), q = obs2.sample(0, ix, iy);
      if (p.phi == 0) continue;
      EXPECT_NEAR(q.vx - p.vx, 0.5, 1e-12);
      EXPECT_NEAR(q.vy - p.vy, -0.3, 1e-12);
      EXPECT_NEAR(q.sxx, p.sxx, 1e-12);
      EXPECT_NEAR(q.sxy, p.sxy, 1e-12);
      EXPECT_NEAR(q.syy, p.syy, 1e-12);
    }
}

// ---------------------------------------------------------------- output and persistence

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(FieldObserver, CsvHasOneRowPerPointPerPhaseAndEmptyPhasesAreBlank) {
  World w(quietBox(20.0));
  ClumpDef clump{{0.0}, {0.0}, 0.25, 5.0};
  w.setIntruder(clump, 10.0, 10.0);
  w.addGrain(11.0, 10.5, 0.45);
  FieldsDef def = fineGrid(1.0, 0.5);  // 5 x 5 points
  def.phases = {0.0, 5.0, 19.0};
  FieldObserver obs(def, 20.0);
  obs.addFrame(w, 1);
  obs.addFrame(w, 1);
  EXPECT_EQ(obs.frames(0), 0u);
  EXPECT_EQ(obs.frames(1), 2u);
  const auto dir = std::filesystem::temp_directory_path() / ("wiggle-fields-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "fields.csv").string();
  obs.writeCsv(path);
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  std::istringstream in(readFile(path));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "phase,x,y,phi,vx,vy,sxx,sxy,syy,pressure,frames");
  int rows = 0;
  while (std::getline(in, line)) {
    ++rows;
    if (rows == 1) {
      EXPECT_EQ(line, "0,-1,-1,,,,,,,,0");
    }
    if (rows == 26) {
      // Phase 5, point (-1, -1): the grain at (+1, +0.5) is 2.06 away, within 3w.
      EXPECT_EQ(line.rfind("5,-1,-1,", 0), 0u) << line;
      EXPECT_EQ(line.substr(line.size() - 2), ",2") << line;
      const double phi = std::stod(line.substr(8));
      EXPECT_NEAR(phi, 0.45 * 0.45 * std::exp(-(4.0 + 2.25)), 1e-12);
    }
  }
  EXPECT_EQ(rows, 3 * 25);
  std::filesystem::remove_all(dir);
  EXPECT_THROW(obs.writeCsv("/nonexistent-dir/fields.csv"), Error);
}

TEST(FieldObserver, SaveAndLoadContinueBitForBit) {
  World w(quietBox(20.0));
  ClumpDef clump{{0.0}, {0.0}, 0.25, 5.0};
  w.setIntruder(clump, 10.0, 10.0);
  w.addGrain(10.3, 10.6, 0.45, 0.1, 0.2);
  w.addGrain(11.0, 10.0, 0.5, -0.3, 0.0);
  w.step();
  FieldsDef def = fineGrid(3.0, 0.5);
  def.phases = {0.0, 10.0};
  def.kinetic = true;
  FieldObserver a(def, 20.0);
  a.addFrame(w, 0);
  a.addFrame(w, 1);
  BinaryWriter out;
  a.save(out);
  FieldObserver b(def, 20.0);
  BinaryReader in(out.bytes().data(), out.bytes().size(), "test checkpoint");
  b.load(in);
  EXPECT_TRUE(in.atEnd());
  w.run(10);
  a.addFrame(w, 0);
  b.addFrame(w, 0);
  BinaryWriter sa, sb;
  a.save(sa);
  b.save(sb);
  EXPECT_EQ(sa.bytes(), sb.bytes());

  FieldsDef other = def;
  other.spacing = 0.25;
  FieldObserver c(other, 20.0);
  BinaryReader in2(out.bytes().data(), out.bytes().size(), "test checkpoint");
  EXPECT_THROW(c.load(in2), Error);
  BinaryReader cut(out.bytes().data(), out.bytes().size() / 2, "test checkpoint");
  FieldObserver d(def, 20.0);
  EXPECT_THROW(d.load(cut), Error);
}

TEST(FieldObserver, RejectsBadDefinitions) {
  FieldsDef def;
  def.width = 0;
  EXPECT_THROW(FieldObserver(def, 60.0), Error);
  def = FieldsDef{};
  def.spacing = -1;
  EXPECT_THROW(FieldObserver(def, 60.0), Error);
  def = FieldsDef{};
  def.spacing = 1e-4;
  EXPECT_THROW(FieldObserver(def, 60.0), Error);
  EXPECT_THROW(FieldObserver(FieldsDef{}, 0.0), Error);
  FieldObserver ok(FieldsDef{}, 60.0);
  EXPECT_EQ(ok.pointsPerSide(), 61u);
  EXPECT_DOUBLE_EQ(ok.gridCoordinate(0), -15.0);
  EXPECT_DOUBLE_EQ(ok.gridCoordinate(60), 15.0);
}

}  // namespace
}  // namespace wiggle
