// V_y after the fact (scenario/run/Remeasure.h, sweep/ResultsTable.h's refreshSettledColumns): a run
// directory as a finished run leaves it, with a synthetic trajectory whose settling is known.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/Error.h"
#include "core/Format.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "scenario/run/Remeasure.h"
#include "sweep/ResultsTable.h"

namespace wiggle {
namespace {

namespace fs = std::filesystem;

class Remeasure : public ::testing::Test {
 protected:
  void SetUp() override {
    char pattern[] = "/tmp/wiggle-remeasure-test-XXXXXX";
    ASSERT_NE(mkdtemp(pattern), nullptr);
    root_ = pattern;
  }
  void TearDown() override { fs::remove_all(root_); }

  // A finished run of the default case (T = 5, t = 100) whose intruder climbs 0.3 d per time unit
  // until t = 40 and then stays: settled a little before t = 40 by the settle rule.
  std::string finishedRun(const std::string& name) const {
    const std::string dir = (root_ / name).string();
    fs::create_directories(dir);
    RunConfig config;
    writeFileAtomically(dir + "/config.toml", toToml(config));
    std::vector<TrajectorySample> samples;
    for (int k = 0; k <= 2000; ++k) {
      const double t = 0.05 * k;
      samples.push_back({t, 30, 25 + 0.3 * std::min(t, 40.0) + 0.4 * std::sin(2 * M_PI * t / 5), 0, 0, 0});
    }
    writeTrajectoryCsv(dir + "/trajectory.csv", samples);
    const double vy = (samples.back().y - samples[200].y) / 90.0;
    writeFileAtomically(
        dir + "/summary.json",
        nlohmann::json{{"status", "ok"}, {"vy", vy}, {"vy_slope", vy}, {"t_f", 100.0}, {"n_grains", 7}}.dump());
    return dir;
  }
  fs::path root_;
};

TEST_F(Remeasure, BothRulesFromTheFilesOfAFinishedRun) {
  const Remeasured r = remeasureRun(finishedRun("run"), {});
  EXPECT_EQ(r.period, 5.0);
  EXPECT_DOUBLE_EQ(r.rate.tInitial, 10.0);
  EXPECT_DOUBLE_EQ(r.rate.tFinal, 100.0);
  EXPECT_TRUE(r.settled.settled);
  EXPECT_GT(r.settled.tSettled, 40 - 1 / 0.3 - 5);
  EXPECT_LE(r.settled.tSettled, 40);
  EXPECT_NEAR(r.settled.vy, 0.3, 0.8 / (r.settled.tSettled - 10));
}

TEST_F(Remeasure, AnyWindowWithinTheRun) {
  const std::string dir = finishedRun("run");
  RemeasureRequest request;
  request.to = 30;  // as if the run had ended at t = 30: t_i = 3, still climbing
  const Remeasured early = remeasureRun(dir, request);
  EXPECT_DOUBLE_EQ(early.rate.tInitial, 3.0);
  EXPECT_DOUBLE_EQ(early.rate.tFinal, 30.0);
  EXPECT_FALSE(early.settled.settled);
  request.from = 50;
  request.to = 100;
  const Remeasured late = remeasureRun(dir, request);  // after the climb: no motion
  EXPECT_NEAR(late.rate.vy, 0.0, 0.02);
  request.to = 150;
  EXPECT_THROW(remeasureRun(dir, request), Error);  // past the run's end
  request.from = 80;
  request.to = 60;
  EXPECT_THROW(remeasureRun(dir, request), Error);
  EXPECT_THROW(remeasureRun((root_ / "nothing").string(), {}), Error);
}

TEST_F(Remeasure, ACorruptTrajectoryIsNamed) {
  const std::string dir = finishedRun("run");
  std::ofstream(dir + "/trajectory.csv", std::ios::app) << "1000,1,2,x,4,5\n";
  try {
    remeasureRun(dir, {});
    FAIL() << "a corrupt trajectory.csv was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("trajectory.csv: line 2003"), std::string::npos) << e.what();
  }
}

TEST_F(Remeasure, RecordingKeepsEveryOtherKeyAndTheRunsOwnVyWhenUnsettled) {
  const std::string dir = finishedRun("run");
  const Remeasured r = remeasureRun(dir, {});
  recordSettled(dir, r.settled, SettleRule{});
  nlohmann::json j = nlohmann::json::parse(readFile(dir + "/summary.json"));
  EXPECT_EQ(j["vy_settled"].get<double>(), r.settled.vy);
  EXPECT_EQ(j["t_settled"].get<double>(), r.settled.tSettled);
  EXPECT_EQ(j["settled"].get<bool>(), true);
  EXPECT_EQ(j["settle_band"].get<double>(), 1.0);
  EXPECT_EQ(j["n_grains"].get<int>(), 7);
  EXPECT_EQ(j.size(), 9u);

  SettledRate unsettled;  // as the rule reports a run that never settled: the file's own vy and t_f
  unsettled.vy = 0.123456789012;
  unsettled.tSettled = 99.99;
  recordSettled(dir, unsettled, SettleRule{});
  j = nlohmann::json::parse(readFile(dir + "/summary.json"));
  EXPECT_EQ(j["vy_settled"], j["vy"]);
  EXPECT_EQ(j["t_settled"], j["t_f"]);
  EXPECT_EQ(j["settled"].get<bool>(), false);
  EXPECT_THROW(recordSettled((root_ / "nothing").string(), unsettled, SettleRule{}), Error);
}

TEST_F(Remeasure, AnOlderResultsTableGetsTheTwoColumnsAfterVySlope) {
  const std::string sweep = (root_ / "sweep").string();
  fs::create_directories(sweep + "/cases");
  const std::string a = finishedRun("sweep/cases/a");
  const Remeasured r = remeasureRun(a, {});
  recordSettled(a, r.settled, SettleRule{});
  writeFileAtomically(sweep + "/results.csv",
                      "case,run_dir,status,vy,vy_slope,wall_s,error\n"
                      "a,cases/a,ok,0.1,0.2,3,\n"
                      "b,cases/b,failed,,,,\"no bed, really\"\n");
  refreshSettledColumns(sweep);
  const auto rows = parseCsv(readFile(sweep + "/results.csv"));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"case", "run_dir", "status", "vy", "vy_slope", "vy_settled", "t_settled",
                                               "wall_s", "error"}));
  EXPECT_EQ(std::stod(rows[1][5]), std::stod(formatNumber(r.settled.vy, 10)));
  EXPECT_EQ(std::stod(rows[1][6]), std::stod(formatNumber(r.settled.tSettled, 10)));
  EXPECT_EQ(rows[1][7], "3");
  EXPECT_EQ(rows[2], (std::vector<std::string>{"b", "cases/b", "failed", "", "", "", "", "", "no bed, really"}));
  const std::string once = readFile(sweep + "/results.csv");
  refreshSettledColumns(sweep);  // a second time changes nothing
  EXPECT_EQ(readFile(sweep + "/results.csv"), once);
}

}  // namespace
}  // namespace wiggle
