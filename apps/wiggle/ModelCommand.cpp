// `wiggle model`: the cavity model's geometry (l, l', T_rise, h, T_max) and V_y(T) for the paper's
// shapes or a user polygon, the clump's atom statistics, and a JSON file with the outline and atoms
// for the plotting package (paper figure 13). docs/MODEL.md documents the output.
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "Arguments.h"
#include "Commands.h"
#include "core/Error.h"
#include "io/AtomicFile.h"
#include "model/CavityModel.h"
#include "model/PaperTable1.h"
#include "scenario/geometry/Clump.h"
#include "scenario/geometry/Shape.h"

namespace wiggle::cli {

namespace {

// What `wiggle model` prints: the table for people, or CSV.
enum class ModelFormat { Text, Csv };

}  // namespace
}  // namespace wiggle::cli

namespace wiggle {
template <>
struct ChoiceNames<cli::ModelFormat> {
  static constexpr std::array<std::string_view, 2> names{"text", "csv"};
};
}  // namespace wiggle

namespace wiggle::cli {
namespace {

struct ModelOptions {
  std::string shape;
  std::string vertices;
  double angle = 0.0;           // [degrees]
  ModelFormat format = ModelFormat::Text;
  std::string periods;
  double amplitude = 5.0;       // [d] the paper's Table 1 is for A/d = 5
  std::string geometryPath;
  bool clump = false;
  // How the atoms are placed (intruder.surface): what --geometry and --clump show; the cavity
  // model itself reads only the outline.
  IntruderSurface surface = IntruderSurface::Smooth;
};

// The intruder a row of the table stands for, its atoms placed as --surface says.
IntruderDef intruderOf(ShapeName kind, const Outline& vertices, const ModelOptions& opt) {
  IntruderDef def;
  def.shape = kind;
  def.vertices.assign(vertices.begin(), vertices.end());
  def.angle = opt.angle;
  def.surface = opt.surface;
  return def;
}

Outline parseVertices(const std::string& text) {
  Outline vertices;
  const std::vector<std::string> items = split(text, ';');
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::vector<std::string> xy = split(items[i], ',');
    if (xy.size() != 2)
      throw Error("--vertices: vertex " + std::to_string(i + 1) + " '" + items[i] +
                  "' is not of the form x,y");
    const std::string what = "--vertices: vertex " + std::to_string(i + 1);
    vertices.push_back({parseNumber(xy[0], what), parseNumber(xy[1], what)});
  }
  return vertices;
}

std::vector<double> parsePeriods(const std::string& text) {
  std::vector<double> periods;
  for (const std::string& item : split(text, ',')) {
    const double t = parseNumber(item, "--periods");
    if (!(t > 0.0)) throw Error("--periods: periods must be positive, got '" + item + "'");
    periods.push_back(t);
  }
  if (periods.empty()) throw Error("--periods: empty list");
  return periods;
}

// One reported row: a shape, or one side of an asymmetric shape ("name:left" / "name:right").
struct Row {
  std::string label;
  std::string shapeName;
  bool wholeShape = true;  // false for a :left / :right row
  CavityGeometry geometry;
  CavitySide side;
};

std::vector<Row> rowsFor(const Shape& shape) {
  const CavityGeometry g = cavityGeometry(shape.outline);
  const std::string name(choiceName(shape.kind));
  if (!g.sidesDiffer()) return {Row{name, name, true, g, g.left}};
  return {Row{name + ":left", name, false, g, g.left}, Row{name + ":right", name, false, g, g.right}};
}

std::string formatted(const char* format, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, value);
  return buf;
}

