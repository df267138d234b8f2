#include "scenario/run/Experiment.h"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <sstream>

#include "analysis/FieldObserver.h"
#include "analysis/RiseRate.h"
#include "core/Console.h"
#include "core/Error.h"
#include "core/Format.h"
#include "core/Machine.h"
#include "core/StopSignal.h"
#include "core/Version.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "model/CavityModel.h"
#include "scenario/bed/BedMaker.h"
#include "scenario/run/Checkpoint.h"
#include "scenario/run/Remeasure.h"
#include "scenario/run/RunObservers.h"
#include "scenario/run/RunProgress.h"
#include "scenario/run/RunSummary.h"
#include "scenario/cost/SpeedRecord.h"

namespace wiggle {

namespace fs = std::filesystem;

std::string runWarningsPath(const std::string& dir) { return dir + "/warnings.txt"; }

std::vector<std::string> readRunWarnings(const std::string& dir) {
  std::vector<std::string> lines;
  if (!fs::exists(runWarningsPath(dir))) return lines;
  std::istringstream in(readFile(runWarningsPath(dir)));
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.push_back(line);
  return lines;
}

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

void writePhaseRates(const std::string& path, const RunState& state) {
  std::string out = "bin,phase_center,vy_mean,samples\n";
  for (int b = 0; b < kPhaseBins; ++b) {
    const std::uint64_t n = state.phaseCount[b];
    out += std::to_string(b) + ',' + formatNumber(b + 0.5, 10) + ',' +
           (n ? formatNumber(state.phaseSum[b] / static_cast<double>(n), 10) : std::string()) + ',' + std::to_string(n) + '\n';
  }
  writeFileAtomically(path, out);
}

void writeModel(const std::string& path, const RunConfig& config, const Shape& shape) {
  std::vector<std::array<double, 2>> outline(shape.outline.begin(), shape.outline.end());
  const CavityGeometry g = cavityGeometry(outline);
  nlohmann::json j = cavityGeometryJson(g);
  j["shape"] = std::string(choiceName(config.intruder.shape));
  j["angle"] = config.intruder.angle;
  // The side with the smaller T_rise sets when rising can start; both are given.
  const CavitySide& main = g.left.tRise <= g.right.tRise ? g.left : g.right;
  j["l"] = main.l;
  j["l_prime"] = main.lPrime;
  j["T_rise"] = main.tRise;
  // The model's amplitude is the swing either side of the motion's centre: drive.amplitude in the
  // displacement form, A T / 2 pi in the velocity form (so it varies along the curve).
  auto modelRate = [&](double period) {
    const double amplitude = displacementAmplitude(config.drive, period);
    return 0.5 * (cavityRiseRate(g, g.left, period, amplitude) + cavityRiseRate(g, g.right, period, amplitude));
  };
  j["amplitude"] = config.drive.amplitude;
  j["drive_form"] = std::string(choiceName(config.drive.form));
  j["period"] = config.drive.period;  // the period vy_at_period is for
  nlohmann::json curve = nlohmann::json::array();
  for (int k = 1; k <= 120; ++k) curve.push_back({0.1 * k, modelRate(0.1 * k)});
  j["curve"] = curve;
  j["vy_at_period"] = modelRate(config.drive.period);
  writeFileAtomically(path, j.dump(2) + "\n");
}

// Says `warning` on the console, in the log and in warnings.txt (hence in summary.json).
void addRunWarning(const std::string& dir, const std::string& warning, LogFile& log) {
  std::string text;
  for (const std::string& w : readRunWarnings(dir)) text += w + "\n";
  writeFileAtomically(runWarningsPath(dir), text + warning + "\n");
  log.line("warning: " + warning);
  std::fprintf(stderr, "wiggle: warning: %s\n", warning.c_str());
}

// The newest checkpoint of the run in `dir` that is sound and of this config, or nothing. When
// there were checkpoints and none could be read, the run starts again from the bed: all its
// progress is lost, which is said loudly (a warning in summary.json), not only in the log.
std::optional<Checkpoint> newestGoodCheckpoint(const std::string& dir, const RunConfig& config,
                                               const std::string& configToml, LogFile& log) {
  std::string refused;
  for (const std::string& path : {checkpointPath(dir), previousCheckpointPath(dir)}) {
    if (!fs::exists(path)) continue;
    try {
      Checkpoint checkpoint = parseCheckpoint(readFile(path), path, config, configToml);
      log.line("resumed from " + path + " at step " + std::to_string(checkpoint.world.stepCount()));
      return checkpoint;
    } catch (const Error& e) {
      log.line(std::string("checkpoint refused: ") + e.what());
      std::fprintf(stderr, "wiggle: warning: %s; trying an older one\n", e.what());
      refused += std::string(refused.empty() ? "" : "; ") + e.what();
    }
  }
  if (!refused.empty()) {
    addRunWarning(dir,
                  "no checkpoint could be read (" + refused +
                      "): the run restarted from the bed at t = 0 and the time spent on it before was lost",
                  log);
  } else if (fs::exists(runProgressPath(dir))) {
    // A run stopped before its first checkpoint (progress.json is written only once a run has
    // begun): said on the console too, so that a resume that starts at t = 0 is never silent.
    const std::string note =
        "no checkpoint in " + dir + " (its run stopped before the first): starting it from the bed at t = 0";
    log.line(note);
    std::fprintf(stderr, "wiggle: %s\n", note.c_str());
  } else {
    log.line("no checkpoint: starting from the bed");
  }
  return std::nullopt;
}

// progress.json (scenario/run/RunProgress.h): each stage as it begins, and the run's progress at most
// every 10 wall seconds (the step loop reports it every 200 steps).
class ProgressFile {
 public:
  ProgressFile(std::string dir, double duration) : dir_(std::move(dir)), duration_(duration) {}
  void stage(RunPhase phase, const std::string& words, double fraction = -1.0, double t = 0.0) {
    writeRunProgress(dir_, {phase, words, fraction, t, duration_, -1.0, 0});
    last_ = Clock::now();
  }
  // Why the run stopped, as it stops (SIGINT or SIGTERM, after its checkpoint; an error), so that
  // `wiggle status` does not show a run that is not running. Best effort: the error that stopped
  // the run (a full disk, say) is what the user must see, not a failure to write this file.
  void stopped(RunPhase phase, const std::string& words, double fraction, double t) noexcept {
    try {
      stage(phase, words, fraction, t);
    } catch (...) {
    }
  }
  void running(double fraction, double t, double etaSeconds, int threads) {
    if (secondsSince(last_) < 10.0) return;
    writeRunProgress(dir_, {RunPhase::Running, "running", fraction, t, duration_, etaSeconds, threads});
    last_ = Clock::now();
  }

