#pragma once
// Whether a sweep's cases run on configs/paper.toml's beds, for the program's figure sweeps
// (tests/scenario/BedMakerTest.cpp) and the study's sweeps (study/tests/StudySweepsTest.cpp).
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "io/Config.h"
#include "io/SweepSpec.h"
#include "scenario/bed/BedMaker.h"
#include "scenario/run/Experiment.h"

namespace wiggle::testing_support {

// Each case of the sweep files (paths relative to the source root) stands for configs/paper.toml
// (the paper's stated protocol) only if its bed is the one paper.toml pours for the case's shape and
// friction, and it runs for the paper's 1e7 steps. The number of cases compared.
inline int expectCasesOnPaperTomlsBeds(const std::vector<std::string>& files) {
  const std::string root = std::string(WIGGLE_SOURCE_DIR) + "/";
  const RunConfig paper = loadRunConfig(root + "configs/paper.toml", {});
  // The bed key of every case, from the clump of its intruder (made once per distinct intruder:
  // making a clump is what costs here).
  std::map<std::tuple<ShapeName, IntruderSurface, double>, ClumpDef> clumps;
  const auto keyOf = [&](const RunConfig& config) {
    const auto [at, made] = clumps.try_emplace({config.intruder.shape, config.intruder.surface, config.intruder.angle});
    if (made) at->second = prepareCase(config).clump;
    return bedKey(config, at->second);
  };
  int compared = 0;
  for (const std::string& file : files) {
    for (const SweepCase& c : loadSweepSpec(root + file).cases) {
      RunConfig expected = paper;
      expected.intruder.shape = c.config.intruder.shape;
      expected.contact.mu = c.config.contact.mu;
      EXPECT_EQ(c.config.intruder.mass, 0.0) << file << ", case " << c.name;  // the clump's mass is its rule's
      EXPECT_EQ(c.config.intruder.massRule, paper.intruder.massRule) << file << ", case " << c.name;
      EXPECT_EQ(keyOf(c.config), keyOf(expected)) << file << ", case " << c.name;
      EXPECT_EQ(c.config.run.duration, paper.run.duration) << file << ", case " << c.name;
      ++compared;
    }
  }
  return compared;
}

}  // namespace wiggle::testing_support
