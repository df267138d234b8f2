// Adding a named shape (CONTRIBUTING.md, "Adding an intruder shape"). The names are an enum and its
// table (io/RunConfig.h) and the outlines a switch (makeShape), so a test cannot add a shape without
// adding it to the program. Instead: the paper's five are a list of their own beside every named
// shape; the recipe names every file that lists the shapes; and a regular hexagon, given as the
// outline a sixth named shape would have, goes through everything after the outline (the config's
// checks, the case, the three surfaces' clumps, the mass shares, the cavity model) with nothing
// per shape.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <numbers>
#include <regex>
#include <set>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "io/Config.h"
#include "model/CavityModel.h"
#include "model/PaperTable1.h"
#include "scenario/case/Case.h"
#include "scenario/geometry/Clump.h"
#include "scenario/geometry/Polygon.h"
#include "scenario/geometry/Shape.h"
#include "support/TestSupport.h"

namespace wiggle {
namespace {

namespace fs = std::filesystem;
using testing_support::sourceFile;

TEST(ShapeRecipe, ThePaperShapesAreAListOfTheirOwn) {
  // Every named shape: every value of the table but "polygon", in its order.
  std::vector<ShapeName> everyButPolygon;
  for (std::size_t i = 0; i < ChoiceNames<ShapeName>::names.size(); ++i)
    if (static_cast<ShapeName>(i) != ShapeName::Polygon) everyButPolygon.push_back(static_cast<ShapeName>(i));
  EXPECT_EQ(namedShapes(), everyButPolygon);
  // The paper's five: its Table 1's rows in their order, each a named shape. Not "every named shape",
  // so a sixth leaves the tests held to the paper's rows (CavityModel.ReproducesPaperTable1FromGeometry)
  // and `wiggle model`'s Table 1 as they are.
  ASSERT_EQ(paperShapes().size(), paperTable1().size());
  for (std::size_t i = 0; i < paperShapes().size(); ++i) {
    EXPECT_EQ(choiceName(paperShapes()[i]), paperTable1()[i].shape) << i;
    EXPECT_NE(std::find(namedShapes().begin(), namedShapes().end(), paperShapes()[i]), namedShapes().end()) << i;
  }
}

// CONTRIBUTING.md's section on adding a shape, from its heading to the next; empty when missing.
std::string recipeSection() {
  const std::string text = sourceFile("CONTRIBUTING.md");
  const std::string heading = "## Adding an intruder shape\n";
  const std::size_t begin = text.find(heading);
  if (begin == std::string::npos) return "";
  const std::size_t end = text.find("\n## ", begin + heading.size());
  return text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

// The paths a text names: src/io/RunConfig.h, or a folder with its slash (study/tools/).
std::vector<std::string> namedPaths(const std::string& text) {
  static const std::regex path(
      R"((?:^|[^A-Za-z0-9_./-])((?:src|apps|tests|tools|python|docs|configs|study)/[A-Za-z0-9_./-]*[A-Za-z0-9_/]))");
  std::vector<std::string> paths;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), path); it != std::sregex_iterator(); ++it)
    paths.push_back((*it)[1].str());
  return paths;
}

// "rect_narrow" -> "ShapeName::RectNarrow", the enum's spelling of a name.
std::string enumeratorOf(std::string_view name) {
  std::string id = "ShapeName::";
  bool upper = true;
  for (const char c : name) {
    if (c == '_') {
      upper = true;
      continue;
    }
    id += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
    upper = false;
  }
  return id;
}

// Whether a text lists every one of `names` as code or a document lists a choice: each as a string
// ("disk" or 'disk'), a document's code span (`disk`), or the enum's value (ShapeName::Disk).
bool listsEvery(const std::string& text, const std::vector<std::string>& names) {
  const auto every = [&](auto spelled) {
    return std::all_of(names.begin(), names.end(),
                       [&](const std::string& n) { return text.find(spelled(n)) != std::string::npos; });
  };
  return every([](const std::string& n) { return '"' + n + '"'; }) ||
         every([](const std::string& n) { return '\'' + n + '\''; }) ||
         every([](const std::string& n) { return '`' + n + '`'; }) || every(enumeratorOf);
}

