// export-lammps: the data file carries wiggle's state to the bit, the deck holds the case's
// parameters, and LAMMPS running the deck follows wiggle's intruder over a short window.
#include "scenario/lammps/LammpsExport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>

#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "scenario/bed/BedMaker.h"
#include "scenario/case/EngineSettings.h"
#include "scenario/geometry/Clump.h"
#include "scenario/geometry/Shape.h"
#include "scenario/lammps/LammpsBed.h"
#include "scenario/run/Experiment.h"
#include "support/TestSupport.h"

namespace wiggle {
namespace {

namespace fs = std::filesystem;

// A small hand-made world: a 20-wide base, a few grains in a loose lattice, a disk clump.
World smallWorld(MassModel model) {
  RunConfig config;
  config.box.width = 20;
  config.grains.massModel = model;
  World world(worldDefFor(config));
  for (int i = 0; i < 20; ++i) world.addFrozen(i, 0.0, 0.5);
  int k = 0;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 18; ++col, ++k)
      world.addGrain(0.55 + col * 1.1, 1.0 + row * 1.05, 0.45 + 0.005 * (k % 11),
                     0.01 * (k % 5) - 0.02, -0.003 * (k % 7), 0.1 * (k % 3) - 0.1);
  world.setIntruder(makeClump(IntruderDef{}, model, 1.0), 10.0, 9.0);
  ClumpMotion motion;
  motion.kind = HorizontalMotion::Sinusoid;
  motion.x0 = 10.0;
  motion.amplitude = 3.0;
  motion.period = 2.0;
  motion.verticalFree = true;
  world.setIntruderMotion(motion);
  return world;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

struct DataAtom {
  int type = 0;
  double diameter = 0, density = 0, x = 0, y = 0, vx = 0, vy = 0, omega = 0;
};

// Reads the Atoms and Velocities sections back (ids are 1-based).
std::map<long, DataAtom> parseData(const std::string& data) {
  std::map<long, DataAtom> atoms;
  std::string section;
  for (const std::string& l : lines(data)) {
    if (l == "Atoms # sphere" || l == "Velocities") {
      section = l;
      continue;
    }
    if (l.empty() || section.empty()) continue;
    std::istringstream in(l);
    long id = 0;
    in >> id;
    DataAtom& a = atoms[id];
    double z = 0, vz = 0, wx = 0, wy = 0;
    if (section == "Velocities") in >> a.vx >> a.vy >> vz >> wx >> wy >> a.omega;
    else in >> a.type >> a.diameter >> a.density >> a.x >> a.y >> z;
    EXPECT_FALSE(in.fail()) << l;
  }
  return atoms;
}

TEST(LammpsExport, DataFileCarriesTheStateBitForBit) {
  RunConfig config;
  config.box.width = 20;
  config.run.duration = 0.5;
  World world = smallWorld(MassModel::Sphere);
  const LammpsDeck deck = makeLammpsDeck(world, prepareCase(config));
  const ParticleStore& s = world.particles();
  const std::size_t clumpAtoms = world.clump().offsetX.size();
  EXPECT_EQ(deck.atoms, s.size() + clumpAtoms);
  EXPECT_EQ(deck.steps, 5000u);
  const auto atoms = parseData(deck.data);
  ASSERT_EQ(atoms.size(), deck.atoms);
  for (std::uint32_t i = 0; i < s.size(); ++i) {
    const DataAtom& a = atoms.at(s.tag[i] + 1);  // wiggle's ids, as its dumps name the grains
    EXPECT_EQ(a.type, i < s.grainCount ? 1 : 2);
    EXPECT_EQ(0.5 * a.diameter, s.radius[i]);  // LAMMPS's radius, to the bit
    EXPECT_EQ(a.x, s.x[i]);
    EXPECT_EQ(a.y, s.y[i]);
    if (i < s.grainCount) {
      EXPECT_EQ(a.vx, s.vx[i]);
      EXPECT_EQ(a.vy, s.vy[i]);
      EXPECT_EQ(a.omega, s.omega[i]);
      // LAMMPS read_data: rmass = density * (4 pi / 3 r^3); wiggle's mass agrees to an ulp or two.
      const double r = 0.5 * a.diameter;
      const double lammpsMass = a.density * (4.0 * std::numbers::pi / 3.0 * r * r * r);
      EXPECT_NEAR(lammpsMass, s.mass[i], 4e-16 * s.mass[i]);
    }
  }
  const ClumpState& c = world.intruder();
  const long maxTag = *std::max_element(s.tag.begin(), s.tag.end());
  for (std::size_t k = 0; k < clumpAtoms; ++k) {
    const DataAtom& a = atoms.at(maxTag + 2 + static_cast<long>(k));  // after the largest id
    EXPECT_EQ(a.type, 3);
    EXPECT_EQ(0.5 * a.diameter, world.clump().atomRadius);
    EXPECT_EQ(a.x, c.x + world.clump().offsetX[k]);
    EXPECT_EQ(a.y, c.y + world.clump().offsetY[k]);
    EXPECT_DOUBLE_EQ(a.vx, 3.0 * 2.0 * std::numbers::pi / 2.0);  // A w at t = 0
    EXPECT_EQ(a.vy, 0.0);
  }
}

TEST(LammpsExport, DeckHoldsTheCaseParameters) {
  RunConfig config;
  config.box.width = 20;
  config.run.duration = 0.5;
  config.run.sampleInterval = 0.01;
  config.run.dumpInterval = 0;
  const World world = smallWorld(MassModel::Sphere);
  const std::string in = makeLammpsDeck(world, prepareCase(config)).input;
  char mass[64];
  std::snprintf(mass, sizeof mass, "%.17g", world.clump().mass);
  for (const std::string& needle :
       {std::string("pair_style gran/hertz/history 2000000 2460000 2500 2500 0.10000000000000001 1\n"),
        std::string("timestep 0.0001\n"), std::string("variable nsteps index 5000\n"),
        std::string("set group intruder mass ") + mass + "\n", std::string("fix integrate grains nve/sphere\n"),
        std::string("fix grav grains gravity 1 vector 0 -1 0\n"), std::string("fix hold base freeze\n"),
        std::string("fix drive intruder move variable v_dx NULL NULL v_vx NULL NULL\n"),
        std::string("variable w equal 3.1415926535897931\n"),  // 2 pi / T, T = 2
        std::string("fix traj all print 100 "), std::string("neighbor 0.20000000000000001 bin\n"),
        std::string("processors * 1 1\n"), std::string("run ${nsteps}\n")})
    EXPECT_NE(in.find(needle), std::string::npos) << "missing: " << needle;
  EXPECT_EQ(in.find("dump snap"), std::string::npos);  // dump_interval 0: no dump
  EXPECT_EQ(in.find("density/disc"), std::string::npos);

  RunConfig disc = config;
  disc.grains.massModel = MassModel::Disc;
  const std::string inDisc = makeLammpsDeck(smallWorld(MassModel::Disc), prepareCase(disc)).input;
  EXPECT_NE(inDisc.find("set group grains density/disc 1\n"), std::string::npos);
  EXPECT_NE(inDisc.find("fix integrate grains nve/sphere disc\n"), std::string::npos);

  World ramped = smallWorld(MassModel::Sphere);
  ClumpMotion motion = ramped.intruderMotion();
  motion.kind = HorizontalMotion::RampedSinusoid;
  motion.rampTime = 4.0;  // two periods
  ramped.setIntruderMotion(motion);
  const std::string inRamp = makeLammpsDeck(ramped, prepareCase(config)).input;
  EXPECT_NE(inRamp.find("variable ramp equal 4\n"), std::string::npos);
  EXPECT_NE(inRamp.find("variable dx equal 3*v_s*sin(v_w*(step*dt))\n"), std::string::npos);
  EXPECT_EQ(in.find("v_s"), std::string::npos);  // the plain drive has no ramp (docs/PHYSICS.md §7)

  // intruder.contact_mass = "atom": the atoms carry M / n in meff and the matching share of the force.
  World shared = smallWorld(MassModel::Sphere);
  shared.setIntruderMass(shared.clump().mass, 151, 0.0);
  const std::string inShared = makeLammpsDeck(shared, prepareCase(config)).input;
  char atomMass[64], share[64], weight[64];
  std::snprintf(atomMass, sizeof atomMass, "%.17g", shared.clump().mass / 151);
  std::snprintf(share, sizeof share, "%.17g", shared.clump().mass / 151 / shared.clump().mass);
  std::snprintf(weight, sizeof weight, "%.17g", shared.clump().mass);  // M g, g = 1
  EXPECT_NE(inShared.find(std::string("set group intruder mass ") + atomMass + "\n"), std::string::npos);
  EXPECT_NE(inShared.find(std::string("variable Fy equal (fcm(intruder,y)-") + weight + ")*" + share + "\n"),
            std::string::npos)
      << inShared;

  World hooke = smallWorld(MassModel::Sphere);  // the deck takes the law from the world it exports
  WorldDef def = hooke.def();
  def.contact.law = contactLaw<HookeLaw>;
  hooke.setParameters(def);
  const std::string inHooke = makeLammpsDeck(hooke, prepareCase(config)).input;
  EXPECT_NE(inHooke.find("pair_style gran/hooke/history 2000000 2460000 2500 2500 0.10000000000000001 1\n"),
            std::string::npos);
  def.contact.law = contactLaw<HertzLimitDampingLaw>;
  hooke.setParameters(def);
  const std::string inLimited = makeLammpsDeck(hooke, prepareCase(config)).input;
  EXPECT_NE(inLimited.find("pair_style gran/hertz/history 2000000 2460000 2500 2500 0.10000000000000001 1 "
                           "limit_damping\npair_coeff * *\n"),
            std::string::npos);
}

TEST(LammpsExport, RefusesAWorldNotAtTheStartOfADrivenRun) {
  RunConfig config;
  config.box.width = 20;
  World world = smallWorld(MassModel::Sphere);
  world.step();
  EXPECT_THROW(makeLammpsDeck(world, prepareCase(config)), Error);  // clock not at 0
  World held(worldDefFor(config));
  held.addFrozen(0, 0, 0.5);
  held.setIntruder(makeClump(IntruderDef{}, MassModel::Sphere, 1.0), 10, 9);
  EXPECT_THROW(makeLammpsDeck(held, prepareCase(config)), Error);  // intruder held, not driven
  // A clump that turns has no deck (fix rigid cannot be combined with fix move): refused by name.
  World turning = smallWorld(MassModel::Sphere);
  turning.setIntruderMass(turning.clump().mass, 1, 10.0);
  ClumpMotion motion = turning.intruderMotion();
  motion.rotationFree = true;
  turning.setIntruderMotion(motion);
  try {
    makeLammpsDeck(turning, prepareCase(config));
    FAIL() << "a turning clump was exported";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("intruder.rotation"), std::string::npos) << e.what();
  }
}

TEST(LammpsExport, WithoutContactHistoryKeepsEveryParticle) {
  World world = smallWorld(MassModel::Sphere);
  world.run(300);  // contacts form, history builds up
  World probe = smallWorld(MassModel::Sphere);
  probe.resetClock();
  const World fresh = withoutContactHistory(probe);
  EXPECT_EQ(fresh.grainCount(), probe.grainCount());
  EXPECT_EQ(fresh.particles().size(), probe.particles().size());
  EXPECT_EQ(fresh.intruder().x, probe.intruder().x);
  EXPECT_EQ(fresh.intruder().y, probe.intruder().y);
  EXPECT_EQ(fresh.intruderMotion().period, probe.intruderMotion().period);
  EXPECT_THROW(withoutContactHistory(world), Error);  // intruder moving vertically: not a run start
}

// A bed as LAMMPS's write_data writes it (image flags, Velocities, a coefficient section, ids in
// no particular order, a box from -10 to 10): grains and base by type, ids kept, x shifted into
// [0, W), the dropped atom replaced by the config's intruder at the box centre and intruder.y0.
TEST(LammpsExport, ReadsABedAsWriteDataWritesIt) {
  RunConfig config;
  config.box.width = 20;
  config.intruder.y0 = 9;
  config.bed.lammpsTypes = "1=grain 2=base 4=grain 3=drop";
  const std::string data =
      "LAMMPS data file via write_data, version 29 Sep 2021, timestep = 2600000\n\n"
      "6 atoms\n4 atom types\n\n-10 10 xlo xhi\n-1 40 ylo yhi\n-0.5 0.5 zlo zhi\n\n"
      "PairIJ Coeffs # gran/hertz/history\n\n1 1\n1 2\n1 3\n1 4\n2 2\n2 3\n2 4\n3 3\n3 4\n4 4\n\n"
      "Atoms # sphere\n\n"
      "7 1 1.0 1.0000000000000002 -9.5 0.95 0 1 0 0\n"
      "2 2 1.0 1.0 -9.5 0 0 0 0 0\n"
      "3 2 1.0 1.0 -8.5 0 0 0 0 0\n"
      "12 4 0.9 1.0 5.25 3.0 0.0 0 0 0\n"
      "40 3 0.5 1.0 0.0 9.0 0 0 0 0\n"
      "9 1 1.1 1.0 9.999999999999998 2.0 0 -1 0 0\n\n"
      "Velocities\n\n7 0.5 -0.25 0 0 0 3.0\n2 0 0 0 0 0 0\n3 0 0 0 0 0 0\n12 0 0 0 0 0 -1.5\n"
      "40 0 0 0 0 0 0\n9 0.125 0 0 0 0 0\n";
  const ClumpDef clump = makeClump(config.intruder, config.grains.massModel, 1.0);
  const World world = readLammpsBed(data, "bed.data", config, clump);
  const ParticleStore& s = world.particles();
  ASSERT_EQ(world.grainCount(), 3u);
  ASSERT_EQ(s.size(), 5u);
  EXPECT_EQ(s.tag, (std::vector<std::uint32_t>{6, 11, 8, 1, 2}));  // grains, then base, in file order
  EXPECT_EQ(s.x[0], 0.5);                                          // -9.5 - xlo
  EXPECT_EQ(s.vx[0], 0.5);
  EXPECT_EQ(s.vy[0], -0.25);
  EXPECT_EQ(s.omega[0], 3.0);
  EXPECT_EQ(s.x[1], 15.25);
  EXPECT_EQ(s.radius[1], 0.45);
  EXPECT_EQ(s.omega[1], -1.5);
  EXPECT_EQ(s.radius[3], 0.5);
  EXPECT_EQ(world.intruder().x, 10.0);
  EXPECT_EQ(world.intruder().y, 9.0);
  EXPECT_EQ(world.clump().offsetX, clump.offsetX);
  // Each role's absence or excess is named: here type 4 without a role.
  config.bed.lammpsTypes = "1=grain 2=base 3=drop";
  try {
    readLammpsBed(data, "bed.data", config, clump);
    ADD_FAILURE() << "type 4 accepted without a role";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("atom 12 has type 4"), std::string::npos) << e.what();
  }
}