 private:
  std::string dir_;
  double duration_;
  Clock::time_point last_ = Clock::now();
};

// A run's start from its bed (cached or made now), the drive started; the bed's key, origin and
// wall time go into `state`.
World startFromBed(const Case& run, RunState& state, LogFile& log, ProgressLine& progress) {
  const RunConfig& config = run.config;
  const auto bedStart = Clock::now();
  std::optional<CachedBed> obtained;
  try {
    obtained.emplace(startRun(run, [&](const BedStatus& s) {
      progress.update(bedStatusLine(s, config.box.bedHeight) + ", " + formatDuration(secondsSince(bedStart)) +
                      " elapsed");
    }));
  } catch (const Error& e) {  // interrupted (the bed so far is saved) or failed: say so in the log too
    progress.clear();
    log.line(e.what());
    throw;
  }
  CachedBed& bed = *obtained;
  progress.clear();
  state.bedWallSeconds = secondsSince(bedStart);
  state.bedKey = bed.key;
  state.bedFromCache = bed.fromCache;
  if (!bed.note.empty()) {
    log.line(bed.note);
    std::fprintf(stderr, "wiggle: warning: %s\n", bed.note.c_str());
  }
  log.line(std::string(bed.fromCache ? "bed loaded from " : "bed made and cached at ") + bed.path + " (" +
           std::to_string(bed.world.grainCount()) + " grains, surface " + formatNumber(freeSurfaceHeight(bed.world)) +
           ", " + formatNumber(state.bedWallSeconds) + " s)");
  return std::move(bed.world);
}

// What makes the result less than it seems, in sentences (summary.json's warnings).
// `extended`: the phase bins began at another step than this run's own 0.1 t_total, so the run was
// resumed with a longer run.duration (a run made in one go averages from its first measured step,
// whatever its V_y window's first sample is).
std::vector<std::string> runWarnings(const RiseRate& rate, double averagedFrom, bool extended) {
  std::vector<std::string> warnings = rateWarnings(rate);
  if (extended)
    warnings.push_back("phase_rates.csv and fields.csv average from t = " + formatNumber(averagedFrom) +
                       ", V_y from t = " + formatNumber(rate.tInitial) +
                       ": the run was extended (resumed with a longer run.duration); the "
                       "trajectory, V_y and the final state are those of a run this long from the start");
  return warnings;
}

RunSummary summarise(const Case& run, const std::string& dir, const World& world, const RunState& state,
                     const FieldObserver& fields, const RiseRate& rate, const SettledRate& settled,
                     const SettleRule& rule, double averagedFrom, bool extended) {
  const RunConfig& config = run.config;
  RunSummary summary;
  summary.vy = rate.vy;
  summary.vySlope = rate.slope;
  summary.vyRule = "(y_f - y_i)/(t_f - t_i), t_i = 0.1 t_total, t_f = t_total or the start of a plateau at "
                   "the free surface (docs/OUTPUT-FORMATS.md)";
  summary.plateau = rate.plateau;
  summary.tInitial = rate.tInitial;
  summary.tFinal = rate.tFinal;
  summary.yInitial = rate.yInitial;
  summary.yFinal = rate.yFinal;
  summary.angleEnd = world.intruderSpin().angle;
  summary.yStart = state.samples.front().y;
  summary.vyWindowPeriods = rate.windowPeriods;
  summary.vySettled = settled.vy;
  summary.tSettled = settled.tSettled;
  summary.settled = settled.settled;
  summary.settleBand = rule.band;
  summary.averagedFromT = averagedFrom;
  summary.warnings = readRunWarnings(dir);
  for (std::string& w : runWarnings(rate, averagedFrom, extended)) summary.warnings.push_back(std::move(w));
  summary.overlapMargin = world.healthMargins().overlap;
  summary.speedMargin = world.healthMargins().speed;
  summary.status = RunStatus::Ok;
  summary.grains = world.grainCount();
  summary.particles = world.particles().size();
  summary.steps = world.stepCount();
  summary.threads = static_cast<std::uint64_t>(omp_get_max_threads());
  summary.simd = simdLevelName(world.kernels().level);
  summary.wallSeconds = state.runWallSeconds + state.bedWallSeconds;
  summary.runWallSeconds = state.runWallSeconds;
  summary.bedWallSeconds = state.bedWallSeconds;
  summary.bedFromCache = state.bedFromCache;
  summary.bedKey = state.bedKey;
  summary.nsPerParticleStep = 1e9 * state.runWallSeconds /
                              (static_cast<double>(world.particles().size()) * static_cast<double>(world.stepCount()));
  summary.stateHash = world.stateHash();
  const NeighbourList& list = world.neighbours();
  summary.neighbourPairs = list.pairCount();
  summary.contacts = world.touchingPairs();
  summary.intruderPairs = world.intruderPairs().size();
  summary.stateBytesPerGrain = static_cast<double>(world.stateBytes()) / std::max(1u, world.grainCount());
  if (world.stepProfile().on()) summary.stepProfile = stepProfileJson(world);
  summary.threadsUsed = threadsUsedJson(world);
  summary.shape = std::string(choiceName(config.intruder.shape));
  summary.amplitude = config.drive.amplitude;
  summary.period = config.drive.period;
  summary.mu = config.contact.mu;
  for (std::size_t p = 0; p < config.fields.phases.size(); ++p) summary.fieldFrames.push_back(fields.frames(p));
  summary.version = versionText();
  return summary;
}

// What this process's stepping cost (a resumed run's earlier stretches not counted).
struct SteppingCost {
  double cpuSeconds = 0.0;   // CPU time of every thread
  double wallSeconds = 0.0;  // the stepping's wall time (RunState::runWallSeconds's share of this process)
  std::uint64_t steps = 0;
};

// Leaves this process's stepping speed for the cost estimates (scenario/cost/SpeedRecord.h), whether
// the run finished or was stopped by a signal: a case of hours mostly runs in stretches that end by
// a signal, and their speed is as good a measure as a finished run's. The figures are this process's
// alone: a resumed run's earlier stretches may have run on another machine. Stretches under 10^4
// steps say more about start-up than about the step.
void recordSteppingSpeed(const RunConfig& config, const World& world, const SteppingCost& stepping) {
  if (stepping.steps < 10000) return;
  const double particleSteps = static_cast<double>(world.particles().size()) * static_cast<double>(stepping.steps);
  recordRunSpeed(config, omp_get_max_threads(), 1e9 * stepping.wallSeconds / particleSteps,
                 1e9 * stepping.cpuSeconds / particleSteps, simdLevelName(world.kernels().level),
                 world.particles().size());
}

// A checkpoint, and beside it the trajectory so far: a run of hours can be plotted (`wiggle plot`)
// and measured to where it got (`wiggle rate`) while it runs or after it stopped; its end rewrites
// trajectory.csv whole.
void saveProgress(const std::string& dir, const std::string& configToml, const World& world, const RunState& state,
                  const FieldObserver& fields) {
  writeCheckpoint(dir, configToml, world, state, fields);
  writeTrajectoryCsv(dir + "/trajectory.csv", state.samples, state.spins);
}

const char* threadChangeWords(ThreadChangeReason reason) {
  switch (reason) {
    case ThreadChangeReason::Waiting: return "its threads waited for each other (another process holds a core)";
    case ThreadChangeReason::IdleCore: return "a core stands idle again";
    case ThreadChangeReason::Trial: return "trying one more thread (no core stood idle; kept if its threads do not wait)";
    case ThreadChangeReason::Ceiling: return "the run's thread count";
    case ThreadChangeReason::Scheduled: return "as scheduled";
  }
  return "";
}

// The thread governor's changes since the last call, a log line each (physics/ThreadGovernor.h).
void logThreadChanges(const World& world, LogFile& log, std::size_t& logged) {
  const std::vector<ThreadChange>& changes = world.threadGovernor().changes();
  for (; logged < changes.size(); ++logged) {
    const ThreadChange& c = changes[logged];
    log.line("threads " + std::to_string(c.from) + " -> " + std::to_string(c.to) + " at step " +
             std::to_string(c.step) + ": " + threadChangeWords(c.reason));
  }
}

// Steps `world` to the end of the run, feeding the observers, with the progress line, periodic
// checkpoints and the stop on a signal (a checkpoint, then an Error saying how to continue).
// Returns false when options.stopAfterSteps stopped it first.
bool stepToTheEnd(const Case& run, const RunOptions& options, const std::string& configToml, World& world,
                  RunState& state, FieldObserver& fields, RunObservers& observers, ProgressLine& progress,
                  ProgressFile& progressFile, LogFile& log) {
  const RunSchedule& steps = run.steps;
  const std::string& dir = options.outDir;
  const double particles = static_cast<double>(world.particles().size());
  auto lastCheckpoint = Clock::now();
  auto chunkStart = Clock::now();
  const std::uint64_t startStep = world.stepCount();
  world.threadGovernor().setPolicy(options.threadPolicy);
  std::size_t loggedChanges = 0;
  const double wallAtStart = state.runWallSeconds;  // a resumed run's earlier stretches
  // Every 200 steps and at the end the progress line, the signal and the checkpoint clock are looked at.
  auto progressAt = [&](std::uint64_t step) { return step % 200 == 0 || step == steps.total; };
  auto stopAfterAt = [&](std::uint64_t step) {
    return options.stopAfterSteps && step - startStep >= options.stopAfterSteps;
  };
  while (world.stepCount() < steps.total) {
    observers.stepTowards(world, steps.total,
                          [&](std::uint64_t step) { return progressAt(step) || stopAfterAt(step); });
    const std::uint64_t step = world.stepCount();
    if (progressAt(step)) {
      state.runWallSeconds += secondsSince(chunkStart);
      chunkStart = Clock::now();
      const StepPace pace{state.runWallSeconds - wallAtStart, step - startStep};
      const double eta = pace.etaSeconds(steps.total - step);
      const double nsPerParticleStep = pace.nsPerParticleStep(particles);
      const double fraction = static_cast<double>(step) / static_cast<double>(steps.total);
      progressFile.running(fraction, world.time(), eta, world.threadGovernor().threads());
      logThreadChanges(world, log, loggedChanges);
      progress.update("[run] " + formatNumber(100.0 * fraction) + "%  t = " + formatNumber(world.time()) + " / " +
                      formatNumber(run.config.run.duration) + "  ETA " + formatDuration(eta) + "  " +
                      formatNumber(nsPerParticleStep) + " ns/particle-step  y = " + formatNumber(world.intruder().y));
      if (const int signal = stopSignalReceived(); signal != 0) {
        saveProgress(dir, configToml, world, state, fields);
        progress.clear();
        log.line("interrupted by signal " + std::to_string(signal) + " at step " + std::to_string(step) +
                 "; checkpoint written");
        throw Interrupted(signal, "interrupted at t = " + formatNumber(world.time()) +
                                      "; continue with: wiggle run --out " + dir + " --resume");
      }
      if (secondsSince(lastCheckpoint) >= run.config.run.checkpointInterval) {
        saveProgress(dir, configToml, world, state, fields);
        lastCheckpoint = Clock::now();
        log.line("checkpoint at step " + std::to_string(step));
      }
    }
    if (stopAfterAt(step)) {
      if (options.checkpointAtStop) saveProgress(dir, configToml, world, state, fields);
      return false;
    }
  }
  state.runWallSeconds += secondsSince(chunkStart);
  logThreadChanges(world, log, loggedChanges);
  return true;
}

// The finished run's files: trajectory, phase rates, fields, model and the summary, written last.
RunOutcome writeRunOutputs(const Case& run, const std::string& dir, const World& world, const RunState& state,
                           const FieldObserver& fields, LogFile& log) {
  const RunConfig& config = run.config;
  const SettleRule rule;
  const auto [rate, settled] = measureRunRates(run, state.samples, paperWindow(config.run.duration), rule);
  writeTrajectoryCsv(dir + "/trajectory.csv", state.samples, state.spins);
  writePhaseRates(dir + "/phase_rates.csv", state);
  if (config.fields.enabled) fields.writeCsv(dir + "/fields.csv");
  writeModel(dir + "/model.json", config, run.shape);

  // Phase rates and field frames accumulate one step per step from 0.1 t_total on; a run extended
  // (resumed with a longer run.duration) began at 0.1 of its first duration. Where that window
  // began follows from the count of accumulated steps.
  std::uint64_t accumulated = 0;
  for (const std::uint64_t n : state.phaseCount) accumulated += n;
  const std::uint64_t firstAveraged = world.stepCount() - accumulated;
  const double averagedFrom = static_cast<double>(firstAveraged) * config.run.dt;
  const bool extended = firstAveraged != run.steps.firstMeasured;
  const RunSummary summary = summarise(run, dir, world, state, fields, rate, settled, rule, averagedFrom, extended);
  writeFileAtomically(dir + "/summary.json", toJson(summary).dump(2) + "\n");
  log.line("done: vy = " + formatNumber(rate.vy) + ", slope = " + formatNumber(rate.slope) +
           ", vy_settled = " + formatNumber(settled.vy) + " (t_settled = " + formatNumber(settled.tSettled) + "), " +
           formatNumber(summary.nsPerParticleStep) + " ns/particle-step, state " + world.stateHash());
  for (const std::string& w : summary.warnings) log.line("warning: " + w);
  if (const std::string shed = threadsShedWarning(summary); !shed.empty()) log.line("warning: " + shed);
  return RunOutcome{summary, dir + "/summary.json"};
}

}  // namespace

