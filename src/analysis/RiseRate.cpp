#include "analysis/RiseRate.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"
#include "core/Format.h"

namespace wiggle {

namespace {

// Index of the first sample at or after time t.
std::size_t firstAtOrAfter(const std::vector<TrajectorySample>& s, double t) {
  return static_cast<std::size_t>(
      std::lower_bound(s.begin(), s.end(), t, [](const TrajectorySample& a, double v) { return a.t < v - 1e-12; }) -
      s.begin());
}

// The samples a window measures: [first, last], the first at or after `from` and the last at or
// before `to`, at least two of them.
struct Span {
  std::size_t first, last;
};

Span windowSpan(const std::vector<TrajectorySample>& samples, RateWindow window) {
  if (samples.size() < 3) throw Error("too few trajectory samples to measure a rise rate");
  if (!(window.to > window.from))
    throw Error("the rate's window ends (t = " + formatNumber(window.to) +
                ") before it begins (t = " + formatNumber(window.from) + ")");
  // One past the last sample at or before `to` (a run's times are step x dt: allow for their rounding).
  const std::size_t end = firstAtOrAfter(samples, window.to + 1e-9 * std::max(1.0, std::fabs(window.to)));
  if (end < 3)
    throw Error("too few trajectory samples before t = " + formatNumber(window.to) + " to measure a rise rate");
  const std::size_t last = end - 1;
  return {std::min(firstAtOrAfter(samples, window.from), last - 1), last};
}

double chord(const std::vector<TrajectorySample>& s, std::size_t a, std::size_t b) {
  return (s[b].y - s[a].y) / (s[b].t - s[a].t);
}

// Least squares over [a, b], centred for accuracy.
double leastSquaresSlope(const std::vector<TrajectorySample>& s, std::size_t a, std::size_t b) {
  const double n = static_cast<double>(b - a + 1);
  double meanT = 0.0, meanY = 0.0;
  for (std::size_t k = a; k <= b; ++k) {
    meanT += s[k].t;
    meanY += s[k].y;
  }
  meanT /= n;
  meanY /= n;
  double stt = 0.0, sty = 0.0;
  for (std::size_t k = a; k <= b; ++k) {
    stt += (s[k].t - meanT) * (s[k].t - meanT);
    sty += (s[k].t - meanT) * (s[k].y - meanY);
  }
  return stt > 0 ? sty / stt : 0.0;
}

// Heights averaged over a window of `width` centred on each sample, among samples [0, last].
class AveragedHeight {
 public:
  AveragedHeight(const std::vector<TrajectorySample>& s, std::size_t last, double width)
      : s_(s), last_(last), half_(0.5 * width), prefix_(last + 2, 0.0) {
    for (std::size_t k = 0; k <= last; ++k) prefix_[k + 1] = prefix_[k] + s[k].y;
  }
  // Centred where possible, truncated at the ends of [0, last] (the plateau rule's use).
  double at(std::size_t k) const {
    const std::size_t lo = firstAtOrAfter(s_, s_[k].t - half_);
    const std::size_t hi = std::min(firstAtOrAfter(s_, s_[k].t + half_), last_ + 1);
    const std::size_t from = std::min(lo, k), to = std::max(hi, k + 1);
    return (prefix_[to] - prefix_[from]) / static_cast<double>(to - from);
  }
  // The samples whose whole window lies within [0, last]: [first, last] of the result; empty when
  // first > last.
  Span whole() const {
    const std::size_t first = firstAtOrAfter(s_, s_[0].t + half_);
    std::size_t end = firstAtOrAfter(s_, s_[last_].t - half_ + 2e-12);
    end = std::min(end, last_ + 1);
    return {first, end == 0 ? 0 : end - 1};
  }

