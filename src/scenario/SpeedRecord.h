#pragma once
// The speed this machine has shown, for cost estimates (`run --check`, `sweep --dry-run`,
// `boundary --dry-run`, a sweep's ETA before its first case ends): every finished run appends one
// line to speed.log in the bed cache directory, and an estimate takes the median of the last runs
// on the same CPU model at one thread. Those runs' speed includes whatever else the machine was
// doing then: the estimate is "as this machine has been running", not a quiet machine's figure.
#include <optional>
#include <string>
#include <vector>

#include "io/RunConfig.h"

namespace wiggle {

// The CPU's model name (/proc/cpuinfo's first "model name"), "" when unknown.
std::string cpuModel();

// Appends "<cpu model>\t<threads>\t<ns per particle-step>\t<load average>" to <cache dir>/speed.log
// as one write (whole lines even when runs end together). Never throws: a run's result does not
// depend on its speed being recorded.
void recordRunSpeed(const RunConfig& config, int threads, double nsPerParticleStep);

struct MeasuredSpeed {
  double nsPerParticleStep = 0.0;  // the median
  std::size_t runs = 0;            // how many runs it is the median of
  std::string path;                // the log it was read from
};

// The median ns per particle-step of the last (up to) 9 one-thread runs on this CPU model in the
// cache directory's speed.log; nothing when there are none.
std::optional<MeasuredSpeed> measuredSpeed(const RunConfig& config);

}  // namespace wiggle
