#include "scenario/LammpsExport.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <numbers>

#include "core/Console.h"
#include "core/Error.h"
#include "core/Format.h"
#include "core/StopSignal.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "scenario/BedMaker.h"
#include "scenario/Case.h"
#include "scenario/Shape.h"

namespace wiggle {

namespace {

// Shortest text that reads back as the same double is not needed here: %.17g always round-trips,
// and LAMMPS reads numbers with strtod/atof, so every value reaches LAMMPS bit for bit.
std::string num(double v) { return formatNumber(v, 17); }

// The same wrap as World::rebuildNeighbours, so that withoutContactHistory and the data file hold
// the very same bits.
double wrapX(double x, double width) {
  while (x < 0.0) x += width;
  while (x >= width) x -= width;
  return x;
}

}  // namespace

namespace {

// data.lammps: the box, every particle (atom_style sphere) and its velocity; the intruder's atoms
// at the clump's position. Returns the atoms' mean offset from the clump's centre (the deck
// recovers the centre from the atoms' mean position with it).
std::array<double, 2> writeLammpsData(const World& world, const RunConfig& config, std::string& d) {
  const WorldDef& def = world.def();
  const ParticleStore& s = world.particles();
  const ClumpDef& clump = world.clump();
  const ClumpState& c = world.intruder();
  const double width = def.boxWidth;
  const std::size_t nAtoms = clump.offsetX.size();
  const std::size_t atoms = s.size() + nAtoms;
  double yLo = -1.0, yHi = 1.0;
  for (std::uint32_t i = 0; i < s.size(); ++i) {
    yLo = std::min(yLo, s.y[i] - s.radius[i] - 0.5);
    yHi = std::max(yHi, s.y[i] + s.radius[i]);
  }
  for (std::size_t a = 0; a < nAtoms; ++a) yHi = std::max(yHi, c.y + clump.offsetY[a] + clump.atomRadius);
  yHi += 5.0;  // the upper y boundary is shrink-wrapped (fm), so this is only a minimum

  d.reserve(atoms * 160 + 1024);
  d += "wiggle export-lammps: " + std::string(choiceName(config.intruder.shape)) + ", W = " + num(width) +
       ", bed height " + num(config.box.bedHeight) + ", seed " + std::to_string(config.box.seed) +
       ", t = 0 of the drive\n\n";
  d += std::to_string(atoms) + " atoms\n3 atom types\n\n";
  d += "0 " + num(width) + " xlo xhi\n" + num(yLo) + " " + num(yHi) + " ylo yhi\n-0.5 0.5 zlo zhi\n\n";
  // atom_style sphere: id type diameter density x y z. The ids are wiggle's (tag + 1, the intruder's
  // atoms after the largest, as in wiggle's dumps), so that LAMMPS's dumps name every grain as
  // wiggle's do and a bed read back (readLammpsBed) keeps them. The diameter 2r is exact in binary, so
  // LAMMPS's radius (0.5 diameter) is wiggle's to the bit. With the grain density rho, read_data
  // gives the sphere mass (4/3) pi r^3 rho (to an ulp: LAMMPS groups the factors differently);
  // for discs the deck resets it with `set density/disc`.
  d += "Atoms # sphere\n\n";
  std::string v = "\nVelocities\n\n";
  v.reserve(atoms * 100);
  char line[320];
  std::uint32_t maxTag = 0;
  for (std::uint32_t i = 0; i < s.size(); ++i) {
    const bool grain = i < s.grainCount;
    const std::uint64_t id = std::uint64_t{s.tag[i]} + 1;
    maxTag = std::max(maxTag, s.tag[i]);
    std::snprintf(line, sizeof line, "%llu %d %s %s %s %s 0\n", static_cast<unsigned long long>(id), grain ? 1 : 2,
                  num(2.0 * s.radius[i]).c_str(), num(def.density).c_str(), num(wrapX(s.x[i], width)).c_str(),
                  num(s.y[i]).c_str());
    d += line;
    std::snprintf(line, sizeof line, "%llu %s %s 0 0 0 %s\n", static_cast<unsigned long long>(id),
                  num(grain ? s.vx[i] : 0.0).c_str(), num(grain ? s.vy[i] : 0.0).c_str(),
                  num(grain ? s.omega[i] : 0.0).c_str());
    v += line;
  }
  double meanOffsetX = 0.0, meanOffsetY = 0.0;
  for (std::size_t a = 0; a < nAtoms; ++a) {
    const std::size_t id = std::size_t{maxTag} + 2 + a;
    // Intruder atoms: diameter 2 r_atom; the density is a placeholder, the deck sets the mass M.
    std::snprintf(line, sizeof line, "%zu 3 %s 1 %s %s 0\n", id, num(2.0 * clump.atomRadius).c_str(),
                  num(wrapX(c.x + clump.offsetX[a], width)).c_str(), num(c.y + clump.offsetY[a]).c_str());
    d += line;
    std::snprintf(line, sizeof line, "%zu %s %s 0 0 0 0\n", id, num(c.vx).c_str(), num(c.vy).c_str());
    v += line;
    meanOffsetX += clump.offsetX[a];
    meanOffsetY += clump.offsetY[a];
  }
  meanOffsetX /= static_cast<double>(nAtoms);
  meanOffsetY /= static_cast<double>(nAtoms);
  d += v;
  return {meanOffsetX, meanOffsetY};

}

// in.wiggle: the deck that runs the data file as wiggle runs the case (docs/LAMMPS-EXPORT.md).
std::string lammpsInput(const World& world, const RunConfig& config, const RunSchedule& steps,
                        std::array<double, 2> meanOffset) {
  const WorldDef& def = world.def();
  const ParticleStore& s = world.particles();
  const ClumpDef& clump = world.clump();
  const ClumpMotion& motion = world.intruderMotion();
  const bool ramped = motion.kind == HorizontalMotion::RampedSinusoid;
  const bool velocityForm = motion.kind == HorizontalMotion::VelocitySinusoid;
  const double meanOffsetX = meanOffset[0], meanOffsetY = meanOffset[1];
  std::string in;
  const ContactParams& p = def.contact;
  const bool disc = def.massModel == MassModel::Disc;
  const double omega = motion.omega();  // the value World::placeIntruder uses
  in += "# wiggle export-lammps: " + std::string(choiceName(config.intruder.shape)) +
        " intruder, A = " + num(motion.amplitude) + ", T = " + num(motion.period) + ", mu = " + num(p.mu) + ", " +
        std::to_string(s.grainCount) + " grains (docs/LAMMPS-EXPORT.md)\n";
  in += "# Run: lmp -in in.wiggle    or    mpirun -np 2 lmp -in in.wiggle\n";
  in += "# Run length: -var nsteps N (default run.duration / run.dt). Intruder trajectory: trajectory.csv,\n";
  in += "# columns t,x,y,vx,vy,fy as wiggle's (fy = vertical contact force on the intruder).\n";
  in += "# Contact history is NOT carried over from wiggle's bed: every contact starts with zero shear.\n";
  in += "units lj\ndimension 2\natom_style sphere\n";
  in += "boundary p fm p\n";
  in += "processors * 1 1\n";  // a tall box: split it in x only (docs/PHYSICS.md §14)
  in += "comm_modify vel yes\n";
  in += "read_data " + std::string(kLammpsDataFile) + "\n\n";
  in += "variable nsteps index " + std::to_string(steps.total) + "\n";
  in += "group grains type 1\ngroup base type 2\ngroup intruder type 3\n";
  if (disc) in += "set group grains density/disc " + num(def.density) + "\nset group base density/disc " + num(def.density) + "\n";
  in += "# Every intruder atom carries the clump's total mass M: meff = m M / (m + M) as in wiggle.\n";
  in += "set group intruder mass " + num(clump.mass) + "\n\n";
  in += "pair_style gran/" + std::string(choiceName(p.law)) + "/history " + num(p.kn) + " " + num(p.kt) + " " +
        num(p.gammaN) + " " + num(p.gammaT) + " " + num(p.mu) + " 1\n";
  in += "pair_coeff * *\n";
  in += "neighbor " + num(def.skin) + " bin\n";
  in += "neigh_modify delay 0 every 1 check yes\n";
  in += "neigh_modify exclude type 2 2 exclude type 3 3\n";
  in += "timestep " + num(def.dt) + "\n\n";
  in += ramped ? "# Drive: x(t) = x0 + A s(t) sin(w t), s = min(1, t / t_ramp), vx = A (s w cos(w t) + s' sin(w t)),\n"
                 "# t = step dt from 0 (as wiggle).\n"
        : velocityForm
            ? "# Drive (drive.form = velocity): vx = A sin(w t), x(t) = x0 + (A / w)(1 - cos(w t)), t = step dt\n"
              "# from 0 (as wiggle).\n"
            : "# Drive: x(t) = x0 + A sin(w t), vx = A w cos(w t), t = step dt from 0 (as wiggle).\n";
  in += "variable w equal " + num(omega) + "\n";
  if (ramped) {
    // As World::placeIntruder's ramp: s = t / t_ramp until t_ramp, then 1; ds/dt = 1 / t_ramp, then 0.
    in += "variable ramp equal " + num(motion.rampTime) + "\n";
    in += "variable s equal (step*dt<v_ramp)*(step*dt)/v_ramp+(step*dt>=v_ramp)\n";
    in += "variable ds equal (step*dt<v_ramp)/v_ramp\n";
    in += "variable dx equal " + num(motion.amplitude) + "*v_s*sin(v_w*(step*dt))\n";
    in += "variable vx equal " + num(motion.amplitude) + "*(v_s*v_w*cos(v_w*(step*dt))+v_ds*sin(v_w*(step*dt)))\n";
  } else if (velocityForm) {
    in += "variable dx equal " + num(motion.amplitude) + "/v_w*(1-cos(v_w*(step*dt)))\n";
    in += "variable vx equal " + num(motion.amplitude) + "*sin(v_w*(step*dt))\n";
  } else {
    in += "variable dx equal " + num(motion.amplitude) + "*sin(v_w*(step*dt))\n";
    in += "variable vx equal " + num(motion.amplitude) + "*v_w*cos(v_w*(step*dt))\n";
  }
  in += "# Free y: each atom gets the clump's force F_contact,y - M g (gravity is not applied to the atoms).\n";
  in += "variable Fy equal fcm(intruder,y)-" + num(clump.mass * def.gravity) + "\n\n";
  in += std::string("fix integrate grains nve/sphere") + (disc ? " disc" : "") + "\n";
  in += "fix grav grains gravity " + num(def.gravity) + " vector 0 -1 0\n";
  in += "fix hold base freeze\n";
  in += "fix drive intruder move variable v_dx NULL NULL v_vx NULL NULL\n";
  in += "fix contact intruder store/force\n";  // the contact forces, before setforce replaces them
  in += "fix clumpy intruder setforce NULL v_Fy NULL\n";
  in += "fix flat all enforce2d\n\n";
  in += "# Intruder centre = atoms' mean position minus their mean offset from the centre.\n";
  in += "compute fcontact intruder reduce sum f_contact[2]\n";
  in += "variable t equal step*dt\n";
  in += "variable xc equal xcm(intruder,x)-(" + num(meanOffsetX) + ")\n";
  in += "variable yc equal xcm(intruder,y)-(" + num(meanOffsetY) + ")\n";
  in += "variable vxc equal vcm(intruder,x)\nvariable vyc equal vcm(intruder,y)\n";
  in += "variable fyc equal c_fcontact\n";
  for (const char* name : {"t", "xc", "yc", "vxc", "vyc", "fyc"})
    in += std::string("variable ") + name + "_f format " + name + " %.17g\n";
  in += "fix traj all print " + std::to_string(steps.sampleEvery) +
        " \"${t_f},${xc_f},${yc_f},${vxc_f},${vyc_f},${fyc_f}\" file " + kLammpsTrajectoryFile +
        " screen no title \"t,x,y,vx,vy,fy\"\n";
  if (steps.dumpEvery)
    in += "dump snap all custom " + std::to_string(steps.dumpEvery) +
          " dump.lammpstrj id type x y z radius vx vy\ndump_modify snap sort id\n";
  in += "thermo_style custom step time ke v_yc v_vyc cpu\n";
  in += "thermo_modify norm no lost error\n";
  in += "thermo " + std::to_string(std::max<std::uint64_t>(1, std::min<std::uint64_t>(10000, steps.total / 10))) + "\n";
  in += "run ${nsteps}\n";
  return in;
}

}  // namespace

LammpsDeck makeLammpsDeck(const World& world, const Case& run) {
  if (!world.hasIntruder()) throw Error("export-lammps: the world has no intruder");
  const ClumpMotion& motion = world.intruderMotion();
  if (!motion.sinusoidal() || !motion.verticalFree)
    throw Error("export-lammps: the intruder must be driven sinusoidally with y free");
  if (world.stepCount() != 0) throw Error("export-lammps: the world's clock must be at t = 0");
  LammpsDeck deck;
  deck.grains = world.particles().grainCount;
  deck.atoms = world.particles().size() + world.clump().offsetX.size();
  deck.steps = run.steps.total;
  const std::array<double, 2> meanOffset = writeLammpsData(world, run.config, deck.data);
  deck.input = lammpsInput(world, run.config, run.steps, meanOffset);
  return deck;
}

void writeLammpsDeck(const std::string& dir, const LammpsDeck& deck) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error("cannot create output directory " + dir + ": " + ec.message());
  writeFileAtomically(dir + "/" + kLammpsDataFile, deck.data);
  writeFileAtomically(dir + "/" + kLammpsInputFile, deck.input);
}

