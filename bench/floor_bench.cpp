// wiggle_floor: the floor of a step, the contact law alone over a driven bed's own listed grain
// pairs, and the step's ratio to it (bench/README.md).
//
//   wiggle_floor [CONFIG.toml] [--set section.key=value]... [--warm-steps N] [--steps N] [--sweeps N]
//                [--threads N] [--json FILE]
//
// The bed is the one `wiggle run` of the same config uses (obtainBed: from the cache, or made now),
// started as runExperiment starts it and driven for --warm-steps steps, so that the list, its
// contacts and their history are a driven bed's. Then:
//   step   World::run(--steps), the engine's step loop as `wiggle run` drives it (--threads
//          threads, 1 by default): the engine's time per step on these particles;
//   floor  every listed grain pair's inputs (PairInputs) and history copied once into contiguous
//          arrays, and the contact law (evaluatePairs, in the widest lanes of the build, through
//          maxOverLanes as World does) swept over all of them --sweeps times: no gather from the
//          particles, no force sums, no intruder, no integration. One thread. The law updates the
//          history in place, so every sweep starts from the same history, restored outside the
//          timed region.
// Both are reported per step and per particle-step, over the same particle count as the benchmark's
// (every atom of the exported LAMMPS data file: grains, base particles and intruder atoms).
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "core/Error.h"
#include "io/Config.h"
#include "physics/ForceKernels.h"
#include "physics/PairKernel.h"
#include "physics/World.h"
#include "scenario/bed/BedMaker.h"
#include "scenario/case/Case.h"

namespace wiggle {
namespace {

using Clock = std::chrono::steady_clock;

// The lanes maxOverLanes sweeps in: the widest this program is compiled for (wigglecore's flags,
// -march=native in a Release build). The engine chooses its own at run time (ForceKernels.h).
constexpr int kFloorLanes = simd::kLaneCount<simd::WidestLanes>;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

struct Options {
  std::optional<std::string> config;
  std::vector<std::string> overrides;
  std::uint64_t warmSteps = 500;
  std::uint64_t steps = 1000;
  int sweeps = 200;
  int threads = 1;
  std::string json;
};

[[noreturn]] void usage(const std::string& why) {
  std::fprintf(stderr,
               "wiggle_floor: %s\nusage: wiggle_floor [CONFIG.toml] [--set section.key=value]... [--warm-steps N] "
               "[--steps N] [--sweeps N] [--threads N] [--json FILE]\n",
               why.c_str());
  std::exit(2);
}

Options parseOptions(int argc, char** argv) {
  Options o;
  auto count = [&](int& a, const std::string& name) {
    if (++a >= argc) usage(name + " needs a value");
    char* end = nullptr;
    const long long v = std::strtoll(argv[a], &end, 10);
    if (*end != '\0' || v < 1) usage(name + " needs a positive whole number, not '" + argv[a] + "'");
    return static_cast<std::uint64_t>(v);
  };
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--set") {
      if (++a >= argc) usage("--set needs section.key=value");
      o.overrides.push_back(argv[a]);
    } else if (arg == "--warm-steps") {
      o.warmSteps = count(a, arg);
    } else if (arg == "--steps") {
      o.steps = count(a, arg);
    } else if (arg == "--sweeps") {
      o.sweeps = static_cast<int>(count(a, arg));
    } else if (arg == "--threads") {
      o.threads = static_cast<int>(count(a, arg));
    } else if (arg == "--json") {
      if (++a >= argc) usage("--json needs a file name");
      o.json = argv[a];
    } else if (arg.rfind("--", 0) != 0 && !o.config) {
      o.config = arg;
    } else {
      usage("unknown argument '" + arg + "'");
    }
  }
  return o;
}

// Every listed grain pair's inputs and history, one array per quantity, indexed by pair: what the
// law reads, laid out so that lanes load straight from memory.
struct PairArrays {
  std::vector<double> dx, dy, dvx, dvy, radI, radJ, omegaI, omegaJ, invMassSum, alarmRadius;
  std::vector<double> shearX, shearY;  // the history when the pairs were taken: every sweep starts from it