std::string RunOutcome::resultLine() const {
  char text[160];
  std::snprintf(text, sizeof text, "V_y = %.6g (least-squares slope %.6g) d per sqrt(d/g)", summary.vy,
                summary.vySlope);
  std::string line = text;
  if (summary.settled) {
    std::snprintf(text, sizeof text, "; settled at t = %.6g: V_y to then (the paper's t_f rule) = %.6g",
                  summary.tSettled, summary.vySettled);
    line += text;
  }
  return line + "; summary in " + summaryPath;
}

std::string runLockPath(const std::string& dir) { return dir + "/.running.lock"; }

bool holdsRun(const std::string& dir) {
  return fs::exists(checkpointPath(dir)) || fs::exists(previousCheckpointPath(dir)) ||
         fs::exists(dir + "/summary.json") || fs::exists(runProgressPath(dir));
}

FileLock prepareRunDirectory(const std::string& dir, const RunConfig& config, const std::string& configToml,
                             bool resume) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw Error("cannot create output directory " + dir + ": " + ec.message());
  FileLock running(runLockPath(dir), false, false, "another wiggle process is running the case in " + dir);
  if (config.run.dumpInterval > 0) fs::create_directories(dir + "/dumps", ec);
  const bool hasCheckpoint = fs::exists(checkpointPath(dir)) || fs::exists(previousCheckpointPath(dir));
  if (!resume && (hasCheckpoint || fs::exists(dir + "/summary.json")))
    throw Error(dir + " already holds a run: use --resume to continue it, or choose another --out");
  if (resume && fs::exists(dir + "/config.toml")) {
    const RunConfig previous = parseRunConfig(readFile(dir + "/config.toml"), dir + "/config.toml");
    if (const std::string why = whyRunCannotContinue(previous, config); !why.empty())
      throw Error("--resume: cannot continue the run in " + dir + ": " + why);
  }
  if (resume)
    removeLeftoverTemporaries(dir);  // of a run killed while writing a file
  else
    fs::remove(runWarningsPath(dir), ec);  // a new run has no history
  writeFileAtomically(dir + "/config.toml", configToml);
  return running;
}

