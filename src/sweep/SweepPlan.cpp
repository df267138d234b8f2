#include "sweep/SweepPlan.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <nlohmann/json.hpp>

#include "core/Error.h"
#include "core/Format.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "scenario/bed/BedMaker.h"
#include "scenario/run/Checkpoint.h"
#include "scenario/run/Experiment.h"
#include "scenario/geometry/Shape.h"
#include "sweep/ResultsTable.h"

namespace wiggle {

namespace fs = std::filesystem;

SweepPlan makeSweepPlan(SweepSpec spec, const std::string& outDir) {
  SweepPlan plan;
  plan.spec = std::move(spec);
  plan.outDir = outDir;
  if (!plan.spec.cases.empty()) plan.speed = speedBasis(plan.spec.cases.front().config);  // its cache's speed log
  std::map<std::string, int> bedIndex;      // key -> index in plan.beds (beds to make)
  std::map<std::string, bool> keySeen;
  std::set<std::string> basesToPour;        // base beds of carved beds, counted in the estimate once
  for (const SweepCase& c : plan.spec.cases) {
    PlannedCase p;
    p.index = c.index;
    p.runDir = "cases/" + c.name;
    p.dir = outDir + "/" + p.runDir;
    p.estimatedParticles = estimatedParticles(c.config);
    ClumpDef clump;
    try {
      // The same checks `wiggle run` makes before touching the bed, so a bad case fails here with
      // the message the run would give, without a process or a bed being spent on it.
      const Case run = prepareCase(c.config);
      p.steps = run.steps.total;
      clump = run.clump;
      if (c.config.bed.file.empty()) p.bedKey = bedKey(c.config, run.clump);  // a pinned bed is never made
    } catch (const Error& e) {
      p.state = CaseState::Failed;
      p.error = e.what();
    }

    bool extends = false;  // the sweep file asks for a longer run than the one there: it is continued
    if (p.state != CaseState::Failed && fs::exists(p.dir + "/config.toml")) {
      try {
        const RunConfig previous = parseRunConfig(readFile(p.dir + "/config.toml"), p.dir + "/config.toml");
        if (const std::string why = whyRunCannotContinue(previous, c.config); !why.empty()) {
          p.state = CaseState::Failed;
          p.error = p.dir + " holds a run of a different config (the sweep file changed?): " + why +
                    "; delete that directory to run this case again";
        }
        extends = c.config.run.duration > previous.run.duration;
      } catch (const Error& e) {
        p.state = CaseState::Failed;
        p.error = e.what();
      }
    }
    // A torn or foreign summary: the case runs again (it resumes from its final checkpoint).
    if (p.state != CaseState::Failed && !extends && caseFinished(p.dir)) p.state = CaseState::Done;
    p.hasCheckpoint = fs::exists(p.dir + "/checkpoint.bin") || fs::exists(p.dir + "/checkpoint.prev.bin");

    if (!p.bedKey.empty()) {
      keySeen[p.bedKey] = true;
      // A bed task only for a case that will run and has no checkpoint (a checkpointed run does
      // not need its bed again), and only when the cache does not hold it yet.
      if (p.state == CaseState::Pending && !p.hasCheckpoint && !fs::exists(bedCachePath(c.config, p.bedKey))) {
        auto [it, fresh] = bedIndex.try_emplace(p.bedKey, static_cast<int>(plan.beds.size()));
        if (fresh) {
          PlannedBed bed;
          bed.key = p.bedKey;
          bed.configPath = outDir + "/beds/bed-" + p.bedKey + ".toml";
          bed.firstCase = c.index;
          bed.cachePath = bedCachePath(c.config, p.bedKey);
          // Carved beds of one seed share a base bed: it is poured once, by the first of them.
          const BedPlan planned = planBed(c.config, clump);
          const bool baseToPour = planned.source == BedPlan::Source::Carve && !planned.baseCached &&
                                  basesToPour.insert(planned.baseKey).second;
          bed.estimatedSeconds = estimatedBedSeconds(c.config, plan.speed.ns, baseToPour);
          plan.beds.push_back(bed);
        }
        p.bedTask = it->second;
      }
    }
    plan.cases.push_back(std::move(p));
  }
  plan.distinctBeds = keySeen.size();
  return plan;
}

std::vector<std::size_t> bedsMadeBy(const SweepPlan& plan, std::optional<std::size_t> only) {
  std::vector<std::size_t> beds;
  for (std::size_t b = 0; b < plan.beds.size(); ++b)
    if (!only || plan.cases[*only].bedTask == static_cast<int>(b)) beds.push_back(b);
  return beds;
}

namespace {

// The replicates in a line, when some cell has more than one bed: "4 cells x 3 beds (box.seed; a
// case is one bed of its cell, cells.csv): a cell about 3m10s of one core", each cell's cost its beds' sum.
std::string cellsLine(const SweepPlan& plan) {
  const std::vector<SweepCell>& cells = plan.spec.cells;
  std::size_t fewest = plan.cases.size(), most = 0;
  for (const SweepCell& c : cells) {
    fewest = std::min(fewest, c.cases.size());
    most = std::max(most, c.cases.size());
  }
  if (most < 2) return "";
  double costliest = 0.0;
  for (const SweepCell& c : cells) {
    double seconds = 0.0;
    for (const std::size_t k : c.cases) seconds += estimatedRunSeconds(plan.spec.cases[k].config, plan.speed.ns);
    costliest = std::max(costliest, seconds);
  }
  const std::string beds = fewest == most ? std::to_string(most) : std::to_string(fewest) + "-" + std::to_string(most);
  return std::to_string(cells.size()) + " cell" + (cells.size() == 1 ? "" : "s") + " x " + beds +
         " beds (box.seed; a case is one bed of its cell, cells.csv), up to " + formatDuration(costliest) +
         " of one core for a cell's runs\n";
}

}  // namespace

std::string dryRunListing(const SweepPlan& plan, int jobs, int threads) {
  const double ns = plan.speed.ns;
  std::ostringstream out;
  out << "sweep " << plan.spec.settings.name << " -> " << plan.outDir << "\n";
  out << "  #  case                                       state     grains      steps   est. run\n";
  double runSeconds = 0.0;
  std::size_t toRun = 0, done = 0, failed = 0;
  for (const PlannedCase& p : plan.cases) {
    const SweepCase& c = plan.spec.cases[p.index];
    std::string state = p.state == CaseState::Done ? "done" : p.state == CaseState::Failed ? "FAILED" : "to run";
    if (p.state == CaseState::Pending && p.hasCheckpoint) state = "resume";
    const double seconds = estimatedRunSeconds(c.config, ns);
    char line[512];
    std::snprintf(line, sizeof line, "%3zu  %-42s %-8s %7.0f %10llu %10s\n", p.index + 1, c.name.c_str(), state.c_str(),
                  estimatedGrains(c.config), static_cast<unsigned long long>(p.steps), formatDuration(seconds).c_str());
    out << line;
    if (p.state == CaseState::Failed) out << "       " << p.error << "\n";
    if (p.state == CaseState::Pending) {
      ++toRun;
      runSeconds += seconds;  // a resumed case is counted whole: an upper bound
    }
    done += p.state == CaseState::Done;
    failed += p.state == CaseState::Failed;
  }
  double bedSeconds = 0.0, longestBed = 0.0;
  for (const PlannedBed& b : plan.beds) {
    bedSeconds += b.estimatedSeconds;
    longestBed = std::max(longestBed, b.estimatedSeconds);
    out << "  bed " << b.key << " (first needed by " << plan.spec.cases[b.firstCase].name << "): est. "
        << formatDuration(b.estimatedSeconds) << "\n";
  }
  // Beds are made in parallel first, one per job; then the cases share the jobs; each job's threads
  // speed it up as the committed table measured for the sweep's first case's bed size.
  const double bedPhase = plan.beds.empty() ? 0.0
                                            : std::max(longestBed, bedSeconds / std::min<double>(jobs, plan.beds.size()));
  const ThreadScaling scaling =
      threadScaling(plan.cases.empty() ? 0.0 : estimatedParticles(plan.spec.cases[plan.cases.front().index].config),
                    threads);
  const double total = (bedPhase + runSeconds / std::max(1, jobs)) / scaling.speedUp;
  out << plan.cases.size() << " cases: " << toRun << " to run, " << done << " done, " << failed << " failed; "
      << plan.beds.size() << " of " << plan.distinctBeds << " distinct beds to make\n";
  if (const std::string cells = cellsLine(plan); !cells.empty()) out << cells;
  out << "estimated cost: " << formatDuration(total) << " wall on " << jobs << " jobs x " << threads
      << " threads (runs " << formatDuration(runSeconds) << " + beds " << formatDuration(bedSeconds)
      << " of single-core time at " << formatNumber(ns, 3) << " ns per particle-step: " << plan.speed.source
      << (threads > 1 ? "; " + std::to_string(threads) + " threads: " + scaling.words : "") << ")\n";
  return out.str();
}

}  // namespace wiggle
