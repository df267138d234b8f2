#include "core/Machine.h"

#include <sched.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <thread>

namespace wiggle {

int availableCores() {
  cpu_set_t set;
  if (::sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

double processCpuSeconds() {
  timespec t{};
  return ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t) == 0
             ? static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec)
             : 0.0;
}

double loadAverage() {
  double load[1];
  return ::getloadavg(load, 1) == 1 ? load[0] : 0.0;
}

int idleCores() { return idleCoresOf(availableCores(), loadAverage()); }

int idleCoresOf(int cores, double load) {
  return std::clamp(cores - static_cast<int>(std::lround(load)), 1, std::max(1, cores));
}

}  // namespace wiggle
