#include "sweep/BoundaryStudy.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <thread>

#include "core/Assert.h"
#include "core/Error.h"
#include "core/Format.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "io/SweepSpec.h"
#include "sweep/MpiQueue.h"
#include "sweep/ResultsTable.h"
#include "sweep/SweepPlan.h"
#include "sweep/SweepStatus.h"

namespace wiggle {

namespace {

// Bed k of a probe is box.seed = the config's seed + k - 1.
std::uint64_t seedOf(const BoundarySpec& spec, const BoundaryCase& c) {
  return spec.base.box.seed + static_cast<std::uint64_t>(c.run.seed - 1);
}

std::string searchLabel(const BoundarySpec& spec, std::size_t search) {
  return spec.overKey.empty() ? std::string() : spec.overKey + " = " + formatNumber(spec.overValues[search]);
}

}  // namespace

const char* rateRuleName(RateRule rule) { return rule == RateRule::Paper ? "paper" : "settled"; }

RunConfig boundaryCaseConfig(const BoundarySpec& spec, const BoundaryCase& c) {
  RunConfig config = spec.base;
  if (!spec.overKey.empty())
    applySetting(config, spec.overKey, toml::value<double>(spec.overValues[c.search]), "--over");
  applySetting(config, spec.key, toml::value<double>(c.run.value), "--vary");
  applySetting(config, "box.seed", toml::value<std::int64_t>(static_cast<std::int64_t>(seedOf(spec, c))), "--beds");
  validateRunConfig(config);
  return config;
}

void checkBoundarySpec(const BoundarySpec& spec) {
  if (!isConfigKey(spec.key)) throw Error("--vary " + spec.key + ": no such config key");
  if (!isRealKey(spec.key))
    throw Error("--vary " + spec.key + ": not a real-valued key (a search needs values between any two)");
  if (!spec.overKey.empty()) {
    if (!isConfigKey(spec.overKey)) throw Error("--over " + spec.overKey + ": no such config key");
    if (!isRealKey(spec.overKey)) throw Error("--over " + spec.overKey + ": not a real-valued key");
    if (spec.overKey == spec.key) throw Error("--over " + spec.overKey + ": the same key as --vary");
    if (spec.overValues.empty()) throw Error("--over " + spec.overKey + ": no values (--over KEY=V1,V2,...)");
    for (std::size_t i = 0; i < spec.overValues.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (spec.overValues[i] == spec.overValues[j])
          throw Error("--over " + spec.overKey + ": " + formatNumber(spec.overValues[i]) + " is given twice");
  }
  try {
    checkBoundaryOptions(spec.options);
  } catch (const Error& e) {
    throw Error(std::string("boundary: ") + e.what());
  }
  // Every value a search can probe (its lattice), so that none stops on a bad value hours in.
  const std::size_t intervals = latticeIntervals(spec.options);
  const std::size_t searches = std::max<std::size_t>(1, spec.overValues.size());
  for (std::size_t s = 0; s < searches; ++s)
    for (std::size_t k = 0; k <= intervals; ++k) {
      try {
        boundaryCaseConfig(spec, {s, {latticeValue(spec.options, k), 1}});
      } catch (const Error& e) {
        throw Error(std::string(e.what()) + " (a value the search may probe: LO and --resolution set them)");
      }
    }
}

std::string boundarySweepFile(const BoundarySpec& spec, const std::vector<BoundaryCase>& cases) {
  std::ostringstream out;
  out << "# Written by `wiggle boundary` before each round: every run its searches have asked for.\n"
      << "# Do not edit; `wiggle status` and `wiggle report` read this directory as a sweep.\n"
      << "[sweep]\nname = \"boundary\"\n\n";
  // [base]: the config as toToml writes it, each section under base.
  std::istringstream base(toToml(spec.base));
  for (std::string line; std::getline(base, line);) {
    if (!line.empty() && line[0] == '[') line = "[base." + line.substr(1);
    out << line << '\n';
  }
  for (const BoundaryCase& c : cases) {
    const RunConfig config = boundaryCaseConfig(spec, c);
    out << "\n[[case]]\n";
    if (!spec.overKey.empty()) out << spec.overKey << " = " << configValueToml(config, spec.overKey) << '\n';
    out << spec.key << " = " << configValueToml(config, spec.key) << '\n';
    out << "box.seed = " << configValueToml(config, "box.seed") << '\n';
  }
  return out.str();
}

std::vector<BoundaryCaseOutcome> SweepBoundaryRunner::run(const BoundarySpec& spec,
                                                          const std::vector<BoundaryCase>& all, std::size_t firstNew) {
  const std::string& dir = options_.outDir;
  const std::string file = dir + "/boundary.toml";
  std::filesystem::create_directories(dir);
  writeFileAtomically(file, boundarySweepFile(spec, all));
  // The case of run i is the sweep's case i ([[case]] tables in order, no grid).
  const SweepSpec sweep = loadSweepSpec(file);
  auto caseDir = [&](std::size_t i) { return dir + "/cases/" + sweep.cases[i].name; };
  bool pending = false;
  for (std::size_t i = firstNew; i < all.size(); ++i) pending = pending || !caseFinished(caseDir(i));
  if (pending) {
    if (options_.mpi)  // the workers read the file just written
      for (int rank = 1; rank < options_.mpi->size(); ++rank) options_.mpi->send(rank, MpiTag::Round, "");
    const SweepOutcome outcome = runSweep(file, options_);
    if (outcome.interrupted) throw Interrupted(outcome.stopSignal, outcome.summary);
  }
  std::optional<SweepStatus> status;  // the sweep's record of the cases that did not finish, read once
  std::vector<BoundaryCaseOutcome> outcomes;
  for (std::size_t i = firstNew; i < all.size(); ++i) {
    BoundaryCaseOutcome o;
    if (caseFinished(caseDir(i))) {
      const CaseResult r = readCaseSummary(caseDir(i));
      o.ok = true;
      o.vy = spec.rate == RateRule::Paper ? r.summary.vy : r.summary.vySettled;
      o.wallSeconds = r.summary.wallSeconds;
    } else {
      if (!status) status = readSweepStatus(dir);
      for (const CaseAtAGlance& c : status->cases)
        if (c.name == sweep.cases[i].name) o.error = c.error;
      if (o.error.empty()) o.error = "the case did not finish";
    }
    outcomes.push_back(o);
  }
  return outcomes;
}

void serveBoundaryRounds(const SweepOptions& options) {
  WIGGLE_ASSERT(options.mpi != nullptr && options.mpi->rank() != 0);
  while (true) {
    const std::optional<MpiMessage> m = options.mpi->poll();
    if (!m) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));  // as the coordinator polls
      continue;
    }
    if (m->tag == MpiTag::Stop) return;
    // A round: its sweep's worker loop, which ends with the round (the coordinator's Stop).
    if (m->tag == MpiTag::Round) runSweep(options.outDir + "/boundary.toml", options);
  }
}

