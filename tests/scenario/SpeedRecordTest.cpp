// The speed log behind the cost estimates (scenario/cost/SpeedRecord.h): what counts, the median of the
// last runs, and a record written by one run read back by the next estimate.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "physics/ForceKernels.h"
#include "scenario/cost/CostModel.h"
#include "scenario/cost/SpeedRecord.h"
#include "sweep/SweepPlan.h"

namespace wiggle {
namespace {

namespace fs = std::filesystem;

class SpeedRecordTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path().string() + "/wiggle-speed-test-" + std::to_string(::getpid());
    fs::remove_all(dir_);
    config_ = loadRunConfig(std::nullopt, {"bed.cache_dir=\"" + dir_ + "\""});
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string dir_;
  RunConfig config_;
};

TEST_F(SpeedRecordTest, NoLogMeansTheCommittedTablesFigureForTheBedsSize) {
  EXPECT_FALSE(measuredSpeed(config_, 3000.0));
  const SpeedBasis small = speedBasis(config_);
  EXPECT_EQ(small.ns, committedCostTable().nsPerParticleStep(estimatedParticles(config_)));
  EXPECT_NE(small.source.find("no one-thread run of a " + speedBuildKind() + " build recorded"), std::string::npos)
      << small.source;
  EXPECT_NE(small.source.find("bench/costs.csv"), std::string::npos) << small.source;
  // The paper's box costs more per particle-step than the default bed (its arrays outgrow the caches).
  const RunConfig paper = loadRunConfig(std::nullopt, {"bed.cache_dir=\"" + dir_ + "\"", "box.width=300", "box.bed_height=195"});
  EXPECT_GT(speedBasis(paper).ns, small.ns);
}

TEST(CostTable, ParsesTheRowsOfWiggleAtOneThreadAndInterpolatesBetweenBeds) {
  const CostTable t = parseCostTable(
      "bed,particles,threads,code,ns_per_particle_step,min,max,rounds,machine,source\n"
      "paper,60000,1,wiggle,40.0,39,41,3,\"CPU X, 2 vCPUs\",run A\n"
      "small,3000,1,wiggle,20.0,19,21,3,\"CPU X, 2 vCPUs\",run A\n"
      "small,3000,2,wiggle,12.0,11,13,3,\"CPU X, 2 vCPUs\",run A\n"
      "small,3000,1,lammps,70.0,69,71,3,\"CPU X, 2 vCPUs\",run A\n");
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.machine, "CPU X, 2 vCPUs");
  // The measured scaling: 20 / 12 at two threads on the small bed; the one bed measured is every
  // bed's figure; a count the table lacks is counted as the largest below it.
  EXPECT_EQ(t.measuredThreads(1), 1);
  EXPECT_EQ(t.measuredThreads(16), 2);
  EXPECT_DOUBLE_EQ(t.speedUp(3000.0, 1), 1.0);
  EXPECT_DOUBLE_EQ(t.speedUp(3000.0, 2), 20.0 / 12.0);
  EXPECT_DOUBLE_EQ(t.speedUp(3000.0, 16), 20.0 / 12.0);
  EXPECT_DOUBLE_EQ(t.speedUp(60000.0, 2), 40.0 / 12.0);  // a bed size it lacks at two: the one it has
  EXPECT_DOUBLE_EQ(t.nsPerParticleStep(1000.0), 20.0);     // below the smallest bed: its figure
  EXPECT_DOUBLE_EQ(t.nsPerParticleStep(31500.0), 30.0);    // half way
  EXPECT_DOUBLE_EQ(t.nsPerParticleStep(100000.0), 40.0);   // above the largest
  EXPECT_THROW(parseCostTable("bed,particles,threads,code\n"), Error);
  EXPECT_THROW(parseCostTable("bed,particles,threads,code,ns_per_particle_step,machine,source\nsmall,x,1,wiggle,20,m,s\n"),
               Error);
  // The committed table has the three presets' beds
  EXPECT_GE(committedCostTable().rows.size(), 3u);
}

TEST_F(SpeedRecordTest, TheMedianOfTheLastNineOneThreadRunsOnThisCpuByThisBuild) {
  fs::create_directories(dir_);
  std::ofstream log(dir_ + "/speed.log");
  const std::string cpu = cpuModel();
  const std::string kind = speedBuildKind();
  // 10 ... 120, by the CPU figure where a line has one (the even k) and else by the wall figure: the
  // last 9 are 40 ... 120; the lines between are not counted.
  for (int k = 1; k <= 12; ++k) {
    if (k % 2)
      log << cpu << "\t1\t" << 10 * k << "\t0.5\t" << kind << "\n";
    else
      log << cpu << "\t1\t" << 1000 * k << "\t3.5\t" << kind << "\t" << 10 * k << "\n";
    log << cpu << "\t1\t1\t0.5\tDebug/scalar\n" << cpu << "\t1\t1\t0.5\n";  // another build; no build kind
  }
  log << "Another CPU\t1\t1\t0\t" << kind << "\n" << cpu << "\t2\t1\t0\t" << kind << "\n";
  log << cpu << "\t1\tnot-a-number\t0\t" << kind << "\n" << cpu << "\t1";
  log.close();
  const auto m = measuredSpeed(config_, 3000.0);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->runs, 9u);
  EXPECT_DOUBLE_EQ(m->nsPerParticleStep, 80.0);
  EXPECT_FALSE(m->sameSize);  // no line says its bed's size
  EXPECT_EQ(speedBasis(config_).ns, 80.0);
  EXPECT_NE(speedBasis(config_).source.find("last 9 one-thread runs of a " + kind +
                                            " build (none yet on a bed of this size;"),
            std::string::npos)
      << speedBasis(config_).source;
}

