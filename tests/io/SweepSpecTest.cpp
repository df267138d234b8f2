// SweepSpec: expansion counts and order, names, parameters, [[case]] lists, settings, and errors
// that name the file, the case and the key.
#include "io/SweepSpec.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <fstream>
#include <set>
#include <sstream>

#include "core/Error.h"
#include "io/Config.h"
#include "support/TestSupport.h"

namespace wiggle {
namespace {

using testing_support::errorOf;

std::string sweepError(const std::string& text) {
  return errorOf([&] { parseSweepSpec(text, "sweep.toml"); });
}

std::vector<std::string> names(const SweepSpec& s) {
  std::vector<std::string> out;
  for (const SweepCase& c : s.cases) out.push_back(c.name);
  return out;
}

TEST(SweepSpec, GridIsTheCartesianProductInFileOrder) {
  // intruder before drive in the file, though toml++ sorts tables by name (drive < intruder).
  const SweepSpec s = parseSweepSpec(R"(
[base.run]
duration = 50
[base.drive]
amplitude = 5

[grid.intruder]
shape = ["disk", "triangle"]
[grid.drive]
period = [1, 5]
)",
                                     "sweep.toml");
  ASSERT_EQ(s.cases.size(), 4u);
  EXPECT_EQ(s.parameterKeys, (std::vector<std::string>{"intruder.shape", "drive.period"}));
  EXPECT_EQ(names(s), (std::vector<std::string>{"shape=disk_period=1", "shape=disk_period=5",
                                                "shape=triangle_period=1", "shape=triangle_period=5"}));
  const ShapeName shapes[] = {ShapeName::Disk, ShapeName::Disk, ShapeName::Triangle, ShapeName::Triangle};
  const double periods[] = {1, 5, 1, 5};
  for (std::size_t i = 0; i < 4; ++i) {
    const SweepCase& c = s.cases[i];
    EXPECT_EQ(c.index, i);
    EXPECT_EQ(c.config.intruder.shape, shapes[i]);
    EXPECT_EQ(c.config.drive.period, periods[i]);
    EXPECT_EQ(c.config.run.duration, 50.0);     // from [base]
    EXPECT_EQ(c.config.drive.amplitude, 5.0);   // from [base]
    EXPECT_EQ(c.config.run.dt, 1e-4);           // default
    ASSERT_EQ(c.parameters.size(), 2u);
    EXPECT_EQ(c.parameters[0].key, "intruder.shape");
    EXPECT_EQ(c.parameters[0].value, choiceName(shapes[i]));
    EXPECT_EQ(c.parameters[1].key, "drive.period");
    EXPECT_EQ(c.parameters[1].value, i % 2 ? "5" : "1");
  }
}

TEST(SweepSpec, KeysWithinASectionAlsoFollowTheFile) {
  const SweepSpec s = parseSweepSpec(
      "[grid.drive]\nperiod = [1, 2, 4]\namplitude = [3, 5]\n[grid.contact]\nmu = [0, 0.1, 0.2, 0.5]\n", "s.toml");
  ASSERT_EQ(s.cases.size(), 24u);
  EXPECT_EQ(s.parameterKeys, (std::vector<std::string>{"drive.period", "drive.amplitude", "contact.mu"}));
  EXPECT_EQ(s.cases[0].name, "period=1_amplitude=3_mu=0");
  EXPECT_EQ(s.cases[1].name, "period=1_amplitude=3_mu=0.1");
  EXPECT_EQ(s.cases[4].name, "period=1_amplitude=5_mu=0");
  EXPECT_EQ(s.cases[8].name, "period=2_amplitude=3_mu=0");
  EXPECT_EQ(s.cases[23].name, "period=4_amplitude=5_mu=0.5");
  const auto all = names(s);
  EXPECT_EQ(std::set<std::string>(all.begin(), all.end()).size(), 24u);
  EXPECT_EQ(s.cases[23].config.contact.mu, 0.5);
  EXPECT_EQ(s.cases[23].config.drive.amplitude, 5.0);
}

TEST(SweepSpec, NamesAreStableAndSurviveGrowingTheGrid) {
  const std::string small = "[grid.drive]\nperiod = [1, 5]\n";
  const std::string grown = "[grid.drive]\nperiod = [0.5, 1, 5, 8]\n";
  EXPECT_EQ(names(parseSweepSpec(small, "a.toml")), names(parseSweepSpec(small, "a.toml")));
  const auto before = names(parseSweepSpec(small, "a.toml"));
  const auto after = names(parseSweepSpec(grown, "a.toml"));
  for (const std::string& n : before) EXPECT_NE(std::find(after.begin(), after.end(), n), after.end()) << n;
  EXPECT_EQ(after[0], "period=0.5");
}

TEST(SweepSpec, SameLeafInTwoSectionsUsesFullKeysInNames) {
  const SweepSpec s = parseSweepSpec("[grid.box]\nwidth = [60, 80]\n[grid.fields]\nwidth = [1, 2]\n", "s.toml");
  ASSERT_EQ(s.cases.size(), 4u);
  EXPECT_EQ(s.cases[1].name, "box.width=60_fields.width=2");
}

TEST(SweepSpec, ArrayValuedKeysCanBeGridded) {
  const SweepSpec s = parseSweepSpec(R"(
[base.intruder]
shape = "polygon"
[grid.intruder]
vertices = [ [[0,0],[4,0],[0,3]], [[0,0],[6,0],[0,2]] ]
[grid.fields]
phases = [[0, 5], [10]]
)",
                                     "s.toml");
  ASSERT_EQ(s.cases.size(), 4u);
  EXPECT_EQ(s.cases[0].name, "vertices=0_0_4_0_0_3_phases=0_5");
  EXPECT_EQ(s.cases[3].config.intruder.vertices[1][0], 6.0);
  EXPECT_EQ(s.cases[3].config.fields.phases, (std::vector<double>{10}));
  EXPECT_EQ(s.cases[0].parameters[0].value, "[[0, 0], [4, 0], [0, 3]]");
  EXPECT_EQ(s.cases[0].parameters[1].value, "[0, 5]");
}

