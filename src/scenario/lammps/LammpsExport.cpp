#include "scenario/lammps/LammpsExport.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include "core/Error.h"
#include "core/Format.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "scenario/case/Case.h"
#include "scenario/geometry/Shape.h"
#include "scenario/lammps/LammpsBed.h"  // wrappedX: the data file holds x as a bed read back keeps it

namespace wiggle {

namespace {

// Shortest text that reads back as the same double is not needed here: %.17g always round-trips,
// and LAMMPS reads numbers with strtod/atof, so every value reaches LAMMPS bit for bit.
std::string num(double v) { return formatNumber(v, 17); }

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
                  num(2.0 * s.radius[i]).c_str(), num(def.density).c_str(), num(wrappedX(s.x[i], width)).c_str(),
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
                  num(wrappedX(c.x + clump.offsetX[a], width)).c_str(), num(c.y + clump.offsetY[a]).c_str());
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
  if (clump.massShares == 1)
    in += "# Every intruder atom carries the clump's total mass M: meff = m M / (m + M) as in wiggle.\n";
  else
    in += "# Every intruder atom carries one glued sphere's mass M / " + std::to_string(clump.massShares) +
          " (intruder.contact_mass = \"atom\"):\n# meff = m m_atom / (m + m_atom) as in wiggle.\n";
  in += "set group intruder mass " + num(clump.contactMass()) + "\n\n";
  in += contactLawTraits(p.law).lammpsPairStyle(p);
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
  // Each atom's y force is its share m_atom / M of the clump's, so that it accelerates by (F - M g) / M
  // whatever its mass (fix aveforce would give it F / n_atoms, which is that only when the atoms'
  // masses add up to M: not so for a shell of atoms that each carry a sphere of the filled body).
  if (clump.massShares == 1) {
    in += "# Free y: each atom gets the clump's force F_contact,y - M g (gravity is not applied to the atoms).\n";
    in += "variable Fy equal fcm(intruder,y)-" + num(clump.mass * def.gravity) + "\n\n";
  } else {
    in += "# Free y: each atom gets its share m_atom / M of the clump's force F_contact,y - M g, so that it\n"
          "# accelerates by (F_contact,y - M g) / M (gravity is not applied to the atoms).\n";
    in += "variable Fy equal (fcm(intruder,y)-" + num(clump.mass * def.gravity) + ")*" +
          num(clump.contactMass() / clump.mass) + "\n\n";
  }
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
  if (motion.rotationFree)
    throw Error("export-lammps: intruder.rotation = \"free\" has no LAMMPS deck: a body that turns is LAMMPS's fix "
                "rigid, which cannot be combined with the fix move that drives x (docs/LAMMPS-EXPORT.md)");
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
    fresh.addGrain(wrappedX(s.x[i], width), s.y[i], s.radius[i], s.vx[i], s.vy[i], s.omega[i]);
  for (std::uint32_t i = s.grainCount; i < s.size(); ++i) fresh.addFrozen(wrappedX(s.x[i], width), s.y[i], s.radius[i]);
  if (world.hasIntruder()) {
    if (world.intruder().vy != 0.0)
      throw Error("withoutContactHistory: the intruder must be at rest vertically (it is at t = 0 of a run)");
    fresh.setIntruder(world.clump(), world.intruder().x, world.intruder().y);
    fresh.setIntruderMotion(world.intruderMotion());
  }
  return fresh;
}

LammpsDeck exportLammps(const World& world, const Case& run, const std::string& dir) {
  LammpsDeck deck = makeLammpsDeck(world, run);
  writeLammpsDeck(dir, deck);
  // The case beside its deck, as a run directory holds it: once LAMMPS has written trajectory.csv,
  // `wiggle rate DIR` measures its V_y by wiggle's own rules.
  writeFileAtomically(dir + "/config.toml", toToml(run.config));
  return deck;
}

}  // namespace wiggle
