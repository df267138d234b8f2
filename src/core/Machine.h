#pragma once
// What the machine offers a run: its cores, and how many of them other work leaves idle.

namespace wiggle {

// Cores this process may run on (its CPU affinity), at least 1.
int availableCores();

// CPU time this process has used so far, all its threads together, in seconds (0 if unknown). A
// run's CPU time per step is its speed on a core of its own, whatever share of the cores it got.
double processCpuSeconds();

// The 1-minute load average (runnable processes, ours included once they run), 0 if unknown.
double loadAverage();

// Seconds the CPUs this process may run on have been idle since boot, summed over those CPUs (from
// /proc/stat); negative where the system does not say. Its change over a stretch of wall time is
// the cores other work left idle in that stretch: how a run sees that a core it gave up is free again.
double idleCpuSeconds();

// The default thread count of a single run: the available cores minus the load of other work (the
// 1-minute load average, rounded), at least 1. OpenMP threads wait for each other at every step's
// barriers by spinning, so on a core that another process also wants, a run's threads keep waiting
// for a descheduled partner: measured 1,045 ns per particle-step for 2 threads beside two other
// jobs on 2 cores, against 55 for 1 thread (bench/HISTORY.md, "Threads on a busy machine").
// The thread count never changes a result, only the speed.
int idleCores();
// The rule itself, for `cores` available cores and a load average `load`.
int idleCoresOf(int cores, double load);

}  // namespace wiggle
