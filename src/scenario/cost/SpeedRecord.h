#pragma once
// The speed this machine has shown, for cost estimates (`run --check`, `sweep --dry-run`,
// `boundary --dry-run`, a sweep's ETA before its first case ends): every run that finishes or is
// stopped by a signal after 10^4 steps or more appends one line, of its own process's stepping, to
// speed.log in the bed cache directory, and an estimate takes the median of the last runs
// on the same CPU model at one thread by the same kind of build (speedBuildKind: a debug or
// sanitized build, or the scalar kernels, run several times slower than a release build). The
// figure an estimate takes is the run's CPU time per particle-step: what a step costs on a core the
// run has to itself, as this machine's cores run beside whatever else they run (a second study
// sharing the caches and memory adds 10-20 %), but not stretched by the share of a core the run
// was given: a run at a low priority beside two others took 4-10 x its CPU time in wall time, and
// wall time per particle-step made every estimate after it that much too long.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "io/RunConfig.h"

namespace wiggle {

// The CPU's model name (/proc/cpuinfo's first "model name"), "" when unknown.
std::string cpuModel();

// What a run's speed depends on besides the CPU and the threads: this program's build type
// (CMAKE_BUILD_TYPE, "+sanitized" when built with a sanitizer) and the force kernels' instruction
// set `simd` (physics/ForceKernels.h, simdLevelName): "Release/avx512".
std::string speedBuildKind(const std::string& simd);
// The build kind of a run started now: this build, with the kernels it would choose (defaultSimdLevel).
std::string speedBuildKind();

// Appends "<cpu model>\t<threads>\t<wall ns per particle-step>\t<load average>\t<build kind>\t<CPU
// ns per particle-step>\t<particles>" to <cache dir>/speed.log as one write (whole lines even when
// runs end together). The CPU figure counts every thread's CPU time. Never throws: a run's result
// does not depend on its speed being recorded.
void recordRunSpeed(const RunConfig& config, int threads, double wallNsPerParticleStep, double cpuNsPerParticleStep,
                    const std::string& simd, std::uint64_t particles);

// A bed within this factor of a run's particle count counts as its size: the cost of a
// particle-step grows with the bed once its arrays outgrow the caches (bench/run_bench.sh,
// 2026-11-27, one Zen 4 core: 27-28 ns for 3,200 and 12,500 particles, 38 for 62,000).
constexpr double kSameSizeFactor = 2.0;

struct MeasuredSpeed {
  double nsPerParticleStep = 0.0;  // the median
  std::size_t runs = 0;            // how many runs it is the median of
  bool sameSize = false;           // the runs were of beds of this run's size (kSameSizeFactor)
  std::string path;                // the log it was read from
  std::string buildKind;           // the build kind it is for (speedBuildKind)
};

// The median CPU ns per particle-step of the last (up to) 9 one-thread runs on this CPU model by
// this build kind, with the force kernels a run would use now (defaultSimdLevel), in the cache
// directory's speed.log, of beds within kSameSizeFactor of `particles` when there are any, else of
// any size; nothing when there are none. Lines without a build kind (written before it was
// recorded) are not counted: which build ran them is not known. Lines without the CPU figure or
// the particle count (written before they were recorded) count with their wall figure and as of
// another size. With `nsOfSize` (ns per particle-step by bed size, the cost table's), each run of a
// known size counts scaled to `particles` by it: a machine's runs of small beds then say how fast
// it is, and the table how a bigger bed slows every machine down.
std::optional<MeasuredSpeed> measuredSpeed(const RunConfig& config, double particles,
                                           const std::function<double(double)>& nsOfSize = {});

}  // namespace wiggle