void printGeometryTable(const std::vector<Row>& rows, const ModelOptions& opt) {
  if (opt.format == ModelFormat::Csv) {
    std::printf("shape,l,l_prime,T_rise,h,T_max\n");
    for (const Row& r : rows)
      std::printf("%s,%.6f,%.6f,%.6f,%.6f,%.6f\n", r.label.c_str(), r.side.l, r.side.lPrime,
                  r.side.tRise, r.geometry.h, r.geometry.tMax);
    return;
  }
  // The paper's Table 1 (model/PaperTable1.h) stands beside unrotated paper shapes only: shown, never
  // used to compute. The model is a prediction; what wiggle's own simulations give is in study/VALIDATION.md.
  bool showPaper = false;
  for (const Row& r : rows) showPaper = showPaper || (opt.angle == 0.0 && r.wholeShape && paperTable1Row(r.shapeName));
  std::printf("The cavity model's prediction (paper section 3.5) from each outline, d = 1, g = 1%s\n",
              opt.angle != 0.0 ? (", rotated by " + formatted("%g", opt.angle) + " deg").c_str()
                               : "");
  std::printf("%-18s %8s %8s %8s %8s %8s", "shape", "l", "l'", "T_rise", "h", "T_max");
  if (showPaper) std::printf("   %8s %8s %9s", "paper l", "T_rise", "observed");
  std::printf("\n");
  for (const Row& r : rows) {
    std::printf("%-18s %8.3f %8.3f %8.3f %8.3f %8.3f", r.label.c_str(), r.side.l, r.side.lPrime,
                r.side.tRise, r.geometry.h, r.geometry.tMax);
    const PaperTable1Row* paper = paperTable1Row(r.shapeName);
    if (showPaper && r.wholeShape && paper) {
      // the observed range as the paper prints it: "2.5-3.0"
      const std::string observed = formatted("%.1f", paper->observedLow) + "-" + formatted("%.1f", paper->observedHigh);
      std::printf("   %8.2f %8.2f %9s", paper->l, paper->tRise, observed.c_str());
    }
    std::printf("\n");
  }
  if (showPaper)
    std::printf(
        "(a model, not a simulation. paper l, T_rise: the model's columns of the paper's Table 1, which\n"
        " truncates: T_rise = sqrt(8) = 2.828 is printed 2.82. observed: the T_rising range the paper's\n"
        " simulations found at A = 5. wiggle's simulated ranges: study/VALIDATION.md, \"Table 1\")\n");
  if (std::any_of(rows.begin(), rows.end(), [](const Row& r) { return r.side.l == 0.0; }))
    std::printf("(l = 0: the outline's lowest point with a vertical tangent is its top, as for the triangle apex\n"
                " down: no fall is needed below the top, so T_rise = sqrt(2 l' / g) with l' = d/2 alone, 1.0)\n");
}

void printRateTable(const std::vector<Row>& rows, const std::vector<double>& periods,
                    const ModelOptions& opt) {
  if (opt.format == ModelFormat::Csv) {
    std::printf("shape,T,vy\n");
    for (const Row& r : rows)
      for (double t : periods)
        std::printf("%s,%.6g,%.6f\n", r.label.c_str(), t,
                    cavityRiseRate(r.geometry, r.side, t, opt.amplitude));
    return;
  }
  std::printf("\nV_y(T) [sqrt(g d)] at A = %g (A_min = %g), the model's own (eq. 3.17)\n", opt.amplitude,
              minimumAmplitude());
  std::printf("%8s", "T");
  for (const Row& r : rows) std::printf(" %14s", r.label.c_str());
  std::printf("\n");
  for (double t : periods) {
    std::printf("%8.3g", t);
    for (const Row& r : rows)
      std::printf(" %14.4f", cavityRiseRate(r.geometry, r.side, t, opt.amplitude));
    std::printf("\n");
  }
  std::printf("(the paper uses its model for where rising starts, T_rise; these rates are the model's own\n"
              " magnitude, not a simulated V_y: set them beside a simulation's only on their own axis)\n");
}

