#include "scenario/run/Checkpoint.h"

#include <filesystem>

#include "core/Error.h"
#include "io/Config.h"
#include "io/StateFile.h"

namespace wiggle {

namespace {
constexpr std::uint32_t kFirstFormatWithSpins = 6;  // io/StateFile.h's version that added RunState::spins
}  // namespace

void RunState::save(BinaryWriter& out) const {
  out.array(samples);
  out.array(phaseSum);
  out.array(phaseCount);
  out.value(dumpBytes);
  out.value(runWallSeconds);
  out.value(bedWallSeconds);
  out.string(bedKey);
  out.value(static_cast<std::uint8_t>(bedFromCache));
  out.array(spins);
}

void RunState::load(BinaryReader& in) {
  samples = in.array<TrajectorySample>();
  phaseSum = in.array<double>();
  phaseCount = in.array<std::uint64_t>();
  if (phaseSum.size() != kPhaseBins || phaseCount.size() != kPhaseBins)
    throw Error(in.what() + " is corrupt: phase bins");
  dumpBytes = in.value<std::uint64_t>();
  runWallSeconds = in.value<double>();
  bedWallSeconds = in.value<double>();
  bedKey = in.string();
  bedFromCache = in.value<std::uint8_t>() != 0;
  if (in.formatVersion() >= kFirstFormatWithSpins) spins = in.array<SpinSample>();
  if (!spins.empty() && spins.size() != samples.size()) throw Error(in.what() + " is corrupt: turns");
}

std::string checkpointPath(const std::string& runDir) { return runDir + "/checkpoint.bin"; }
std::string previousCheckpointPath(const std::string& runDir) { return runDir + "/checkpoint.prev.bin"; }

void writeCheckpoint(const std::string& runDir, const std::string& configToml, const World& world,
                     const RunState& state, const FieldObserver& fields) {
  BinaryWriter out;
  out.string(configToml);
  world.save(out);
  state.save(out);
  fields.save(out);
  // Keep the previous good checkpoint until the new one is safely in place.
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(checkpointPath(runDir))) fs::rename(checkpointPath(runDir), previousCheckpointPath(runDir), ec);
  writeStateFile(checkpointPath(runDir), "checkpoint", out.bytes());
}

std::string whyRunCannotContinue(const RunConfig& past, const RunConfig& now) {
  const std::string key =
      firstDifferingKey(past, now, {"run.duration", "run.plot", "run.checkpoint_interval", "run.profile"});
  if (!key.empty())
    return key + " is " + configValueString(now, key) + " here but " + configValueString(past, key) +
           " in the run (only run.duration, longer, run.plot, run.checkpoint_interval and run.profile may change)";
  if (now.run.duration < past.run.duration)
    return "run.duration = " + configValueString(now, "run.duration") + " is shorter than the run's " +
           configValueString(past, "run.duration") + " (a run can be extended, not cut)";
  return "";
}

namespace {

// "" when the run whose config text is `stored` can be continued with `config`, else why not.
std::string whyStoredRunCannotContinue(const std::string& stored, const std::string& name, const RunConfig& config) {
  try {
    return whyRunCannotContinue(parseRunConfig(stored, name + " (its config)"), config);
  } catch (const Error& e) {
    return e.what();  // e.g. a key this version no longer knows
  }
}

}  // namespace

Checkpoint parseCheckpoint(const std::string& file, const std::string& name, const RunConfig& config,
                           const std::string& configToml) {
  const StatePayload payload = parseStateFile(file, name, "checkpoint");
  BinaryReader in(payload.bytes.data(), payload.bytes.size(), name, payload.version);
  // The same config, read back: a checkpoint written before a key was added (and so without it)
  // holds that key's default, and stays valid as long as the run does not change it.
  const std::string stored = in.string();
  if (stored != configToml)
    if (const std::string why = whyStoredRunCannotContinue(stored, name, config); !why.empty())
      throw Error(name + " belongs to another config: " + why);
  World world = World::load(in);
  RunState state;
  state.load(in);
  FieldObserver fields(config.fields, config.box.width);
  fields.load(in);
  if (!in.atEnd()) throw Error(name + " has trailing data");
  return Checkpoint{std::move(world), std::move(state), std::move(fields)};
}

}  // namespace wiggle