  void push(const PairInputs<double>& in) {
    dx.push_back(in.dx);
    dy.push_back(in.dy);
    dvx.push_back(in.dvx);
    dvy.push_back(in.dvy);
    radI.push_back(in.radI);
    radJ.push_back(in.radJ);
    omegaI.push_back(in.omegaI);
    omegaJ.push_back(in.omegaJ);
    invMassSum.push_back(in.invMassSum);
    alarmRadius.push_back(in.alarmRadius);
  }
  template <class V>
  PairInputs<V> inputs(std::uint32_t k) const {
    using simd::load;
    return {load<V>(dx.data() + k),         load<V>(dy.data() + k),         load<V>(dvx.data() + k),
            load<V>(dvy.data() + k),        load<V>(radI.data() + k),       load<V>(radJ.data() + k),
            load<V>(omegaI.data() + k),     load<V>(omegaJ.data() + k),     load<V>(invMassSum.data() + k),
            load<V>(alarmRadius.data() + k)};
  }
};

// The grain list's pairs as the step sees them: inputs through the engine's own grainPairInputs,
// from Kinematics records filled from the store (World keeps the same copy of the same values),
// and the list's history.
PairArrays listedPairs(const World& world) {
  const ParticleStore& s = world.particles();
  const NeighbourList& list = world.neighbours();
  std::vector<Kinematics> kin(s.size());
  for (std::uint32_t i = 0; i < s.size(); ++i) kin[i] = {s.x[i], s.y[i], s.vx[i], s.vy[i]};
  PairArrays pairs;
  for (std::uint32_t k = 0; k < list.pairCount(); ++k)
    pairs.push(grainPairInputs(kin.data(), s, list.owner[k], list.partner[k], world.def().boxWidth));
  pairs.shearX = list.shearX;
  pairs.shearY = list.shearY;
  return pairs;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct FloorTiming {
  double medianSeconds = 0.0, minSeconds = 0.0;  // per sweep over all pairs
  std::uint32_t touching = 0;                     // pairs with a force after the sweep
};

FloorTiming timeFloor(const WorldDef& def, const PairArrays& pairs, int sweeps) {
  const auto n = static_cast<std::uint32_t>(pairs.dx.size());
  std::vector<double> shearX(n), shearY(n), forceX(n), forceY(n), torqueArm(n);
  const PairSlots slots{shearX.data(), shearY.data(), forceX.data(), forceY.data(), torqueArm.data()};
  std::vector<double> seconds;
  volatile double sink = 0.0;  // the excess is used, so the sweep cannot be dropped
  for (int r = 0; r < sweeps; ++r) {
    std::copy(pairs.shearX.begin(), pairs.shearX.end(), shearX.begin());
    std::copy(pairs.shearY.begin(), pairs.shearY.end(), shearY.begin());
    const auto start = Clock::now();
    const double excess = maxOverLanes(n, [&](std::uint32_t k, auto lane) {
      using V = decltype(lane);
      return evaluatePairs<HertzLaw>(pairs.inputs<V>(k), k, slots, def.contact, def.dt, true, def.maxOverlapRatio);
    });
    seconds.push_back(secondsSince(start));
    sink = sink + excess;
  }
  FloorTiming t;
  t.medianSeconds = median(seconds);
  t.minSeconds = *std::min_element(seconds.begin(), seconds.end());
  for (std::uint32_t k = 0; k < n; ++k) t.touching += (forceX[k] != 0.0 || forceY[k] != 0.0) ? 1 : 0;
  return t;
}

int run(const Options& o) {
  const Case c = prepareCase(loadRunConfig(o.config, o.overrides));
  omp_set_num_threads(o.threads);
  const auto bedStart = Clock::now();
  CachedBed bed = obtainBed(c.config, c.clump);
  std::fprintf(stderr, "wiggle_floor: bed %s %s (%.1f s)\n", bed.fromCache ? "loaded from" : "made and cached at",
               bed.path.c_str(), secondsSince(bedStart));
  World world = std::move(bed.world);
  // As runExperiment starts a run (Experiment.cpp, startFromBed).
  if (!c.config.run.keepBedHistory) world.clearContactHistory();
  startDrive(world, c);
  world.run(o.warmSteps);

  const PairArrays pairs = listedPairs(world);
  const auto pairCount = static_cast<std::uint32_t>(pairs.dx.size());
  // The benchmark's particle count: the LAMMPS data file has every store particle and every atom.
  const std::uint64_t particles = world.particles().size() + world.clump().offsetX.size();

  const auto stepStart = Clock::now();
  world.run(o.steps);
  const double stepSeconds = secondsSince(stepStart) / static_cast<double>(o.steps);

  const FloorTiming law = timeFloor(world.def(), pairs, o.sweeps);
  const double perParticle = 1e9 / static_cast<double>(particles);
  const double floorNs = law.medianSeconds * perParticle, stepNs = stepSeconds * perParticle;
  std::printf("particles %llu (grains %u, base %u, intruder atoms %zu), listed grain pairs %u (%u touching)\n",
              static_cast<unsigned long long>(particles), world.grainCount(), world.particles().baseCount(),
              world.clump().offsetX.size(), pairCount, law.touching);
  const int engineLanes = forceKernels(defaultSimdLevel(), world.def().contact.law).lanes;
  std::printf("floor: %.2f ns per particle-step (min %.2f), %.2f ns per pair; %d sweeps, 1 thread, %d lanes\n",
              floorNs, law.minSeconds * perParticle, 1e9 * law.medianSeconds / pairCount, o.sweeps, kFloorLanes);
  std::printf("step:  %.2f ns per particle-step (%llu steps, %d thread%s, %d lanes)\n", stepNs,
              static_cast<unsigned long long>(o.steps), o.threads, o.threads == 1 ? "" : "s", engineLanes);
  // A portable build (or WIGGLE_SIMD) can give the floor and the step different widths: then the
  // ratio is not the step's overhead alone.
  if (engineLanes != kFloorLanes)
    std::fprintf(stderr, "wiggle_floor: warning: the floor runs %d lanes, the engine %d; build with -march=native "
                 "(the bench preset) and leave WIGGLE_SIMD unset to compare like with like\n", kFloorLanes, engineLanes);
  std::printf("step / floor: %.2f\n", stepNs / floorNs);
  if (!o.json.empty()) {
    FILE* f = std::fopen(o.json.c_str(), "w");
    if (!f) throw Error("cannot write " + o.json);
    std::fprintf(f,
                 "{\"particles\": %llu, \"pairs\": %u, \"touching\": %u, \"sweeps\": %d, \"floor_sweep_s\": %.9g, "
                 "\"floor_sweep_min_s\": %.9g, \"floor_ns_per_particle_step\": %.4f, \"floor_ns_per_pair\": %.4f, "
                 "\"step_s\": %.9g, \"step_threads\": %d, \"steps\": %llu, \"step_ns_per_particle_step\": %.4f, "
                 "\"step_over_floor\": %.4f, \"floor_lanes\": %d, \"step_lanes\": %d}\n",
                 static_cast<unsigned long long>(particles), pairCount, law.touching, o.sweeps, law.medianSeconds,
                 law.minSeconds, floorNs, 1e9 * law.medianSeconds / pairCount, stepSeconds, o.threads,
                 static_cast<unsigned long long>(o.steps), stepNs, stepNs / floorNs, kFloorLanes, engineLanes);
    if (std::fclose(f) != 0) throw Error("cannot write " + o.json);
  }
  return 0;
}

}  // namespace
}  // namespace wiggle

int main(int argc, char** argv) {
  try {
    return wiggle::run(wiggle::parseOptions(argc, argv));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "wiggle_floor: %s\n", e.what());
    return 1;
  }
}
