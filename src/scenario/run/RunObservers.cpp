#include "scenario/run/RunObservers.h"

#include "io/AtomicFile.h"
#include "scenario/lammps/LammpsDump.h"

namespace wiggle {

void RunObservers::dumpFrame(const World& world) {
  const std::string frame = lammpsDumpFrame(world);
  appendToFile(dumpPath_, frame);
  state_.dumpBytes += frame.size();
}

void RunObservers::stepTowards(World& world, std::uint64_t end, const std::function<bool(std::uint64_t)>& stopAt) {
  auto stopsAt = [&](std::uint64_t step) { return step == end || (stopAt && stopAt(step)); };
  while (world.stepCount() < end) {
    std::uint64_t to = world.stepCount() + 1;
    while (!stopsAt(to) && !needsGrainsAt(to)) ++to;
    // After each step the intruder and its turn are whole (World::runWatchingIntruder).
    world.runWatchingIntruder(to - world.stepCount(), [this, &world](const ClumpState&, std::uint64_t step, double) {
      state_.recordStep(run_.steps, world, step);
    });
    if (const std::size_t p = fieldPhaseAt(to)) fields_.addFrame(world, p - 1);
    if (dumpAt(to)) dumpFrame(world);
    if (stopsAt(to)) return;
  }
}

std::size_t RunObservers::fieldPhaseAt(std::uint64_t step) const {
  const RunSchedule& steps = run_.steps;
  if (!run_.config.fields.enabled || step <= steps.firstMeasured) return 0;
  for (std::size_t p = 0; p < steps.fieldPhaseStep.size(); ++p)
    if (step % steps.period == steps.fieldPhaseStep[p]) return p + 1;
  return 0;
}

}  // namespace wiggle