// Every file of the tree's code, tests, tools and documents that lists every one of the paper's
// shapes. Those names, not namedShapes()'s: a list of every named shape holds them, and so does a list
// of the paper's own (its table, its study, its sweeps), which a new shape leaves alone; the recipe
// says which is which. With namedShapes()'s names, a list a new shape should have joined and did not
// would go unseen.
std::set<std::string> filesListingThePaperShapes() {
  std::vector<std::string> names;
  for (const ShapeName shape : paperShapes()) names.emplace_back(choiceName(shape));
  const std::set<std::string> textFiles = {".h",    ".cpp",  ".in",   ".py", ".md",
                                           ".json", ".toml", ".bash", ".sh", ".cmake"};
  constexpr std::uintmax_t kMaxBytes = 2 << 20;  // data files are larger and list no shapes
  const fs::path root(WIGGLE_SOURCE_DIR);
  std::set<std::string> found;
  for (const char* top : {"src", "apps", "tests", "tools", "python", "docs", "configs", "study"}) {
    std::error_code ec;
    // Error codes, not exceptions: other tests may make and remove folders meanwhile.
    for (fs::recursive_directory_iterator it(root / top, fs::directory_options::skip_permission_denied, ec), end;
         !ec && it != end; it.increment(ec)) {
      const fs::path& path = it->path();
      std::error_code kind;
      if (it->is_directory(kind)) {
        const std::string leaf = path.filename().string();
        if (leaf.starts_with('.') || leaf == "__pycache__") it.disable_recursion_pending();
        continue;
      }
      if (!it->is_regular_file(kind) || !textFiles.contains(path.extension().string())) continue;
      if (it->file_size(kind) > kMaxBytes || kind) continue;
      const std::string relative = path.lexically_relative(root).generic_string();
      if (listsEvery(sourceFile(relative), names)) found.insert(relative);
    }
  }
  return found;
}

TEST(ShapeRecipe, ContributingNamesEveryFileThatListsTheShapes) {
  // The check can fail: a list with one name missing is not a list of them all.
  EXPECT_TRUE(listsEvery("{\"a_b\", \"c\"}", {"a_b", "c"}));
  EXPECT_TRUE(listsEvery("ShapeName::ABc, ShapeName::D", {"a_bc", "d"}));
  EXPECT_FALSE(listsEvery("{\"a_b\"} `c`", {"a_b", "c"}));

  const std::string section = recipeSection();
  ASSERT_FALSE(section.empty()) << "CONTRIBUTING.md has no section \"## Adding an intruder shape\"";
  const std::vector<std::string> named = namedPaths(section);
  const fs::path root(WIGGLE_SOURCE_DIR);
  for (const std::string& p : named)
    EXPECT_TRUE(fs::exists(root / p)) << "CONTRIBUTING.md, \"Adding an intruder shape\", names " << p
                                      << ", which is not in the tree";
  const auto inRecipe = [&](const std::string& file) {
    return std::any_of(named.begin(), named.end(),
                       [&](const std::string& p) { return p == file || (p.ends_with('/') && file.starts_with(p)); });
  };
  const std::set<std::string> lists = filesListingThePaperShapes();
  // The one table of names and the outlines are among them, so the search is looking.
  EXPECT_TRUE(lists.contains("src/io/RunConfig.h"));
  EXPECT_TRUE(lists.contains("src/scenario/geometry/Shape.cpp"));
  for (const std::string& file : lists)
    EXPECT_TRUE(inRecipe(file)) << file << " lists every shape of the paper: CONTRIBUTING.md, \"Adding an "
                                << "intruder shape\", must name it, as a file a new shape edits or one it leaves alone";
}

// A regular hexagon of side `side`, flat top and bottom, counter-clockwise, its centroid at the origin:
// the outline a named shape's case in makeShape returns (makeShape neither turns nor moves it).
Outline regularHexagon(double side) {
  Outline out;
  for (int k = 0; k < 6; ++k) {
    const double a = std::numbers::pi / 3.0 * k;
    out.push_back({side * std::cos(a), side * std::sin(a)});
  }
  return out;
}

