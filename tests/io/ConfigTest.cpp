// Config: the key table against an independent list of RunConfig's fields, exact round trips,
// every class of error, and the precedence defaults < file < --set.
#include "io/Config.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include "core/Choice.h"
#include "core/Error.h"
#include "support/TestSupport.h"

namespace wiggle {
namespace {

bool sameBits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

// Written out by hand from RunConfig.h (not from the key table), so a field the table forgets or
// maps twice shows up here. Returns the names of the fields that differ (bitwise for doubles).
std::vector<std::string> differingFields(const RunConfig& a, const RunConfig& b) {
  std::vector<std::string> out;
  auto num = [&](const char* name, double x, double y) {
    if (!sameBits(x, y)) out.push_back(name);
  };
  auto other = [&](const char* name, bool equal) {
    if (!equal) out.push_back(name);
  };
  num("box.width", a.box.width, b.box.width);
  num("box.bedHeight", a.box.bedHeight, b.box.bedHeight);
  other("box.seed", a.box.seed == b.box.seed);
  num("grains.dMin", a.grains.dMin, b.grains.dMin);
  num("grains.dMax", a.grains.dMax, b.grains.dMax);
  other("grains.massModel", a.grains.massModel == b.grains.massModel);
  num("contact.kn", a.contact.kn, b.contact.kn);
  num("contact.kt", a.contact.kt, b.contact.kt);
  num("contact.gammaN", a.contact.gammaN, b.contact.gammaN);
  num("contact.gammaT", a.contact.gammaT, b.contact.gammaT);
  num("contact.mu", a.contact.mu, b.contact.mu);
  other("contact.law", a.contact.law == b.contact.law);
  other("intruder.shape", a.intruder.shape == b.intruder.shape);
  bool sameVertices = a.intruder.vertices.size() == b.intruder.vertices.size();
  for (std::size_t i = 0; sameVertices && i < a.intruder.vertices.size(); ++i) {
    sameVertices = sameBits(a.intruder.vertices[i][0], b.intruder.vertices[i][0]) &&
                   sameBits(a.intruder.vertices[i][1], b.intruder.vertices[i][1]);
  }
  other("intruder.vertices", sameVertices);
  num("intruder.angle", a.intruder.angle, b.intruder.angle);
  num("intruder.y0", a.intruder.y0, b.intruder.y0);
  num("intruder.mass", a.intruder.mass, b.intruder.mass);
  other("intruder.massRule", a.intruder.massRule == b.intruder.massRule);
  other("intruder.surface", a.intruder.surface == b.intruder.surface);
  other("intruder.contactMass", a.intruder.contactMass == b.intruder.contactMass);
  other("intruder.rotation", a.intruder.rotation == b.intruder.rotation);
  num("drive.amplitude", a.drive.amplitude, b.drive.amplitude);
  num("drive.period", a.drive.period, b.drive.period);
  other("drive.rampPeriods", a.drive.rampPeriods == b.drive.rampPeriods);
  other("drive.form", a.drive.form == b.drive.form);
  num("bed.batchHeight", a.bed.batchHeight, b.bed.batchHeight);
  other("bed.pour", a.bed.pour == b.bed.pour);
  other("bed.cavity", a.bed.cavity == b.bed.cavity);
  num("bed.pourFraction", a.bed.pourFraction, b.bed.pourFraction);
  num("bed.pourSpeed", a.bed.pourSpeed, b.bed.pourSpeed);
  num("bed.mu", a.bed.mu, b.bed.mu);
  num("bed.intruderMass", a.bed.intruderMass, b.bed.intruderMass);
  num("bed.settleSpeed", a.bed.settleSpeed, b.bed.settleSpeed);
  num("bed.restEnergy", a.bed.restEnergy, b.bed.restEnergy);
  num("bed.relaxDamping", a.bed.relaxDamping, b.bed.relaxDamping);
  num("bed.maxTime", a.bed.maxTime, b.bed.maxTime);
  other("bed.cacheDir", a.bed.cacheDir == b.bed.cacheDir);
  other("bed.file", a.bed.file == b.bed.file);
  other("bed.swapIntruder", a.bed.swapIntruder == b.bed.swapIntruder);
  other("bed.lammpsTypes", a.bed.lammpsTypes == b.bed.lammpsTypes);
  num("run.dt", a.run.dt, b.run.dt);
  num("run.duration", a.run.duration, b.run.duration);
  num("run.sampleInterval", a.run.sampleInterval, b.run.sampleInterval);
  num("run.checkpointInterval", a.run.checkpointInterval, b.run.checkpointInterval);
  num("run.dumpInterval", a.run.dumpInterval, b.run.dumpInterval);
  other("run.plot", a.run.plot == b.run.plot);
  other("run.keepBedHistory", a.run.keepBedHistory == b.run.keepBedHistory);
  other("run.profile", a.run.profile == b.run.profile);
  other("fields.enabled", a.fields.enabled == b.fields.enabled);
  bool samePhases = a.fields.phases.size() == b.fields.phases.size();
  for (std::size_t i = 0; samePhases && i < a.fields.phases.size(); ++i) {
    samePhases = sameBits(a.fields.phases[i], b.fields.phases[i]);
  }
  other("fields.phases", samePhases);
  num("fields.radius", a.fields.radius, b.fields.radius);
  num("fields.spacing", a.fields.spacing, b.fields.spacing);
  num("fields.width", a.fields.width, b.fields.width);
  other("fields.kinetic", a.fields.kinetic == b.fields.kinetic);
  num("engine.skin", a.engine.skin, b.engine.skin);
  num("engine.intruderSkin", a.engine.intruderSkin, b.engine.intruderSkin);
  other("engine.sortInterval", a.engine.sortInterval == b.engine.sortInterval);
  return out;
}

// Every TOML key (docs/CONFIG.md names), a valid non-default value, and the field it must land in.
const std::vector<std::tuple<std::string, std::string, std::string>>& everyKey() {
  static const std::vector<std::tuple<std::string, std::string, std::string>> keys = {
      {"box.width", "61", "box.width"},
      {"box.bed_height", "51.5", "box.bedHeight"},
      {"box.seed", "17", "box.seed"},
      {"grains.d_min", "0.8", "grains.dMin"},
      {"grains.d_max", "1.2", "grains.dMax"},
      {"grains.mass_model", "disc", "grains.massModel"},
      {"contact.kn", "3e6", "contact.kn"},
      {"contact.kt", "3.5e6", "contact.kt"},
      {"contact.gamma_n", "100", "contact.gammaN"},
      {"contact.gamma_t", "200", "contact.gammaT"},
      {"contact.mu", "0.5", "contact.mu"},
      {"contact.law", "hooke", "contact.law"},
      {"intruder.shape", "triangle", "intruder.shape"},
      {"intruder.vertices", "[[0,0],[4,0],[0,3]]", "intruder.vertices"},
      {"intruder.angle", "30", "intruder.angle"},
      {"intruder.y0", "20", "intruder.y0"},
      {"intruder.mass", "40", "intruder.mass"},
      {"intruder.mass_rule", "glued_disk", "intruder.massRule"},
      {"intruder.surface", "glued", "intruder.surface"},
      {"intruder.contact_mass", "atom", "intruder.contactMass"},
      {"intruder.rotation", "free", "intruder.rotation"},
      {"drive.amplitude", "1", "drive.amplitude"},
      {"drive.period", "2", "drive.period"},
      {"drive.ramp_periods", "3", "drive.rampPeriods"},
      {"drive.form", "velocity", "drive.form"},
      {"bed.batch_height", "10", "bed.batchHeight"},
      {"bed.pour", "random", "bed.pour"},
      {"bed.cavity", "carved", "bed.cavity"},
      {"bed.pour_fraction", "0.45", "bed.pourFraction"},
      {"bed.pour_speed", "2", "bed.pourSpeed"},
      {"bed.settle_speed", "0.1", "bed.settleSpeed"},
      {"bed.rest_energy", "1e-5", "bed.restEnergy"},
      {"bed.relax_damping", "2", "bed.relaxDamping"},
      {"bed.max_time", "500", "bed.maxTime"},
      {"bed.mu", "0.3", "bed.mu"},
      {"bed.intruder_mass", "9.5", "bed.intruderMass"},
      {"bed.cache_dir", "/tmp/beds", "bed.cacheDir"},
      {"bed.file", "/tmp/bed.bin", "bed.file"},
      {"bed.swap_intruder", "true", "bed.swapIntruder"},
      {"bed.lammps_types", "\"1=grain 2=base 3=drop 4=base\"", "bed.lammpsTypes"},
      {"run.dt", "2e-4", "run.dt"},
      {"run.duration", "10", "run.duration"},
      {"run.sample_interval", "0.1", "run.sampleInterval"},
      {"run.checkpoint_interval", "60", "run.checkpointInterval"},
      {"run.dump_interval", "0", "run.dumpInterval"},
      {"run.plot", "false", "run.plot"},
      {"run.bed_history", "false", "run.keepBedHistory"},
      {"run.profile", "true", "run.profile"},
      {"fields.enabled", "false", "fields.enabled"},
      {"fields.phases", "[0, 5]", "fields.phases"},
      {"fields.radius", "10", "fields.radius"},
      {"fields.spacing", "0.25", "fields.spacing"},
      {"fields.width", "2", "fields.width"},
      {"fields.kinetic", "true", "fields.kinetic"},
      {"engine.skin", "0.3", "engine.skin"},
      {"engine.intruder_skin", "1.5", "engine.intruderSkin"},
      {"engine.sort_interval", "100", "engine.sortInterval"},
  };
  return keys;
}

using testing_support::errorOf;

std::string parseError(const std::string& toml) {
  return errorOf([&] { parseRunConfig(toml, "config.toml"); });
}

TEST(Config, KeyListIsExactlyTheSpecKeys) {
  std::set<std::string> expected;
  for (const auto& [key, value, field] : everyKey()) expected.insert(key);
  const std::vector<std::string> keys = configKeys();
  EXPECT_EQ(keys.size(), 57u);
  EXPECT_EQ(std::set<std::string>(keys.begin(), keys.end()), expected);
}

TEST(Config, EveryKeyReachesItsOwnFieldAndNoOther) {
  for (const auto& [key, value, field] : everyKey()) {
    RunConfig c;
    applyOverride(c, key + "=" + value);
    const std::vector<std::string> diff = differingFields(RunConfig{}, c);
    ASSERT_EQ(diff.size(), 1u) << key;
    EXPECT_EQ(diff[0], field) << key;
  }
}

// contact.law takes every registered law's word (physics/ContactLaws.h), the third one included.
TEST(Config, ContactLawTakesEveryLawsWord) {
  EXPECT_EQ(choiceNameList<ContactLaw>(), (std::vector<std::string_view>{"hertz", "hooke", "hertz_limit_damping"}));
  for (const std::string_view name : choiceNameList<ContactLaw>())
    EXPECT_EQ(choiceName(loadRunConfig(std::nullopt, {"contact.law=" + std::string(name)}).contact.law), name);
  EXPECT_EQ(loadRunConfig(std::nullopt, {"contact.law=hertz_limit_damping"}).contact.law,
            contactLaw<HertzLimitDampingLaw>);
}

TEST(Config, DefaultsAreValidAndNoPathMeansDefaults) {
  EXPECT_NO_THROW(validateRunConfig(RunConfig{}));
  const RunConfig c = loadRunConfig(std::nullopt, {});
  EXPECT_TRUE(differingFields(RunConfig{}, c).empty());
  EXPECT_TRUE(sameRunConfig(RunConfig{}, c));
}

TEST(Config, DefaultsRoundTripThroughToml) {
  const RunConfig c;
  const RunConfig back = parseRunConfig(toToml(c), "resolved.toml");
  EXPECT_TRUE(differingFields(c, back).empty());
}

TEST(Config, AwkwardValuesRoundTripBitForBit) {
  RunConfig c;
  c.box.width = 301;
  c.box.bedHeight = 0.1 + 0.2;  // 0.30000000000000004 needs 17 digits
  c.intruder.y0 = 0.1;
  c.box.seed = static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());
  c.grains.dMin = 1.0 / 3.0;
  c.grains.dMax = 2.0 / 3.0;
  c.grains.massModel = MassModel::Disc;
  c.contact.kn = 1e7 / 3.0;
  c.contact.kt = 123456789012345678.0;  // above 1e15: written in exponent form
  c.contact.gammaN = 0.0;
  c.contact.mu = 5e-324;  // smallest denormal
  c.intruder.shape = ShapeName::Polygon;
  c.intruder.vertices = {{0.0, -1e-300}, {4.25, 0.0}, {-0.0, 3.0 / 7.0}};
  c.intruder.angle = -0.0;
  c.intruder.mass = 1e300;
  c.drive.period = 0.3;  // 0.3 / 1e-4 = 2999.9999999999995: a whole number within round-off
  c.bed.cacheDir = "dir with \"quotes\", back\\slash, tab\t and \xc3\xa9";
  c.run.dumpInterval = 0.0;
  c.run.duration = 2e-4;
  c.run.sampleInterval = 1e-4;
  c.fields.phases = {0.1, 19.999999999999996, 0.0};
  c.engine.sortInterval = 1;
  ASSERT_NO_THROW(validateRunConfig(c));
  const std::string text = toToml(c);
  const RunConfig back = parseRunConfig(text, "resolved.toml");
  EXPECT_TRUE(differingFields(c, back).empty()) << text;
  EXPECT_EQ(toToml(back), text);
  EXPECT_TRUE(sameRunConfig(c, back));
  c.intruder.angle = 0.0;  // -0 and +0 are different bits, so not the same config
  EXPECT_FALSE(sameRunConfig(c, back));
}

TEST(Config, RandomDoublesRoundTripBitForBit) {
  std::mt19937_64 rng(12345);
  for (int i = 0; i < 500; ++i) {
    double v = std::bit_cast<double>(rng());
    if (!std::isfinite(v)) continue;
    RunConfig c;
    c.intruder.angle = v;                  // any finite value allowed
    c.contact.kn = std::fabs(v) > 0 ? std::fabs(v) : 1.0;
    const RunConfig back = parseRunConfig(toToml(c), "r.toml");
    ASSERT_TRUE(sameBits(back.intruder.angle, v)) << v;
    ASSERT_TRUE(sameBits(back.contact.kn, c.contact.kn));
  }
}

TEST(Config, ToTomlCommentsEveryKeyWithItsUnit) {
  const std::string text = toToml(RunConfig{});
  for (const auto& [key, value, field] : everyKey()) {
    const std::string leaf = key.substr(key.find('.') + 1);
    EXPECT_NE(text.find("\n" + leaf + " = "), std::string::npos) << key;
  }
  EXPECT_NE(text.find("[drive]\namplitude = 3.0"), std::string::npos);
  EXPECT_NE(text.find("period = 5.0"), std::string::npos);
  EXPECT_NE(text.find("[sqrt(d/g)]"), std::string::npos);
}

TEST(Config, FileValuesAreApplied) {
  const RunConfig c = parseRunConfig(
      "[drive]\nperiod = 2   # an integer where a real number is expected\namplitude = 0.5\n"
      "[intruder]\nshape = \"polygon\"\nvertices = [[0, 0], [4, 0], [0, 3]]\n"
      "[fields]\nphases = [0, 10]\n[box]\nseed = 99\n",
      "config.toml");
  EXPECT_EQ(c.drive.period, 2.0);
  EXPECT_EQ(c.drive.amplitude, 0.5);
  EXPECT_EQ(c.intruder.shape, ShapeName::Polygon);
  ASSERT_EQ(c.intruder.vertices.size(), 3u);
  EXPECT_EQ(c.intruder.vertices[1][0], 4.0);
  EXPECT_EQ(c.intruder.vertices[2][1], 3.0);
  EXPECT_EQ(c.fields.phases, (std::vector<double>{0, 10}));
  EXPECT_EQ(c.box.seed, 99u);
  EXPECT_EQ(c.run.dt, 1e-4);  // untouched keys keep their defaults
}

// A file, its expected error substring.
struct BadCase {
  const char* toml;
  const char* message;
};

class ConfigErrors : public ::testing::TestWithParam<BadCase> {};

TEST_P(ConfigErrors, NameTheKeyAndTheProblem) {
  const std::string message = parseError(GetParam().toml);
  EXPECT_NE(message.find(GetParam().message), std::string::npos) << "got: " << message;
  EXPECT_EQ(message.rfind("config.toml", 0), 0u) << message;  // the file comes first
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;  // one line
}

INSTANTIATE_TEST_SUITE_P(
    Each, ConfigErrors,
    ::testing::Values(
        BadCase{"[drive]\nperiod = -1\n", "config.toml:2: drive.period = -1: must be > 0"},
        BadCase{"[drive]\nperiod = 0\n", "drive.period = 0: must be > 0"},
        BadCase{"[drive]\nperod = 5\n", "unknown key 'drive.perod' (did you mean 'drive.period'?)"},
        BadCase{"[drvie]\nperiod = 5\n", "unknown section 'drvie' (did you mean 'drive'?)"},
        BadCase{"[physics]\ng = 1\n", "unknown section 'physics'"},
        BadCase{"[box]\ndt = 1e-4\n", "unknown key 'box.dt' (did you mean 'run.dt'?)"},
        BadCase{"period = 5\n", "unknown key 'period' (did you mean 'drive.period'?)"},
        BadCase{"drive = 5\n", "'drive' must be a table"},
        BadCase{"[drive.sub]\nx = 1\n", "unknown key 'drive.sub'"},
        BadCase{"[box]\nwidth = \"sixty\"\n", "box.width = \"sixty\": expected a number, got string"},
        BadCase{"[run]\nplot = 1\n", "run.plot = 1: expected true or false, got integer"},
        BadCase{"[box]\nseed = 1.5\n", "box.seed = 1.5: expected an integer, got floating-point number"},
        BadCase{"[box]\nseed = -2\n", "box.seed = -2: must be >= 0"},
        BadCase{"[intruder]\nshape = 3\n", "intruder.shape = 3: expected one of disk"},
        BadCase{"[box]\nwidth = 60\n\n[drive]\nperiod = = 5\n", "config.toml:5:"},
        BadCase{"[box]\nwidth = 60\n\n[drive]\nperiod = = 5\n", "TOML syntax error"},
        BadCase{"[box\n", "config.toml:1:"},
        BadCase{"[drive]\nperiod = nan\n", "drive.period = nan: must be a finite number"},
        BadCase{"[drive]\namplitude = inf\n", "drive.amplitude = inf: must be a finite number"},
        BadCase{"[intruder]\nangle = -inf\n", "intruder.angle = -inf: must be a finite number"},
        BadCase{"[grains]\nd_min = 0\n", "grains.d_min = 0: must be > 0"},
        BadCase{"[grains]\nd_min = 1.0\nd_max = 0.95\n", "grains.d_max = 0.95: must be >= grains.d_min (1)"},
        BadCase{"[grains]\nmass_model = \"cube\"\n", "grains.mass_model = \"cube\": must be one of sphere, disc"},
        // A name no shape has (not "hexagon": CONTRIBUTING.md's example of a new one); the names the
        // message lists follow the table, ChoiceNames<ShapeName>, and the help's test checks them all.
        BadCase{"[intruder]\nshape = \"blob\"\n", "intruder.shape = \"blob\": must be one of disk, "},
        BadCase{"[intruder]\nshape = \"polygon\"\n", "intruder.vertices: shape = \"polygon\" needs at least 3"},
        BadCase{"[intruder]\nshape = \"polygon\"\nvertices = [[0, 0], [1, 0]]\n", "needs at least 3 [x, y] pairs, got 2"},
        BadCase{"[intruder]\nvertices = [[0, 0], [1, 0], [0, 1]]\n", "intruder.vertices: only used with shape = \"polygon\""},
        BadCase{"[intruder]\nshape = \"polygon\"\nvertices = [[0, 0], [1, 0, 2], [0, 1]]\n", "element 2: expected an [x, y] pair"},
        BadCase{"[intruder]\nshape = \"polygon\"\nvertices = [[0, 0], [1, \"a\"], [0, 1]]\n", "element 2: expected an [x, y] pair"},
        BadCase{"[intruder]\nshape = \"polygon\"\nvertices = [[0, 0], [1, nan], [0, 1]]\n", "element 2 must be finite"},
        BadCase{"[intruder]\ny0 = 0\n", "intruder.y0 = 0: must be > 0"},
        BadCase{"[intruder]\ny0 = 50\n", "intruder.y0 = 50: must be < box.bed_height (50)"},
        BadCase{"[intruder]\nmass = -1\n", "intruder.mass = -1: must be >= 0"},
        BadCase{"[drive]\namplitude = -0.5\n", "drive.amplitude = -0.5: must be >= 0"},
        BadCase{"[drive]\nform = \"velocity\"\nramp_periods = 2\n",
                "drive.ramp_periods = 2: only with drive.form = \"displacement\""},
        BadCase{"[drive]\nform = \"speed\"\n", "drive.form"},
        BadCase{"[contact]\nlaw = \"linear\"\n", "contact.law"},
        BadCase{"[drive]\nperiod = 5.00005\n", "drive.period = 5.00005: must be a whole number of run.dt steps"},
        BadCase{"[drive]\nperiod = 0.00005\n", "drive.period = 0.00005: must be a whole number of run.dt steps"},
        BadCase{"[run]\ndt = 0\n", "run.dt = 0: must be > 0"},
        BadCase{"[run]\nduration = 0.00005\n", "run.duration = 0.00005: must be >= run.dt (0.0001)"},
        BadCase{"[run]\nduration = 0.05\n",
                "run.duration = 0.05: shorter than two run.sample_interval (0.05), too few trajectory samples to "
                "measure a rise rate"},
        BadCase{"[run]\nduration = -1\n", "run.duration = -1: must be > 0"},
        BadCase{"[run]\nsample_interval = 0.00015\n", "run.sample_interval = 0.00015: must be a whole number of run.dt steps"},
        BadCase{"[run]\nduration = 0.50005\n", "run.duration = 0.50005: must be a whole number of run.dt steps"},
        BadCase{"[run]\nsample_interval = 0\n", "run.sample_interval = 0: must be > 0"},
        BadCase{"[run]\ndump_interval = 0.33333\n", "run.dump_interval = 0.33333: must be 0 or a whole number"},
        BadCase{"[run]\ncheckpoint_interval = 0\n", "run.checkpoint_interval = 0: must be > 0"},
        BadCase{"[box]\nwidth = 60.5\n", "box.width = 60.5: must be a whole number"},
        BadCase{"[box]\nwidth = -60\n", "box.width = -60: must be > 0"},
        BadCase{"[box]\nbed_height = 0\n", "box.bed_height = 0: must be > 0"},
        BadCase{"[fields]\nphases = [0, 20]\n", "fields.phases = [0, 20]: element 2 must be >= 0 and < 20"},
        BadCase{"[fields]\nphases = [-1]\n", "element 1 must be >= 0 and < 20"},
        BadCase{"[fields]\nphases = [0, \"5\"]\n", "element 2: expected a number, got string"},
        BadCase{"[fields]\nphases = 5\n", "fields.phases = 5: expected an array of numbers, got integer"},
        BadCase{"[contact]\nkn = 0\n", "contact.kn = 0: must be > 0"},
        BadCase{"[contact]\nkt = -1\n", "contact.kt = -1: must be > 0"},
        BadCase{"[contact]\ngamma_n = -1\n", "contact.gamma_n = -1: must be >= 0"},
        BadCase{"[contact]\ngamma_t = -1\n", "contact.gamma_t = -1: must be >= 0"},
        BadCase{"[contact]\nmu = -0.1\n", "contact.mu = -0.1: must be >= 0"},
        BadCase{"[engine]\nsort_interval = 0\n", "engine.sort_interval = 0: must be >= 1"},
        BadCase{"[bed]\ncache_dir = 5\n", "bed.cache_dir = 5: expected a string, got integer"},
        BadCase{"[bed]\npour = \"funnel\"\n", "bed.pour = \"funnel\": must be one of lattice, random"},
        BadCase{"[bed]\ncavity = \"dug\"\n", "bed.cavity = \"dug\": must be one of poured, carved"},
        BadCase{"[bed]\npour_fraction = 0\n", "bed.pour_fraction = 0: must be > 0 and <= 0.6"},
        BadCase{"[bed]\npour_fraction = 0.61\n", "bed.pour_fraction = 0.61: must be > 0 and <= 0.6"},
        BadCase{"[bed]\npour_speed = -1\n", "bed.pour_speed = -1: must be >= 0"}),
    // Named by position: the default name would be the struct's bytes (pointers, different in every
    // build), which CTest then uses as the test's name.
    [](const ::testing::TestParamInfo<BadCase>& info) { return "case_" + std::to_string(info.index); });

TEST(Config, BoundaryValuesThatAreAllowed) {
  EXPECT_NO_THROW(parseRunConfig("[drive]\namplitude = 0\n", "c.toml"));
  EXPECT_NO_THROW(parseRunConfig("[bed]\npour = \"random\"\npour_fraction = 0.6\npour_speed = 0\n", "c.toml"));
  EXPECT_NO_THROW(parseRunConfig("[contact]\nmu = 0\ngamma_n = 0\ngamma_t = 0\n", "c.toml"));
  EXPECT_NO_THROW(parseRunConfig("[fields]\nphases = [0, 19.99]\n", "c.toml"));
  EXPECT_NO_THROW(parseRunConfig("[fields]\nphases = []\n", "c.toml"));
  EXPECT_NO_THROW(parseRunConfig("[run]\nduration = 0.0002\nsample_interval = 0.0001\ndump_interval = 0\n", "c.toml"));
  EXPECT_NO_THROW(parseRunConfig("[run]\nduration = 0.1\n", "c.toml"));  // t = 0, 0.05, 0.1: three samples
  EXPECT_NO_THROW(parseRunConfig("[grains]\nd_min = 1\nd_max = 1\n", "c.toml"));
  // Whole numbers of steps up to round-off: 0.3 / 1e-4 and 0.07 / 1e-4 are not exact in binary.
  EXPECT_NO_THROW(parseRunConfig("[drive]\nperiod = 0.3\n[run]\nsample_interval = 0.07\n", "c.toml"));
  EXPECT_NO_THROW(parseRunConfig("[drive]\nperiod = 0.25\n[run]\ndt = 0.001\n", "c.toml"));
}

TEST(Config, ValidateChecksConfigsBuiltInCode) {
  RunConfig c;
  c.run.dt = -1e-4;
  EXPECT_NE(errorOf([&] { validateRunConfig(c); }).find("run.dt = -0.0001: must be > 0"), std::string::npos);
  c = RunConfig{};
  c.intruder.shape = static_cast<ShapeName>(17);  // not a shape: a cast in code, or a corrupt file
  EXPECT_NE(errorOf([&] { validateRunConfig(c); }).find("intruder.shape = \"(no such value)\": must be one of"),
            std::string::npos);
  c = RunConfig{};
  c.box.seed = ~std::uint64_t{0};  // cannot be written as a TOML integer
  EXPECT_NE(errorOf([&] { validateRunConfig(c); }).find("box.seed"), std::string::npos);
  c = RunConfig{};
  c.contact.kn = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(errorOf([&] { validateRunConfig(c); }).find("contact.kn = nan: must be a finite number"),
            std::string::npos);
}

TEST(Config, SetValuesAreReadAsToml) {
  RunConfig c;
  applyOverride(c, "drive.period=5");
  EXPECT_EQ(c.drive.period, 5.0);
  applyOverride(c, "intruder.shape=triangle");  // bare word: a string
  EXPECT_EQ(c.intruder.shape, ShapeName::Triangle);
  applyOverride(c, "intruder.shape=\"square\"");
  EXPECT_EQ(c.intruder.shape, ShapeName::Square);
  applyOverride(c, " intruder.vertices = [[0,0],[4,0],[0,3]] ");
  ASSERT_EQ(c.intruder.vertices.size(), 3u);
  EXPECT_EQ(c.intruder.vertices[2][1], 3.0);
  applyOverride(c, "fields.phases=[0,5]");
  EXPECT_EQ(c.fields.phases, (std::vector<double>{0, 5}));
  applyOverride(c, "run.dt=.5");  // not TOML, but a number
  EXPECT_EQ(c.run.dt, 0.5);
  applyOverride(c, "run.plot=false");
  EXPECT_FALSE(c.run.plot);
  applyOverride(c, "bed.cache_dir=/tmp/my beds");
  EXPECT_EQ(c.bed.cacheDir, "/tmp/my beds");
  applyOverride(c, "box.seed=12345678901234");
  EXPECT_EQ(c.box.seed, 12345678901234u);
}

TEST(Config, SetErrors) {
  RunConfig c;
  EXPECT_NE(errorOf([&] { applyOverride(c, "drive.period"); }).find("expected section.key=value"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { applyOverride(c, "drive.perod=5"); })
                .find("--set: unknown key 'drive.perod' (did you mean 'drive.period'?)"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { applyOverride(c, "drive.period=-1"); }).find("--set: drive.period = -1: must be > 0"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { applyOverride(c, "box.width=abc"); })
                .find("box.width = \"abc\": expected a number, got string"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { applyOverride(c, "fields.phases=[0,5"); }).find("not a TOML value"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { applyOverride(c, "drive.period=inf"); }).find("must be a finite number"),
            std::string::npos);
}

class TempFile {
 public:
  explicit TempFile(const std::string& text)
      : path_(std::filesystem::temp_directory_path() /
              ("wiggle_config_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
               "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".toml")) {
    std::ofstream(path_) << text;
  }
  ~TempFile() { std::filesystem::remove(path_); }
  std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

TEST(Config, SetTakesPrecedenceOverTheFileInOrder) {
  TempFile file("[drive]\nperiod = 2\namplitude = 1\n[intruder]\nshape = \"square\"\n");
  const RunConfig fromFile = loadRunConfig(file.path(), {});
  EXPECT_EQ(fromFile.drive.period, 2.0);
  EXPECT_EQ(fromFile.intruder.shape, ShapeName::Square);
  const RunConfig c = loadRunConfig(file.path(), {"drive.period=4", "intruder.shape=disk", "drive.period=8"});
  EXPECT_EQ(c.drive.period, 8.0);     // the last --set wins
  EXPECT_EQ(c.drive.amplitude, 1.0);  // the file where --set is silent
  EXPECT_EQ(c.intruder.shape, ShapeName::Disk);
  EXPECT_EQ(c.run.duration, 100.0);   // the default where both are silent
  const RunConfig noFile = loadRunConfig(std::nullopt, {"drive.period=1"});
  EXPECT_EQ(noFile.drive.period, 1.0);
  EXPECT_EQ(noFile.drive.amplitude, 3.0);
}

TEST(Config, LoadErrorsNameTheSource) {
  TempFile file("[drive]\nperiod = 5\n");
  // Cross-key checks run after --set: a dt that does not divide the file's period.
  const std::string m = errorOf([&] { loadRunConfig(file.path(), {"run.dt=0.3"}); });
  EXPECT_EQ(m.rfind(file.path() + " with --set: drive.period = 5: must be a whole number", 0), 0u) << m;
  TempFile bad("[drive]\nperiod = -3\n");
  EXPECT_EQ(errorOf([&] { loadRunConfig(bad.path(), {}); }), bad.path() + ":2: drive.period = -3: must be > 0");
}

// Issue 53: a config that cannot be read says why, whoever names it (the command checks its paths
// first; the Python module and sweeps read through the same loader).
TEST(Config, UnreadableConfigSaysWhy) {
  EXPECT_EQ(errorOf([] { loadRunConfig(std::string("/nonexistent/x.toml"), {}); }),
            "cannot read config file '/nonexistent/x.toml': No such file or directory");
  // A directory: a stream would read it as an empty file, that is as the default case.
  const std::string dir = std::string(WIGGLE_SOURCE_DIR) + "/configs";
  EXPECT_EQ(errorOf([&] { loadRunConfig(dir, {}); }), "cannot read config file '" + dir + "': Is a directory");
  if (geteuid() != 0) {  // root reads any file
    TempFile locked("[drive]\nperiod = 5\n");
    std::filesystem::permissions(locked.path(), std::filesystem::perms::none);
    EXPECT_EQ(errorOf([&] { loadRunConfig(locked.path(), {}); }),
              "cannot read config file '" + locked.path() + "': Permission denied");
  }
}

TEST(Config, HelpListsEveryKeyWithDefaultAndUnit) {
  const std::string help = configHelp();
  for (const auto& [key, value, field] : everyKey()) {
    const std::string section = key.substr(0, key.find('.'));
    const std::string leaf = key.substr(key.find('.') + 1);
    const auto at = help.find("[" + section + "]");
    ASSERT_NE(at, std::string::npos) << section;
    EXPECT_NE(help.find("  " + leaf + " = ", at), std::string::npos) << key;
  }
  EXPECT_NE(help.find("period = 5.0"), std::string::npos);
  EXPECT_NE(help.find("[sqrt(d/g)]"), std::string::npos);
  // Every shape in the one table of their names, so a new named shape needs no edit here.
  EXPECT_NE(help.find("one of " + joinedNames(choiceNameList<ShapeName>(), " | ")), std::string::npos);
}

TEST(Config, ValueStringsForColumnsAndNames) {
  RunConfig c;
  EXPECT_EQ(configValueString(c, "drive.period"), "5");
  EXPECT_EQ(configValueString(c, "run.dt"), "0.0001");
  c.bed.restEnergy = 1e-8;
  EXPECT_EQ(configValueString(c, "bed.rest_energy"), "1e-08");
  EXPECT_EQ(configValueString(c, "intruder.shape"), "disk");
  EXPECT_EQ(configValueString(c, "grains.mass_model"), "sphere");
  EXPECT_EQ(configValueString(c, "fields.phases"), "[0, 5, 10, 15, 19]");
  EXPECT_EQ(configValueString(c, "box.seed"), "1");
  EXPECT_EQ(configValueString(c, "run.plot"), "true");
  EXPECT_NE(errorOf([&] { configValueString(c, "drive.perod"); }).find("did you mean 'drive.period'"),
            std::string::npos);
}

TEST(Config, ShippedPresetsLoad) {
  const std::string dir = std::string(WIGGLE_SOURCE_DIR) + "/configs/";
  const RunConfig small = loadRunConfig(dir + "small.toml", {});
  EXPECT_EQ(small.box.width, 60.0);
  EXPECT_EQ(small.box.bedHeight, 50.0);
  EXPECT_EQ(small.intruder.y0, 25.0);
  EXPECT_EQ(small.drive.amplitude, 3.0);
  EXPECT_EQ(small.drive.period, 5.0);
  EXPECT_EQ(small.run.duration, 100.0);
  const RunConfig paper = loadRunConfig(dir + "paper.toml", {});
  EXPECT_EQ(paper.box.width, 300.0);
  EXPECT_EQ(paper.box.bedHeight, 195.0);
  EXPECT_EQ(paper.box.bedHeight - paper.intruder.y0, 105.0);  // docs/PHYSICS.md §2: 105 d below the surface
  EXPECT_EQ(paper.run.duration, 1000.0);
  EXPECT_EQ(paper.run.dt, 1e-4);
  EXPECT_EQ(paper.contact.mu, 0.1);
  // The paper's stated protocol (docs/PHYSICS.md §12): grains poured at random batch by batch, every
  // intruder of glued 0.5 d spheres with one mass for all shapes.
  EXPECT_EQ(paper.bed.pour, BedPour::Random);
  EXPECT_EQ(paper.bed.cavity, BedCavity::Poured);
  EXPECT_EQ(paper.intruder.surface, IntruderSurface::Glued);
  EXPECT_EQ(paper.intruder.massRule, MassRule::GluedDisk);
  EXPECT_EQ(paper.intruder.mass, 0.0);
}

TEST(Config, DocsListTheCurrentKeys) {
  // docs/CONFIG.md pastes configHelp(); regenerate that block when a key changes.
  std::ifstream in(std::string(WIGGLE_SOURCE_DIR) + "/docs/CONFIG.md");
  ASSERT_TRUE(in) << "docs/CONFIG.md missing";
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find(configHelp()), std::string::npos)
      << "docs/CONFIG.md does not contain the current configHelp() output";
}

}  // namespace
}  // namespace wiggle