World withoutContactHistory(const World& world) {
  const ParticleStore& s = world.particles();
  const double width = world.def().boxWidth;
  World fresh(world.def());
  for (std::uint32_t i = 0; i < s.grainCount; ++i)
    fresh.addGrain(wrapX(s.x[i], width), s.y[i], s.radius[i], s.vx[i], s.vy[i], s.omega[i]);
  for (std::uint32_t i = s.grainCount; i < s.size(); ++i) fresh.addFrozen(wrapX(s.x[i], width), s.y[i], s.radius[i]);
  if (world.hasIntruder()) {
    if (world.intruder().vy != 0.0)
      throw Error("withoutContactHistory: the intruder must be at rest vertically (it is at t = 0 of a run)");
    fresh.setIntruder(world.clump(), world.intruder().x, world.intruder().y);
    fresh.setIntruderMotion(world.intruderMotion());
  }
  return fresh;
}

LammpsExportResult exportLammps(const Case& run, const std::string& dir, bool progressLine) {
  const RunConfig& config = run.config;
  // On a terminal a rewritten status line; otherwise (a log, a benchmark script) a line every 30 s,
  // so that a bed that takes an hour to make shows that it is getting on.
  ProgressLine progress(
      progressLine,
      [&](const std::string& text) {
        if (!progress.onTerminal()) std::fprintf(stderr, "%s\n", text.c_str());
      },
      30.0);
  const StopSignalGuard stopOnSignal;  // SIGINT/SIGTERM while the bed is made: save it, then stop
  CachedBed bed = obtainBed(config, run.clump, [&](const BedStatus& st) {
    if (progressLine) progress.update(bedStatusLine(st, config.box.bedHeight));
  });
  progress.clear();
  if (!bed.note.empty()) std::fprintf(stderr, "wiggle: warning: %s\n", bed.note.c_str());
  // Exactly what runExperiment does before its first step.
  World& world = bed.world;
  startDrive(world, run);
  LammpsExportResult result;
  result.deck = makeLammpsDeck(world, run);
  result.bedPath = bed.path;
  result.bedFromCache = bed.fromCache;
  writeLammpsDeck(dir, result.deck);
  // The case beside its deck, as a run directory holds it: once LAMMPS has written trajectory.csv,
  // `wiggle rate DIR` measures its V_y by wiggle's own rules.
  writeFileAtomically(dir + "/config.toml", toToml(config));
  return result;
}

}  // namespace wiggle