TEST_F(SpeedRecordTest, TheBuildKindNamesTheBuildTypeAndTheKernels) {
  const std::string kind = speedBuildKind("avx2");
  EXPECT_GT(kind.find('/'), 0u) << kind;  // the build type before it
  EXPECT_EQ(kind.substr(kind.size() - 5), "/avx2") << kind;
  EXPECT_NE(kind, speedBuildKind("scalar"));
}

TEST_F(SpeedRecordTest, ARecordedRunIsReadBackByItsCpuFigure) {
  const std::string simd = simdLevelName(defaultSimdLevel());
  recordRunSpeed(config_, 1, 94.0, 23.5, simd, 3000);     // a quarter of a core: its wall figure is not its speed
  recordRunSpeed(config_, 2, 15.0, 29.0, simd, 3000);     // two threads: not a one-thread figure
  recordRunSpeed(config_, 1, 5.0, 5.0, "unknown", 3000);  // other kernels than an estimate's run would use
  recordRunSpeed(config_, 1, 24.5, 24.5, simd, 3000);
  const auto m = measuredSpeed(config_, 3000.0);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->runs, 2u);
  EXPECT_DOUBLE_EQ(m->nsPerParticleStep, 24.0);
  EXPECT_TRUE(m->sameSize);
  EXPECT_EQ(m->path, dir_ + "/speed.log");
}

// A particle-step costs more in a bed that outgrows the caches (the paper bed's 62,000 particles:
// 38 ns against 27-28 for 3,000-12,500 on one Zen 4 core), so an estimate takes the runs of beds of
// its own size when the log has any, and all of them when it has none.
TEST_F(SpeedRecordTest, RunsOfBedsOfTheEstimatesSizeComeFirst) {
  const std::string simd = simdLevelName(defaultSimdLevel());
  recordRunSpeed(config_, 1, 27.0, 27.0, simd, 3243);
  recordRunSpeed(config_, 1, 28.0, 28.0, simd, 3243);
  recordRunSpeed(config_, 1, 38.0, 38.0, simd, 62327);
  recordRunSpeed(config_, 1, 40.0, 40.0, simd, 62327);
  const auto paper = measuredSpeed(config_, 62000.0);
  ASSERT_TRUE(paper);
  EXPECT_TRUE(paper->sameSize);
  EXPECT_EQ(paper->runs, 2u);
  EXPECT_DOUBLE_EQ(paper->nsPerParticleStep, 39.0);
  const auto small = measuredSpeed(config_, 3243.0 * kSameSizeFactor);  // the factor's edge counts
  ASSERT_TRUE(small);
  EXPECT_TRUE(small->sameSize);
  EXPECT_DOUBLE_EQ(small->nsPerParticleStep, 27.5);
  const auto between = measuredSpeed(config_, 12500.0);  // 3.9 x the one, 0.2 x the other
  ASSERT_TRUE(between);
  EXPECT_FALSE(between->sameSize);
  EXPECT_EQ(between->runs, 4u);
  EXPECT_DOUBLE_EQ(between->nsPerParticleStep, 33.0);
}

// A machine that has run only small beds says how fast it is; the cost table says how a bigger bed
// slows every machine: each run counts scaled to the estimate's size by the table's curve.
TEST_F(SpeedRecordTest, RunsOfAnotherSizeCountScaledByTheTablesSizeDependence) {
  const std::string simd = simdLevelName(defaultSimdLevel());
  recordRunSpeed(config_, 1, 24.0, 24.0, simd, 3000);
  recordRunSpeed(config_, 1, 26.0, 26.0, simd, 3000);
  const auto curve = [](double n) { return n <= 3000.0 ? 20.0 : 40.0; };  // the table: twice the cost at 60,000
  const auto paper = measuredSpeed(config_, 60000.0, curve);
  ASSERT_TRUE(paper);
  EXPECT_FALSE(paper->sameSize);
  EXPECT_DOUBLE_EQ(paper->nsPerParticleStep, 50.0);  // 25 here where the table has 20: 50 where it has 40
  EXPECT_DOUBLE_EQ(measuredSpeed(config_, 60000.0)->nsPerParticleStep, 25.0);  // unscaled without the curve
  EXPECT_DOUBLE_EQ(measuredSpeed(config_, 3000.0, curve)->nsPerParticleStep, 25.0);
}

}  // namespace
}  // namespace wiggle
