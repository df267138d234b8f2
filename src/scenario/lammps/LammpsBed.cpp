#include "scenario/lammps/LammpsBed.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>

#include "core/Error.h"
#include "core/Format.h"
#include "io/Config.h"
#include "scenario/case/EngineSettings.h"

namespace wiggle {

double wrappedX(double x, double width) {
  while (x < 0.0) x += width;
  while (x >= width) x -= width;
  return x;
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

// A word in double quotes, for messages. Appended, not "\"" + word: in this unit GCC 12 at -O3 takes
// that form for an overlapping copy (a false -Wrestrict, GCC PR 105329), and CI builds with -Werror.
std::string quoted(std::string_view word) {
  std::string q(1, '"');
  q.append(word);
  q.push_back('"');
  return q;
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
      fail(l, quoted(w) + " is not a finite number");
    return v;
  }
  std::uint64_t count(const DataLine& l, std::size_t word, std::uint64_t max) const {
    const std::string_view w = l.words[word];
    std::uint64_t v = 0;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec != std::errc() || end != w.data() + w.size() || v > max)
      fail(l, quoted(w) + " is not a whole number from 0 to " + std::to_string(max));
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
      r.fail(head, quoted(head.words[0]) + " where a section was expected (more lines than its header counts?)");
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
      const double x = wrappedX(a.x - xlo, width);
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