namespace wiggle {

namespace {

// A data file's lines as LAMMPS reads them: words split at blanks, a comment (from '#') kept apart
// (the Atoms section names its style there), blank lines skipped; each with its line number.
struct DataLine {
  std::size_t number = 0;
  std::vector<std::string_view> words;
  std::string_view comment;
};

std::vector<DataLine> dataLines(const std::string& text) {
  std::vector<DataLine> out;
  std::size_t start = 0, number = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + start, end - start);
    start = end + 1;
    if (++number == 1) continue;  // the title line
    DataLine l{number, {}, {}};
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) {
      l.comment = line.substr(hash + 1);
      line = line.substr(0, hash);
    }
    for (std::size_t i = 0; i < line.size();) {
      const std::size_t b = line.find_first_not_of(" \t\r", i);
      if (b == std::string_view::npos) break;
      const std::size_t e = std::min(line.size(), line.find_first_of(" \t\r", b));
      l.words.push_back(line.substr(b, e - b));
      i = e;
    }
    if (!l.words.empty()) out.push_back(l);
  }
  return out;
}

std::string_view trimmed(std::string_view s) {
  const std::size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string_view::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r") + 1 - b);
}

struct DataAtom {
  std::uint64_t id = 0;
  int type = 0;
  double diameter = 0, density = 0, x = 0, y = 0, vx = 0, vy = 0, omega = 0;
};

