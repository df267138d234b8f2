#include "scenario/case/EngineSettings.h"

#include <cmath>

namespace wiggle {

WorldDef worldDefFor(const RunConfig& config) {
  WorldDef def;
  def.boxWidth = config.box.width;
  def.dt = config.run.dt;
  def.massModel = config.grains.massModel;
  def.contact = config.contact;
  def.skin = config.engine.skin;
  def.intruderSkin = config.engine.intruderSkin;
  def.sortInterval = config.engine.sortInterval;
  // The fastest a grain falls without the drive: from the top of the last batch poured (thrown
  // down at bed.pour_speed when the pour is random).
  def.referenceImpactSpeed = std::sqrt(2.0 * def.gravity * (config.box.bedHeight + config.bed.batchHeight));
  if (config.bed.pour == BedPour::Random)
    def.referenceImpactSpeed = std::sqrt(def.referenceImpactSpeed * def.referenceImpactSpeed +
                                         config.bed.pourSpeed * config.bed.pourSpeed);
  return def;
}

}  // namespace wiggle
