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
  nlohmann::json j = {{"name", start.name}, {"jobs", start.jobs}, {"threads", start.threads}};
  if (start.beds) {
    j["beds"] = nlohmann::json::array();
    for (const BedToMake& b : *start.beds)
      j["beds"].push_back({{"key", b.key}, {"cache", b.cachePath}, {"estimate_s", b.estimatedSeconds}});
  }
  writeFileAtomically(path, j.dump(2) + "\n");
}

std::optional<SweepStart> readSweepStart(const std::string& sweepDir) {
  const std::string path = sweepStartPath(sweepDir);
  if (!std::filesystem::exists(path)) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(readFile(path));
    SweepStart start{j.at("name").get<std::string>(), j.at("jobs").get<int>(), j.at("threads").get<int>(), {}};
    if (j.contains("beds")) {
      start.beds.emplace();
      for (const nlohmann::json& b : j.at("beds"))
        start.beds->push_back({b.at("key").get<std::string>(), b.at("cache").get<std::string>(),
                               b.at("estimate_s").get<double>()});
    }
    return start;
  } catch (const std::exception&) {  // a foreign or damaged file: nothing known
    return std::nullopt;
  }
}

}  // namespace wiggle