void releaseBoundaryWorkers(MpiQueue& mpi) {
  for (int rank = 1; rank < mpi.size(); ++rank) mpi.send(rank, MpiTag::Stop, "");
}

namespace {

void writeOutputs(const BoundarySpec& spec, const BoundaryResult& result, const std::string& outDir) {
  std::filesystem::create_directories(outDir);
  writeFileAtomically(outDir + "/boundary.json", boundaryJson(spec, result).dump(2) + "\n");
  writeFileAtomically(outDir + "/boundary.csv", boundaryCsv(spec, result));
}

}  // namespace

BoundaryResult runBoundary(const BoundarySpec& spec, BoundaryRunner& runner, const std::string& outDir) {
  checkBoundarySpec(spec);
  BoundaryResult result;
  const std::size_t searches = std::max<std::size_t>(1, spec.overValues.size());
  for (std::size_t s = 0; s < searches; ++s) result.searches.emplace_back(spec.options);
  for (;;) {
    const std::size_t firstNew = result.cases.size();
    for (std::size_t s = 0; s < searches; ++s)
      for (const BoundaryRun& r : result.searches[s].next()) result.cases.push_back({s, r});
    if (result.cases.size() == firstNew) break;
    const std::vector<BoundaryCaseOutcome> outcomes = runner.run(spec, result.cases, firstNew);
    if (outcomes.size() != result.cases.size() - firstNew)
      throw Error("boundary: internal error: the runner returned " + std::to_string(outcomes.size()) +
                  " outcomes for " + std::to_string(result.cases.size() - firstNew) + " runs");
    for (std::size_t i = 0; i < outcomes.size(); ++i) {
      const BoundaryCase& c = result.cases[firstNew + i];
      if (outcomes[i].ok)
        result.searches[c.search].record(c.run, outcomes[i].vy);
      else
        result.searches[c.search].recordFailure(c.run);
      result.outcomes.push_back(outcomes[i]);
    }
    writeOutputs(spec, result, outDir);
  }
  writeOutputs(spec, result, outDir);
  return result;
}

