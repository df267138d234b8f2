// results.csv (sweep/ResultsTable.h): its columns come from one table, which docs/results-schema.json
// repeats for the Python package; a row's numbers are empty unless the case is ok.
#include "sweep/ResultsTable.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/SweepSpec.h"
#include "support/TestSupport.h"

namespace wiggle {
namespace {

using testing_support::sourceFile;

// The schema file the Python package is checked against is this table; on a change, replace
// docs/results-schema.json by the text this test prints.
TEST(ResultsTable, SchemaFileIsTheTable) {
  const std::string expected = resultsSchema().dump(2) + "\n";
  EXPECT_EQ(sourceFile("docs/results-schema.json"), expected) << "docs/results-schema.json should be:\n" << expected;
}

// The ETA's pace: a case paused for most of its wall time (SIGSTOP beside a benchmark) must not
// set the pace of the cases still to run, as the total time over the total work would (about 1000 ns
// here, against the 30 ns of every case that ran without a pause).
TEST(ResultsTable, ThePaceIsTheMedianCaseNotThePausedOne) {
  auto ok = [](double wallSeconds, double particleSteps) {
    CaseResult r;
    r.status = CaseStatus::Ok;
    r.summary.runWallSeconds = wallSeconds;
    r.summary.particles = 1;
    r.summary.steps = static_cast<std::uint64_t>(particleSteps);
    return r;
  };
  CaseResult pending;
  std::vector<CaseResult> results = {ok(300.0, 1e10), ok(30000.0, 1e10), ok(310.0, 1e10), pending};
  EXPECT_DOUBLE_EQ(sweepNsPerParticleStep(results, std::nullopt, 55.0), 31.0);
  results.push_back(ok(290.0, 1e10));
  EXPECT_DOUBLE_EQ(sweepNsPerParticleStep(results, std::nullopt, 55.0), 30.5);  // four: the mean of the middle two
  EXPECT_DOUBLE_EQ(sweepNsPerParticleStep({pending}, std::nullopt, 55.0), 55.0);  // none finished: the cost model's
}

// A --case task's pace is its own case's: the sweep's other cases may have run on another machine
// (here 1000 ns a particle-step, a slower one), so until its own finishes it is the cost model's.
TEST(ResultsTable, ACaseTaskPacesByItsOwnCaseOnly) {
  auto ok = [](double wallSeconds) {
    CaseResult r;
    r.status = CaseStatus::Ok;
    r.summary.runWallSeconds = wallSeconds;
    r.summary.particles = 1;
    r.summary.steps = 10'000'000'000;
    return r;
  };
  std::vector<CaseResult> results = {ok(10000.0), CaseResult{}, ok(10000.0)};
  EXPECT_DOUBLE_EQ(sweepNsPerParticleStep(results, std::size_t{1}, 55.0), 55.0);  // its own not finished
  EXPECT_DOUBLE_EQ(sweepNsPerParticleStep(results, std::nullopt, 55.0), 1000.0);   // the whole sweep's
  results[1] = ok(300.0);
  EXPECT_DOUBLE_EQ(sweepNsPerParticleStep(results, std::size_t{1}, 55.0), 30.0);
}

// A case stopped with the sweep says so once: "interrupted at t = 12.5", not "interrupted:
// interrupted at t = 12.5"; other words get the prefix.
TEST(ResultsTable, AnInterruptedCaseSaysSoOnce) {
  EXPECT_EQ(interruptedError("interrupted at t = 12.5 (checkpoint written)"), "interrupted at t = 12.5 (checkpoint written)");
  EXPECT_EQ(interruptedError("interrupted by signal 15 while making the bed"), "interrupted by signal 15 while making the bed");
  EXPECT_EQ(interruptedError("child exited with status 1"), "interrupted: child exited with status 1");
}

TEST(ResultsTable, QuotesCellsThatNeedIt) {
  EXPECT_EQ(csvCell("disk"), "disk");
  EXPECT_EQ(csvCell("[0, 5]"), "\"[0, 5]\"");
  EXPECT_EQ(csvCell("say \"hi\""), "\"say \"\"hi\"\"\"");
}

TEST(ResultsTable, RowsForPendingOkAndFailedCases) {
  const SweepSpec spec =
      parseSweepSpec("[[case]]\nname = \"deep\"\nintruder.y0 = 20\n[grid.drive]\nperiod = [1, 2, 3]\n", "t.toml");
  std::vector<CaseResult> results(3);
  results[0].status = CaseStatus::Ok;
  results[0].summary.vy = 0.125;
  results[0].summary.vySlope = -0.5;
  results[0].summary.vySettled = 0.25;
  results[0].summary.tSettled = 60;
  results[0].summary.wallSeconds = 3;
  results[0].summary.grains = 100;
  results[0].summary.steps = 2000;
  results[0].summary.stateHash = "abc";
  results[0].summary.warnings = {"one, with a comma", "two"};
  results[1].status = CaseStatus::Failed;
  results[1].error = "box.width = 5 is too narrow, really";
  const std::string csv = resultsCsv(spec, {"cases/a", "cases/b", "cases/c"}, results);
  const auto rows = parseCsv(csv);
  ASSERT_EQ(rows.size(), 4u);
  const std::vector<std::string> header = {"case",
                                           "run_dir",
                                           "status",
                                           "vy",
                                           "vy_slope",
                                           "vy_settled",
                                           "t_settled",
                                           "wall_s",
                                           "case_label",
                                           "intruder.y0",
                                           "drive.period",
                                           "intruder.shape",
                                           "drive.amplitude",
                                           "contact.mu",
                                           "box.seed",
                                           "n_grains",
                                           "steps",
                                           "ns_per_particle_step",
                                           "state_hash",
                                           "error",
                                           "warnings"};
  EXPECT_EQ(rows[0], header);
  EXPECT_EQ(rows[1], (std::vector<std::string>{"deep_period=1",
                                               "cases/a",
                                               "ok",
                                               "0.125",
                                               "-0.5",
                                               "0.25",
                                               "60",
                                               "3",
                                               "deep",
                                               "20",
                                               "1",
                                               "disk",
                                               "3",
                                               "0.1",
                                               "1",
                                               "100",
                                               "2000",
                                               "0",
                                               "abc",
                                               "",
                                               "one, with a comma | two"}));
  EXPECT_EQ(rows[2][2], "failed");
  EXPECT_EQ(rows[2][3], "");
  EXPECT_EQ(rows[2][rows[2].size() - 2], "box.width = 5 is too narrow, really");
  EXPECT_EQ(rows[2].back(), "");
  EXPECT_EQ(rows[3][2], "pending");
  EXPECT_EQ(rows[3][10], "3");
}

}  // namespace
}  // namespace wiggle