class DataReader {
 public:
  explicit DataReader(std::string name) : name_(std::move(name)) {}

  [[noreturn]] void fail(const std::string& what) const { throw Error(name_ + ": " + what); }
  [[noreturn]] void fail(const DataLine& l, const std::string& what) const {
    fail("line " + std::to_string(l.number) + ": " + what);
  }

  double number(const DataLine& l, std::size_t word) const {
    const std::string_view w = l.words[word];
    double v = 0;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec != std::errc() || end != w.data() + w.size() || !std::isfinite(v))
      fail(l, "\"" + std::string(w) + "\" is not a finite number");
    return v;
  }
  std::uint64_t count(const DataLine& l, std::size_t word, std::uint64_t max) const {
    const std::string_view w = l.words[word];
    std::uint64_t v = 0;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec != std::errc() || end != w.data() + w.size() || v > max)
      fail(l, "\"" + std::string(w) + "\" is not a whole number from 0 to " + std::to_string(max));
    return v;
  }

 private:
  std::string name_;
};

bool isSection(const DataLine& l) {
  static const char* const kSections[] = {"Atoms", "Velocities", "Masses",    "Pair",      "PairIJ",
                                          "Bonds", "Angles",     "Dihedrals", "Impropers", "Ellipsoids",
                                          "Lines", "Triangles",  "Bodies"};
  for (const char* s : kSections)
    if (l.words[0] == s) return true;
  return false;
}

