#include "scenario/run/RunProgress.h"

#include <array>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/Error.h"
#include "core/Format.h"
#include "io/AtomicFile.h"

namespace wiggle {

namespace {

constexpr std::array<RunPhase, 5> kPhases = {RunPhase::Starting, RunPhase::Running, RunPhase::Finished,
                                             RunPhase::Interrupted, RunPhase::Failed};

// A progress.json of an earlier wiggle, which wrote no "phase": the phase its words begin with; a
// run that had stepped and wrote none of these words was running.
RunPhase phaseOfStageWords(const std::string& stage, double fraction) {
  const auto startsWith = [&stage](const char* prefix) { return stage.rfind(prefix, 0) == 0; };
  if (stage == "finished") return RunPhase::Finished;
  if (startsWith("interrupted")) return RunPhase::Interrupted;
  if (startsWith("failed")) return RunPhase::Failed;
  return stage == "running" || fraction >= 0.0 ? RunPhase::Running : RunPhase::Starting;
}

}  // namespace

double StepPace::etaSeconds(std::uint64_t stepsLeft) const {
  if (steps == 0) return -1.0;
  return seconds / static_cast<double>(steps) * static_cast<double>(stepsLeft);
}

double StepPace::nsPerParticleStep(double particles) const {
  if (steps == 0 || particles <= 0.0) return 0.0;
  return 1e9 * seconds / (particles * static_cast<double>(steps));
}

const char* runPhaseName(RunPhase phase) {
  switch (phase) {
    case RunPhase::Starting: return "starting";
    case RunPhase::Running: return "running";
    case RunPhase::Finished: return "finished";
    case RunPhase::Interrupted: return "interrupted";
    case RunPhase::Failed: return "failed";
  }
  return "unknown";
}

std::string interruptedStage(double t) { return "interrupted at t = " + formatNumber(t); }

std::string failedStage(double t, const std::string& why) { return "failed at t = " + formatNumber(t) + ": " + why; }

std::string failedMakingBedStage(const std::string& why) { return "failed while making or loading its bed: " + why; }

std::string threadsNowWords(const RunProgress& p) {
  if (p.phase != RunPhase::Running || p.threads <= 0) return "";
  return ", on " + std::to_string(p.threads) + (p.threads == 1 ? " thread" : " threads");
}

std::string runProgressPath(const std::string& runDir) { return runDir + "/progress.json"; }

void writeRunProgress(const std::string& runDir, const RunProgress& p) {
  const nlohmann::json j = {{"phase", runPhaseName(p.phase)}, {"stage", p.stage}, {"fraction", p.fraction},
                            {"t", p.t}, {"duration", p.duration}, {"eta_s", p.etaSeconds},
                            {"threads", p.threads}};
  writeFileAtomically(runProgressPath(runDir), j.dump(2) + "\n");
}

std::optional<RunProgress> readRunProgress(const std::string& runDir) {
  const std::string path = runProgressPath(runDir);
  if (!std::filesystem::exists(path)) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(readFile(path));
    RunProgress p;
    p.stage = j.at("stage").get<std::string>();
    p.fraction = j.at("fraction").get<double>();
    p.t = j.at("t").get<double>();
    p.duration = j.at("duration").get<double>();
    p.etaSeconds = j.at("eta_s").get<double>();
    p.threads = j.value("threads", 0);  // written since the thread governor
    if (!j.contains("phase")) {
      p.phase = phaseOfStageWords(p.stage, p.fraction);
      return p;
    }
    const std::string name = j.at("phase").get<std::string>();
    for (RunPhase phase : kPhases)
      if (name == runPhaseName(phase)) {
        p.phase = phase;
        return p;
      }
    return std::nullopt;  // a phase this wiggle does not know: a newer or damaged file
  } catch (const std::exception&) {  // a foreign or damaged file: no progress known
    return std::nullopt;
  }
}

}  // namespace wiggle