CachedBed startRun(const Case& run, const BedProgress& progress) {
  CachedBed bed = obtainBed(run.config, run.clump, progress);
  if (!run.config.run.keepBedHistory) bed.world.clearContactHistory();
  startDrive(bed.world, run);
  return bed;
}

RunOutcome runExperiment(const Case& run, const RunOptions& options) {
  if (options.threads > 0) omp_set_num_threads(options.threads);
  const RunConfig& config = run.config;
  const std::string dir = options.outDir;
  const std::string configToml = toToml(config);
  const FileLock running = prepareRunDirectory(dir, config, configToml, options.resume);
  LogFile log(dir + "/log.txt");
  log.line("wiggle " + versionText() + (options.resume ? " run --resume" : " run") + " in " + dir +
           " with " + std::to_string(omp_get_max_threads()) + (omp_get_max_threads() == 1 ? " thread, " : " threads, ") +
           simdLevelName(defaultSimdLevel()) + " force kernels");

  RunState state;
  FieldObserver fields(config.fields, config.box.width);
  ProgressFile progressFile(dir, config.run.duration);
  auto fractionDone = [&run](const World& w) {
    return static_cast<double>(w.stepCount()) / static_cast<double>(run.steps.total);
  };
  std::optional<World> loaded;
  if (options.resume) {
    if (std::optional<Checkpoint> checkpoint = newestGoodCheckpoint(dir, config, configToml, log)) {
      loaded.emplace(std::move(checkpoint->world));
      state = std::move(checkpoint->state);
      fields = std::move(checkpoint->fields);
      progressFile.stage(RunPhase::Starting, "resumed from its checkpoint", fractionDone(*loaded), loaded->time());
    }
  }

  const std::string dumpPath = dir + "/dumps/dump.lammpstrj";
  // A rewritten line on a terminal; the log gets it every 30 s.
  ProgressLine progress(options.progressLine, [&log](const std::string& text) { log.line(text); }, 30.0);
  // SIGINT/SIGTERM while the bed is made or the run steps: save the bed in the making or a
  // checkpoint, then stop. Not while the outputs are written: there they stop the process at once.
  std::optional<StopSignalGuard> stopOnSignal;
  stopOnSignal.emplace();
  if (!loaded) {
    progressFile.stage(RunPhase::Starting, "making or loading its bed");
    try {
      loaded.emplace(startFromBed(run, state, log, progress));
    } catch (const Interrupted&) {
      progressFile.stopped(RunPhase::Interrupted, kInterruptedMakingBedStage, -1.0, 0.0);
      throw;
    } catch (const Error& e) {
      progressFile.stopped(RunPhase::Failed, failedMakingBedStage(e.what()), -1.0, 0.0);
      throw;
    }
    progressFile.stage(RunPhase::Starting, state.bedFromCache ? "bed loaded from the cache, run started" : "bed made, run started");
    // A run without dumps leaves no dump file (not an empty one); one with dumps starts it afresh.
    std::error_code ec;
    if (run.steps.dumpEvery)
      std::ofstream(dumpPath, std::ios::trunc);
    else
      fs::remove(dumpPath, ec);
    state.dumpBytes = 0;
  } else {
    // Drop dump frames written after the checkpoint: they will be written again.
    std::error_code ec;
    if (fs::exists(dumpPath)) fs::resize_file(dumpPath, state.dumpBytes, ec);
    if (ec) throw Error("cannot truncate " + dumpPath + ": " + ec.message());
  }
  World& world = *loaded;
  world.enableStepProfile(config.run.profile);  // this process's stepping (a resumed run: since the resume)
  RunObservers observers(run, state, fields, dumpPath);
  if (world.stepCount() == 0 && state.samples.empty()) {
    // The forces of the start (drive on, bed history as configured), which the first step would
    // evaluate anyway: the first sample's fy and the first dump frame are then those of step 0, not
    // the bed's last, and the same whether the bed was just made or loaded from the cache (a
    // loaded bed's pair forces are zero: World::save does not hold them).
    world.evaluateForces();
    observers.sample(world);
    if (run.steps.dumpEvery) observers.dumpFrame(world);
  }

  bool finished = false;
  const double cpuAtStart = processCpuSeconds();
  const double wallAtStart = state.runWallSeconds;
  const std::uint64_t stepAtStart = world.stepCount();
  const auto steppingSoFar = [&] {
    return SteppingCost{processCpuSeconds() - cpuAtStart, state.runWallSeconds - wallAtStart,
                        world.stepCount() - stepAtStart};
  };
  try {
    finished = stepToTheEnd(run, options, configToml, world, state, fields, observers, progress, progressFile, log);
  } catch (const Interrupted&) {
    progress.clear();
    progressFile.stopped(RunPhase::Interrupted, interruptedStage(world.time()), fractionDone(world), world.time());
    recordSteppingSpeed(config, world, steppingSoFar());
    throw;
  } catch (const Error& e) {
    progress.clear();
    progressFile.stopped(RunPhase::Failed, failedStage(world.time(), e.what()), fractionDone(world), world.time());
    throw;
  } catch (...) {
    progress.clear();
    throw;
  }
  progress.clear();
  if (!finished) {  // as if killed: nothing more is written
    RunOutcome stopped;
    stopped.summary.status = RunStatus::Stopped;
    return stopped;
  }
  recordSteppingSpeed(config, world, steppingSoFar());
  writeCheckpoint(dir, configToml, world, state, fields);
  stopOnSignal.reset();
  progressFile.stage(RunPhase::Running, "writing its results", 1.0, world.time());
  RunOutcome outcome = writeRunOutputs(run, dir, world, state, fields, log);
  progressFile.stage(RunPhase::Finished, "finished", 1.0, world.time());
  return outcome;
}

}  // namespace wiggle
