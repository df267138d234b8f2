// Beds (scenario/bed/BedMaker.h): the bed keys of both pours and the keys a bed depends on, a tiny
// random-poured bed made to rest (and continued to the same bits after a stop), the damped
// relaxation, carved beds, and the presets' beds.
#include <gtest/gtest.h>

#include <omp.h>
#include <unistd.h>
#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numbers>
#include <tuple>

#include "core/Error.h"
#include "core/Format.h"
#include "core/StopSignal.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "io/SweepSpec.h"
#include "scenario/bed/BedMaker.h"
#include "scenario/run/Experiment.h"
#include "support/PaperBeds.h"
#include "support/TestSupport.h"

namespace wiggle {
namespace {

namespace fs = std::filesystem;

// Other values of a key to try, as --set text: numbers scaled and shifted (a candidate the config
// refuses is skipped), the other names of a choice, the other truth value, a changed list; none for
// text keys (file and directory names: the bed key is that of the config's own bed).
std::vector<std::string> otherValues(const RunConfig& c, const std::string& key) {
  const std::string now = configValueToml(c, key);
  std::vector<std::string> out;
  if (const auto names = configKeyChoices(key); !names.empty()) {
    for (const std::string& name : names) out.push_back("\"" + name + "\"");
  } else if (now == "true" || now == "false") {
    out.push_back(now == "true" ? "false" : "true");
  } else if (now.starts_with("[[")) {  // a point list: the outline scaled
    out.push_back("[[-1.8, -1.8], [1.8, -1.8], [1.8, 1.8], [-1.8, 1.8]]");
  } else if (now.starts_with("[")) {
    out.push_back("[1.0]");
  } else if (!now.empty() && (std::isdigit(static_cast<unsigned char>(now[0])) || now[0] == '-')) {
    const double v = std::stod(now);
    if (isRealKey(key)) {
      for (double x : {v * 1.25, v * 0.8, v * 2, v * 0.5, v + 1, v + 0.5})
        if (x != v) out.push_back(formatNumber(x, 17));
    } else {
      for (double x : {v + 1, v + 2}) out.push_back(std::to_string(static_cast<long long>(x)));
    }
  }
  std::erase(out, now);
  return out;
}

// The keys the key table declares as shaping the bed (config's keyShapesBed) are exactly those whose
// change changes the bed key: every key is set to another value in two configs (the defaults; a
// random-poured, carved polygon, where the keys that only some protocols or shapes read count), and
// the bed key must change for a declared key in at least one of them, and for no other key in any.
TEST(BedMaker, BedKeyHashesExactlyTheKeysDeclaredToShapeTheBed) {
  const std::vector<RunConfig> bases = {
      loadRunConfig(std::nullopt, {}),
      loadRunConfig(std::nullopt,
                    {"bed.pour=random", "bed.cavity=carved", "bed.relax_damping=1", "intruder.shape=polygon",
                     "intruder.vertices=[[-1.5,-1.5],[1.5,-1.5],[1.5,1.5],[-1.5,1.5]]"})};
  for (const std::string& key : configKeys()) {
    // Valid only with bed.file (which replaces the config's bed): which intruder runs on that bed.
    if (key == "bed.swap_intruder") {
      EXPECT_FALSE(keyShapesBed(key));
      continue;
    }
    bool tried = false, changed = false;
    for (const RunConfig& base : bases) {
      const std::string before = bedKey(base, prepareCase(base).clump);
      for (const std::string& value : otherValues(base, key)) {
        RunConfig c = base;
        std::string after;
        try {
          applyOverride(c, key + "=" + value);
          validateRunConfig(c);
          after = bedKey(c, prepareCase(c).clump);
        } catch (const Error&) {
          continue;  // a value this config refuses: try the next
        }
        tried = true;
        changed = changed || after != before;
        break;
      }
    }
    if (configValueToml(bases[0], key).starts_with("\"") && configKeyChoices(key).empty()) continue;  // text
    EXPECT_TRUE(tried) << key << ": no other value of it was accepted; give otherValues one";
    EXPECT_EQ(changed, keyShapesBed(key))
        << key
        << (keyShapesBed(key) ? " is declared to shape the bed, but the bed key ignores it"
                              : " changes the bed key but is not declared to shape the bed");
  }
}

TEST(BedMaker, LatticeBedKeyIsUnchangedAndRandomKeysDiffer) {
  // The keys these configs had before bed.pour existed (made by the code of that time). They
  // change only on purpose: a new bed format (kBedFormat, kOldestStateFormatVersion) or a new clump.
  const RunConfig defaults = loadRunConfig(std::nullopt, {});
  const RunConfig tiny = loadRunConfig(
      std::nullopt, {"box.width=12", "box.bed_height=8", "intruder.shape=polygon",
                     "intruder.vertices=[[-0.75,-0.75],[0.75,-0.75],[0.75,0.75],[-0.75,0.75]]", "intruder.y0=4",
                     "drive.amplitude=1"});
  const ClumpDef disk = prepareCase(defaults).clump, square = prepareCase(tiny).clump;
  EXPECT_EQ(bedKey(defaults, disk), "b8ece11933d4975e");
  EXPECT_EQ(bedKey(tiny, square), "8e5d9db187fd83f2");
  // The lattice ignores the random pour's parameters, and so does its key.
  RunConfig lattice = defaults;
  lattice.bed.pourFraction = 0.5;
  lattice.bed.pourSpeed = 3.0;
  EXPECT_EQ(bedKey(lattice, disk), "b8ece11933d4975e");
  // The random pour has its own keys, one per fraction and speed.
  RunConfig random = defaults;
  random.bed.pour = BedPour::Random;
  const std::string randomKey = bedKey(random, disk);
  EXPECT_NE(randomKey, "b8ece11933d4975e");
  RunConfig other = random;
  other.bed.pourFraction = 0.5;
  EXPECT_NE(bedKey(other, disk), randomKey);
  other = random;
  other.bed.pourSpeed = 3.0;
  EXPECT_NE(bedKey(other, disk), randomKey);
  EXPECT_NE(bedKey(other, disk), bedKey(other, square));
  // The damped relaxation: off keeps the key, on has keys of its own.
  RunConfig damped = defaults;
  damped.bed.relaxDamping = 0.0;
  EXPECT_EQ(bedKey(damped, disk), "b8ece11933d4975e");
  damped.bed.relaxDamping = 2.0;
  const std::string dampedKey = bedKey(damped, disk);
  EXPECT_NE(dampedKey, "b8ece11933d4975e");
  damped.bed.relaxDamping = 1.0;
  EXPECT_NE(bedKey(damped, disk), dampedKey);
  // The contact law: Hertz (the default) keeps the key, Hooke has its own.
  RunConfig hooke = defaults;
  hooke.contact.law = contactLaw<HookeLaw>;
  EXPECT_NE(bedKey(hooke, disk), "b8ece11933d4975e");
  EXPECT_NE(baseBedKey(hooke), baseBedKey(defaults));
}

// The process's own scratch directory, emptied when first used and removed at exit: a directory
// left by an earlier process of the same id (ids are reused) must not look like an earlier run.
std::string scratch(const std::string& name) {
  static const testing_support::ScratchDir dir("bedmaker-test");
  fs::create_directories(dir.path());  // (some tests remove it to start over)
  return dir / name;
}

// One thread for the tiny beds (the bits do not depend on it): about 100 grains gain nothing from
// two, and a second thread on a busy core makes every step wait for it.
struct OneThread {
  int saved = omp_get_max_threads();
  OneThread() { omp_set_num_threads(1); }
  ~OneThread() { omp_set_num_threads(saved); }
};

// A 12 x 8 bed (about 80 grains) around a 1.5 x 1.5 square, poured at random.
RunConfig tinyRandomConfig() {
  return loadRunConfig(std::nullopt,
                       {"box.width=12", "box.bed_height=8", "intruder.shape=polygon",
                        "intruder.vertices=[[-0.75,-0.75],[0.75,-0.75],[0.75,0.75],[-0.75,0.75]]", "intruder.y0=4",
                        "drive.amplitude=1", "bed.pour=random", "bed.batch_height=10", "bed.rest_energy=1e-4",
                        "bed.max_time=100"});
}

// bed.mu: a case run at one friction on the bed poured at another is given that bed, the same
// key, cache entry and grains, and runs with its own contact.mu; without bed.mu its own bed.
TEST(BedMaker, BedMuGivesTheBedOfThatFrictionRunWithTheCasesOwn) {
  const OneThread oneThread;
  const RunConfig defaults = loadRunConfig(std::nullopt, {});
  const RunConfig pinned = loadRunConfig(std::nullopt, {"contact.mu=0.5", "bed.mu=0.1"});
  const RunConfig own = loadRunConfig(std::nullopt, {"contact.mu=0.5"});
  const ClumpDef disk = prepareCase(defaults).clump;
  EXPECT_EQ(bedKey(pinned, disk), "b8ece11933d4975e");  // the default bed's key, as it has always been
  EXPECT_NE(bedKey(own, disk), "b8ece11933d4975e");
  EXPECT_EQ(baseBedKey(pinned), baseBedKey(defaults));

  const std::string cache = scratch("bed-mu-cache");
  RunConfig tiny = tinyRandomConfig();
  tiny.bed.cacheDir = cache;
  const ClumpDef square = prepareCase(tiny).clump;
  const CachedBed poured = obtainBed(tiny, square);  // made now at mu = 0.1, and cached
  RunConfig frictionless = tiny;
  frictionless.contact.mu = 0.0;
  frictionless.bed.mu = 0.1;
  const CachedBed given = obtainBed(frictionless, square);
  EXPECT_TRUE(given.fromCache);
  EXPECT_EQ(given.key, poured.key);
  EXPECT_EQ(given.world.stateHash(), poured.world.stateHash());  // the same grains, velocities, histories
  EXPECT_EQ(given.world.def().contact.mu, 0.0);
  EXPECT_EQ(poured.world.def().contact.mu, 0.1);
  fs::remove_all(cache);
}

// bed.intruder_mass: a case run with one intruder mass on the bed poured around another is given
// that bed (the same key, cache entry and grains) with its own mass; without it, its own bed.
TEST(BedMaker, BedIntruderMassGivesTheBedOfThatMassRunWithTheCasesOwn) {
  const OneThread oneThread;
  const RunConfig defaults = loadRunConfig(std::nullopt, {});
  const ClumpDef disk = prepareCase(defaults).clump;
  const std::string heavier = "intruder.mass=" + formatNumber(2 * disk.mass, 17);
  const RunConfig pinned = loadRunConfig(std::nullopt, {heavier, "bed.intruder_mass=" + formatNumber(disk.mass, 17)});
  const RunConfig own = loadRunConfig(std::nullopt, {heavier});
  EXPECT_EQ(prepareCase(pinned).clump.mass, 2 * disk.mass);
  EXPECT_EQ(bedKey(pinned, prepareCase(pinned).clump), "b8ece11933d4975e");  // the default bed's key
  EXPECT_NE(bedKey(own, prepareCase(own).clump), "b8ece11933d4975e");

  const std::string cache = scratch("bed-intruder-mass-cache");
  RunConfig tiny = tinyRandomConfig();
  tiny.bed.cacheDir = cache;
  const ClumpDef square = prepareCase(tiny).clump;
  const CachedBed poured = obtainBed(tiny, square);  // made now around the square of its own mass
  RunConfig light = tiny;
  light.intruder.mass = square.mass / 3;
  light.bed.intruderMass = square.mass;
  const ClumpDef lightSquare = prepareCase(light).clump;
  ASSERT_EQ(lightSquare.mass, square.mass / 3);
  const CachedBed given = obtainBed(light, lightSquare);
  EXPECT_TRUE(given.fromCache);
  EXPECT_EQ(given.key, poured.key);
  EXPECT_EQ(given.world.clump().mass, square.mass / 3);
  EXPECT_EQ(poured.world.clump().mass, square.mass);
  const ParticleStore& a = given.world.particles();
  const ParticleStore& b = poured.world.particles();
  ASSERT_EQ(given.world.grainCount(), poured.world.grainCount());
  for (std::uint32_t i = 0; i < given.world.grainCount(); ++i) {  // the same grains where they lay
    ASSERT_EQ(a.x[i], b.x[i]) << i;
    ASSERT_EQ(a.y[i], b.y[i]) << i;
    ASSERT_EQ(a.vx[i], b.vx[i]) << i;
  }
  fs::remove_all(cache);
}

TEST(BedMaker, TinyRandomBedComesToRestAndContinuesToTheSameBits) {
  const OneThread oneThread;
  const RunConfig config = tinyRandomConfig();
  const ClumpDef clump = prepareCase(config).clump;
  int batches = 0;
  const World bed = makeBed(config, clump, [&](const BedStatus& s) { batches = s.batch; });
  EXPECT_GE(batches, 2);
  const ParticleStore& s = bed.particles();
  ASSERT_GT(bed.grainCount(), 60u);
  double kinetic = bed.kineticEnergy() / bed.grainCount();
  EXPECT_LT(kinetic, 10 * config.bed.restEnergy);
  for (std::uint32_t i = 0; i < bed.grainCount(); ++i) {
    ASSERT_LE(s.y[i], config.box.bedHeight) << i;
    ASSERT_GT(s.y[i], 0.5) << i;
  }
  const double surface = freeSurfaceHeight(bed);
  EXPECT_GT(surface, config.box.bedHeight - 1.5);
  EXPECT_LT(surface, config.box.bedHeight + 0.6);
  std::printf("tiny random bed: %u grains in %d batches, surface %.3f, t = %.1f\n", bed.grainCount(), batches, surface,
              bed.time());

  // Stopped by SIGTERM while pouring, saved and continued: the same bits (the attempt serial
  // numbers are part of the saved bed in the making).
  RunConfig stopped = config;
  stopped.bed.cacheDir = scratch("cache");
  {
    const StopSignalGuard guard;
    int reports = 0;
    EXPECT_THROW(obtainBed(stopped, clump,
                           [&](const BedStatus& st) {
                             if (st.stage == BedStage::Pouring && st.batch == 1 && ++reports == 3) std::raise(SIGTERM);
                           }),
                 Error);
  }
  ASSERT_TRUE(fs::exists(bedPartialPath(stopped, bedKey(stopped, clump))));
  const CachedBed continued = obtainBed(stopped, clump);
  EXPECT_FALSE(continued.fromCache);
  EXPECT_EQ(continued.world.stateHash(), bed.stateHash());
  EXPECT_FALSE(fs::exists(bedPartialPath(stopped, bedKey(stopped, clump))));

  // A kill between writing the finished bed and removing its partial file leaves the partial
  // behind: the next use of the cached bed removes it.
  const std::string partial = bedPartialPath(stopped, bedKey(stopped, clump));
  fs::copy_file(continued.path, partial);
  EXPECT_TRUE(obtainBed(stopped, clump).fromCache);
  EXPECT_FALSE(fs::exists(partial));
  fs::remove_all(scratch(""));
}

// bed.relax_damping: the levelled bed comes to rest in less simulated time, its grains where the
// undamped relaxation leaves them to well within a grain, and a bed stopped while relaxing
// continues to the same bits (the damping is applied at the same steps either way).
TEST(BedMaker, DampedRelaxationRestsSoonerAndContinuesToTheSameBits) {
  const OneThread oneThread;
  RunConfig config = tinyRandomConfig();
  config.bed.pour = BedPour::Lattice;
  config.bed.restEnergy = 1e-6;
  const ClumpDef clump = prepareCase(config).clump;
  const World plain = makeBed(config, clump);
  RunConfig damped = config;
  damped.bed.relaxDamping = 5.0;
  double relaxStart = 0.0;
  const World bed = makeBed(damped, clump, [&](const BedStatus& s) {
    if (s.stage == BedStage::Pouring) relaxStart = s.time;
  });
  std::printf("tiny lattice bed: at rest at t = %.2f undamped, %.2f damped (relaxation from t = %.2f)\n", plain.time(),
              bed.time(), relaxStart);
  EXPECT_LT(bed.time() - relaxStart, plain.time() - relaxStart);
  ASSERT_EQ(bed.grainCount(), plain.grainCount());  // the same pour: only the relaxation differs
  std::map<std::uint32_t, std::uint32_t> plainIndex;  // storage order is re-sorted: match grains by tag
  for (std::uint32_t i = 0; i < plain.grainCount(); ++i) plainIndex[plain.particles().tag[i]] = i;
  double largest = 0.0;
  for (std::uint32_t i = 0; i < bed.grainCount(); ++i) {
    const std::uint32_t j = plainIndex.at(bed.particles().tag[i]);
    largest = std::max(largest, std::hypot(bed.particles().x[i] - plain.particles().x[j],
                                           bed.particles().y[i] - plain.particles().y[j]));
  }
  std::printf("largest displacement between the two relaxed beds: %.3g d\n", largest);
  EXPECT_LT(largest, 0.5);
  EXPECT_LT(bed.kineticEnergy() / bed.grainCount(), damped.bed.restEnergy);

  damped.bed.cacheDir = scratch("cache-damped");
  {
    const StopSignalGuard guard;
    int reports = 0;
    EXPECT_THROW(obtainBed(damped, clump,
                           [&](const BedStatus& st) {
                             if (st.stage == BedStage::Relaxing && ++reports == 3) std::raise(SIGTERM);
                           }),
                 Error);
  }
  ASSERT_TRUE(fs::exists(bedPartialPath(damped, bedKey(damped, clump))));
  EXPECT_EQ(obtainBed(damped, clump).world.stateHash(), bed.stateHash());
  fs::remove_all(scratch(""));
}

// bed.cavity = "carved": one base bed per seed, poured without an intruder, serves every shape and
// position; each carved bed holds no grain inside its intruder, is at rest, and is the same bed
// whether made in one go (makeBed), obtained through the cache, or carved again after a stop.
TEST(BedMaker, CarvedBedsShareOneBaseBedAndRestAroundTheirIntruder) {
  const OneThread oneThread;
  RunConfig config = tinyRandomConfig();
  config.bed.pour = BedPour::Lattice;
  config.bed.cavity = BedCavity::Carved;
  config.bed.cacheDir = scratch("cache-carved");
  RunConfig triangleConfig = config;
  triangleConfig.intruder.vertices = {{-1.0, -0.6}, {1.0, -0.6}, {0.0, 1.0}};
  triangleConfig.intruder.y0 = 3.5;
  const ClumpDef square = prepareCase(config).clump, triangle = prepareCase(triangleConfig).clump;

  // Keys: one base for both; carved keys of their own, apart from the poured bed's.
  EXPECT_EQ(baseBedKey(config), baseBedKey(triangleConfig));
  EXPECT_NE(bedKey(config, square), bedKey(triangleConfig, triangle));
  RunConfig poured = config;
  poured.bed.cavity = BedCavity::Poured;
  EXPECT_NE(bedKey(config, square), bedKey(poured, square));
  EXPECT_NE(baseBedKey(config), bedKey(poured, square));

  const CachedBed first = obtainBed(config, square);
  const CachedBed second = obtainBed(triangleConfig, triangle);
  EXPECT_FALSE(first.fromCache);
  EXPECT_FALSE(second.fromCache);
  int beds = 0;
  for (const auto& entry : fs::directory_iterator(config.bed.cacheDir)) beds += entry.path().extension() == ".bin";
  EXPECT_EQ(beds, 3);  // the base, poured once, and the two carved beds
  const World base = parseCachedBed(readFile(bedCachePath(config, baseBedKey(config))), "base", baseBedKey(config));
  EXPECT_FALSE(base.hasIntruder());
  EXPECT_GE(freeSurfaceHeight(base), config.box.bedHeight);  // poured to the target, levelled by each cut
  std::uint32_t levelled = 0;  // the base's grains a carved bed keeps but for its intruder's
  for (std::uint32_t i = 0; i < base.grainCount(); ++i) levelled += base.particles().y[i] <= config.box.bedHeight;

  for (const auto& [bed, cfg, clump] : {std::tie(first.world, config, square), std::tie(second.world, triangleConfig, triangle)}) {
    ASSERT_TRUE(bed.hasIntruder());
    EXPECT_EQ(bed.intruder().y, cfg.intruder.y0);
    EXPECT_LT(bed.grainCount(), levelled);
    EXPECT_GT(bed.grainCount(), levelled - 12);  // only the grains where the intruder now is
    for (std::uint32_t i = 0; i < bed.grainCount(); ++i) ASSERT_LE(bed.particles().y[i], cfg.box.bedHeight + 0.5);
    EXPECT_LT(bed.kineticEnergy() / bed.grainCount(), cfg.bed.restEnergy);
    // Grains rest against the intruder (overlaps of order m g / k_n), none inside it.
    const ParticleStore& s = bed.particles();
    double deepest = 0.0;
    for (std::uint32_t i = 0; i < bed.grainCount(); ++i)
      for (std::size_t a = 0; a < clump.offsetX.size(); ++a)
        deepest = std::max(deepest, s.radius[i] + clump.atomRadius -
                                        std::hypot(s.x[i] - (0.5 * cfg.box.width + clump.offsetX[a]),
                                                   s.y[i] - (cfg.intruder.y0 + clump.offsetY[a])));
    EXPECT_LT(deepest, 0.01);
  }
  EXPECT_EQ(makeBed(config, square).stateHash(), first.world.stateHash());
  EXPECT_TRUE(obtainBed(config, square).fromCache);

  // Stopped while the carved bed relaxes: nothing of it is kept, and the next call carves it again
  // from the cached base, to the same bits.
  fs::remove(bedCachePath(config, bedKey(config, square)));
  {
    const StopSignalGuard guard;
    int reports = 0;
    EXPECT_THROW(obtainBed(config, square,
                           [&](const BedStatus& st) {
                             if (st.stage == BedStage::Relaxing && ++reports == 2) std::raise(SIGTERM);
                           }),
                 Error);
  }
  EXPECT_FALSE(fs::exists(bedCachePath(config, bedKey(config, square))));
  EXPECT_EQ(obtainBed(config, square).world.stateHash(), first.world.stateHash());
  fs::remove_all(scratch(""));
}

TEST(BedMaker, ThePaperScaleSweepsRunOnPaperTomlsBeds) {
  // The paper's figure sweeps stand for configs/paper.toml (the paper's stated protocol): each case on
  // the bed paper.toml pours for its shape and friction, for the paper's 1e7 steps. The study's own
  // paper-scale sweep is checked the same way in study/tests/StudySweepsTest.cpp.
  EXPECT_GE(
      testing_support::expectCasesOnPaperTomlsBeds(
          {"configs/sweeps/fig5_paper.toml", "configs/sweeps/fig6_paper.toml", "configs/sweeps/fig14_paper.toml"}),
      500);
}

}  // namespace
}  // namespace wiggle
