#include "scenario/CostModel.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include "io/Config.h"
#include "scenario/BedMaker.h"
#include "scenario/Case.h"
#include "scenario/SpeedRecord.h"

namespace wiggle {

SpeedBasis speedBasis(const RunConfig& config) {
  SpeedBasis basis;
  if (const std::optional<MeasuredSpeed> m = measuredSpeed(config, estimatedParticles(config))) {
    basis.ns = m->nsPerParticleStep;
    basis.source = "the median of this machine's last " + std::to_string(m->runs) + " one-thread run" +
                   (m->runs == 1 ? "" : "s") + " of a " + m->buildKind + " build" +
                   (m->sameSize ? " on beds of this size" : " (none yet on a bed of this size)") + " (" + m->path + ")";
  } else {
    basis.source = "no one-thread run of a " + speedBuildKind() +
                   " build recorded on this machine yet, so the reference machine's figure, docs/SWEEPS.md";
  }
  return basis;
}

double estimatedParticles(const RunConfig& config) { return estimatedGrains(config) + config.box.width; }

double estimatedRunSeconds(const RunConfig& config, double nsPerParticleStep) {
  const double steps = static_cast<double>(wholeStepsIn(config.run.duration, config.run.dt));
  return 1e-9 * nsPerParticleStep * estimatedParticles(config) * steps;
}

double estimatedBedSeconds(const RunConfig& config, double nsPerParticleStep, bool withBase) {
  // While pouring, the bed holds on average about half (b + 1) / (2 b) of its final grains over
  // b batches; then the whole bed relaxes.
  const double batches = std::max(1.0, std::ceil(config.box.bedHeight / config.bed.batchHeight));
  const double pourTime = 0.5 * (batches + 1.0) * CostModel::bedTimePerBatch;
  const bool carved = config.bed.cavity == BedCavity::Carved;
  const double relaxTime = config.bed.relaxDamping > 0 ? CostModel::dampedRelaxTime
                           : carved                    ? CostModel::carvedRelaxTime
                                                       : CostModel::bedRelaxTime;
  const double simulatedTime = relaxTime + (carved && !withBase ? 0.0 : pourTime);
  return 1e-9 * nsPerParticleStep * estimatedParticles(config) * simulatedTime / config.run.dt;
}

BedPlan planBed(const RunConfig& config, const ClumpDef& clump) {
  BedPlan plan;
  if (!config.bed.file.empty()) {
    plan.source = BedPlan::Source::File;
    plan.path = config.bed.file;
    return plan;
  }
  plan.key = bedKey(config, clump);
  plan.path = bedCachePath(config, plan.key);
  if (std::filesystem::exists(plan.path)) {
    plan.source = BedPlan::Source::Cached;
  } else if (config.bed.cavity == BedCavity::Carved) {
    plan.source = BedPlan::Source::Carve;
    plan.baseKey = baseBedKey(config);
    plan.baseCached = std::filesystem::exists(bedCachePath(config, plan.baseKey));
  }
  return plan;
}

}  // namespace wiggle
