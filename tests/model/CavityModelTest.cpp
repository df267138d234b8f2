// The cavity model against the paper's Table 1, hand-derived geometries, and a direct numerical
// integration of the model's own integral (paper eqs. 3.9-3.12).
#include "model/CavityModel.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "core/Error.h"
#include "model/PaperTable1.h"
#include "scenario/geometry/Clump.h"
#include "scenario/geometry/Shape.h"

namespace wiggle {
namespace {

using Pts = std::vector<std::array<double, 2>>;
constexpr double kPi = std::numbers::pi;

TEST(CavityModel, ReproducesPaperTable1FromGeometry) {
  // The paper's Table 1 (l, T_rise; model/PaperTable1.h), printed truncated to two decimals: one row
  // for each of the paper's shapes.
  ASSERT_EQ(paperTable1().size(), paperShapes().size());
  for (const ShapeName shape : paperShapes()) {
    const PaperTable1Row* e = paperTable1Row(choiceName(shape));
    ASSERT_NE(e, nullptr) << choiceName(shape);
    const CavityGeometry g = cavityGeometry(makeShape(shape).outline);
    EXPECT_FALSE(g.sidesDiffer()) << e->shape;
    EXPECT_NEAR(g.left.l, e->l, 0.01) << e->shape;
    EXPECT_NEAR(g.left.tRise, e->tRise, 0.01) << e->shape;
    // Truncation, not rounding: the computed value is at or above the printed one.
    EXPECT_GE(g.left.tRise, e->tRise) << e->shape;
    EXPECT_LT(g.left.tRise - e->tRise, 0.01) << e->shape;
    EXPECT_LT(e->observedLow, e->observedHigh) << e->shape;
  }
}

TEST(CavityModel, PaperShapesExactValues) {
  const CavityGeometry disk = cavityGeometry(makeShape(ShapeName::Disk).outline);
  EXPECT_DOUBLE_EQ(disk.y0, 3.5);
  EXPECT_DOUBLE_EQ(disk.left.yNoReturn, 0.0);  // the equator
  EXPECT_DOUBLE_EQ(disk.h, 7.0);
  EXPECT_DOUBLE_EQ(disk.left.tRise, std::sqrt(8.0));
  EXPECT_DOUBLE_EQ(disk.tMax, std::sqrt(56.0));

  const double height = 9.5 * std::sqrt(3.0) / 2.0;
  const CavityGeometry tri = cavityGeometry(makeShape(ShapeName::Triangle).outline);
  EXPECT_NEAR(tri.left.l, height, 1e-12);  // apex to base corners
  EXPECT_NEAR(tri.right.l, height, 1e-12);
  EXPECT_NEAR(tri.y0, 2.0 * height / 3.0, 1e-12);  // centroid convention
  EXPECT_NEAR(tri.left.tRise, std::sqrt(2.0 * (height + 0.5)), 1e-12);
}

TEST(CavityModel, RegularHexagonFlatTopVertexAtEachSide) {
  // Circumradius 2: vertices at 0, 60, ..., 300 deg; flat top at sqrt(3), side vertices at y = 0.
  Pts hex;
  for (int k = 0; k < 6; ++k)
    hex.push_back({2.0 * std::cos(k * kPi / 3.0), 2.0 * std::sin(k * kPi / 3.0)});
  hex[0] = {2.0, 0.0};
  hex[3] = {-2.0, 0.0};
  const CavityGeometry g = cavityGeometry(hex);
  EXPECT_NEAR(g.y0, std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(g.left.yNoReturn, 0.0, 1e-12);
  EXPECT_NEAR(g.right.yNoReturn, 0.0, 1e-12);
  EXPECT_NEAR(g.left.l, std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(g.h, 2.0 * std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(g.left.tRise, std::sqrt(2.0 * (std::sqrt(3.0) + 0.5)), 1e-12);
  EXPECT_NEAR(g.tMax, std::sqrt(16.0 * std::sqrt(3.0)), 1e-12);
  EXPECT_FALSE(g.sidesDiffer());
}

TEST(CavityModel, LShapeHasOneValuePerSide) {
  // A "Gamma": a 1-wide stem on the left (x in [0,1], y in [0,3]) and an arm to the right at the
  // top (y in [2,3]). Left extreme: the stem's vertical side, lowest end y = 0. Right extreme: the
  // arm's vertical end x = 3, y in [2,3], lowest end y = 2.
  const Pts gamma = {{0, 0}, {1, 0}, {1, 2}, {3, 2}, {3, 3}, {0, 3}};
  const CavityGeometry g = cavityGeometry(gamma);
  EXPECT_DOUBLE_EQ(g.y0, 3.0);
  EXPECT_DOUBLE_EQ(g.h, 3.0);
  EXPECT_DOUBLE_EQ(g.left.yNoReturn, 0.0);
  EXPECT_DOUBLE_EQ(g.right.yNoReturn, 2.0);
  EXPECT_DOUBLE_EQ(g.left.l, 3.0);
  EXPECT_DOUBLE_EQ(g.right.l, 1.0);
  EXPECT_DOUBLE_EQ(g.right.lPrime, 1.5);
  EXPECT_DOUBLE_EQ(g.right.tRise, std::sqrt(3.0));
  EXPECT_TRUE(g.sidesDiffer());
  // Recentred and reordered (clockwise) through makeShape: the same lengths.
  const Pts clockwise(gamma.rbegin(), gamma.rend());
  const CavityGeometry g2 = cavityGeometry(makeShape(ShapeName::Polygon, clockwise).outline);
  EXPECT_NEAR(g2.left.l, 3.0, 1e-12);
  EXPECT_NEAR(g2.right.l, 1.0, 1e-12);
}

TEST(CavityModel, DiamondUsesItsSideCorners) {
  // The square rotated by 45 deg: a diamond with half-diagonal 6.5 / sqrt(2); the side corners are
  // at the centre's height.
  const double half = 6.5 / std::sqrt(2.0);
  const CavityGeometry g = cavityGeometry(makeShape(ShapeName::Square, {}, 45.0).outline);
  EXPECT_NEAR(g.y0, half, 1e-12);
  EXPECT_NEAR(g.left.yNoReturn, 0.0, 1e-12);
  EXPECT_NEAR(g.right.yNoReturn, 0.0, 1e-12);
  EXPECT_NEAR(g.left.l, half, 1e-12);
  EXPECT_NEAR(g.h, 2.0 * half, 1e-12);
}

TEST(CavityModel, RightTriangleWithVerticalSide) {
  // Flat top from (0,3) to (4,3), vertical left side down to (0,0), hypotenuse back up to (4,3).
  // Left: the vertical side's lower end, y_nr = 0, l = 3. Right: the single corner (4,3), l = 0.
  const CavityGeometry g = cavityGeometry(Pts{{0, 0}, {4, 3}, {0, 3}});
  EXPECT_DOUBLE_EQ(g.left.yNoReturn, 0.0);
  EXPECT_DOUBLE_EQ(g.left.l, 3.0);
  EXPECT_DOUBLE_EQ(g.right.yNoReturn, 3.0);
  EXPECT_DOUBLE_EQ(g.right.l, 0.0);
  EXPECT_DOUBLE_EQ(g.right.tRise, 1.0);  // sqrt(2 * 0.5)
  // Standing on its legs, (0,0), (4,0), (0,3): both extremes at y = 0, so one value.
  const CavityGeometry up = cavityGeometry(Pts{{0, 0}, {4, 0}, {0, 3}});
  EXPECT_DOUBLE_EQ(up.left.l, 3.0);
  EXPECT_DOUBLE_EQ(up.right.l, 3.0);
  EXPECT_FALSE(up.sidesDiffer());
}

TEST(CavityModel, RotatedTriangleSidesDiffer) {
  const CavityGeometry g = cavityGeometry(makeShape(ShapeName::Triangle, {}, 10.0).outline);
  EXPECT_TRUE(g.sidesDiffer());
  // Rotating CCW lowers the left base corner (it becomes the lowest point: l_left = h) and raises
  // the right one.
  EXPECT_NEAR(g.left.l, g.h, 1e-12);
  EXPECT_LT(g.right.l, g.left.l - 1.0);
}

// V_y from the model's integral, evaluated numerically (Simpson): V_y = (2 pi / T^2) Lambda with
// Lambda = integral over t in [sqrt(l'/2g), T/2] of (2 g t^2 - l') sin(2 pi t / T) dt.
double riseRateByQuadrature(double lPrime, double period, double g = 1.0) {
  const double t0 = std::sqrt(lPrime / (2.0 * g)), t1 = 0.5 * period;
  if (t1 <= t0) return 0.0;
  const int n = 20000;
  const double hstep = (t1 - t0) / n;
  auto f = [&](double t) { return (2.0 * g * t * t - lPrime) * std::sin(2.0 * kPi * t / period); };
  double sum = f(t0) + f(t1);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(t0 + i * hstep);
  return 2.0 * kPi / (period * period) * sum * hstep / 3.0;
}

TEST(CavityModel, RiseRateMatchesTheIntegral) {
  for (const ShapeName kind : paperShapes()) {
    const std::string_view name = choiceName(kind);
    const CavityGeometry g = cavityGeometry(makeShape(kind).outline);
    for (double t = g.left.tRise + 0.05; t < g.tMax; t += 0.37)
      EXPECT_NEAR(cavityRiseRate(g, g.left, t, 5.0), riseRateByQuadrature(g.left.lPrime, t), 1e-9)
          << name << " T=" << t;
  }
}

TEST(CavityModel, RiseRateRegimes) {
  const CavityGeometry g = cavityGeometry(makeShape(ShapeName::Disk).outline);
  const double tRise = std::sqrt(8.0);
  EXPECT_EQ(cavityRiseRate(g, g.left, 1.0, 5.0), 0.0);     // below T_rise: no rise
  EXPECT_EQ(cavityRiseRate(g, g.left, tRise, 5.0), 0.0);   // at T_rise
  EXPECT_NEAR(cavityRiseRate(g, g.left, tRise * (1 + 1e-6), 5.0), 0.0, 1e-9);  // continuous
  EXPECT_GT(cavityRiseRate(g, g.left, 5.0, 5.0), 0.0);
  EXPECT_DOUBLE_EQ(cavityRiseRate(g, g.left, 10.0, 5.0), (7.0 - 3.5) / 10.0);  // T > T_max
  EXPECT_DOUBLE_EQ(cavityRiseRate(g, g.left, g.tMax, 5.0), 3.5 / g.tMax);     // T = T_max
  EXPECT_EQ(cavityRiseRate(g, g.left, 5.0, 0.5), 0.0);  // A <= A_min = d/2
  EXPECT_GT(cavityRiseRate(g, g.left, 5.0, 0.51), 0.0);
  // Hand value at T = 4 from eq. 3.15: x = sqrt(8)/4.
  const double x = tRise / 4.0;
  const double hand = 2.0 * ((1 - 2 / (kPi * kPi)) - x * x - 2 / (kPi * kPi) * std::cos(kPi * x) -
                             2 / kPi * x * std::sin(kPi * x));
  EXPECT_NEAR(cavityRiseRate(g, g.left, 4.0, 5.0), hand, 1e-15);
  EXPECT_NEAR(hand, 0.1238, 1e-4);
}

TEST(CavityModel, RejectsBadInput) {
  EXPECT_THROW(cavityGeometry(Pts{{0, 0}, {1, 1}}), Error);
  EXPECT_THROW(cavityGeometry(Pts{{0, 0}, {1, NAN}, {0, 1}}), Error);
  const CavityGeometry g = cavityGeometry(makeShape(ShapeName::Disk).outline);
  EXPECT_THROW(cavityRiseRate(g, g.left, 0.0, 5.0), Error);
}

#ifdef WIGGLE_BINARY
// The `wiggle model` command's stable surface (docs/PHYSICS.md §13): csv columns, one row per paper shape, the
// :left/:right split, the geometry JSON and a one-line error with a non-zero status.
std::string runWiggle(const std::string& args, int* status = nullptr) {
  std::string out;
  FILE* pipe = popen((std::string(WIGGLE_BINARY) + " " + args + " 2>&1").c_str(), "r");
  if (!pipe) return out;
  char buf[512];
  while (std::fgets(buf, sizeof buf, pipe)) out += buf;
  const int rc = pclose(pipe);
  if (status) *status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;  // the exit code
  return out;
}

TEST(CavityModelCommand, CsvTable1) {
  const std::string out = runWiggle("model --format csv");
  EXPECT_EQ(out.substr(0, out.find('\n')), "shape,l,l_prime,T_rise,h,T_max");
  EXPECT_NE(out.find("\ndisk,3.500000,4.000000,2.828427,7.000000,7.483315\n"), std::string::npos)
      << out;
  EXPECT_NE(out.find("\ntriangle,8.227241,"), std::string::npos) << out;
  int lines = 0;
  for (char c : out) lines += c == '\n';
  EXPECT_EQ(lines, 6);
}

TEST(CavityModelCommand, AsymmetricSidesAndRates) {
  const std::string out = runWiggle("model --vertices \"0,0;1,0;1,2;3,2;3,3;0,3\" --format csv");
  EXPECT_NE(out.find("polygon:left,3.000000,"), std::string::npos) << out;
  EXPECT_NE(out.find("polygon:right,1.000000,"), std::string::npos) << out;
  const std::string rates = runWiggle("model --shape disk --periods 2,10 --format csv");
  EXPECT_EQ(rates, "shape,T,vy\ndisk,2,0.000000\ndisk,10,0.350000\n");
}

TEST(CavityModelCommand, GeometryJsonAndErrors) {
  const auto path =
      std::filesystem::temp_directory_path() / ("wiggle_model_test_geometry-" + std::to_string(::getpid()) + ".json");
  std::filesystem::remove(path);
  int status = -1;
  runWiggle("model --shape triangle --geometry " + path.string(), &status);
  EXPECT_EQ(status, 0);
  std::ifstream in(path);
  const std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const char* key : {"\"shape\"", "\"outline\"", "\"atoms\"", "\"atom_radius\"", "\"y0\"",
                          "\"y_nr_left\"", "\"y_nr_right\"", "\"l_left\"", "\"l_right\"", "\"h\"",
                          "\"T_rise_left\"", "\"T_rise_right\"", "\"T_max\""})
    EXPECT_NE(json.find(key), std::string::npos) << key;
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".tmp"));
  std::filesystem::remove(path);
  const std::string err = runWiggle("model --vertices \"0,0;2,2;2,0;0,2\"", &status);
  EXPECT_NE(status, 0);
  EXPECT_EQ(err, "wiggle: --vertices: the outline is self-intersecting: edge 1-2 meets edge 3-4 "
                 "(vertices numbered from 1)\n");
}

// --surface places the atoms as intruder.surface does for a run: the glued clump's atoms in the JSON
// are the run's clump's (its offsets are relative to the centroid, the JSON's to the outline's frame,
// so the counts and the nearest-neighbour spacing are compared).
TEST(CavityModelCommand, GeometryOfTheGluedSurfaceIsTheRunsClump) {
  const auto path =
      std::filesystem::temp_directory_path() / ("wiggle_model_test_glued-" + std::to_string(::getpid()) + ".json");
  int status = -1;
  runWiggle("model --shape square --surface glued --geometry " + path.string(), &status);
  ASSERT_EQ(status, 0);
  std::ifstream in(path);
  const std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(path);
  IntruderDef def;
  def.shape = ShapeName::Square;
  def.surface = IntruderSurface::Glued;
  const ClumpDef clump = makeClump(def, MassModel::Sphere, 1.0);
  EXPECT_NE(json.find("\"surface\":\"glued\""), std::string::npos) << json.substr(0, 200);
  const std::size_t atoms = clump.offsetX.size();
  IntruderDef smooth = def;
  smooth.surface = IntruderSurface::Smooth;
  ASSERT_NE(atoms, makeClump(smooth, MassModel::Sphere, 1.0).offsetX.size());  // the option matters here
  const auto count = [&](const std::string& key) {                             // the length of the array after "key":
    const std::size_t at = json.find("\"" + key + "\":[");
    std::size_t depth = 0, items = 0;
    for (std::size_t i = json.find('[', at); i < json.size(); ++i) {
      if (json[i] == '[' && ++depth == 2) ++items;
      if (json[i] == ']' && --depth == 0) break;
    }
    return items;
  };
  EXPECT_EQ(count("atoms"), atoms);
  const std::string err = runWiggle("model --shape square --surface rough", &status);
  EXPECT_EQ(status, 2);
  EXPECT_NE(err.find("--surface: 'rough' is not one of smooth | glued"), std::string::npos) << err;
}
#endif

}  // namespace
}  // namespace wiggle
