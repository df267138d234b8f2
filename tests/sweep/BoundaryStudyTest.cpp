// `wiggle boundary`'s driver (sweep/BoundaryStudy.h) on a stand-in runner with a known V_y: the
// rounds, one search per --over value, the outputs and the sweep file the real runner writes. The
// same driver on real runs, resumed: SweepRunnerTest.BoundaryRunsAsASweepAndResumesWithTheSameDecisions.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <functional>

#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "io/SweepSpec.h"
#include "sweep/BoundaryStudy.h"

namespace wiggle {
namespace {

namespace fs = std::filesystem;

// V_y = f(value, over value) + a small bed-to-bed term that depends on the seed only.
class StandIn : public BoundaryRunner {
 public:
  explicit StandIn(std::function<double(double, double)> vy) : vy_(std::move(vy)) {}
  std::vector<BoundaryCaseOutcome> run(const BoundarySpec& spec, const std::vector<BoundaryCase>& all,
                                       std::size_t firstNew) override {
    ++rounds;
    std::vector<BoundaryCaseOutcome> out;
    for (std::size_t i = firstNew; i < all.size(); ++i) {
      const RunConfig c = boundaryCaseConfig(spec, all[i]);
      BoundaryCaseOutcome o;
      o.ok = !(failAt && std::fabs(c.drive.period - *failAt) < 1e-9);
      o.error = o.ok ? "" : "the simulation blew up";
      o.vy = vy_(c.drive.period, c.drive.amplitude) + 0.0002 * (static_cast<double>(c.box.seed % 3) - 1.0);
      o.wallSeconds = 10.0;
      out.push_back(o);
      ++runs;
    }
    return out;
  }
  int rounds = 0, runs = 0;
  std::optional<double> failAt;