TEST(SweepSpec, CaseListTimesGrid) {
  const SweepSpec s = parseSweepSpec(R"(
[base.drive]
amplitude = 3

[[case]]
name = "disk"
intruder.shape = "disk"

[[case]]
name = "right triangle"
[case.intruder]
shape = "polygon"
vertices = [[0, 0], [6, 0], [0, 6]]

[grid.drive]
period = [1, 5]
)",
                                     "s.toml");
  ASSERT_EQ(s.cases.size(), 4u);
  EXPECT_EQ(names(s), (std::vector<std::string>{"disk_period=1", "disk_period=5", "right_triangle_period=1",
                                                "right_triangle_period=5"}));
  EXPECT_EQ(s.parameterKeys,
            (std::vector<std::string>{"case", "intruder.shape", "intruder.vertices", "drive.period"}));
  EXPECT_EQ(s.cases[0].parameters[0].value, "disk");
  EXPECT_EQ(s.cases[0].parameters[2].value, "[]");
  EXPECT_EQ(s.cases[3].parameters[0].value, "right triangle");
  EXPECT_EQ(s.cases[3].config.intruder.shape, ShapeName::Polygon);
  EXPECT_EQ(s.cases[3].config.intruder.vertices.size(), 3u);
  EXPECT_EQ(s.cases[3].config.drive.period, 5.0);
  EXPECT_EQ(s.cases[0].config.intruder.vertices.size(), 0u);  // a case does not leak into the next
}