 private:
  const std::vector<TrajectorySample>& s_;
  std::size_t last_;
  double half_;
  std::vector<double> prefix_;
};

}  // namespace

RiseRate measureRiseRate(const std::vector<TrajectorySample>& samples, RateWindow window, double period,
                         double surfacedHeight, double plateauTolerance) {
  const auto [first, last] = windowSpan(samples, window);
  RiseRate rate;
  const AveragedHeight averaged(samples, last, std::max(period, 1.0));
  const double yEnd = averaged.at(last);
  std::size_t end = last;
  std::size_t plateauStart = last;
  while (plateauStart > first && std::fabs(averaged.at(plateauStart - 1) - yEnd) <= plateauTolerance) --plateauStart;
  const bool travelled = std::fabs(yEnd - averaged.at(first)) >= 4.0 * plateauTolerance;
  const bool longPlateau = samples[last].t - samples[plateauStart].t >= 0.1 * window.to;
  if (yEnd >= surfacedHeight && travelled && longPlateau && plateauStart > first) {
    end = plateauStart;
    rate.plateau = true;
  }

  rate.tInitial = samples[first].t;
  rate.tFinal = samples[end].t;
  rate.yInitial = samples[first].y;
  rate.yFinal = samples[end].y;
  rate.vy = chord(samples, first, end);
  rate.windowPeriods = (rate.tFinal - rate.tInitial) / period;
  rate.slope = leastSquaresSlope(samples, first, end);
  return rate;
}

double SettleRule::smoothing(double period) const { return period * std::ceil(kSmoothingTime / period - 1e-9); }

SettledRate measureSettledRate(const std::vector<TrajectorySample>& samples, RateWindow window, double period,
                               const RiseRate& unsettled, const SettleRule& rule) {
  if (!(rule.band > 0)) throw Error("the settle band must be positive (it is " + formatNumber(rule.band) + " d)");
  const auto [first, last] = windowSpan(samples, window);
  SettledRate none;
  none.vy = unsettled.vy;
  none.tSettled = unsettled.tFinal;

  const AveragedHeight averaged(samples, last, rule.smoothing(period));
  const Span whole = averaged.whole();
  const std::size_t from = std::max(first, whole.first);
  if (whole.last <= from) return none;
  // Suffix extremes and sums of the averaged heights over [j, whole.last]; the earliest j whose
  // suffix lies within the band of its own mean is the candidate.
  const std::size_t n = whole.last - from + 1;
  std::vector<double> heights(n);
  for (std::size_t k = 0; k < n; ++k) heights[k] = averaged.at(from + k);
  double hi = heights[n - 1], lo = heights[n - 1], sum = 0.0;
  std::size_t candidate = n;  // none yet
  double level = 0.0;         // the candidate's mean: the final level
  for (std::size_t k = n; k-- > 0;) {
    hi = std::max(hi, heights[k]);
    lo = std::min(lo, heights[k]);
    sum += heights[k];
    const double mean = sum / static_cast<double>(n - k);
    if (hi - mean <= rule.band && mean - lo <= rule.band) {
      candidate = k;
      level = mean;
    }
  }
  if (candidate == n || candidate == 0) return none;

  const std::size_t settle = from + candidate;
  const double span = samples[last].t - samples[first].t;
  const bool travelled = std::fabs(level - heights[0]) >= SettleRule::kTravelBands * rule.band;
  const bool longApproach = samples[settle].t - samples[first].t >= SettleRule::kMinFraction * span;
  const bool longPlateau = samples[last].t - samples[settle].t >= SettleRule::kMinFraction * span;
  if (!travelled || !longApproach || !longPlateau) return none;
  const double approach = chord(samples, first, settle);
  if (std::fabs(leastSquaresSlope(samples, settle, last)) > SettleRule::kFlatRatio * std::fabs(approach)) return none;

  SettledRate rate;
  rate.vy = approach;
  rate.tSettled = samples[settle].t;
  rate.settled = true;
  return rate;
}

std::vector<std::string> rateWarnings(const RiseRate& rate) {
  std::vector<std::string> warnings;
  const std::string window = "t = " + formatNumber(rate.tInitial) + " to " + formatNumber(rate.tFinal);
  if (rate.windowTooShort())
    warnings.push_back("V_y is measured over " + formatNumber(rate.windowPeriods) + " drive periods (" + window +
                       "), fewer than " + formatNumber(RiseRate::kMinWindowPeriods) +
                       ": it reflects the phase of the drive more than a drift; run longer (run.duration)");
  const std::string transient = "the start-up transient of the drive (the first " +
                                formatNumber(RiseRate::kStartupTime) + " time units, where the whole bed is set moving)";
  if (rate.withinStartupTransient())
    warnings.push_back("V_y is measured from " + window + ", within " + transient +
                       ": it is not a steady rise or sink; run longer (run.duration; the presets run to t = 100)");
  if (rate.startsInStartupTransient())
    warnings.push_back("V_y is measured from " + window + ", " + formatNumber(std::round(100 * rate.startupShare())) +
                       " % of it within " + transient + ": it mixes the start-up with what follows; measure from t = " +
                       formatNumber(RiseRate::kStartupTime) + " on (wiggle rate DIR --from " +
                       formatNumber(RiseRate::kStartupTime) + ") or run longer (the presets run to t = 100)");
  return warnings;
}

}  // namespace wiggle
