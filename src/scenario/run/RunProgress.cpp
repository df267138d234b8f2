#include "scenario/run/RunProgress.h"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/Error.h"
#include "core/Format.h"
#include "io/AtomicFile.h"

namespace wiggle {

std::string interruptedStage(double t) { return "interrupted at t = " + formatNumber(t); }

std::string failedStage(double t, const std::string& why) { return "failed at t = " + formatNumber(t) + ": " + why; }

std::string runProgressPath(const std::string& runDir) { return runDir + "/progress.json"; }

void writeRunProgress(const std::string& runDir, const RunProgress& p) {
  const nlohmann::json j = {
      {"stage", p.stage}, {"fraction", p.fraction}, {"t", p.t}, {"duration", p.duration}, {"eta_s", p.etaSeconds}};
  writeFileAtomically(runProgressPath(runDir), j.dump(2) + "\n");
}

std::optional<RunProgress> readRunProgress(const std::string& runDir) {
  const std::string path = runProgressPath(runDir);
  if (!std::filesystem::exists(path)) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(readFile(path));
    return RunProgress{j.at("stage").get<std::string>(), j.at("fraction").get<double>(), j.at("t").get<double>(),
                       j.at("duration").get<double>(), j.at("eta_s").get<double>()};
  } catch (const std::exception&) {  // a foreign or damaged file: no progress known
    return std::nullopt;
  }
}

}  // namespace wiggle