TEST(SweepSpec, UnnamedCasesAreNamedByTheirValues) {
  const SweepSpec s = parseSweepSpec(
      "[[case]]\ndrive.period = 1\ndrive.amplitude = 0.5\n[[case]]\ncontact.mu = 0.3\n", "s.toml");
  ASSERT_EQ(s.cases.size(), 2u);
  EXPECT_EQ(s.cases[0].name, "period=1_amplitude=0.5");
  EXPECT_EQ(s.cases[1].name, "mu=0.3");
  EXPECT_EQ(s.parameterKeys, (std::vector<std::string>{"drive.period", "drive.amplitude", "contact.mu"}));
  EXPECT_EQ(s.cases[1].parameters[0].value, "5");  // the base value where the case is silent
  EXPECT_EQ(s.cases[1].config.contact.mu, 0.3);
}

TEST(SweepSpec, NoGridNoCasesIsTheBase) {
  const SweepSpec s = parseSweepSpec("[base.drive]\nperiod = 2\n", "dir/only.toml");
  ASSERT_EQ(s.cases.size(), 1u);
  EXPECT_EQ(s.cases[0].name, "base");
  EXPECT_TRUE(s.parameterKeys.empty());
  EXPECT_EQ(s.cases[0].config.drive.period, 2.0);
  EXPECT_EQ(s.settings.name, "only");
}

TEST(SweepSpec, SweepSettings) {
  const SweepSpec s = parseSweepSpec("[sweep]\nname = \"fig5\"\njobs = 4\nthreads_per_case = 2\n", "s.toml");
  EXPECT_EQ(s.settings.name, "fig5");
  EXPECT_EQ(s.settings.jobs, 4);
  EXPECT_EQ(s.settings.threadsPerCase, 2);
  EXPECT_NE(sweepError("[sweep]\njob = 4\n").find("unknown key 'sweep.job'"), std::string::npos);
  EXPECT_NE(sweepError("[sweep]\njobs = -1\n").find("sweep.jobs = -1: must be >= 0"), std::string::npos);
}

TEST(SweepSpec, ABadGridValueNamesTheCaseAndTheKey) {
  const std::string m = sweepError("[grid.intruder]\nshape = [\"disk\"]\n[grid.drive]\nperiod = [1, -2]\n");
  EXPECT_EQ(m, "sweep.toml: case 2 'shape=disk_period=-2': line 4 [grid]: drive.period = -2: must be > 0");
  // A cross-key problem that only some cases have.
  const std::string cross = sweepError("[grid.drive]\nperiod = [5, 5.00005]\n");
  EXPECT_NE(cross.find("case 2 'period=5.00005': drive.period = 5.00005: must be a whole number"), std::string::npos)
      << cross;
  const std::string shape = sweepError("[grid.intruder]\nshape = [\"disk\", \"circle\"]\n");
  EXPECT_NE(shape.find("case 2 'shape=circle'"), std::string::npos) << shape;
  EXPECT_NE(shape.find("intruder.shape = \"circle\": must be one of"), std::string::npos) << shape;
  const std::string inCase = sweepError("[[case]]\nname = \"a\"\ndrive.period = 1\n[[case]]\nname = \"b\"\ndrive.amplitude = -1\n");
  EXPECT_NE(inCase.find("case 2 'b': line 6 [[case]]: drive.amplitude = -1: must be >= 0"), std::string::npos)
      << inCase;
}

