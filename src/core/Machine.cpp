#include "core/Machine.h"

#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <sstream>
#include <string>
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

double idleCpuSeconds() {
  cpu_set_t set;
  if (::sched_getaffinity(0, sizeof set, &set) != 0) return -1.0;
  std::ifstream stat("/proc/stat");
  const long ticksPerSecond = ::sysconf(_SC_CLK_TCK);
  if (!stat || ticksPerSecond <= 0) return -1.0;
  // Lines "cpuN user nice system idle iowait ...": idle and iowait are the time nothing ran.
  double ticks = 0.0;
  bool found = false;
  for (std::string line; std::getline(stat, line);) {
    if (line.rfind("cpu", 0) != 0 || line.size() < 4 || !std::isdigit(static_cast<unsigned char>(line[3]))) continue;
    std::istringstream fields(line.substr(3));
    int cpu = -1;
    double user = 0, nice = 0, system = 0, idle = 0, iowait = 0;
    if (!(fields >> cpu >> user >> nice >> system >> idle >> iowait)) continue;
    if (cpu < 0 || cpu >= CPU_SETSIZE || !CPU_ISSET(cpu, &set)) continue;
    ticks += idle + iowait;
    found = true;
  }
  return found ? ticks / static_cast<double>(ticksPerSecond) : -1.0;
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
