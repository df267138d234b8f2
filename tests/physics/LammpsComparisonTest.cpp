// wiggle's engine against LAMMPS itself (docs/PHYSICS.md §4-5): the same small configurations, run in Debian's
// LAMMPS (29 Sep 2021, `pair_style gran/hertz/history`, `fix nve/sphere`, `fix freeze`,
// `fix rigid`), compared step by step. The reference data and the decks that made it are in
// tests/data/lammps/*.json, written by tools/lammps_reference/make_reference.py (see its README);
// CI needs only the stored data.
//
// Compared at every stored step: grain positions, velocities, spins, forces (contacts plus
// gravity) and torques; the clump atoms' positions and velocities and the clump's total contact
// force; and per contact, what LAMMPS's PairGranHertzHistory::single() returns (normal force
// coefficient and the shear force fs1, fs2 on the first atom). single() evaluates the stored
// shear history with the full-step velocities, so it is recomputed here from wiggle's state with
// the same formula (lammpsSingle below, a transcription of single() in 2D): agreement checks
// wiggle's shear history itself, not only its effect on the motion.
//
// Tolerance (why these numbers). wiggle does not add a particle's pair forces in LAMMPS's order,
// divides twice per pair where LAMMPS divides seven times (ContactLaw.h) and writes the kick as
// dt/2 * (1/m), so a force can differ from LAMMPS's by a few ulps at any step, and the dynamics then amplify that difference: stiff Hertz
// contacts and every collision multiply it (by ~1e6 over 8000 steps of the pile). Rather than guess
// the amplification, each case is also run in wiggle a second time with every initial grain
// coordinate, velocity and spin moved by one ulp; the distance between the two wiggle runs (the
// "probe") is what round-off alone does over the compared horizon. A quantity passes if its largest
// deviation from LAMMPS is below kRoundOffFactor (100) times the probe's, plus kFloor (1e-12) of
// its scale (largest |value| LAMMPS reports for it) for stretches where the probe is still exactly
// zero. 100x leaves room for LAMMPS's round-off being a different perturbation than one ulp in the
// initial state. Measured (relative to scale): oblique 6e-16, bounce 1.7e-12, pile 8e-12,
// clump 2.7e-9, each 4x to 1e5x below its bound (printed by each test). Real modelling errors (a
// factor in a damping term, meff of a frozen or rigid partner, no history projection, a wrong cap
// rescaling, disc instead of sphere inertia) exceed the bound by 3e4x to 2e11x
// (tools/lammps_reference/README.md lists what was tried).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "physics/World.h"

