#include "scenario/cost/SpeedRecord.h"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/Format.h"
#include "core/Machine.h"
#include "core/Median.h"
#include "physics/ForceKernels.h"
#include "scenario/bed/BedMaker.h"

namespace wiggle {

namespace {

constexpr std::size_t lastRuns = 9;

std::string speedLogPath(const RunConfig& config) { return bedCacheDir(config) + "/speed.log"; }

// GCC says a sanitizer is on by these macros, clang by __has_feature.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

}  // namespace

std::string speedBuildKind(const std::string& simd) {
  return std::string(WIGGLE_BUILD_TYPE) + (kSanitized ? "+sanitized" : "") + "/" + simd;
}

std::string speedBuildKind() { return speedBuildKind(simdLevelName(defaultSimdLevel())); }

std::string cpuModel() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("model name", 0) != 0) continue;
    const auto colon = line.find(':');
    if (colon == std::string::npos) break;
    std::string name = line.substr(colon + 1);
    name.erase(0, name.find_first_not_of(' '));
    std::replace(name.begin(), name.end(), '\t', ' ');
    return name;
  }
  return "";
}

void recordRunSpeed(const RunConfig& config, int threads, double wallNsPerParticleStep, double cpuNsPerParticleStep,
                    const std::string& simd, std::uint64_t particles) {
  if (!(wallNsPerParticleStep > 0) || !(cpuNsPerParticleStep > 0)) return;
  const std::string line = cpuModel() + "\t" + std::to_string(threads) + "\t" + formatNumber(wallNsPerParticleStep, 6) +
                           "\t" + formatNumber(loadAverage(), 3) + "\t" + speedBuildKind(simd) + "\t" +
                           formatNumber(cpuNsPerParticleStep, 6) + "\t" + std::to_string(particles) + "\n";
  std::error_code ec;
  std::filesystem::create_directories(bedCacheDir(config), ec);
  // O_APPEND and one write(): concurrent runs' lines do not interleave.
  const int fd = ::open(speedLogPath(config).c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) return;
  [[maybe_unused]] const ssize_t written = ::write(fd, line.data(), line.size());
  ::close(fd);
}

std::optional<MeasuredSpeed> measuredSpeed(const RunConfig& config, double particles,
                                           const std::function<double(double)>& nsOfSize) {
  std::ifstream in(speedLogPath(config));
  if (!in) return std::nullopt;
  const std::string cpu = cpuModel();
  const std::string kind = speedBuildKind();
  std::vector<double> speeds, sameSize;
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    std::string model, threads, wallNs, load, build, cpuNs;
    if (!std::getline(fields, model, '\t') || !std::getline(fields, threads, '\t') ||
        !std::getline(fields, wallNs, '\t') || !std::getline(fields, load, '\t') || !std::getline(fields, build, '\t'))
      continue;  // a line cut short (a full disk), written before the build kind was, or foreign: skipped
    if (model != cpu || threads != "1" || build != kind) continue;
    std::string count;
    std::getline(fields, cpuNs, '\t');  // these two are absent from lines written before they were recorded
    std::getline(fields, count);
    try {
      double v = std::stod(cpuNs.empty() ? wallNs : cpuNs);
      if (!(v > 0 && v < 1e6)) continue;
      const double n = count.empty() ? 0.0 : std::stod(count);
      if (nsOfSize && n > 0) v *= nsOfSize(particles) / nsOfSize(n);
      speeds.push_back(v);
      if (n * kSameSizeFactor >= particles && n <= particles * kSameSizeFactor) sameSize.push_back(v);
    } catch (const std::exception&) {
    }
  }
  const bool ofThisSize = !sameSize.empty();
  if (ofThisSize) speeds.swap(sameSize);
  if (speeds.empty()) return std::nullopt;
  if (speeds.size() > lastRuns) speeds.erase(speeds.begin(), speeds.end() - lastRuns);
  MeasuredSpeed m;
  m.nsPerParticleStep = median(speeds);
  m.runs = speeds.size();
  m.sameSize = ofThisSize;
  m.path = speedLogPath(config);
  m.buildKind = kind;
  return m;
}

}  // namespace wiggle