TEST(SweepSpec, StructuralErrorsNameTheFileAndKey) {
  EXPECT_NE(sweepError("[grid.drive]\nperod = [1, 5]\n").find("sweep.toml:2: unknown key 'grid.drive.perod' (did you mean 'grid.drive.period'?)"),
            std::string::npos);
  EXPECT_NE(sweepError("[base.drvie]\nperiod = 1\n").find("unknown section 'base.drvie' (did you mean 'base.drive'?)"),
            std::string::npos);
  EXPECT_NE(sweepError("[base.drive]\nperiod = -1\n").find("sweep.toml:2: drive.period = -1: must be > 0"),
            std::string::npos);
  EXPECT_NE(sweepError("[grid.drive]\nperiod = 5\n").find("sweep.toml:2: grid.drive.period: expected an array"),
            std::string::npos);
  EXPECT_NE(sweepError("[grid.drive]\nperiod = []\n").find("grid.drive.period: empty array"), std::string::npos);
  EXPECT_NE(sweepError("[drive]\nperiod = 5\n").find("unknown table 'drive' (did you mean 'base.drive'?)"),
            std::string::npos);
  EXPECT_NE(sweepError("[grids.drive]\nperiod = [5]\n").find("did you mean 'grid'?"), std::string::npos);
  EXPECT_NE(sweepError("[[case]]\ndrive.period = 1\n[grid.drive]\nperiod = [1, 5]\n")
                .find("drive.period is set both in [[case]] 1"),
            std::string::npos);
  EXPECT_NE(sweepError("[grid.drive]\nperiod = [1, 1.0]\n").find("cases 1 and 2 have the same name 'period=1'"),
            std::string::npos);
  EXPECT_NE(sweepError("[grid.drive\n").find("sweep.toml:1:"), std::string::npos);
  EXPECT_NE(sweepError("case = 3\n").find("'case' must be a list of tables"), std::string::npos);
}

TEST(SweepSpec, UnreadableFileSaysWhy) {
  EXPECT_EQ(errorOf([] { loadSweepSpec("/nonexistent/sweep.toml"); }),
            "cannot read sweep file '/nonexistent/sweep.toml': No such file or directory");
  const std::string dir = std::string(WIGGLE_SOURCE_DIR) + "/configs/sweeps";
  EXPECT_EQ(errorOf([&] { loadSweepSpec(dir); }), "cannot read sweep file '" + dir + "': Is a directory");
}

TEST(SweepSpec, ShippedSweepFilesExpand) {
  // Every sweep file under configs/sweeps must expand without error (they are user-facing).
  const std::filesystem::path dir = std::filesystem::path(WIGGLE_SOURCE_DIR) / "configs" / "sweeps";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "no " << dir;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".toml") continue;
    EXPECT_NO_THROW(loadSweepSpec(entry.path().string())) << entry.path();
  }
}

// Beds as replicates (issue 80): `beds = N` runs every case on box.seed 1..N, the seed varying
// fastest, and groups the cases into cells (a case without its seed).
TEST(SweepSpec, BedsRunEveryCaseOnSeedsOneToNAndGroupThemIntoCells) {
  const SweepSpec s = parseSweepSpec(R"(
[sweep]
beds = 3
[grid.drive]
period = [1, 5]
)",
                                     "sweep.toml");
  EXPECT_EQ(s.settings.beds, 3);
  EXPECT_EQ(names(s), (std::vector<std::string>{"period=1_seed=1", "period=1_seed=2", "period=1_seed=3",
                                                "period=5_seed=1", "period=5_seed=2", "period=5_seed=3"}));
  EXPECT_EQ(s.parameterKeys, (std::vector<std::string>{"drive.period", "box.seed"}));
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(s.cases[i].config.box.seed, static_cast<std::uint64_t>(i % 3 + 1));
    EXPECT_EQ(s.cases[i].cell, i / 3);
  }
  ASSERT_EQ(s.cells.size(), 2u);
  EXPECT_EQ(s.cells[0].name, "period=1");
  EXPECT_EQ(s.cells[1].name, "period=5");
  EXPECT_EQ(s.cells[1].cases, (std::vector<std::size_t>{3, 4, 5}));

  // Nothing else varying: one cell, "base"; a sweep without beds has cells of one case each.
  const SweepSpec only = parseSweepSpec("[sweep]\nbeds = 2\n", "sweep.toml");
  EXPECT_EQ(names(only), (std::vector<std::string>{"seed=1", "seed=2"}));
  ASSERT_EQ(only.cells.size(), 1u);
  EXPECT_EQ(only.cells[0].name, "base");
  const SweepSpec plain = parseSweepSpec("[grid.drive]\nperiod = [1, 5]\n", "sweep.toml");
  ASSERT_EQ(plain.cells.size(), 2u);
  EXPECT_EQ(plain.cells[0].name, "period=1");
  EXPECT_EQ(plain.cells[0].cases, std::vector<std::size_t>{0});
  EXPECT_EQ(plain.settings.beds, 0);

  // A box.seed grid of N seeds is the N beds, where the grid puts it; an unnamed [[case]]'s seed is
  // left out of its cell's name.
  const SweepSpec listed = parseSweepSpec(R"(
[sweep]
beds = 2
[grid.box]
seed = [4, 7]
[grid.drive]
period = [1, 5]
)",
                                          "sweep.toml");
  EXPECT_EQ(names(listed),
            (std::vector<std::string>{"seed=4_period=1", "seed=4_period=5", "seed=7_period=1", "seed=7_period=5"}));
  ASSERT_EQ(listed.cells.size(), 2u);
  EXPECT_EQ(listed.cells[0].name, "period=1");
  EXPECT_EQ(listed.cells[0].cases, (std::vector<std::size_t>{0, 2}));
  const SweepSpec caseSeeds = parseSweepSpec(R"(
[[case]]
box.seed = 1
intruder.shape = "square"
[[case]]
box.seed = 2
intruder.shape = "square"
)",
                                             "sweep.toml");
  ASSERT_EQ(caseSeeds.cells.size(), 1u);
  EXPECT_EQ(caseSeeds.cells[0].name, "shape=square");
}

