#include "sweep/SweepStart.h"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "io/AtomicFile.h"

namespace wiggle {

std::string sweepStartPath(const std::string& sweepDir) { return sweepDir + "/sweep.json"; }

std::string sweepLockPath(const std::string& sweepDir) { return sweepDir + "/.sweep.lock"; }

void writeSweepStart(const std::string& sweepDir, const SweepStart& start) {
  const std::string path = sweepStartPath(sweepDir);
  if (start.jobs == 0 && std::filesystem::exists(path)) return;
  const nlohmann::json j = {{"name", start.name}, {"jobs", start.jobs}, {"threads", start.threads}};
  writeFileAtomically(path, j.dump(2) + "\n");
}

std::optional<SweepStart> readSweepStart(const std::string& sweepDir) {
  const std::string path = sweepStartPath(sweepDir);
  if (!std::filesystem::exists(path)) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(readFile(path));
    return SweepStart{j.at("name").get<std::string>(), j.at("jobs").get<int>(), j.at("threads").get<int>()};
  } catch (const std::exception&) {  // a foreign or damaged file: nothing known
    return std::nullopt;
  }
}

}  // namespace wiggle