 private:
  std::function<double(double, double)> vy_;
};

class BoundaryStudyTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path().string() + "/wiggle-boundary-study-" + std::to_string(::getpid());
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static BoundarySpec periodSearch() {
    BoundarySpec spec;
    spec.base = loadRunConfig(std::nullopt, {});
    spec.options.lo = 1.0;
    spec.options.hi = 5.0;
    spec.options.points = 5;
    spec.options.resolution = 0.1;
    return spec;
  }
  std::string dir_;
};

TEST_F(BoundaryStudyTest, OneSearchPerOverValueEachWithItsCrossing) {
  BoundarySpec spec = periodSearch();
  spec.overKey = "drive.amplitude";
  spec.overValues = {3.0, 5.0};
  // The crossing moves with the amplitude: T = 3.45 at A = 3, T = 2.25 at A = 5.
  StandIn runner([](double T, double A) { return 0.05 * (T - (5.25 - 0.6 * A)); });
  const BoundaryResult result = runBoundary(spec, runner, dir_);
  ASSERT_EQ(result.searches.size(), 2u);
  const auto at3 = result.searches[0].crossings(), at5 = result.searches[1].crossings();
  ASSERT_EQ(at3.size(), 1u);
  ASSERT_EQ(at5.size(), 1u);
  EXPECT_EQ(at3[0].from, Verdict::Sinking);
  EXPECT_DOUBLE_EQ(at3[0].below, 3.4);
  EXPECT_DOUBLE_EQ(at3[0].above, 3.5);
  EXPECT_DOUBLE_EQ(at5[0].below, 2.2);
  EXPECT_DOUBLE_EQ(at5[0].above, 2.3);
  // The two searches ran side by side: one round for the scan and one per bisection step, not
  // one set of rounds per search.
  EXPECT_LE(runner.rounds, 8);
  EXPECT_EQ(static_cast<std::size_t>(runner.runs), result.outcomes.size());

  const auto json = nlohmann::json::parse(readFile(dir_ + "/boundary.json"));
  EXPECT_EQ(json["key"], "drive.period");
  EXPECT_EQ(json["over_key"], "drive.amplitude");
  ASSERT_EQ(json["searches"].size(), 2u);
  EXPECT_EQ(json["searches"][1]["over"], 5.0);
  EXPECT_EQ(json["searches"][1]["crossings"][0]["below"], 2.2);
  EXPECT_EQ(json["searches"][1]["crossings"][0]["from"], "sinking");
  EXPECT_TRUE(json["searches"][0]["finished"].get<bool>());
  // Against a grid at the resolution (41 values) with the beds the search needed (2): 82 runs each.
  EXPECT_EQ(json["searches"][0]["grid"]["cases"], 82);
  EXPECT_LT(json["searches"][0]["cost"]["runs"].get<int>(), 30);

  const std::string csv = readFile(dir_ + "/boundary.csv");
  EXPECT_NE(csv.find("drive.amplitude,3,crossing,sinking,rising,3.4,3.5,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("drive.amplitude,5,crossing,sinking,rising,2.2,2.3,"), std::string::npos) << csv;
  const std::string lines = boundaryLines(spec, result);
  EXPECT_NE(lines.find("drive.amplitude = 3: sinking -> rising between drive.period = 3.4 and 3.5"), std::string::npos)
      << lines;
}

TEST_F(BoundaryStudyTest, AFailedRunIsSetAsideAndReported) {
  BoundarySpec spec = periodSearch();
  StandIn runner([](double T, double) { return 0.05 * (T - 2.75); });
  runner.failAt = 3.0;
  const BoundaryResult result = runBoundary(spec, runner, dir_);
  const auto crossings = result.searches[0].crossings();
  ASSERT_EQ(crossings.size(), 1u);
  EXPECT_DOUBLE_EQ(crossings[0].below, 2.7);
  EXPECT_DOUBLE_EQ(crossings[0].above, 2.8);
  const auto json = nlohmann::json::parse(readFile(dir_ + "/boundary.json"));
  bool reported = false;
  for (const auto& p : json["searches"][0]["probes"])
    if (p["value"] == 3.0) reported = p["verdict"] == "failed" && p["errors"][0] == "the simulation blew up";
  EXPECT_TRUE(reported);
  EXPECT_NE(boundaryLines(spec, result).find("the run at drive.period = 3 failed"), std::string::npos);
}

TEST_F(BoundaryStudyTest, NoCrossingIsSaidAsSuch) {
  BoundarySpec spec = periodSearch();
  StandIn runner([](double T, double) { return 0.1 + 0.01 * T; });
  const BoundaryResult result = runBoundary(spec, runner, dir_);
  EXPECT_EQ(result.outcomes.size(), 10u);  // the scan, two beds each, nothing to bisect
  EXPECT_NE(boundaryLines(spec, result).find("no crossing over drive.period = 1-5: rising throughout"),
            std::string::npos);
}

TEST_F(BoundaryStudyTest, ABandOfOneValueIsSaidAtThatValue) {
  BoundarySpec spec = periodSearch();
  StandIn runner([](double T, double) { return 0.1 * std::fabs(T - 3.0); });  // touches zero at T = 3 only
  const BoundaryResult result = runBoundary(spec, runner, dir_);
  const std::string lines = boundaryLines(spec, result);
  EXPECT_NE(lines.find("V_y indistinguishable from zero at drive.period = 3 (no change of sign across it)"),
            std::string::npos)
      << lines;
  EXPECT_EQ(lines.find("over drive.period = 3-3"), std::string::npos) << lines;
}

TEST_F(BoundaryStudyTest, TheSweepFileHoldsEveryRunInOrder) {
  BoundarySpec spec = periodSearch();
  spec.base.box.seed = 7;
  spec.overKey = "contact.mu";
  spec.overValues = {0.1, 0.5};
  const std::vector<BoundaryCase> cases = {{0, {2.7, 1}}, {1, {2.7, 2}}, {0, {5.0, 3}}};
  const SweepSpec sweep = parseSweepSpec(boundarySweepFile(spec, cases), "boundary.toml");
  ASSERT_EQ(sweep.cases.size(), cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i)
    EXPECT_TRUE(sameRunConfig(sweep.cases[i].config, boundaryCaseConfig(spec, cases[i]))) << i;
  EXPECT_EQ(sweep.cases[1].config.box.seed, 8u);  // bed 2 is the config's seed + 1
  EXPECT_EQ(sweep.cases[1].name, "mu=0.5_period=2.7_seed=8");
}

TEST_F(BoundaryStudyTest, EveryValueTheSearchMayProbeIsCheckedBeforeAnythingRuns) {
  BoundarySpec spec = periodSearch();
  spec.options.resolution = 0.00015;  // 1.00015 is not a whole number of run.dt = 1e-4 steps
  StandIn runner([](double T, double) { return T - 3; });
  try {
    runBoundary(spec, runner, dir_);
    FAIL() << "not refused";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("drive.period = 1.00015"), std::string::npos) << e.what();
  }
  EXPECT_EQ(runner.runs, 0);
  spec.options.resolution = 0.1;
  spec.key = "box.seed";
  EXPECT_THROW(checkBoundarySpec(spec), Error);  // not a real-valued key
  spec.key = "drive.period";
  spec.overKey = "drive.period";
  spec.overValues = {1.0};
  EXPECT_THROW(checkBoundarySpec(spec), Error);  // the same key twice
}

}  // namespace
}  // namespace wiggle
