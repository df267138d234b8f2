#include "core/Machine.h"

#include <sched.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <thread>

namespace wiggle {

int availableCores() {
  cpu_set_t set;
  if (::sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
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
