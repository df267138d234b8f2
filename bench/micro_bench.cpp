// Google Benchmark micro-benchmarks of the engine's hot parts (docs/PERFORMANCE.md):
//   BM_ContactKernel   the engine's chunked pair evaluation (PairKernel.h: 4 lanes where the CPU has
//                      AVX) over a batch of pairs (~75 % touching), the chunk's inputs filled from arrays
//   BM_ContactKernelScalar  the same pairs one at a time through the composed law (the reference)
//   BM_IntruderContacts addIntruderContactForces: the clump's contacts and force sum in the pile
//   BM_LaneSqrt, BM_LaneDivide  throughput of the lanes' sqrt and division over varied operands,
//                      the hardware figures behind bench/HISTORY.md's limit estimate
//   BM_NeighbourBuild  NeighbourList::build on a settled pile, carrying history from the old list
//   BM_WorldStep       one full World::step of the settled pile with a wiggling disk
//   BM_FieldFrame      one FieldObserver frame (Phi, v, contact stress on the 61 x 61 grid)
// Build: the `wiggle_bench` target (CMake builds bench/*.cpp when libbenchmark is found).
// Run:   OMP_NUM_THREADS=1 build/<dir>/wiggle_bench [--benchmark_filter=...]
// Items per second are pairs (kernel), particles (build, step) or grains in reach (frame).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "analysis/FieldObserver.h"
#include "io/RunConfig.h"
#include "physics/HertzLaw.h"
#include "physics/PairKernel.h"
#include "physics/World.h"
#include "scenario/bed/BedMaker.h"
#include "scenario/case/EngineSettings.h"
#include "scenario/geometry/Clump.h"
#include "scenario/geometry/Shape.h"

