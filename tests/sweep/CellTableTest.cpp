// cells.csv (sweep/CellTable.h): a cell's mean, standard deviation and standard error over its beds,
// the verdict by the one rule (rises / sinks at |mean| >= 2 se with n >= 2, else not resolved; one
// bed is never a verdict), and the file's rows for a sweep with `beds = N`, part-run cells included.
#include "sweep/CellTable.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "io/SweepSpec.h"
#include "sweep/ResultsTable.h"

namespace wiggle {
namespace {

TEST(CellTable, TheVerdictIsTwoStandardErrorsOfTheCellsOwnBedsWithTwoBedsOrMore) {
  const CellStats none = cellStats({});
  EXPECT_EQ(none.n, 0u);
  EXPECT_EQ(none.verdict, CellVerdict::NotResolved);

  const CellStats one = cellStats({0.5});  // far from zero, but one bed: a sign, not a verdict
  EXPECT_EQ(one.n, 1u);
  EXPECT_EQ(one.mean, 0.5);
  EXPECT_EQ(one.verdict, CellVerdict::NotResolved);

  const CellStats rises = cellStats({0.09, 0.08, 0.10});
  EXPECT_NEAR(rises.mean, 0.09, 1e-15);
  EXPECT_NEAR(rises.sd, 0.01, 1e-15);
  EXPECT_NEAR(rises.se, 0.01 / std::sqrt(3.0), 1e-15);
  EXPECT_EQ(rises.verdict, CellVerdict::Rises);
  EXPECT_EQ(cellStats({-0.09, -0.08, -0.10}).verdict, CellVerdict::Sinks);

  // At the edge: two beds 0.1 and 0.3 have mean 0.2, sd 0.1414, se 0.1: |mean| = 2 se exactly.
  EXPECT_EQ(cellStats({0.1, 0.3}).verdict, CellVerdict::Rises);
  EXPECT_EQ(cellStats({0.1, 0.31}).verdict, CellVerdict::NotResolved);  // se 0.105 > mean / 2
  EXPECT_EQ(cellStats({-0.05, 0.05}).verdict, CellVerdict::NotResolved);
  EXPECT_EQ(cellStats({0.0, 0.0}).verdict, CellVerdict::NotResolved);  // no scatter, but no sign either

  EXPECT_EQ(cellState(0, 3), CellState::NotRun);
  EXPECT_EQ(cellState(2, 3), CellState::PartRun);
  EXPECT_EQ(cellState(3, 3), CellState::Done);
}

TEST(CellTable, OneBedIsSaidAsOneBedNeverAsAVerdict) {
  EXPECT_EQ(cellInWords(cellStats({0.0886}), 1), "+0.0886 (one bed: its sign is not a verdict)");
  EXPECT_EQ(cellInWords(cellStats({0.0886}), 2),
            "+0.0886 (one bed: its sign is not a verdict; part-run: 1 of its 2 beds)");
  EXPECT_EQ(cellInWords(cellStats({0.09, 0.08, 0.10}), 3), "+0.09 +- 0.0058 (3 beds): rises");
  EXPECT_EQ(cellInWords(cellStats({}), 2), "no bed run yet (of 2)");
}

TEST(CellTable, CellsCsvHasOneRowPerCellWithItsBedsAndTheRule) {
  const SweepSpec spec = parseSweepSpec("[sweep]\nbeds = 2\n[grid.drive]\nperiod = [1, 5]\n", "sweep.toml");
  auto ok = [](double vy) {
    CaseResult r;
    r.status = CaseStatus::Ok;
    r.summary.vy = vy;
    return r;
  };
  CaseResult failed;
  failed.status = CaseStatus::Failed;
  // period=1: both beds ok; period=5: one ok, one failed (a rerun retries it: part-run).
  const std::vector<CaseResult> results = {ok(-0.02), ok(-0.03), ok(0.09), failed};
  const std::vector<std::vector<std::string>> rows = parseCsv(cellsCsv(spec, results));
  ASSERT_EQ(rows.size(), 3u);
  const std::vector<std::string> header = {
      "cell", "drive.period", "intruder.shape", "drive.amplitude", "contact.mu", "state",       "beds",
      "n",    "vy_mean",      "vy_sd",          "vy_se",           "verdict",    "verdict_rule"};
  EXPECT_EQ(rows[0], header);  // results.csv's parameters less box.seed
  EXPECT_EQ(rows[1][0], "period=1");
  EXPECT_EQ(rows[1][1], "1");
  EXPECT_EQ(rows[1][5], "done");
  EXPECT_EQ(rows[1][6], "2");
  EXPECT_EQ(rows[1][7], "2");
  EXPECT_NEAR(std::stod(rows[1][8]), -0.025, 1e-12);
  EXPECT_NEAR(std::stod(rows[1][9]), std::sqrt(0.00005), 1e-10);
  EXPECT_NEAR(std::stod(rows[1][10]), 0.005, 1e-10);
  EXPECT_EQ(rows[1][11], "sinks");  // |-0.025| >= 2 x 0.005
  EXPECT_EQ(rows[1][12], kCellVerdictRule);
  EXPECT_EQ(rows[2][0], "period=5");
  EXPECT_EQ(rows[2][5], "part-run");
  EXPECT_EQ(rows[2][7], "1");
  EXPECT_EQ(rows[2][9], "");  // one bed: no standard deviation, no standard error, no verdict
  EXPECT_EQ(rows[2][10], "");
  EXPECT_EQ(rows[2][11], "not resolved");
}

}  // namespace
}  // namespace wiggle
