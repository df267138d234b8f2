// libFuzzer target: the checkpoint reader (`wiggle run --resume`). The input is a checkpoint file
// with its checksum made right (FuzzInput.h). A checkpoint belongs to one config, whose TOML opens
// its payload: the target reads that TOML back as the run's config, so that a mutated file is
// compared with a config it can match and the World, run-state and field readers behind it run.
#include <cstdint>
#include <string>

#include "FuzzInput.h"
#include "core/Error.h"
#include "core/BinaryStream.h"
#include "io/Config.h"
#include "io/StateFile.h"
#include "scenario/run/Checkpoint.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string file = wiggle::fuzz::withValidChecksum(data, size);
  try {
    const wiggle::StatePayload payload = wiggle::parseStateFile(file, "fuzz.bin", "checkpoint");
    wiggle::BinaryReader in(payload.bytes.data(), payload.bytes.size(), "fuzz.bin", payload.version);
    const std::string configToml = in.string();
    const wiggle::RunConfig config = wiggle::parseRunConfig(configToml, "fuzz.bin config");
    wiggle::Checkpoint checkpoint = wiggle::parseCheckpoint(file, "fuzz.bin", config, configToml);
    (void)checkpoint.world.stateHash();
  } catch (const wiggle::Error&) {
  }
  return 0;
}