namespace wiggle {
namespace {

// A deterministic stand-in for the generator of core/Rng.h (the benchmark needs no stream ids).
struct Lcg {
  std::uint64_t s;
  double next() {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(s >> 11) * 0x1.0p-53;
  }
};

// A batch of pairs with ~75 % overlapping (by up to 0.5 %), as gathered pair inputs in arrays.
struct PairBatch {
  std::vector<double> dx, dy, dvx, dvy, ri, rj, wi, wj, invMassSum, alarm, sx, sy, fx, fy, arm;
  explicit PairBatch(std::size_t n) {
    for (auto* v : {&dx, &dy, &dvx, &dvy, &ri, &rj, &wi, &wj, &invMassSum, &alarm, &sx, &sy, &fx, &fy, &arm})
      v->resize(n);
    Lcg rng{42};
    for (std::size_t k = 0; k < n; ++k) {
      ri[k] = 0.45 + 0.1 * rng.next();
      rj[k] = 0.45 + 0.1 * rng.next();
      const double angle = 2.0 * 3.141592653589793 * rng.next();
      const double dist = (ri[k] + rj[k]) * (0.995 + 0.02 * rng.next());
      dx[k] = dist * std::cos(angle);
      dy[k] = dist * std::sin(angle);
      dvx[k] = 0.1 * (rng.next() - 0.5);
      dvy[k] = 0.1 * (rng.next() - 0.5);
      wi[k] = rng.next() - 0.5;
      wj[k] = rng.next() - 0.5;
      invMassSum[k] = 1.0 / 0.26;  // meff 0.26
      alarm[k] = std::min(ri[k], rj[k]);
      sx[k] = 1e-5 * (rng.next() - 0.5);
      sy[k] = 1e-5 * (rng.next() - 0.5);
    }
  }
  template <class V>
  PairInputs<V> inputs(std::size_t k) const {
    auto load = [k](const std::vector<double>& v) { return simd::load<V>(v.data() + k); };
    return {load(dx), load(dy), load(dvx), load(dvy), load(ri), load(rj), load(wi), load(wj), load(invMassSum),
            load(alarm)};
  }
  PairSlots slots() { return {sx.data(), sy.data(), fx.data(), fy.data(), arm.data()}; }
};

// The engine's chunked evaluation (PairKernel.h) over the batch, 64 pairs at a time; with
// `scalar`, the composed law one pair at a time instead (the reference: same bits, no lanes).
void runContactKernel(benchmark::State& state, bool scalar) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  PairBatch batch(n);
  const ContactParams params;
  const PairSlots slots = batch.slots();
  // The history is written back, so every pass starts from the same one.
  const std::vector<double> sx0 = batch.sx, sy0 = batch.sy;
  PairChunk chunk;
  for (auto _ : state) {
    std::copy(sx0.begin(), sx0.end(), batch.sx.begin());
    std::copy(sy0.begin(), sy0.end(), batch.sy.begin());
    if (scalar) {
      for (std::size_t k = 0; k < n; ++k) {
        const PairInputs<double> in = batch.inputs<double>(k);
        const ContactForce c =
            historyContact<HertzLaw>(params, 1e-4, in.dx, in.dy, in.dvx, in.dvy, in.radI, in.radJ, in.omegaI, in.omegaJ,
                                     in.invMassSum, batch.sx[k], batch.sy[k], true);
        batch.sx[k] = c.shearX;
        batch.sy[k] = c.shearY;
        batch.fx[k] = c.fx;
        batch.fy[k] = c.fy;
        batch.arm[k] = c.torqueArm;
      }
    } else {
      for (std::size_t first = 0; first < n; first += kChunk) {
        const auto count = static_cast<std::uint32_t>(std::min<std::size_t>(kChunk, n - first));
        for (std::uint32_t m = 0; m < count; ++m) chunk.set(m, batch.inputs<double>(first + m));
        const double excess =
            evaluateChunk<HertzLaw>(chunk, count, static_cast<std::uint32_t>(first), slots, params, 1e-4, true, 1.0);
        benchmark::DoNotOptimize(excess);
      }
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(n));
}

// One operation over 4,096 varied operands in [0.5, 2), 4 lanes at a time (doubles without AVX):
// independent operations, so the time per operation is the unit's throughput, not its latency, on
// operands like the kernel's. Items are lanes.
template <class Op>
void runLaneThroughput(benchmark::State& state, Op op) {
#if WIGGLE_SIMD_DOUBLE4
  using V = simd::Double4;
#else
  using V = double;
#endif
  constexpr std::size_t kCount = 4096;
  std::vector<double> in(kCount), out(kCount);
  Lcg rng{3};
  for (double& v : in) v = 0.5 + 1.5 * rng.next();
  for (auto _ : state) {
    for (std::size_t k = 0; k < kCount; k += simd::kLaneCount<V>) simd::store(out.data() + k, op(simd::load<V>(in.data() + k)));
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * kCount);
}
void BM_LaneSqrt(benchmark::State& state) {
  runLaneThroughput(state, [](auto x) {
    using simd::sqrt;
    return sqrt(x);
  });
}
void BM_LaneDivide(benchmark::State& state) {
  runLaneThroughput(state, [](auto x) { return decltype(x)(1.0) / x; });
}
BENCHMARK(BM_LaneSqrt);
BENCHMARK(BM_LaneDivide);

void BM_ContactKernel(benchmark::State& state) { runContactKernel(state, false); }
void BM_ContactKernelScalar(benchmark::State& state) { runContactKernel(state, true); }
BENCHMARK(BM_ContactKernelScalar)->Arg(4096);
BENCHMARK(BM_ContactKernel)->Arg(4096)->Arg(65536);

// A settled pile of about 1,200 grains in a 40-wide box with a disk held in it, then driven
// (A = 3, T = 5). Made once: grains on a loose lattice, dropped and left to settle for t = 3.
const World& settledPile() {
  static const World pile = [] {
    RunConfig config;
    config.box.width = 40;
    World world(worldDefFor(config));
    for (int i = 0; i < 40; ++i) world.addFrozen(i, 0.0, 0.5);
    Lcg rng{7};
    for (int row = 0; row < 32; ++row)
      for (int col = 0; col < 36; ++col) {
        const double x = 0.6 + col * 1.1;
        const double y = 1.2 + row * 1.1;
        if (std::fabs(x - 20.0) < 4.3 && std::fabs(y - 12.0) < 4.3) continue;  // room for the disk
        world.addGrain(x, y, 0.45 + 0.1 * rng.next());
      }
    world.setIntruder(makeClump(IntruderDef{}, MassModel::Sphere, 1.0), 20.0, 12.0);
    world.run(30000);
    ClumpMotion motion;
    motion.kind = HorizontalMotion::Sinusoid;
    motion.x0 = 20.0;
    motion.amplitude = 3.0;
    motion.period = 5.0;
    motion.verticalFree = true;
    world.setIntruderMotion(motion);
    world.resetClock();
    world.run(2000);
    return world;
  }();
  return pile;
}

void BM_NeighbourBuild(benchmark::State& state) {
  const World& pile = settledPile();
  const ParticleStore& store = pile.particles();
  for (auto _ : state) {
    NeighbourList fresh;
    fresh.build(store, pile.def().boxWidth, pile.def().skin, pile.neighbours(), {});
    benchmark::DoNotOptimize(fresh.partner.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * store.size());
  state.counters["pairs"] = static_cast<double>(pile.neighbours().pairCount());
}
BENCHMARK(BM_NeighbourBuild)->Unit(benchmark::kMicrosecond);

void BM_IntruderContacts(benchmark::State& state) {
  const World& pile = settledPile();
  ParticleStore store = pile.particles();
  ClumpState clump = pile.intruder();
  IntruderPairs pairs = pile.intruderPairs();
  for (auto _ : state) {
    const double excess = addIntruderContactForces(store, pile.clump(), clump, pairs, pile.def().contact,
                                                   pile.def().dt, pile.def().boxWidth, true, 0.25);
    benchmark::DoNotOptimize(excess);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * pairs.size());
  state.counters["pairs"] = static_cast<double>(pairs.size());
}
BENCHMARK(BM_IntruderContacts)->Unit(benchmark::kMicrosecond);

void BM_WorldStep(benchmark::State& state) {
  World world = settledPile();
  for (auto _ : state) world.step();
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * world.particles().size());
  state.counters["ns_per_particle_step"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * world.particles().size() * 1e-9,
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_WorldStep)->Unit(benchmark::kMicrosecond);

void BM_FieldFrame(benchmark::State& state) {
  const World& pile = settledPile();
  FieldObserver observer(FieldsDef{}, pile.def().boxWidth);
  for (auto _ : state) observer.addFrame(pile, 0);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_FieldFrame)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace wiggle

BENCHMARK_MAIN();
