// wiggle_core_latency: how long one cache line takes to travel between two CPUs of this machine.
//
// Two threads of wiggle share data every step (the edges of their strips, the barriers), so how far
// apart the hypervisor or the board puts two CPUs decides what a second thread can pay. This pins
// one thread to CPU a and one to CPU b (every pair of the CPUs this process may run on, or the
// pairs given) and bounces a counter between them: each waits for the other's last value and
// writes the next. A round trip is two transfers of the line; the line's one-way time is half of it.
// Same core complex (shared L3 slice): tens of ns; another complex or socket: hundreds.
//
//     wiggle_core_latency [--rounds N] [--pair A,B]...
#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

namespace {

struct alignas(64) Line {
  std::atomic<long> value{0};
};

[[noreturn]] void usage(const char* why) {
  std::fprintf(stderr, "wiggle_core_latency: %s\nusage: wiggle_core_latency [--rounds N] [--pair A,B]...\n", why);
  std::exit(2);
}

bool pinTo(int cpu) {
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  return pthread_setaffinity_np(pthread_self(), sizeof set, &set) == 0;
}

// Median of `repeats` timings of `rounds` round trips between CPUs a (this thread) and b, in ns
// per round trip.
double roundTrip(int a, int b, long rounds, int repeats) {
  if (!pinTo(a)) usage(("cannot pin to CPU " + std::to_string(a)).c_str());
  std::vector<double> ns;
  for (int r = 0; r < repeats; ++r) {
    Line line;
    std::atomic<bool> pinned{false};
    std::thread echo([&] {
      if (!pinTo(b)) usage(("cannot pin to CPU " + std::to_string(b)).c_str());
      pinned = true;
      for (long k = 1; k < 2 * rounds; k += 2) {
        while (line.value.load(std::memory_order_acquire) != k) {
        }
        line.value.store(k + 1, std::memory_order_release);
      }
    });
    while (!pinned) {
    }
    const auto start = std::chrono::steady_clock::now();
    for (long k = 0; k < 2 * rounds; k += 2) {
      line.value.store(k + 1, std::memory_order_release);
      while (line.value.load(std::memory_order_acquire) != k + 2) {
      }
    }
    const auto stop = std::chrono::steady_clock::now();
    echo.join();
    ns.push_back(std::chrono::duration<double, std::nano>(stop - start).count() / static_cast<double>(rounds));
  }
  std::sort(ns.begin(), ns.end());
  return ns[ns.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  long rounds = 200000;
  std::vector<std::pair<int, int>> pairs;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) usage(("missing value after " + arg).c_str());
    const std::string value = argv[++i];
    char* end = nullptr;
    if (arg == "--rounds") {
      rounds = std::strtol(value.c_str(), &end, 10);
      if (*end != '\0' || rounds < 1) usage("--rounds takes a whole number >= 1");
    } else if (arg == "--pair") {
      const long a = std::strtol(value.c_str(), &end, 10);
      if (*end != ',') usage("--pair takes two CPU numbers, A,B");
      const long b = std::strtol(end + 1, &end, 10);
      if (*end != '\0' || a < 0 || b < 0 || a == b || a >= CPU_SETSIZE || b >= CPU_SETSIZE)
        usage("--pair takes two different CPU numbers, A,B");
      pairs.emplace_back(static_cast<int>(a), static_cast<int>(b));
    } else {
      usage(("unknown option " + arg).c_str());
    }
  }
  cpu_set_t allowed;
  if (sched_getaffinity(0, sizeof allowed, &allowed) != 0) usage("cannot read this process's CPUs");
  std::vector<int> cpus;
  for (int c = 0; c < CPU_SETSIZE; ++c)
    if (CPU_ISSET(c, &allowed)) cpus.push_back(c);
  if (pairs.empty())
    for (std::size_t i = 0; i < cpus.size(); ++i)
      for (std::size_t j = i + 1; j < cpus.size(); ++j) pairs.emplace_back(cpus[i], cpus[j]);
  if (pairs.empty()) usage("this process may run on one CPU only: nothing to measure");
  for (const auto& [a, b] : pairs) {
    if (!CPU_ISSET(a, &allowed) || !CPU_ISSET(b, &allowed))
      usage(("CPU " + std::to_string(CPU_ISSET(a, &allowed) ? b : a) + " is not one this process may run on").c_str());
    const double ns = roundTrip(a, b, rounds, 5);
    std::printf("CPUs %d and %d: round trip %.1f ns, one way %.1f ns (median of 5 x %ld)\n", a, b, ns, ns / 2, rounds);
  }
  return 0;
}
