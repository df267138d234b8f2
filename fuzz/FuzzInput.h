#pragma once
// Helpers shared by the libFuzzer targets (docs/RELIABILITY.md, tools/fuzz.sh).
#include <cstdint>
#include <cstring>
#include <string>

#include "core/Hash.h"

namespace wiggle::fuzz {

// The fuzzer's bytes as a state file whose trailing checksum is made right (io/StateFile.h: the
// last 8 bytes are FNV-1a 64 of everything before). A random mutation almost never passes the
// checksum, so without this the fuzzer would only ever meet "fails its checksum"; with it, every
// reader behind the checksum (header, World, run state, fields, bed key) is exercised.
inline std::string withValidChecksum(const std::uint8_t* data, std::size_t size) {
  std::string file(reinterpret_cast<const char*>(data), size);
  if (file.size() < sizeof(std::uint64_t)) return file;
  Hasher h;
  h.addBytes(file.data(), file.size() - sizeof(std::uint64_t));
  const std::uint64_t sum = h.value();
  std::memcpy(file.data() + file.size() - sizeof sum, &sum, sizeof sum);
  return file;
}

}  // namespace wiggle::fuzz
