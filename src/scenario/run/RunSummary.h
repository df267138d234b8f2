#pragma once
// summary.json, typed: what a finished run reports (docs/OUTPUT-FORMATS.md). One table of fields
// (name, unit, meaning, member) writes the file, reads it back (the sweep's results table), and is
// the schema the Python package reads (docs/summary-schema.json, checked against this table by a
// test), so the three cannot drift apart.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/Choice.h"

namespace wiggle {

// How a run ended: ok (its outputs and summary.json are written) or stopped (a signal or the
// stopAfterSteps hook: only its checkpoints, and it resumes). summary.json's "status" is its word.
enum class RunStatus { Ok, Stopped };
template <>
struct ChoiceNames<RunStatus> {
  static constexpr std::array<std::string_view, 2> names{"ok", "stopped"};
};

struct RunSummary {
  // the rise rate (analysis/RiseRate.h)
  double vy = 0.0, vySlope = 0.0;
  std::string vyRule;
  bool plateau = false;
  double tInitial = 0.0, tFinal = 0.0, yInitial = 0.0, yFinal = 0.0, yStart = 0.0;
  double angleEnd = 0.0;  // how far the intruder turned by the end [rad] (intruder.rotation = "free")
  double vyWindowPeriods = 0.0, averagedFromT = 0.0;
  double vySettled = 0.0, tSettled = 0.0, settleBand = 0.0;  // the paper's t_f rule (measureSettledRate)
  bool settled = false;
  std::vector<std::string> warnings;
  // the blow-up detector (docs/RELIABILITY.md, section 7)
  double overlapMargin = 0.0, speedMargin = 0.0;
  RunStatus status = RunStatus::Ok;
  // size and cost
  std::uint64_t grains = 0, particles = 0, steps = 0, threads = 0;
  std::string simd;  // the force kernels' instruction set (physics/ForceKernels.h)
  double wallSeconds = 0.0, runWallSeconds = 0.0, bedWallSeconds = 0.0;
  bool bedFromCache = false;
  std::string bedKey;
  double nsPerParticleStep = 0.0;
  std::string stateHash;
  // engine diagnostics at the end of the run
  std::uint64_t neighbourPairs = 0, contacts = 0, intruderPairs = 0;
  double stateBytesPerGrain = 0.0;
  nlohmann::json stepProfile;  // run.profile: stepProfileJson; null (absent from the file) when off
  nlohmann::json threadsUsed;  // threadsUsedJson; null (absent) when the run had one thread to give
  // the case's parameters again, for convenience
  std::string shape;
  double amplitude = 0.0, period = 0.0, mu = 0.0;
  std::vector<std::uint64_t> fieldFrames;  // frames averaged per fields.phases entry
  std::string version;                     // of the wiggle that wrote it
};

struct SummaryField {
  const char* name;     // the JSON key
  const char* unit;     // "" for none
  const char* meaning;  // one line
  std::variant<double RunSummary::*, bool RunSummary::*, std::uint64_t RunSummary::*, std::string RunSummary::*,
               std::vector<std::string> RunSummary::*, std::vector<std::uint64_t> RunSummary::*,
               RunStatus RunSummary::*, nlohmann::json RunSummary::*>
      member;
};

// Every field, in the file's order.
const std::vector<SummaryField>& summaryFields();

nlohmann::json toJson(const RunSummary& summary);

// Reads a summary.json object; a key that is missing keeps its default (files written by an older
// wiggle), a key of the wrong type throws wiggle::Error naming it.
RunSummary summaryFromJson(const nlohmann::json& json);

class World;
// summary.json's threads_used: the wall seconds this process's stepping spent at each thread count
// ({"2": 812.5, "1": 95.0}; physics/ThreadGovernor.h); null when it never measured (one thread).
nlohmann::json threadsUsedJson(const World& world);
// The warning when the run shed threads, else "": "another process took a core: ran on 1 thread (of
// 2) for 43 % of this process's stepping". For the log and the terminal, not `warnings`: it says
// what the run cost, never what its result is worth (the bits are the same).
std::string threadsShedWarning(const RunSummary& summary);

// summary.json's step_profile (docs/OUTPUT-FORMATS.md): threads, steps, step_s, serial_share,
// wait_share, serial_and_wait_share, per stage its kind, seconds, share and calls (with the
// parallel stages' work_s, wait_s and wait_share), and strip_imbalance: the force stage's load
// imbalance on the run's last list at 2, 4, 8, 16 and 32 threads (World::stripImbalance).
nlohmann::json stepProfileJson(const World& world);

// The schema as JSON: [{"name", "type", "unit", "meaning"}, ...] (docs/summary-schema.json).
nlohmann::json summarySchema();

}  // namespace wiggle