namespace wiggle {
namespace {

using nlohmann::json;

constexpr double kRoundOffFactor = 100.0;
constexpr double kFloor = 1e-12;

json loadCase(const std::string& name) {
  const std::string path = std::string(WIGGLE_TEST_DATA) + "/lammps/" + name + ".json";
  std::ifstream in(path);
  if (!in) throw Error("cannot open LAMMPS reference " + path);
  return json::parse(in);
}

struct Built {
  std::map<int, std::uint32_t> tagOfId;   // LAMMPS id -> wiggle tag (grains and base)
  std::map<int, std::uint32_t> atomOfId;  // LAMMPS id -> clump atom index
};

// Builds the World of a case; `velocityUlps` moves every initial grain position, velocity and spin
// component up by that many ulps (the round-off probe described above).
World buildWorld(const json& c, Built& b, int velocityUlps = 0) {
  WorldDef def;
  def.boxWidth = c["box_width"];
  def.dt = c["dt"];
  def.gravity = c["gravity"];
  def.density = c["density"];
  def.massModel = c["mass_model"] == "sphere" ? MassModel::Sphere : MassModel::Disc;
  const json& k = c["contact"];
  def.contact = ContactParams{k["kn"], k["kt"], k["gamma_n"], k["gamma_t"], k["mu"]};
  def.contact.law = choiceNamed<ContactLaw>(k.value("law", "hertz")).value();
  World w(def);
  auto nudge = [velocityUlps](double v) {
    for (int u = 0; u < velocityUlps; ++u) v = std::nextafter(v, 1e300);
    return v;
  };
  ClumpDef clump;
  std::uint32_t tag = 0;
  for (const json& p : c["particles"]) {
    const int id = p["id"];
    const std::string kind = p["kind"];
    if (kind == "grain") {
      w.addGrain(nudge(p["x"]), nudge(p["y"]), p["radius"], nudge(p["vx"]), nudge(p["vy"]),
                 nudge(p["omega"]));
      b.tagOfId[id] = tag++;
    } else if (kind == "frozen") {
      w.addFrozen(p["x"], p["y"], p["radius"]);
      b.tagOfId[id] = tag++;
    } else {
      b.atomOfId[id] = static_cast<std::uint32_t>(clump.offsetX.size());
      clump.offsetX.push_back(double(p["x"]) - double(c["clump"]["center_x"]));
      clump.offsetY.push_back(double(p["y"]) - double(c["clump"]["center_y"]));
    }
  }
  if (!clump.offsetX.empty()) {
    const json& cl = c["clump"];
    clump.atomRadius = cl["atom_radius"];
    clump.mass = cl["mass"];
    clump.massShares = cl.value("mass_shares", 1u);
    w.setIntruder(clump, cl["center_x"], cl["center_y"]);
    ClumpMotion motion;
    motion.kind = HorizontalMotion::ConstantVelocity;
    motion.x0 = cl["center_x"];
    motion.velocity = cl["vx"];
    motion.verticalFree = true;
    w.setIntruderMotion(motion);
  }
  return w;
}

// State of one LAMMPS atom as wiggle has it.
struct AtomState {
  double x, y, vx, vy, omega, radius, mass;
  bool frozen, clump;
};

// `halfStep`: the velocities half a step back (v - dt/2 F/m), which is what LAMMPS holds for a ghost
// atom when a dump is written: ghosts got their velocities in the forward communication after
// the first half kick, and the second half kick updates owned atoms only. compute pair/local runs
// single() with a ghost j for every pair across the periodic boundary (on one process), so for
// those pairs atom 2 must be taken at the half step.
AtomState atomState(const World& w, const Built& b, const std::vector<std::uint32_t>& indexOfTag,
                    int id, bool halfStep = false) {
  const double h = halfStep ? 0.5 * w.def().dt : 0.0;
  if (auto it = b.atomOfId.find(id); it != b.atomOfId.end()) {
    const ClumpState& s = w.intruder();
    const double m = w.clump().mass;
    const double ay = w.intruderMotion().verticalFree ? (s.contactFy - m * w.def().gravity) / m : 0.0;
    return {s.x + w.clump().offsetX[it->second], s.y + w.clump().offsetY[it->second], s.vx,
            s.vy - h * ay, 0.0, w.clump().atomRadius, w.clump().contactMass(), false, true};
  }
  const ParticleStore& p = w.particles();
  const std::uint32_t i = indexOfTag.at(b.tagOfId.at(id));
  return {p.x[i], p.y[i], p.vx[i] - h * p.fx[i] * p.invMass[i], p.vy[i] - h * p.fy[i] * p.invMass[i],
          p.omega[i] - h * p.torque[i] * p.invInertia[i], p.radius[i], p.mass[i],
          i >= p.grainCount, false};
}

// A deck's `pair_style` line: the style and the keywords after its six coefficients.
struct PairStyle {
  std::string style;
  std::vector<std::string> keywords;
  bool operator==(const PairStyle&) const = default;
};
PairStyle pairStyleIn(const std::string& deck) {
  std::istringstream lines(deck);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream in(line);
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    if (words.size() >= 8 && words[0] == "pair_style") return {words[1], {words.begin() + 8, words.end()}};
  }
  throw Error("no pair_style line in the deck");
}

// LAMMPS PairGranHertzHistory::single() and PairGranHookeHistory::single() (29 Sep 2021) in 2D
// (the same but for Hertz's factor polyhertz), as the reference deck's pair style asks: the shear
// force on atom 1 from the stored history (shearX, shearY in atom 1's frame) and the current
// velocities, capped at mu |Fn| without touching the history; with `limit_damping` the normal force
// is first clamped at zero. Returns {ccel r, fs1, fs2}: the normal force (ccel r, as compute
// pair/local's `force` output) and the shear force on atom 1.
struct SingleOut {
  double ccel, fs1, fs2;
};
SingleOut lammpsSingle(const ContactParams& p, const PairStyle& style, double width, const AtomState& a,
                       const AtomState& b, double shearX, double shearY) {
  double delx = a.x - b.x;
  delx -= width * std::round(delx / width);
  const double dely = a.y - b.y;
  const double rsq = delx * delx + dely * dely;
  const double radsum = a.radius + b.radius;
  if (rsq >= radsum * radsum) return {0.0, 0.0, 0.0};
  const double r = std::sqrt(rsq), rinv = 1.0 / r, rsqinv = 1.0 / rsq;
  const double vr1 = a.vx - b.vx, vr2 = a.vy - b.vy;
  const double vnnr = vr1 * delx + vr2 * dely;
  const double vt1 = vr1 - delx * vnnr * rsqinv, vt2 = vr2 - dely * vnnr * rsqinv;
  const double wr3 = (a.radius * a.omega + b.radius * b.omega) * rinv;
  double meff = a.mass * b.mass / (a.mass + b.mass);
  if (a.frozen) meff = b.mass;
  if (b.frozen) meff = a.mass;
  const double damp = meff * p.gammaN * vnnr * rsqinv;
  double ccel = p.kn * (radsum - r) * rinv - damp;
  const double polyhertz =
      style.style == "gran/hertz/history" ? std::sqrt((radsum - r) * a.radius * b.radius / radsum) : 1.0;
  ccel *= polyhertz;
  const auto& k = style.keywords;
  if (std::find(k.begin(), k.end(), "limit_damping") != k.end() && ccel < 0.0) ccel = 0.0;
  const double vtr1 = vt1 + dely * wr3, vtr2 = vt2 - delx * wr3;
  const double shrmag = std::sqrt(shearX * shearX + shearY * shearY);
  double fs1 = -polyhertz * (p.kt * shearX + meff * p.gammaT * vtr1);
  double fs2 = -polyhertz * (p.kt * shearY + meff * p.gammaT * vtr2);
  const double fs = std::sqrt(fs1 * fs1 + fs2 * fs2);
  const double fn = p.mu * std::fabs(ccel * r);
  if (fs > fn) {
    if (shrmag != 0.0) {
      fs1 *= fn / fs;
      fs2 *= fn / fs;
    } else {
      fs1 = fs2 = 0.0;
    }
  }
  return {ccel * r, fs1, fs2};  // compute pair/local reports |r| times single()'s fforce
}

// History of the pair (id1, id2) in id1's frame, from the grain list or the intruder list.
bool pairHistory(const World& w, const Built& b, const std::vector<std::uint32_t>& indexOfTag,
                 int id1, int id2, double& sx, double& sy) {
  const bool clump1 = b.atomOfId.count(id1) != 0, clump2 = b.atomOfId.count(id2) != 0;
  if (clump1 || clump2) {
    const std::uint32_t g = indexOfTag.at(b.tagOfId.at(clump1 ? id2 : id1));
    const std::uint32_t a = b.atomOfId.at(clump1 ? id1 : id2);
    const IntruderPairs& ip = w.intruderPairs();
    for (std::uint32_t k = 0; k < ip.size(); ++k) {
      if (ip.grain[k] == g && ip.atom[k] == a) {
        const double sign = clump1 ? -1.0 : 1.0;  // stored in the grain's frame
        sx = sign * ip.shearX[k];
        sy = sign * ip.shearY[k];
        return true;
      }
    }
    return false;
  }
  const std::uint32_t i = indexOfTag.at(b.tagOfId.at(id1)), j = indexOfTag.at(b.tagOfId.at(id2));
  const NeighbourList& nl = w.neighbours();
  for (std::uint32_t k = 0; k < nl.pairCount(); ++k) {
    const bool same = nl.owner[k] == i && nl.partner[k] == j;
    const bool flipped = nl.owner[k] == j && nl.partner[k] == i;
    if (same || flipped) {
      const double sign = same ? 1.0 : -1.0;  // stored in the owner's frame
      sx = sign * nl.shearX[k];
      sy = sign * nl.shearY[k];
      return true;
    }
  }
  return false;
}

// Largest deviation of one quantity over the run, in units of its scale.
struct Deviation {
  double maxAbs = 0.0;     // max |wiggle - LAMMPS|
  double scale = 0.0;      // max |LAMMPS|
  double probe = 0.0;      // max |wiggle - wiggle with 1-ulp velocities| (round-off growth)
  int worstStep = 0;
  std::string worstWhere;  // LAMMPS atom id(s) of the largest deviation
  double drift = 0.0;       // allowance for a sum LAMMPS accumulates step by step (clump x)
  double relative() const { return maxAbs / std::max(scale, 1e-300); }
  double bound() const { return kRoundOffFactor * probe + kFloor * scale + drift; }
};

struct Comparison {
  std::map<std::string, Deviation> dev;
  int contactsCompared = 0;
  int contactsCapped = 0;   // wiggle pairs whose tangential force sat on the Coulomb cap
  int contactsSticking = 0;
  int lammpsPulling = 0;  // LAMMPS contact rows whose normal force is negative (the damping pulls)
  int lammpsClamped = 0;  // ... and exactly zero (limit_damping clamped it)
  double clumpYTravel = 0.0;
};

void record(Comparison& cmp, const std::string& q, double wiggle, double lammps, double probe,
            int step, const std::string& where) {
  Deviation& d = cmp.dev[q];
  const double e = std::fabs(wiggle - lammps);
  if (e > d.maxAbs) {
    d.maxAbs = e;
    d.worstStep = step;
    d.worstWhere = where;
  }
  d.scale = std::max(d.scale, std::fabs(lammps));
  d.probe = std::max(d.probe, std::fabs(wiggle - probe));
}

std::vector<std::uint32_t> indexByTag(const World& w) {
  const ParticleStore& p = w.particles();
  std::vector<std::uint32_t> index(p.size());
  for (std::uint32_t i = 0; i < p.size(); ++i) index[p.tag[i]] = i;
  return index;
}

Comparison compareCase(const std::string& name) {
  const json c = loadCase(name);
  Built b, bp;
  World w = buildWorld(c, b);
  World probe = buildWorld(c, bp, 1);
  const double width = c["box_width"];
  const ContactParams& params = w.def().contact;
  // The law wiggle runs writes the pair style LAMMPS ran (the export's deck, ContactLaws.h).
  const PairStyle style = pairStyleIn(c["deck"]);
  EXPECT_EQ(pairStyleIn(contactLawTraits(params.law).lammpsPairStyle(params)), style)
      << name << ": wiggle's law " << choiceName(params.law) << " is not the deck's " << style.style;
  Comparison cmp;
  double clumpYMin = 1e300, clumpYMax = -1e300;
  auto wrapped = [width](double d) { return d - width * std::round(d / width); };

  for (const json& frame : c["frames"]) {
    const int step = frame["step"];
    while (w.stepCount() < static_cast<std::uint64_t>(step)) {
      w.step();
      probe.step();
    }
    const auto idx = indexByTag(w), pidx = indexByTag(probe);
    const json& a = frame["atoms"];
    double clumpFx = 0.0, clumpFy = 0.0, clumpMass = 0.0;
    for (std::size_t k = 0; k < a["id"].size(); ++k) {
      const int id = a["id"][k];
      const AtomState s = atomState(w, b, idx, id), ps = atomState(probe, bp, pidx, id);
      const std::string where = "atom " + std::to_string(id);
      const std::string who = s.clump ? "clump " : "grain ";
      // Positions: minimum image in x (LAMMPS and wiggle wrap at different steps).
      const double lx = a["x"][k];
      record(cmp, who + "x", lx + wrapped(s.x - lx), lx, lx + wrapped(ps.x - lx), step, where);
      record(cmp, who + "y", s.y, a["y"][k], ps.y, step, where);
      record(cmp, who + "vx", s.vx, a["vx"][k], ps.vx, step, where);
      record(cmp, who + "vy", s.vy, a["vy"][k], ps.vy, step, where);
      if (s.clump) {
        // LAMMPS's per-atom force includes gravity on the atom's mass.
        const double m = c["particles"][id - 1]["mass"];
        clumpFx += double(a["fx"][k]);
        clumpFy += double(a["fy"][k]) + m * double(c["gravity"]);
        clumpMass += m;
        clumpYMin = std::min(clumpYMin, s.y);
        clumpYMax = std::max(clumpYMax, s.y);
        continue;
      }
      const ParticleStore& p = w.particles();
      const ParticleStore& pp = probe.particles();
      const std::uint32_t i = idx[b.tagOfId.at(id)], pi = pidx[bp.tagOfId.at(id)];
      record(cmp, "grain omega", s.omega, a["omega"][k], ps.omega, step, where);
      record(cmp, "grain fx", p.fx[i], a["fx"][k], pp.fx[pi], step, where);
      record(cmp, "grain fy", p.fy[i], a["fy"][k], pp.fy[pi], step, where);
      record(cmp, "grain torque", p.torque[i], a["torque"][k], pp.torque[pi], step, where);
    }
    if (w.hasIntruder()) {
      const std::string where = "clump";
      record(cmp, "clump contact fx", w.intruder().contactFx, clumpFx, probe.intruder().contactFx,
             step, where);
      record(cmp, "clump contact fy", w.intruder().contactFy, clumpFy, probe.intruder().contactFy,
             step, where);
      EXPECT_NEAR(clumpMass, w.clump().mass, 1e-14 * clumpMass);
    }

    if (!frame.contains("contacts")) continue;
    const json& ct = frame["contacts"];
    std::map<int, double> lammpsX;  // LAMMPS's x of every atom at this step
    for (const json& p : c["particles"]) lammpsX[p["id"]] = p["x"];
    for (std::size_t k = 0; k < a["id"].size(); ++k) lammpsX[a["id"][k]] = a["x"][k];
    // wiggle must hold a history for exactly the pairs LAMMPS reports as touching.
    int touchingInWiggle = 0;
    {
      const ParticleStore& p = w.particles();
      const NeighbourList& nl = w.neighbours();
      for (std::uint32_t k = 0; k < nl.pairCount(); ++k) {
        const std::uint32_t i = nl.owner[k], j = nl.partner[k];
        const double dx = wrapped(p.x[i] - p.x[j]), dy = p.y[i] - p.y[j];
        const double rs = p.radius[i] + p.radius[j];
        if (dx * dx + dy * dy < rs * rs && (i < p.grainCount || j < p.grainCount)) ++touchingInWiggle;
      }
      const IntruderPairs& ip = w.intruderPairs();
      for (std::uint32_t k = 0; k < ip.size(); ++k) {
        const std::uint32_t g = ip.grain[k];
        const double dx = wrapped(p.x[g] - (w.intruder().x + w.clump().offsetX[ip.atom[k]]));
        const double dy = p.y[g] - (w.intruder().y + w.clump().offsetY[ip.atom[k]]);
        const double rs = p.radius[g] + w.clump().atomRadius;
        if (dx * dx + dy * dy < rs * rs) ++touchingInWiggle;
      }
    }
    EXPECT_EQ(touchingInWiggle, static_cast<int>(ct["id1"].size())) << name << " step " << step;
    for (std::size_t k = 0; k < ct["id1"].size(); ++k) {
      const int id1 = ct["id1"][k], id2 = ct["id2"][k];
      double sx = 0, sy = 0, psx = 0, psy = 0;
      const bool found = pairHistory(w, b, idx, id1, id2, sx, sy);
      const bool pfound = pairHistory(probe, bp, pidx, id1, id2, psx, psy);
      EXPECT_TRUE(found) << name << " step " << step << ": no wiggle pair for LAMMPS contact " << id1
                         << "-" << id2;
      if (!found || !pfound) continue;
      // Across the periodic boundary (in LAMMPS's own coordinates), atom 2 is a ghost.
      const bool ghost = std::fabs(lammpsX.at(id1) - lammpsX.at(id2)) > 0.5 * width;
      const AtomState s1 = atomState(w, b, idx, id1), s2 = atomState(w, b, idx, id2, ghost);
      const std::string where = "pair " + std::to_string(id1) + "-" + std::to_string(id2);
      const SingleOut o = lammpsSingle(params, style, width, s1, s2, sx, sy);
      const SingleOut po = lammpsSingle(params, style, width, atomState(probe, bp, pidx, id1),
                                        atomState(probe, bp, pidx, id2, ghost), psx, psy);
      record(cmp, "contact fn", o.ccel, ct["fn"][k], po.ccel, step, where);
      if (double(ct["fn"][k]) < 0.0) ++cmp.lammpsPulling;
      if (double(ct["fn"][k]) == 0.0) ++cmp.lammpsClamped;
      record(cmp, "contact fs1", o.fs1, ct["fs1"][k], po.fs1, step, where);
      record(cmp, "contact fs2", o.fs2, ct["fs2"][k], po.fs2, step, where);
      ++cmp.contactsCompared;
    }
    // Sticking or sliding, from the force wiggle applied in this step (not single()'s
    // re-evaluation): sliding pairs sit on |Ft| = mu |Fn| to round-off.
    const ParticleStore& p = w.particles();
    const NeighbourList& nl = w.neighbours();
    for (std::uint32_t k = 0; k < nl.pairCount(); ++k) {
      const std::uint32_t i = nl.owner[k], j = nl.partner[k];
      const double dx = wrapped(p.x[i] - p.x[j]), dy = p.y[i] - p.y[j];
      const double r = std::hypot(dx, dy);
      if (r >= p.radius[i] + p.radius[j]) continue;
      const double fn = (nl.forceX[k] * dx + nl.forceY[k] * dy) / r;
      const double ft = std::fabs(nl.forceX[k] * dy - nl.forceY[k] * dx) / r;
      if (std::fabs(ft - params.mu * std::fabs(fn)) <= 1e-9 * std::fabs(fn)) ++cmp.contactsCapped;
      else if (ft < params.mu * std::fabs(fn)) ++cmp.contactsSticking;
    }
  }
  if (w.hasIntruder()) {
    cmp.clumpYTravel = clumpYMax - clumpYMin;
    // The clump's x is prescribed in wiggle (x0 + v t) but summed in LAMMPS (xcm += dt vcm each
    // step), so it is exempt from the probe: allow half an ulp of x per step summed.
    Deviation& d = cmp.dev["clump x"];
    d.drift = static_cast<double>(w.stepCount()) * 0.5 * (std::nextafter(d.scale, 1e300) - d.scale);
  }
  return cmp;
}

void checkAndReport(const std::string& name, const Comparison& cmp) {
  std::printf("LAMMPS comparison '%s': %d contact rows compared, %d capped / %d sticking pair-steps\n",
              name.c_str(), cmp.contactsCompared, cmp.contactsCapped, cmp.contactsSticking);
  for (const auto& [q, d] : cmp.dev) {
    std::printf("  %-18s max|dev| %.3e (rel %.2e of scale %.3e, step %d, %s); 1-ulp probe %.3e; bound %.3e\n",
                q.c_str(), d.maxAbs, d.relative(), d.scale, d.worstStep, d.worstWhere.c_str(), d.probe,
                d.bound());
    EXPECT_LE(d.maxAbs, d.bound()) << name << ": " << q << " deviates from LAMMPS by " << d.maxAbs
                                   << " (scale " << d.scale << ", step " << d.worstStep << ")";
  }
}

TEST(LammpsComparison, ObliqueCollisionSticksThenSlides) {
  const Comparison cmp = compareCase("oblique");
  checkAndReport("oblique", cmp);
  EXPECT_GT(cmp.contactsCompared, 50);
  // The case is meant to go through both friction regimes (the Coulomb cap's rescaling, docs/PHYSICS.md §4).
  EXPECT_GE(cmp.contactsSticking, 10);
  EXPECT_GE(cmp.contactsCapped, 3);
}

TEST(LammpsComparison, GrainBouncesAndRestsOnFrozenBase) {
  const Comparison cmp = compareCase("bounce");
  checkAndReport("bounce", cmp);
  EXPECT_GT(cmp.contactsCompared, 50);
}

TEST(LammpsComparison, PolydispersePileSettles) {
  const Comparison cmp = compareCase("pile");
  checkAndReport("pile", cmp);
  EXPECT_GT(cmp.contactsCompared, 50);
}

TEST(LammpsComparison, RigidClumpPushesGrains) {
  const Comparison cmp = compareCase("clump");
  checkAndReport("clump", cmp);
  EXPECT_GT(cmp.contactsCompared, 50);
  EXPECT_GT(cmp.clumpYTravel, 0.05);  // the clump really moves vertically
}

// The other coupling of a glued body (intruder.contact_mass = "atom"): LAMMPS moves the clump with
// fix move (x prescribed, y integrated) and fix aveforce (every atom the group's mean y force), so
// each contact's meff holds the atom's own mass, M / 37, while the clump moves as one body of mass M.
TEST(LammpsComparison, ClumpWithItsAtomsMassInTheContactsPushesGrains) {
  const json c = loadCase("clump_atom_mass");
  ASSERT_EQ(c["clump"]["mass_shares"], 37);
  const Comparison cmp = compareCase("clump_atom_mass");
  checkAndReport("clump_atom_mass", cmp);
  EXPECT_GT(cmp.clumpYTravel, 0.05);
}

// The second law (contact.law = "hooke", LAMMPS's gran/hooke/history) on the pile and the clump.
TEST(LammpsComparison, PolydispersePileSettlesUnderHooke) {
  const Comparison cmp = compareCase("pile_hooke");
  checkAndReport("pile_hooke", cmp);
  EXPECT_GT(cmp.contactsCompared, 50);
}

TEST(LammpsComparison, RigidClumpPushesGrainsUnderHooke) {
  const Comparison cmp = compareCase("clump_hooke");
  checkAndReport("clump_hooke", cmp);
  EXPECT_GT(cmp.contactsCompared, 50);
  EXPECT_GT(cmp.clumpYTravel, 0.05);
}

// The third law (contact.law = "hertz_limit_damping", LAMMPS's gran/hertz/history with
// limit_damping) on the pile and the clump. Their Hertz runs have pulling contacts at stored steps
// (`pile` 6, `clump` 8 rows); under the clamp LAMMPS reports none, and clamped ones instead.
// A case under limit_damping, compared as any other; LAMMPS's contacts there never pull, and some
// sit at exactly zero.
Comparison compareClampedCase(const std::string& name) {
  const Comparison cmp = compareCase(name);
  checkAndReport(name, cmp);
  EXPECT_GT(cmp.contactsCompared, 50);
  EXPECT_EQ(cmp.lammpsPulling, 0) << name;
  EXPECT_GT(cmp.lammpsClamped, 0) << name;
  return cmp;
}

TEST(LammpsComparison, PolydispersePileSettlesUnderHertzLimitDamping) {
  compareClampedCase("pile_hertz_limit_damping");
}

TEST(LammpsComparison, RigidClumpPushesGrainsUnderHertzLimitDamping) {
  EXPECT_GT(compareClampedCase("clump_hertz_limit_damping").clumpYTravel, 0.05);
}

// So that the clamp above is tested: the Hertz runs of the same cases do pull at stored steps.
TEST(LammpsComparison, HertzReferenceRunsHavePullingContacts) {
  for (const std::string name : {"pile", "clump"}) {
    int pulling = 0;
    const json c = loadCase(name);  // held: a temporary's member would not outlive the loop's start
    for (const json& frame : c["frames"])
      if (frame.contains("contacts"))
        for (const json& fn : frame["contacts"]["fn"]) pulling += double(fn) < 0.0;
    EXPECT_GT(pulling, 0) << name;
  }
}

}  // namespace
}  // namespace wiggle