GridComparison gridComparison(const BoundarySpec& spec, const BoundarySearch& search) {
  GridComparison g;
  g.spacing = spec.options.resolution;
  g.points = latticeIntervals(spec.options) + 1;
  for (const Probe& p : search.probes()) g.beds = std::max(g.beds, p.vy.size());
  g.cases = g.points * g.beds;
  return g;
}

nlohmann::json boundaryJson(const BoundarySpec& spec, const BoundaryResult& result) {
  using nlohmann::json;
  const BoundaryOptions& o = spec.options;
  json j;
  j["key"] = spec.key;
  j["range"] = {o.lo, o.hi};
  j["points"] = o.points;
  j["resolution"] = o.resolution;
  j["beds"] = {o.minBeds, o.maxBeds};
  j["known_scatter"] = o.knownScatter;
  j["rate"] = rateRuleName(spec.rate);
  j["rule"] = o.knownScatter > 0 ? "|mean V_y| > 1.96 x known_scatter / sqrt(beds), at least beds[0] beds"
                                 : "|mean V_y| > Student's t(0.975, beds - 1) x standard error, at least beds[0] beds";
  j["first_seed"] = spec.base.box.seed;
  j["over_key"] = spec.overKey;
  j["searches"] = json::array();
  const std::size_t searches = result.searches.size();
  for (std::size_t s = 0; s < searches; ++s) {
    const BoundarySearch& search = result.searches[s];
    json js;
    js["over"] = spec.overKey.empty() ? json(nullptr) : json(spec.overValues[s]);
    js["finished"] = search.finished();
    double wall = 0.0;
    std::size_t runs = 0;
    std::map<double, std::vector<std::string>> errors;
    for (std::size_t i = 0; i < result.outcomes.size(); ++i) {
      if (result.cases[i].search != s) continue;
      ++runs;
      wall += result.outcomes[i].wallSeconds;
      if (!result.outcomes[i].ok) errors[result.cases[i].run.value].push_back(result.outcomes[i].error);
    }
    js["probes"] = json::array();
    for (const Probe& p : search.probes()) {
      json jp = {{"value", p.value}, {"verdict", verdictName(p.verdict)}, {"vy", p.vy}, {"beds", p.vy.size()}};
      if (!p.vy.empty()) jp["mean"] = p.mean;
      if (!p.vy.empty()) jp["standard_error"] = p.standardError;
      if (const auto it = errors.find(p.value); it != errors.end()) jp["errors"] = it->second;
      js["probes"].push_back(jp);
    }
    js["crossings"] = json::array();
    for (const Crossing& c : search.crossings()) {
      json jc = {{"below", c.below}, {"above", c.above}, {"from", verdictName(c.from)}, {"to", verdictName(c.to)}};
      jc["neutral"] = c.neutralLo ? json({*c.neutralLo, *c.neutralHi}) : json(nullptr);
      js["crossings"].push_back(jc);
    }
    js["neutral_bands"] = json::array();
    for (const NeutralBand& b : search.neutralBands())
      js["neutral_bands"].push_back({{"first", b.first},
                                     {"last", b.last},
                                     {"below", b.below ? json(*b.below) : json(nullptr)},
                                     {"above", b.above ? json(*b.above) : json(nullptr)}});
    const GridComparison g = gridComparison(spec, search);
    js["cost"] = {{"runs", runs}, {"wall_s", wall}};
    js["grid"] = {{"spacing", g.spacing}, {"points", g.points}, {"beds", g.beds}, {"cases", g.cases}};
    j["searches"].push_back(js);
  }
  return j;
}

