#include "analysis/Trajectory.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string_view>

#include "core/Error.h"
#include "core/Format.h"
#include "io/AtomicFile.h"

namespace wiggle {

namespace {
constexpr std::string_view kHeader = "t,x,y,vx,vy,fy";
constexpr std::string_view kSpinColumns = ",angle,omega";
}  // namespace

void writeTrajectoryCsv(const std::string& path, const std::vector<TrajectorySample>& samples,
                        const std::vector<SpinSample>& spins) {
  if (!spins.empty() && spins.size() != samples.size())
    throw Error(path + ": " + std::to_string(spins.size()) + " turns for " + std::to_string(samples.size()) +
                " samples");
  std::string out = std::string(kHeader) + std::string(spins.empty() ? "" : kSpinColumns) + "\n";
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const TrajectorySample& s = samples[i];
    out += formatNumber(s.t, 10) + ',' + formatNumber(s.x, 10) + ',' + formatNumber(s.y, 10) + ',' +
           formatNumber(s.vx, 10) + ',' + formatNumber(s.vy, 10) + ',' + formatNumber(s.fy, 10);
    if (!spins.empty()) out += ',' + formatNumber(spins[i].angle, 10) + ',' + formatNumber(spins[i].omega, 10);
    out += '\n';
  }
  writeFileAtomically(path, out);
}

std::vector<TrajectorySample> readTrajectoryCsv(const std::string& path) {
  std::istringstream in(readFile(path));
  std::string line;
  auto withoutCr = [](std::string& text) {
    if (!text.empty() && text.back() == '\r') text.pop_back();
  };
  if (std::getline(in, line)) withoutCr(line);
  if (line.rfind(kHeader, 0) != 0 || (line.size() > kHeader.size() && line[kHeader.size()] != ','))
    throw Error(path + ": not a trajectory.csv (its first line must start '" + std::string(kHeader) + "')");
  std::vector<TrajectorySample> samples;
  for (int lineNo = 2; std::getline(in, line); ++lineNo) {
    withoutCr(line);
    if (line.empty()) continue;
    double v[6];
    const char* p = line.c_str();
    for (int k = 0; k < 6; ++k) {
      char* end = nullptr;
      errno = 0;
      v[k] = std::strtod(p, &end);
      const bool last = k == 5;
      if (end == p || errno == ERANGE || !std::isfinite(v[k]) || (last ? *end != '\0' && *end != ',' : *end != ','))
        throw Error(path + ": line " + std::to_string(lineNo) + " does not start with six numbers");
      p = end + (k < 5 ? 1 : 0);
    }
    if (!samples.empty() && !(v[0] > samples.back().t))
      throw Error(path + ": line " + std::to_string(lineNo) + ": time " + formatNumber(v[0]) + " does not follow " +
                  formatNumber(samples.back().t));
    samples.push_back({v[0], v[1], v[2], v[3], v[4], v[5]});
  }
  return samples;
}

}  // namespace wiggle
