// libFuzzer target: the bed-cache reader. The input is a cached bed file with its checksum made
// right (FuzzInput.h); its payload opens with the bed's key, which the target passes as the
// expected key so that the World reader behind it runs.
#include <cstdint>
#include <string>

#include "FuzzInput.h"
#include "core/Error.h"
#include "core/BinaryStream.h"
#include "io/StateFile.h"
#include "scenario/bed/BedMaker.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string file = wiggle::fuzz::withValidChecksum(data, size);
  try {
    const wiggle::StatePayload payload = wiggle::parseStateFile(file, "fuzz.bin", "bed");
    wiggle::BinaryReader in(payload.bytes.data(), payload.bytes.size(), "fuzz.bin", payload.version);
    const std::string key = in.string();
    const wiggle::World world = wiggle::parseCachedBed(file, "fuzz.bin", key);
    (void)world.stateHash();
  } catch (const wiggle::Error&) {
  }
  return 0;
}