std::string boundaryCsv(const BoundarySpec& spec, const BoundaryResult& result) {
  std::ostringstream out;
  out << "over_key,over,kind,from,to,below,above,neutral_first,neutral_last,vy_below,se_below,beds_below,vy_above,"
         "se_above,beds_above\n";
  const auto probeAt = [](const BoundarySearch& s, double v) -> const Probe* {
    for (const Probe& p : s.probes())
      if (p.value == v) return &p;
    return nullptr;
  };
  const auto probeCells = [&](const BoundarySearch& s, const std::optional<double>& v) {
    const Probe* p = v ? probeAt(s, *v) : nullptr;
    if (!p) return std::string(",,");
    return formatNumber(p->mean, 10) + "," + formatNumber(p->standardError, 10) + "," + std::to_string(p->vy.size());
  };
  const auto cell = [](const std::optional<double>& v) { return v ? formatNumber(*v, 10) : std::string(); };
  for (std::size_t s = 0; s < result.searches.size(); ++s) {
    const BoundarySearch& search = result.searches[s];
    const std::string over =
        spec.overKey.empty() ? std::string(",") : spec.overKey + "," + formatNumber(spec.overValues[s], 10);
    for (const Crossing& c : search.crossings())
      out << over << ",crossing," << verdictName(c.from) << ',' << verdictName(c.to) << ',' << cell(c.below) << ','
          << cell(c.above) << ',' << cell(c.neutralLo) << ',' << cell(c.neutralHi) << ',' << probeCells(search, c.below)
          << ',' << probeCells(search, c.above) << '\n';
    for (const NeutralBand& b : search.neutralBands())
      out << over << ",neutral,,," << cell(b.below) << ',' << cell(b.above) << ',' << cell(b.first) << ','
          << cell(b.last) << ',' << probeCells(search, b.below) << ',' << probeCells(search, b.above) << '\n';
  }
  return out.str();
}

namespace {
// "over KEY = a-b", or "at KEY = a" when the span is one value (a band of one probe).
std::string valueSpan(const std::string& keyIs, double first, double last) {
  if (first == last) return "at " + keyIs + formatNumber(first);
  return "over " + keyIs + formatNumber(first) + "-" + formatNumber(last);
}
}  // namespace

