// The study's sweeps (study/sweeps/): each expands, and each stands for what its results are read as
// (the preset's beds, the paper's beds, a longer run of a shorter study's cases). Label "study".
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>
#include <tuple>

#include "io/Config.h"
#include "io/SweepSpec.h"
#include "scenario/bed/BedMaker.h"
#include "scenario/run/Experiment.h"
#include "support/PaperBeds.h"

namespace wiggle {
namespace {

const std::string kStudySweeps = std::string(WIGGLE_SOURCE_DIR) + "/study/sweeps/";

TEST(StudySweeps, EverySweepFileExpands) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kStudySweeps)) {
    if (entry.path().extension() != ".toml") continue;
    EXPECT_NO_THROW(loadSweepSpec(entry.path().string())) << entry.path();
    ++files;
  }
  EXPECT_GE(files, 30);
}

TEST(StudySweeps, PaperDepthSweepsRunOnThePresetsBeds) {
  // The study's results under results/paper_depth/ stand for configs/paper_depth.toml only if its
  // sweeps pour the preset's beds: the same bed key once the preset takes the case's shape, seed and
  // width (the keys the box and seed studies vary on purpose).
  const RunConfig preset = loadRunConfig(std::string(WIGGLE_SOURCE_DIR) + "/configs/paper_depth.toml", {});
  EXPECT_EQ(preset.box.bedHeight - preset.intruder.y0, 105.0);  // the paper's depth
  int compared = 0;
  for (const char* file :
       {"paper_depth_box.toml", "paper_depth_seeds.toml", "paper_depth_table1.toml", "paper_depth_runlength.toml",
        "paper_depth_table1_bed2.toml", "paper_depth_fig5.toml", "paper_depth_fig5_bed2.toml", "paper_depth_t1000.toml",
        "paper_depth_fig2_t1000.toml", "paper_depth_t1000_bed2.toml", "paper_depth_velocity.toml",
        "paper_depth_fields.toml",
        "paper_depth_friction.toml",       // the friction study at every mu on the preset's beds (bed.mu)
        "paper_depth_mass_t1000.toml"}) {  // the glued disk's mass on the preset's beds (bed.intruder_mass)
    for (const SweepCase& c : loadSweepSpec(kStudySweeps + file).cases) {
      RunConfig expected = preset;
      expected.box.width = c.config.box.width;
      expected.box.seed = c.config.box.seed;
      expected.intruder.shape = c.config.intruder.shape;
      EXPECT_EQ(bedKey(c.config, prepareCase(c.config).clump), bedKey(expected, prepareCase(expected).clump))
          << file << ", case " << c.name;
      ++compared;
    }
  }
  EXPECT_GE(compared, 30);
}

TEST(StudySweeps, ThePaperBoxStudyRunsOnPaperTomlsBeds) {
  // results/paper_box/t1000 stands for configs/paper.toml (the paper's stated protocol) as the
  // figure sweeps do (tests/scenario/BedMakerTest.cpp): each case on the bed paper.toml pours.
  EXPECT_GE(testing_support::expectCasesOnPaperTomlsBeds({"study/sweeps/paper_box_t1000.toml"}), 7);
}

TEST(StudySweeps, TheT1000StudiesAreTheT100StudiesRunLonger) {
  // results/paper_depth/table1_t1000 (table1_t1000_bed2, fig2_t1000) read their first t = 100 as
  // table1's (table1_bed2's, fig5's) runs, the same bits, and continue those runs' checkpoints when
  // they are at hand: a case of the shorter sweep's name must be that case but for run.duration.
  // A case the shorter sweep does not have (a period added where the paper's clock moved a
  // crossing) must be a case of it with the same intruder but for run.duration and drive.period.
  // A shape the shorter sweep lacks altogether (a second bed added for the factor screen, issue 51)
  // must be the first bed's long run of that name (less "_s2") but for box.seed.
  const std::string root = kStudySweeps;
  const SweepSpec firstBed = loadSweepSpec(root + "paper_depth_t1000.toml");
  const auto named = [](const SweepSpec& spec, const std::string& name) {
    return std::find_if(spec.cases.begin(), spec.cases.end(), [&](const SweepCase& t) { return t.name == name; });
  };
  for (const auto& [shorter, longer, count, extended, secondBeds] :
       {std::tuple{"paper_depth_table1.toml", "paper_depth_t1000.toml", 15u, 0u, 0u},
        std::tuple{"paper_depth_table1_bed2.toml", "paper_depth_t1000_bed2.toml", 9u, 1u, 1u},
        std::tuple{"paper_depth_fig5.toml", "paper_depth_fig2_t1000.toml", 10u, 0u, 0u}}) {
    const SweepSpec base = loadSweepSpec(root + shorter);
    const SweepSpec longRuns = loadSweepSpec(root + longer);
    EXPECT_EQ(longRuns.cases.size(), count) << longer;
    std::uint32_t newPeriods = 0;
    std::uint32_t fromFirstBed = 0;
    for (const SweepCase& c : longRuns.cases) {
      EXPECT_EQ(c.config.run.duration, 1000.0) << c.name;
      RunConfig expected;
      const auto sameShape = std::find_if(base.cases.begin(), base.cases.end(), [&](const SweepCase& t) {
        return t.config.intruder.shape == c.config.intruder.shape;
      });
      if (const auto same = named(base, c.name); same != base.cases.end()) {
        expected = same->config;
      } else if (sameShape != base.cases.end()) {
        ++newPeriods;
        expected = sameShape->config;
        expected.drive.period = c.config.drive.period;
      } else {
        ++fromFirstBed;
        ASSERT_TRUE(c.name.ends_with("_s2")) << longer << ": " << c.name;
        const auto first = named(firstBed, c.name.substr(0, c.name.size() - 3));
        ASSERT_NE(first, firstBed.cases.end()) << longer << ": " << c.name;
        expected = first->config;
        expected.box.seed = c.config.box.seed;
        EXPECT_NE(c.config.box.seed, first->config.box.seed) << longer << ": " << c.name;
      }
      expected.run.duration = c.config.run.duration;
      EXPECT_EQ(toToml(c.config), toToml(expected)) << longer << ": " << c.name;
    }
    EXPECT_EQ(newPeriods, extended) << longer;
    EXPECT_EQ(fromFirstBed, secondBeds) << longer;
  }
}

}  // namespace
}  // namespace wiggle