TEST(ShapeRecipe, AHexagonNeedsNothingBeyondItsOutline) {
  // Side 4: 41.6 d^2, among the paper shapes' 38.5 (disk) to 42.75 (rectangles).
  const double side = 4.0, apothem = side * std::sqrt(3.0) / 2.0;
  const Outline hexagon = regularHexagon(side);
  // What makeShape asks of a named shape's outline: counter-clockwise, centroid at the origin. The
  // polygon path (which orders and centres any outline) then leaves it as it is.
  EXPECT_NEAR(signedArea(hexagon), 1.5 * std::sqrt(3.0) * side * side, 1e-9);
  EXPECT_NEAR(areaCentroid(hexagon)[0], 0.0, 1e-12);
  EXPECT_NEAR(areaCentroid(hexagon)[1], 0.0, 1e-12);
  const Shape shape = makeShape(ShapeName::Polygon, hexagon);
  ASSERT_EQ(shape.outline.size(), hexagon.size());
  for (std::size_t i = 0; i < hexagon.size(); ++i) {
    EXPECT_NEAR(shape.outline[i][0], hexagon[i][0], 1e-12) << i;
    EXPECT_NEAR(shape.outline[i][1], hexagon[i][1], 1e-12) << i;
  }

  // The config's checks and the case (the clump, its fit in the box and the bed) with each surface.
  for (const IntruderSurface surface : {IntruderSurface::Smooth, IntruderSurface::Glued, IntruderSurface::Lattice}) {
    const std::string_view name = choiceName(surface);
    RunConfig config;
    config.intruder.shape = ShapeName::Polygon;
    config.intruder.vertices = hexagon;
    config.intruder.surface = surface;
    EXPECT_NO_THROW(validateRunConfig(config)) << name;
    const Case c = prepareCase(config, BedNeeded::No);
    EXPECT_FALSE(c.clump.offsetX.empty()) << name;
    // Every atom wholly inside the outline, give or take a corner atom's overshoot (none at 120 deg).
    for (std::size_t a = 0; a < c.clump.offsetX.size(); ++a)
      EXPECT_GE(depthInside(c.shape.outline, {c.clump.offsetX[a], c.clump.offsetY[a]}), c.clump.atomRadius - 0.1)
          << name << " atom " << a;
    if (surface != IntruderSurface::Lattice) {  // the shells' own measures, as Shape's tests hold them
      const ClumpOptions options = clumpOptionsFor(config.intruder);
      const ClumpQuality q = measureClump(c.shape, clumpAtomsFor(config.intruder, c.shape), options);
      EXPECT_LE(q.maxOvershoot, 0.1) << name;
      EXPECT_LE(q.maxOutlineGap, surface == IntruderSurface::Smooth ? 0.1 : 0.105) << name;
      EXPECT_LE(q.maxSurfaceSpacing, 2.0 * options.atomRadius + 1e-9) << name;
      EXPECT_LT(q.maxLodgeDepth, 0.05) << name;
    }
    // intruder.contact_mass = "atom": its mass shared by the spheres it is built of.
    IntruderDef atom = config.intruder;
    atom.contactMass = ContactMass::Atom;
    EXPECT_GT(contactMassShares(atom), 100u) << name;
  }

  // The cavity model from the outline: y_nr at the side vertices, at the centre's height (docs/MODEL.md).
  const CavityGeometry g = cavityGeometry(shape.outline);
  EXPECT_FALSE(g.sidesDiffer());
  EXPECT_NEAR(g.y0, apothem, 1e-12);
  EXPECT_NEAR(g.left.yNoReturn, 0.0, 1e-12);
  EXPECT_NEAR(g.left.l, apothem, 1e-12);
  EXPECT_NEAR(g.h, 2.0 * apothem, 1e-12);
  EXPECT_NEAR(g.left.tRise, std::sqrt(2.0 * (apothem + 0.5)), 1e-12);
  EXPECT_GT(cavityRiseRate(g, g.left, 6.0, 5.0), 0.0);  // T_rise = 2.82 < T = 6 < T_max = 7.44
}

}  // namespace
}  // namespace wiggle