bool is(const DataLine& l, std::initializer_list<std::string_view> tail) {
  if (l.words.size() != tail.size() + 1) return false;
  std::size_t i = 1;
  for (std::string_view w : tail)
    if (l.words[i++] != w) return false;
  return true;
}

}  // namespace

World readLammpsBed(const std::string& text, const std::string& name, const RunConfig& config, const ClumpDef& clump) {
  const DataReader r(name);
  const std::vector<DataLine> lines = dataLines(text);
  constexpr std::uint64_t kMaxAtoms = std::uint64_t{1} << 31, kMaxId = std::numeric_limits<std::uint32_t>::max();
  // Header: counts and box, up to the first section.
  std::uint64_t atomCount = 0, typeCount = 0;
  bool haveAtoms = false, haveTypes = false, haveX = false;
  double xlo = 0, xhi = 0;
  std::size_t k = 0;
  for (; k < lines.size() && !isSection(lines[k]); ++k) {
    const DataLine& l = lines[k];
    if (is(l, {"atoms"})) {
      atomCount = r.count(l, 0, kMaxAtoms);
      haveAtoms = true;
    } else if (is(l, {"atom", "types"})) {
      typeCount = r.count(l, 0, 1u << 20);
      haveTypes = true;
    } else if (l.words.size() == 4 && l.words[2] == "xlo" && l.words[3] == "xhi") {
      xlo = r.number(l, 0);
      xhi = r.number(l, 1);
      haveX = true;
    } else if (l.words.size() == 4 &&
               ((l.words[2] == "ylo" && l.words[3] == "yhi") || (l.words[2] == "zlo" && l.words[3] == "zhi"))) {
      // y is bounded by the base (LAMMPS's boundary f or fm in y), z is the 2D plane: nothing to map
    } else if (l.words.size() == 6 && l.words[3] == "xy") {
      r.fail(l, "a triclinic box (xy xz yz): wiggle's box is rectangular");
    } else if (l.words.size() >= 2 && l.words[0].find_first_not_of("0123456789") == std::string_view::npos) {
      // Counts of what a bed has none of (bonds, angles, their types, extra ... per atom): only 0.
      if (r.count(l, 0, kMaxAtoms) != 0) r.fail(l, "a bed has atoms only, no " + std::string(l.words[1]));
    } else {
      r.fail(l, "not a LAMMPS data file header line");
    }
  }
  if (!haveAtoms || !haveTypes || !haveX)
    r.fail("not a LAMMPS data file (no \"atoms\", \"atom types\" or \"xlo xhi\" line in its header)");
  const double width = config.box.width;
  if (xhi - xlo != width)
    r.fail("its box is " + formatNumber(xhi - xlo) + " d wide (xlo xhi), box.width = " + formatNumber(width));

  // Sections: Atoms (atom_style sphere), Velocities; coefficient sections are skipped.
  std::vector<DataAtom> atoms;
  std::map<std::uint64_t, std::size_t> index;  // atom id -> atoms[]
  while (k < lines.size()) {
    const DataLine& head = lines[k++];
    std::uint64_t rows = 0;
    if (head.words.size() == 1 && head.words[0] == "Atoms") {
      if (!atoms.empty()) r.fail(head, "a second Atoms section");
      if (const std::string_view style = trimmed(head.comment); !style.empty() && style != "sphere")
        r.fail(head, "atom_style " + std::string(style) +
                         ": wiggle reads atom_style sphere (id type diameter density x y z)");
      rows = atomCount;
    } else if (head.words.size() == 1 && (head.words[0] == "Velocities" || head.words[0] == "Masses")) {
      rows = head.words[0] == "Masses" ? typeCount : atomCount;
    } else if (is(head, {"Coeffs"}) && (head.words[0] == "Pair" || head.words[0] == "PairIJ")) {
      rows = head.words[0] == "Pair" ? typeCount : typeCount * (typeCount + 1) / 2;
    } else if (isSection(head)) {
      r.fail(head, "a " + std::string(head.words[0]) + " section: a bed holds atoms only");
    } else {
      r.fail(head, "\"" + std::string(head.words[0]) +
                       "\" where a section was expected (more lines than its header counts?)");
    }
    bool truncated = k + rows > lines.size();
    for (std::uint64_t i = 0; i < rows && !truncated; ++i) truncated = isSection(lines[k + i]);
    if (truncated)
      r.fail(head, std::string(head.words[0]) + " section holds fewer lines than the header counts (" +
                       std::to_string(rows) + "): truncated?");
    for (std::uint64_t i = 0; i < rows; ++i) {
      const DataLine& l = lines[k++];
      if (head.words[0] == "Atoms") {
        // id type diameter density x y z, and image flags after them when write_data wrote them.
        if (l.words.size() != 7 && l.words.size() != 10)
          r.fail(l, std::to_string(l.words.size()) +
                        " columns: atom_style sphere has 7 (id type diameter density x y z) "
                        "or 10 with image flags");
        DataAtom a;
        a.id = r.count(l, 0, kMaxId);
        a.type = static_cast<int>(r.count(l, 1, typeCount));
        a.diameter = r.number(l, 2);
        a.density = r.number(l, 3);
        a.x = r.number(l, 4);
        a.y = r.number(l, 5);
        if (a.id == 0 || a.type == 0) r.fail(l, "atom ids and types start at 1");
        if (!(a.diameter > 0)) r.fail(l, "atom " + std::to_string(a.id) + " has diameter " + formatNumber(a.diameter));
        if (r.number(l, 6) != 0) r.fail(l, "atom " + std::to_string(a.id) + " is off the z = 0 plane: not a 2D bed");
        if (!index.emplace(a.id, atoms.size()).second) r.fail(l, "atom id " + std::to_string(a.id) + " twice");
        atoms.push_back(a);
      } else if (head.words[0] == "Velocities") {
        if (l.words.size() != 7) r.fail(l, "atom_style sphere's velocities are 7 columns (id vx vy vz wx wy wz)");
        const auto it = index.find(r.count(l, 0, kMaxId));
        if (it == index.end()) r.fail(l, "a velocity for an atom id the Atoms section does not have (or has later)");
        DataAtom& a = atoms[it->second];
        a.vx = r.number(l, 1);
        a.vy = r.number(l, 2);
        a.omega = r.number(l, 6);
      }
    }
  }
  // (Without a Velocities section every atom is at rest, as read_data has it.)
  if (atoms.size() != atomCount) r.fail("no Atoms section");

  // The roles, then the world: grains first (a world keeps them before the base), each group in the
  // file's order.
  const std::map<int, LammpsRole> roles = lammpsTypeRoles(config.bed.lammpsTypes);
  const WorldDef def = worldDefFor(config);
  World world(def);
  std::vector<std::uint32_t> grainIds, baseIds;
  double dropX = 0, dropY = 0, dropped = 0;
  for (LammpsRole pass : {LammpsRole::Grain, LammpsRole::Base}) {
    for (const DataAtom& a : atoms) {
      const auto role = roles.find(a.type);
      if (role == roles.end())
        r.fail("atom " + std::to_string(a.id) + " has type " + std::to_string(a.type) +
               ", which bed.lammps_types = \"" + config.bed.lammpsTypes + "\" gives no role");
      const double x = wrapX(a.x - xlo, width);
      if (role->second == LammpsRole::Drop && pass == LammpsRole::Grain) {
        double dx = x - 0.5 * width;  // near the centre: the nearest image
        dx -= width * std::round(dx / width);
        dropX += dx;
        dropY += a.y;
        dropped += 1;
      }
      if (role->second != pass) continue;
      // read_data gives a sphere of density rho the mass rho (4 pi / 3) r^3; wiggle gives a grain the
      // mass of its grains.mass_model with the config's density, so the file's density must be that
      // density (as export-lammps and fix pour's dens write it).
      if (pass == LammpsRole::Grain && std::fabs(a.density / def.density - 1.0) > 1e-9)
        r.fail("atom " + std::to_string(a.id) + " (a grain) has density " + formatNumber(a.density) +
               ", wiggle's grains " + formatNumber(def.density));
      try {
        if (pass == LammpsRole::Grain) {
          world.addGrain(x, a.y, 0.5 * a.diameter, a.vx, a.vy, a.omega);
          grainIds.push_back(static_cast<std::uint32_t>(a.id - 1));
        } else {
          world.addFrozen(x, a.y, 0.5 * a.diameter);
          baseIds.push_back(static_cast<std::uint32_t>(a.id - 1));
        }
      } catch (const Error& e) {  // the world's own checks (a grain below the base, ...)
        r.fail("atom " + std::to_string(a.id) + ": " + e.what());
      }
    }
  }
  if (grainIds.empty()) r.fail("no grains (bed.lammps_types = \"" + config.bed.lammpsTypes + "\")");
  // The dropped atoms were the intruder the bed was made around: it must be where this config puts
  // its own, or grains would sit inside the new one.
  if (dropped > 0) {
    double offsetX = 0, offsetY = 0;
    for (std::size_t a = 0; a < clump.offsetX.size(); ++a) {
      offsetX += clump.offsetX[a];
      offsetY += clump.offsetY[a];
    }
    const double n = static_cast<double>(clump.offsetX.size());
    const double gapX = dropX / dropped - offsetX / n, gapY = dropY / dropped - (config.intruder.y0 + offsetY / n);
    if (std::hypot(gapX, gapY) > 0.5)
      r.fail("its dropped atoms (the intruder it was made around) are centred at (" +
             formatNumber(0.5 * width + dropX / dropped) + ", " + formatNumber(dropY / dropped) +
             "), this config's intruder at (" + formatNumber(0.5 * width) + ", " + formatNumber(config.intruder.y0) +
             ")");
  }
  grainIds.insert(grainIds.end(), baseIds.begin(), baseIds.end());
  world.adoptParticleIds(grainIds);
  world.setIntruder(clump, 0.5 * width, config.intruder.y0);
  return world;
}

}  // namespace wiggle
