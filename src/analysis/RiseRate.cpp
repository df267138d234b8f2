#include "analysis/RiseRate.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"

namespace wiggle {

namespace {

// Index of the first sample at or after time t.
std::size_t firstAtOrAfter(const std::vector<TrajectorySample>& s, double t) {
  return static_cast<std::size_t>(
      std::lower_bound(s.begin(), s.end(), t, [](const TrajectorySample& a, double v) { return a.t < v - 1e-12; }) -
      s.begin());
}

}  // namespace

RiseRate measureRiseRate(const std::vector<TrajectorySample>& samples, double totalTime, double period,
                         double surfacedHeight, double plateauTolerance) {
  if (samples.size() < 3) throw Error("too few trajectory samples to measure a rise rate");
  RiseRate rate;
  const std::size_t first = std::min(firstAtOrAfter(samples, 0.1 * totalTime), samples.size() - 2);
  const std::size_t last = samples.size() - 1;

  // Window-averaged height (prefix sums; window max(T, 1) centred where possible).
  const double window = std::max(period, 1.0);
  std::vector<double> prefix(samples.size() + 1, 0.0);
  for (std::size_t k = 0; k < samples.size(); ++k) prefix[k + 1] = prefix[k] + samples[k].y;
  auto averaged = [&](std::size_t k) {
    const std::size_t lo = firstAtOrAfter(samples, samples[k].t - 0.5 * window);
    std::size_t hi = firstAtOrAfter(samples, samples[k].t + 0.5 * window);
    hi = std::min(hi, samples.size());
    const std::size_t from = std::min(lo, k), to = std::max(hi, k + 1);
    return (prefix[to] - prefix[from]) / static_cast<double>(to - from);
  };
  const double yEnd = averaged(last);
  std::size_t end = last;
  std::size_t plateauStart = last;
  while (plateauStart > first && std::fabs(averaged(plateauStart - 1) - yEnd) <= plateauTolerance) --plateauStart;
  const bool travelled = std::fabs(yEnd - averaged(first)) >= 4.0 * plateauTolerance;
  const bool longPlateau = samples[last].t - samples[plateauStart].t >= 0.1 * totalTime;
  if (yEnd >= surfacedHeight && travelled && longPlateau && plateauStart > first) {
    end = plateauStart;
    rate.plateau = true;
  }

  rate.tInitial = samples[first].t;
  rate.tFinal = samples[end].t;
  rate.yInitial = samples[first].y;
  rate.yFinal = samples[end].y;
  rate.vy = (rate.yFinal - rate.yInitial) / (rate.tFinal - rate.tInitial);
  rate.windowPeriods = (rate.tFinal - rate.tInitial) / period;

  // Least squares over [first, end], centred for accuracy.
  const double n = static_cast<double>(end - first + 1);
  double meanT = 0.0, meanY = 0.0;
  for (std::size_t k = first; k <= end; ++k) {
    meanT += samples[k].t;
    meanY += samples[k].y;
  }
  meanT /= n;
  meanY /= n;
  double stt = 0.0, sty = 0.0;
  for (std::size_t k = first; k <= end; ++k) {
    stt += (samples[k].t - meanT) * (samples[k].t - meanT);
    sty += (samples[k].t - meanT) * (samples[k].y - meanY);
  }
  rate.slope = stt > 0 ? sty / stt : 0.0;
  return rate;
}

}  // namespace wiggle