std::string boundaryLines(const BoundarySpec& spec, const BoundaryResult& result) {
  std::ostringstream out;
  const std::string& key = spec.key;
  std::size_t runs = 0, grid = 0;
  double wall = 0.0;
  for (std::size_t s = 0; s < result.searches.size(); ++s) {
    const BoundarySearch& search = result.searches[s];
    const std::string label = searchLabel(spec, s);
    const std::string head = label.empty() ? std::string() : label + ": ";
    const auto crossings = search.crossings();
    const auto bands = search.neutralBands();
    for (const Crossing& c : crossings) {
      out << head << verdictName(c.from) << " -> " << verdictName(c.to) << " between " << key << " = "
          << formatNumber(c.below) << " and " << formatNumber(c.above);
      if (c.neutralLo) out << " (V_y indistinguishable from zero " << valueSpan("", *c.neutralLo, *c.neutralHi) << ")";
      out << '\n';
    }
    for (const NeutralBand& b : bands) {
      const bool inCrossing = std::any_of(crossings.begin(), crossings.end(),
                                          [&](const Crossing& c) { return c.neutralLo && *c.neutralLo == b.first; });
      if (inCrossing) continue;
      out << head << "V_y indistinguishable from zero " << valueSpan(key + " = ", b.first, b.last)
          << " (no change of sign across it)\n";
    }
    if (crossings.empty() && bands.empty()) {
      Verdict v = Verdict::Undecided;
      for (const Probe& p : search.probes())
        if (p.verdict == Verdict::Rising || p.verdict == Verdict::Sinking) v = p.verdict;
      out << head << "no crossing over " << key << " = " << formatNumber(spec.options.lo) << "-"
          << formatNumber(spec.options.hi)
          << (v == Verdict::Undecided ? " (no probe decided)" : std::string(": ") + verdictName(v) + " throughout")
          << '\n';
    }
    for (const Probe& p : search.probes())
      if (p.failed)
        out << head << "the run at " << key << " = " << formatNumber(p.value) << " failed (boundary.json)\n";
    grid += gridComparison(spec, search).cases;
  }
  for (std::size_t i = 0; i < result.outcomes.size(); ++i) wall += result.outcomes[i].wallSeconds;
  runs = result.outcomes.size();
  out << runs << " runs (" << formatDuration(wall)
      << " of case time); a grid at the same spacing with the same beds: " << grid << " runs\n";
  return out.str();
}

std::string boundaryPlanListing(const BoundarySpec& spec) {
  checkBoundarySpec(spec);
  const BoundaryOptions& o = spec.options;
  const std::size_t searches = std::max<std::size_t>(1, spec.overValues.size());
  std::vector<BoundaryCase> first;
  for (std::size_t s = 0; s < searches; ++s)
    for (const BoundaryRun& r : BoundarySearch(o).next()) first.push_back({s, r});
  std::ostringstream out;
  out << "first round: " << first.size() << " runs\n";
  double run = 0.0, bed = 0.0;
  const SpeedBasis speed = speedBasis(spec.base);
  std::map<std::string, bool> beds;
  for (const BoundaryCase& c : first) {
    const RunConfig config = boundaryCaseConfig(spec, c);
    run += estimatedRunSeconds(config, speed.ns);
    // A bed per seed and --over value at most (fewer when the --over key does not change the bed).
    const std::string bedId = std::to_string(c.search) + "/" + std::to_string(config.box.seed);
    if (!beds[bedId]) bed += estimatedBedSeconds(config, speed.ns);
    beds[bedId] = true;
    const std::string label = searchLabel(spec, c.search);
    out << "  " << (label.empty() ? "" : label + ", ") << spec.key << " = " << formatNumber(c.run.value)
        << ", box.seed = " << config.box.seed << '\n';
  }
  // Bisections of one coarse interval down to one lattice step.
  const double steps = static_cast<double>(latticeIntervals(o)) / (o.points - 1);
  const int bisections = static_cast<int>(std::ceil(std::log2(std::max(1.0, steps))));
  out << "estimated cost of the first round: " << formatDuration(run) << " of runs and up to " << formatDuration(bed)
      << " of beds (less for beds already cached), on one core at " << formatNumber(speed.ns, 3)
      << " ns per particle-step: " << speed.source << "\n"
      << "then: more beds (up to " << o.maxBeds << ") where the sign is not decided, and about " << bisections
      << " bisections of each change of verdict, " << o.minBeds << "-" << o.maxBeds << " beds each\n";
  return out.str();
}

}  // namespace wiggle
