#include "analysis/Trajectory.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/Error.h"
#include "core/Format.h"
#include "io/AtomicFile.h"

namespace wiggle {

namespace {
constexpr const char* kHeader = "t,x,y,vx,vy,fy";
}  // namespace

void writeTrajectoryCsv(const std::string& path, const std::vector<TrajectorySample>& samples) {
  std::string out = std::string(kHeader) + "\n";
  for (const auto& s : samples)
    out += formatNumber(s.t, 10) + ',' + formatNumber(s.x, 10) + ',' + formatNumber(s.y, 10) + ',' +
           formatNumber(s.vx, 10) + ',' + formatNumber(s.vy, 10) + ',' + formatNumber(s.fy, 10) + '\n';
  writeFileAtomically(path, out);
}

std::vector<TrajectorySample> readTrajectoryCsv(const std::string& path) {
  std::istringstream in(readFile(path));
  std::string line;
  auto withoutCr = [](std::string& text) {
    if (!text.empty() && text.back() == '\r') text.pop_back();
  };
  if (std::getline(in, line)) withoutCr(line);
  if (line != kHeader) throw Error(path + ": not a trajectory.csv (its first line must be '" + kHeader + "')");
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
      const char expected = k < 5 ? ',' : '\0';
      if (end == p || errno == ERANGE || !std::isfinite(v[k]) || *end != expected)
        throw Error(path + ": line " + std::to_string(lineNo) + " is not six numbers");
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