TEST(SweepSpec, BedsThatContradictTheSeedsAreRefusedNamingBoth) {
  auto expectError = [](const std::string& text, std::vector<std::string> words) {
    const std::string e = sweepError(text);
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    for (const std::string& w : words) EXPECT_NE(e.find(w), std::string::npos) << e << " lacks " << w;
  };
  expectError("[sweep]\nbeds = 0\n", {"sweep.toml:2", "sweep.beds = 0", "from 1"});
  expectError("[sweep]\nbeds = 2.5\n", {"sweep.beds", "integer"});
  expectError("[sweep]\nbeds = 3\n[grid.box]\nseed = [1, 2]\n", {"sweep.beds = 3", "lists 2 seeds", "agree"});
  expectError("[sweep]\nbeds = 2\n[[case]]\nbox.seed = 5\n", {"sweep.beds = 2", "[[case]] 1", "box.seed"});
  expectError("[sweep]\nbeds = 2\n[base.box]\nseed = 5\n", {"sweep.beds = 2", "[base]", "box.seed = 5"});
  expectError("[sweep]\nbedz = 2\n", {"unknown key 'sweep.bedz'", "beds"});
}

TEST(SweepSpec, ExamplesInTheDocsParse) {
  // Each ```toml block of docs/CONFIG.md starts with "# run" or "# sweep" and must be accepted.
  std::ifstream in(std::string(WIGGLE_SOURCE_DIR) + "/docs/CONFIG.md");
  ASSERT_TRUE(in);
  std::stringstream all;
  all << in.rdbuf();
  const std::string text = all.str();
  std::vector<std::size_t> sweepSizes;
  int runs = 0;
  for (std::size_t at = text.find("```toml\n"); at != std::string::npos; at = text.find("```toml\n", at + 1)) {
    const std::size_t begin = at + 8;
    const std::size_t end = text.find("```", begin);
    ASSERT_NE(end, std::string::npos);
    const std::string block = text.substr(begin, end - begin);
    if (block.rfind("# sweep", 0) == 0) {
      sweepSizes.push_back(parseSweepSpec(block, "CONFIG.md").cases.size());
    } else {
      ASSERT_EQ(block.rfind("# run", 0), 0u) << block;
      EXPECT_NO_THROW(parseRunConfig(block, "CONFIG.md")) << block;
      ++runs;
    }
  }
  EXPECT_EQ(runs, 2);
  // The counts the text states: figure 5 (4 x 10), shapes x periods x seeds, 3 cases x 2 periods.
  EXPECT_EQ(sweepSizes, (std::vector<std::size_t>{40, 30, 6}));
}

}  // namespace
}  // namespace wiggle
