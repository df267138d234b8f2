#include "sweep/SweepRunner.h"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "core/Error.h"
#include "core/Machine.h"
#include "core/StopSignal.h"
#include "io/AtomicFile.h"
#include "io/FileLock.h"
#include "sweep/Coordinator.h"
#include "sweep/MpiQueue.h"
#include "sweep/SweepPlan.h"
#include "sweep/SweepStart.h"

namespace wiggle {

namespace fs = std::filesystem;

namespace {

std::string selfExecutable() {
  std::error_code ec;
  const auto path = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw Error("sweep: cannot find the wiggle binary (/proc/self/exe): " + ec.message());
  return path.string();
}

// The case `key` names (wiggle sweep --case): its number in the --dry-run listing (from 1) or its name.
std::size_t findCase(const SweepSpec& spec, const std::string& key) {
  for (std::size_t c = 0; c < spec.cases.size(); ++c)
    if (spec.cases[c].name == key) return c;
  std::size_t number = 0;
  const auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), number);
  if (ec == std::errc() && end == key.data() + key.size() && number >= 1 && number <= spec.cases.size())
    return number - 1;
  throw Error("--case " + key + ": no such case in " + spec.settings.name + " (" + std::to_string(spec.cases.size()) +
              " cases: a number from 1 to " + std::to_string(spec.cases.size()) +
              " or a name, as --dry-run lists them)");
}

int envInt(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::atoi(v) : 0;
}

}  // namespace

SweepOutcome runSweep(const std::string& sweepFile, const SweepOptions& options) {
  SweepSpec spec = loadSweepSpec(sweepFile);
  const std::string outDir = options.outDir.empty() ? "sweep-" + spec.settings.name : options.outDir;
  std::optional<std::size_t> only;
  if (!options.onlyCase.empty()) only = findCase(spec, options.onlyCase);

  std::unique_ptr<MpiQueue> ownMpi;
  MpiQueue* mpi = options.mpi;
  if (!mpi && !only && options.allowMpi && !options.dryRun && MpiQueue::launchedAsMultipleProcesses()) {
    ownMpi = std::make_unique<MpiQueue>();  // throws when built without MPI
    if (ownMpi->size() >= 2) mpi = ownMpi.get();
  }

  SweepRunSettings settings;
  settings.executable = options.executable.empty() ? selfExecutable() : options.executable;
  if (mpi) {
    settings.jobs = options.jobs > 0 ? options.jobs : 1;
    const int cpus = envInt("SLURM_CPUS_PER_TASK");
    settings.threads = options.threads > 0             ? options.threads
                       : spec.settings.threadsPerCase > 0 ? spec.settings.threadsPerCase
                                                          : std::max(1, cpus / settings.jobs);
  } else {
    const int cores = availableCores();
    settings.jobs = options.jobs > 0 ? options.jobs : spec.settings.jobs > 0 ? spec.settings.jobs : cores;
    settings.threads = options.threads > 0             ? options.threads
                       : spec.settings.threadsPerCase > 0 ? spec.settings.threadsPerCase
                                                          : 0;  // decided below, from the work left
  }

  if (mpi && mpi->rank() != 0) {
    SweepPlan plan;  // workers need only the cases and the directory
    plan.spec = std::move(spec);
    plan.outDir = outDir;
    return runWorkerRank(plan, settings, *mpi);
  }

  std::error_code ec;
  if (!options.dryRun) {
    fs::create_directories(outDir + "/cases", ec);
    if (ec) throw Error("cannot create sweep directory " + outDir + ": " + ec.message());
  }
  std::optional<FileLock> lock;
  if (!options.dryRun) {
    lock.emplace(sweepLockPath(outDir), only.has_value(), false, "another wiggle sweep is running in " + outDir);
    // Only this coordinator writes here (the lock says so): files a killed one was writing go.
    if (!only) {
      removeLeftoverTemporaries(outDir);
      removeLeftoverTemporaries(outDir + "/beds");
    }
  }
  SweepPlan plan = makeSweepPlan(std::move(spec), outDir);

  if (!mpi) {
    // Independent cases scale better than threads: as many single-threaded cases as cores. With
    // fewer tasks than cores, the spare cores go to the cases' threads.
    std::size_t tasks = plan.beds.size();
    for (const PlannedCase& p : plan.cases) tasks += p.state == CaseState::Pending;
    const int cores = availableCores();
    if (only) settings.jobs = 1;  // its bed, then the case
    else if (options.jobs <= 0 && plan.spec.settings.jobs <= 0 && tasks > 0)
      settings.jobs = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(settings.jobs), tasks));
    if (settings.threads <= 0) settings.threads = std::max(1, cores / std::max(1, settings.jobs));
  }

  if (options.dryRun) {
    if (MpiQueue::launcherRank() == 0)  // under mpirun, one listing
      (options.listing ? *options.listing : std::cout) << dryRunListing(plan, settings.jobs, settings.threads);
    SweepOutcome out;
    out.outDir = outDir;
    out.cases = plan.cases.size();
    return out;
  }

  // SIGINT/SIGTERM: the coordinator passes SIGTERM on to the running cases (they write a
  // checkpoint) and stops handing out work.
  std::optional<StopSignalGuard> stopOnSignal;
  if (options.handleSignals) stopOnSignal.emplace();
  return coordinateSweep(plan, settings, options, mpi, only);
}

}  // namespace wiggle