void printClumpTable(const std::vector<IntruderDef>& intruders, const std::vector<Shape>& shapes,
                     const ModelOptions& opt) {
  const bool csv = opt.format == ModelFormat::Csv;
  if (csv)
    std::printf("shape,atoms,surface_atoms,guard_atoms,max_overshoot,max_outline_gap,"
                "max_envelope_depth,max_surface_spacing,max_lodge_depth,min_corner_deg\n");
  else
    std::printf("%-12s %6s %8s %6s %9s %9s %9s %8s %8s %8s\n", "shape", "atoms", "surface",
                "guard", "overshoot", "out.gap", "env.depth", "spacing", "lodge", "corner");
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    const Shape& shape = shapes[k];
    const ClumpAtoms atoms = clumpAtomsFor(intruders[k], shape);
    const ClumpQuality q = measureClump(shape, atoms, clumpOptionsFor(intruders[k]));
    std::printf(csv ? "%s,%zu,%zu,%zu,%.4f,%.4f,%.4f,%.4f,%.4f,%.1f\n"
                    : "%-12s %6zu %8zu %6zu %9.4f %9.4f %9.4f %8.4f %8.4f %8.1f\n",
                std::string(choiceName(shape.kind)).c_str(), q.surfaceAtoms + q.guardAtoms, q.surfaceAtoms, q.guardAtoms,
                std::max(0.0, q.maxOvershoot), q.maxOutlineGap, q.maxEnvelopeDepth,
                q.maxSurfaceSpacing, q.maxLodgeDepth, q.minInteriorAngle);
  }
  if (!csv)
    std::printf("(lengths in d: atoms' reach beyond the outline, outline's distance from the "
                "atoms, deepest cusp of the envelope, neighbour spacing, how deep a 0.9 grain "
                "sinks between two surface atoms; sharpest convex corner in degrees)\n");
}

void writeGeometryJson(const IntruderDef& intruder, const Shape& shape, const ModelOptions& opt) {
  const ClumpAtoms atoms = clumpAtomsFor(intruder, shape);
  const CavityGeometry g = cavityGeometry(shape.outline);
  nlohmann::json j = cavityGeometryJson(g);
  j["shape"] = choiceName(shape.kind);
  j["surface"] = choiceName(opt.surface);
  j["outline"] = shape.outline;
  std::vector<OutlinePoint> all = atoms.surface;
  all.insert(all.end(), atoms.guard.begin(), atoms.guard.end());
  j["atoms"] = all;
  j["n_surface_atoms"] = atoms.surface.size();  // atoms[0 .. n) are the shell, the rest guards
  j["atom_radius"] = atoms.atomRadius;
  writeFileAtomically(opt.geometryPath, j.dump() + "\n");
}

void runModel(const ModelOptions& opt) {
  if (!std::isfinite(opt.angle)) throw Error("--angle: not a finite number");
  if (!std::isfinite(opt.amplitude) || opt.amplitude < 0.0)
    throw Error("--amplitude: must be a finite number >= 0");
  // --shape's word, parsed here by the one table of shape names.
  std::optional<ShapeName> chosen;
  if (!opt.shape.empty()) {
    chosen = choiceNamed<ShapeName>(opt.shape);
    if (!chosen)
      throw Error("--shape: unknown shape '" + opt.shape + "' (expected one of " +
                  joinedNames(choiceNameList<ShapeName>()) + ")");
  }
  std::vector<IntruderDef> intruders;
  if (!opt.vertices.empty()) {
    if (chosen && *chosen != ShapeName::Polygon)
      throw Error("--vertices: only with --shape polygon (or no --shape), not '" + opt.shape + "'");
    const Outline vertices = parseVertices(opt.vertices);
    requireValidPolygon(vertices, "--vertices");  // the same check as makeShape, named for the CLI
    intruders.push_back(intruderOf(ShapeName::Polygon, vertices, opt));
  } else if (chosen) {
    if (*chosen == ShapeName::Polygon) throw Error("--shape polygon: needs --vertices \"x1,y1;x2,y2;...\"");
    intruders.push_back(intruderOf(*chosen, {}, opt));
  } else {
    if (!opt.geometryPath.empty())
      throw Error("--geometry: choose one shape with --shape or --vertices");
    for (const ShapeName kind : paperShapes()) intruders.push_back(intruderOf(kind, {}, opt));
  }
  std::vector<Shape> shapes;
  for (const IntruderDef& intruder : intruders) shapes.push_back(makeShape(intruder));
  std::vector<double> periods;
  if (!opt.periods.empty()) periods = parsePeriods(opt.periods);

  std::vector<Row> rows;
  for (const Shape& shape : shapes)
    for (Row& row : rowsFor(shape)) rows.push_back(std::move(row));

  if (opt.clump) {
    printClumpTable(intruders, shapes, opt);
  } else if (opt.format == ModelFormat::Csv && !periods.empty()) {
    printRateTable(rows, periods, opt);  // one csv table per invocation: the rates replace Table 1
  } else {
    printGeometryTable(rows, opt);
    if (!periods.empty()) printRateTable(rows, periods, opt);
  }
  if (!opt.geometryPath.empty()) writeGeometryJson(intruders.front(), shapes.front(), opt);
}

}  // namespace