// ---------------------------------------------------------------- against LAMMPS

struct Row {
  double t, x, y, vx, vy, fy;
};

std::vector<Row> readTrajectory(const std::string& path) {
  std::vector<Row> rows;
  std::ifstream in(path);
  std::string l;
  while (std::getline(in, l)) {
    if (l.empty() || l[0] == '#' || l[0] == 't') continue;  // fix print's title line starts with "# " or "t,"
    Row r{};
    if (std::sscanf(l.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf", &r.t, &r.x, &r.y, &r.vx, &r.vy, &r.fy) == 6) rows.push_back(r);
  }
  return rows;
}

std::map<long, Row> runWiggle(World world, std::uint64_t steps, std::uint64_t every) {
  std::map<long, Row> rows;
  for (std::uint64_t k = 1; k <= steps; ++k) {
    world.step();
    if (k % every == 0) {
      const ClumpState& c = world.intruder();
      rows[static_cast<long>(k)] = {world.time(), c.x, c.y, c.vx, c.vy, c.contactFy};
    }
  }
  return rows;
}

bool haveLammps() { return std::system("command -v lmp > /dev/null 2>&1") == 0; }

// Exports a tiny bed (about 220 grains around the 7-wide disk, made once and cached under the
// test's temporary directory) with drive.ramp_periods = `rampPeriods`, runs the deck in LAMMPS for
// 2,000 steps (t = 0.2) of the drive at A = 3, T = 2 and compares its intruder with wiggle's.
void expectLammpsFollowsWiggle(const std::string& rampPeriods, const std::string& form = "displacement",
                               const std::string& law = "hertz", const std::string& intruderSets = "") {
  const testing_support::ScratchDir scratch("lammps-export");  // WIGGLE_KEEP_TEST_DIRS=1 keeps LAMMPS's log
  const fs::path& root = scratch.path();
  std::vector<std::string> sets{"box.width=20", "box.bed_height=14", "box.seed=7", "intruder.y0=7", "drive.amplitude=3",
                                "drive.period=2", "drive.ramp_periods=" + rampPeriods, "drive.form=" + form,
                                "contact.law=" + law, "run.duration=0.2", "run.sample_interval=0.01",
                                "run.dump_interval=0", "bed.rest_energy=1e-6"};
  std::string label = "deck-ramp" + rampPeriods + "-" + form + "-" + law;
  std::istringstream items(intruderSets);  // intruder keys, as "key=value key=value"
  for (std::string item; items >> item;) {
    sets.push_back("intruder." + item);
    label += "-" + item.substr(item.find('=') + 1);
  }
  RunConfig config = loadRunConfig(std::nullopt, sets);
  config.bed.cacheDir = (root / "cache").string();
  const std::string dir = (root / label).string();
  fs::remove_all(dir);
  const Case run = prepareCase(config);
  ASSERT_EQ(exportLammps(startRun(run).world, run, dir).steps, 2000u);  // as `wiggle export-lammps` does

  const std::string command = "cd '" + dir + "' && lmp -in in.wiggle -log log.lammps -screen none";
  ASSERT_EQ(std::system(command.c_str()), 0) << "LAMMPS failed: see " << dir << "/log.lammps";
  const std::vector<Row> lammps = readTrajectory(dir + "/trajectory.csv");
  ASSERT_GE(lammps.size(), 20u);

  // The world LAMMPS starts from: the bed at t = 0 of the drive, without contact history.
  const ClumpDef clump = makeClump(config.intruder, config.grains.massModel, 1.0);
  CachedBed bed = obtainBed(config, clump);
  ASSERT_TRUE(bed.fromCache);
  startDrive(bed.world, run);
  const auto fresh = runWiggle(withoutContactHistory(bed.world), 2000, 100);
  const auto withHistory = runWiggle(bed.world, 2000, 100);

  // Deviations over the window. Scales: y ~ 7, velocities ~ 10 (vx) and ~ 0.1 (vy), forces ~ 30.
  double dx = 0, dy = 0, dvx = 0, dvy = 0, dfy = 0, hy = 0, hvy = 0, hfy = 0, fyScale = 0;
  int matched = 0;
  for (const Row& l : lammps) {
    const long step = std::lround(l.t / 1e-4);
    const auto it = fresh.find(step);
    if (it == fresh.end()) continue;
    ++matched;
    const Row& w = it->second;
    const Row& h = withHistory.at(step);
    dx = std::max(dx, std::fabs(l.x - w.x));
    dy = std::max(dy, std::fabs(l.y - w.y));
    dvx = std::max(dvx, std::fabs(l.vx - w.vx));
    dvy = std::max(dvy, std::fabs(l.vy - w.vy));
    dfy = std::max(dfy, std::fabs(l.fy - w.fy));
    fyScale = std::max(fyScale, std::fabs(w.fy));
    hy = std::max(hy, std::fabs(h.y - w.y));
    hvy = std::max(hvy, std::fabs(h.vy - w.vy));
    hfy = std::max(hfy, std::fabs(h.fy - w.fy));
  }
  ASSERT_EQ(matched, 20) << "LAMMPS rows at steps 100..2000 expected";
  std::printf("LAMMPS vs wiggle (no history), 2000 steps: |dx| %.3g |dy| %.3g |dvx| %.3g |dvy| %.3g |dfy| %.3g "
              "(fy scale %.3g)\n", dx, dy, dvx, dvy, dfy, fyScale);
  std::printf("wiggle with vs without the bed's contact history: |dy| %.3g |dvy| %.3g |dfy| %.3g\n", hy, hvy, hfy);
  // Tolerances: LAMMPS and wiggle round differently (operation order in sums, masses to an ulp,
  // x0 + A sin + offset vs (x0 + offset) + A sin), and the granular dynamics amplify the
  // differences; measured deviations are recorded in docs/LAMMPS-EXPORT.md. The bounds are 1e-9
  // relative to each quantity's scale, far below what the lost contact history does (above).
  EXPECT_LT(dx, 1e-12 * 20);
  EXPECT_LT(dy, 1e-9 * 7);
  EXPECT_LT(dvx, 1e-9 * 10);
  EXPECT_LT(dvy, 1e-9 * 1);
  EXPECT_LT(dfy, 1e-9 * fyScale);
  // And the comparison can tell: the history alone moves the intruder by far more.
  EXPECT_GT(hfy, 100 * dfy);
}

TEST(LammpsExport, SlowLammpsRunOfTheDeckFollowsWiggle) {
  if (!haveLammps()) GTEST_SKIP() << "lmp (LAMMPS) not found: apt-get install lammps to run this comparison";
  expectLammpsFollowsWiggle("0");
}

TEST(LammpsExport, SlowLammpsRunOfARampedDriveFollowsWiggle) {
  if (!haveLammps()) GTEST_SKIP() << "lmp (LAMMPS) not found: apt-get install lammps to run this comparison";
  expectLammpsFollowsWiggle("1");  // the whole window is inside the ramp (t_ramp = T = 2)
}

TEST(LammpsExport, SlowLammpsRunOfAVelocityDriveFollowsWiggle) {
  if (!haveLammps()) GTEST_SKIP() << "lmp (LAMMPS) not found: apt-get install lammps to run this comparison";
  expectLammpsFollowsWiggle("0", "velocity");  // vx = 3 sin(pi t): the deck's fix move variable
}

TEST(LammpsExport, SlowLammpsRunOfAHookeBedFollowsWiggle) {
  if (!haveLammps()) GTEST_SKIP() << "lmp (LAMMPS) not found: apt-get install lammps to run this comparison";
  expectLammpsFollowsWiggle("0", "displacement", "hooke");  // a bed poured and driven under gran/hooke/history
}

// intruder.contact_mass = "atom": each of the smooth disk's shell atoms carries one of the 151
// glued spheres' mass, M / 151, in meff, and gets that share of the clump's force.
TEST(LammpsExport, SlowLammpsRunOfAnAtomContactMassFollowsWiggle) {
  if (!haveLammps()) GTEST_SKIP() << "lmp (LAMMPS) not found: apt-get install lammps to run this comparison";
  expectLammpsFollowsWiggle("0", "displacement", "hertz", "contact_mass=atom");
}

// intruder.surface = "lattice": the triangle of touching spheres filling its outline (slant faces
// as staircases), turned apex down, with its atoms' mass in the contacts.
TEST(LammpsExport, SlowLammpsRunOfALatticeTriangleFollowsWiggle) {
  if (!haveLammps()) GTEST_SKIP() << "lmp (LAMMPS) not found: apt-get install lammps to run this comparison";
  expectLammpsFollowsWiggle("0", "displacement", "hertz", "shape=triangle angle=180 y0=9 surface=lattice contact_mass=atom");
}

TEST(LammpsExport, SlowLammpsRunOfAHertzLimitDampingBedFollowsWiggle) {
  if (!haveLammps()) GTEST_SKIP() << "lmp (LAMMPS) not found: apt-get install lammps to run this comparison";
  expectLammpsFollowsWiggle("0", "displacement", "hertz_limit_damping");  // gran/hertz/history ... limit_damping
}

}  // namespace
}  // namespace wiggle
