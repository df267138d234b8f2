// Google Benchmark micro-benchmarks of the engine's hot parts (docs/PERFORMANCE.md):
//   BM_ContactKernel   hertzHistoryContact over a batch of pairs (SoA inputs, ~70 % touching)
//   BM_NeighbourBuild  NeighbourList::build on a settled pile, carrying history from the old list
//   BM_WorldStep       one full World::step of the settled pile with a wiggling disk
//   BM_FieldFrame      one FieldObserver frame (Phi, v, contact stress on the 61 x 61 grid)
// Build: the `wiggle_bench` target (CMake builds bench/*.cpp when libbenchmark is found).
// Run:   OMP_NUM_THREADS=1 build/<dir>/wiggle_bench [--benchmark_filter=...]
// Items per second are pairs (kernel), particles (build, step) or grains in reach (frame).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "analysis/FieldObserver.h"
#include "io/RunConfig.h"
#include "physics/ContactLaw.h"
#include "physics/World.h"
#include "scenario/BedMaker.h"
#include "scenario/Shape.h"

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

void BM_ContactKernel(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  Lcg rng{42};
  std::vector<double> dx(n), dy(n), dvx(n), dvy(n), ri(n), rj(n), wi(n), wj(n), meff(n), sx(n), sy(n);
  for (std::size_t k = 0; k < n; ++k) {
    ri[k] = 0.45 + 0.1 * rng.next();
    rj[k] = 0.45 + 0.1 * rng.next();
    const double angle = 2.0 * 3.141592653589793 * rng.next();
    const double dist = (ri[k] + rj[k]) * (0.995 + 0.02 * rng.next());  // ~75 % overlapping, up to 0.5 %
    dx[k] = dist * std::cos(angle);
    dy[k] = dist * std::sin(angle);
    dvx[k] = 0.1 * (rng.next() - 0.5);
    dvy[k] = 0.1 * (rng.next() - 0.5);
    wi[k] = rng.next() - 0.5;
    wj[k] = rng.next() - 0.5;
    meff[k] = 0.26;
    sx[k] = 1e-5 * (rng.next() - 0.5);
    sy[k] = 1e-5 * (rng.next() - 0.5);
  }
  const ContactParams params;
  std::vector<double> fx(n), fy(n), arm(n);
  for (auto _ : state) {
    for (std::size_t k = 0; k < n; ++k) {
      const ContactForce c = hertzHistoryContact(params, 1e-4, dx[k], dy[k], dvx[k], dvy[k], ri[k], rj[k], wi[k], wj[k],
                                                 meff[k], sx[k], sy[k], true);
      fx[k] = c.fx;
      fy[k] = c.fy;
      arm[k] = c.torqueArm;
    }
    benchmark::DoNotOptimize(fx.data());
    benchmark::DoNotOptimize(fy.data());
    benchmark::DoNotOptimize(arm.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(n));
}
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