// An option whose value is one of an enum's words (its ChoiceNames table); `help` holds one %s for
// the list of words. `owner` keeps `target` alive as long as the command.
template <class E>
void addChoiceOption(CLI::App* cmd, const std::string& flag, E* target, std::shared_ptr<ModelOptions> owner,
                     const std::string& help) {
  const std::string words = joinedNames(choiceNameList<E>(), " | ");
  std::string text = help;
  text.replace(text.find("%s"), 2, words);
  cmd->add_option_function<std::string>(
      flag,
      [flag, target, owner, words](const std::string& name) {
        const std::optional<E> value = choiceNamed<E>(name);
        if (!value) throw CLI::ValidationError(flag, "'" + name + "' is not one of " + words);
        *target = *value;
      },
      text);
}

void addModelCommand(CLI::App& app) {
  auto opt = std::make_shared<ModelOptions>();
  auto* cmd = app.add_subcommand(
      "model",
      "The cavity model's prediction (paper section 3.5): l, l', T_rise, h and T_max of a shape from its "
      "outline; with no shape, all five paper shapes beside the paper's Table 1 (its model columns and "
      "the T_rising its simulations observed). A model, not a simulation: wiggle's own T_rising is in "
      "study/VALIDATION.md. Shapes whose two sides give different l (not "
      "mirror-symmetric) get one row per side, named shape:left / shape:right (the cavity on "
      "that side).");
  cmd->add_option("--shape", opt->shape, joinedNames(choiceNameList<ShapeName>(), " | "));
  cmd->add_option("--vertices", opt->vertices,
                  "polygon outline \"x1,y1;x2,y2;...\" [d], either orientation, convex or concave");
  cmd->add_option("--angle", opt->angle, "rotation about the centroid, counter-clockwise [degrees]");
  addChoiceOption(cmd, "--format", &opt->format, opt, "%s (default text)");
  cmd->add_option("--periods", opt->periods,
                  "also print V_y(T) at these periods \"0.5,1,2,...\" [sqrt(d/g)]; with csv, "
                  "only the V_y table (columns shape,T,vy)");
  cmd->add_option("--amplitude", opt->amplitude,
                  "amplitude A for --periods [d] (default 5; V_y = 0 for A <= A_min = 0.5)");
  cmd->add_option("--geometry", opt->geometryPath,
                  "write the chosen shape's outline, atoms and model points to this JSON file");
  addChoiceOption(cmd, "--surface", &opt->surface, opt,
                  "how the atoms are placed, as intruder.surface: %s (default smooth); for --geometry and --clump");
  cmd->add_flag("--clump", opt->clump,
                "print the atom clump's statistics (counts, envelope deviation, lodge depth) "
                "instead of the model table");
  cmd->callback([opt] { runModel(*opt); });
}

}  // namespace wiggle::cli
