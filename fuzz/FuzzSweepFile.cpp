// libFuzzer target: a sweep file, expanded into its cases as `wiggle sweep` does first.
#include <cstdint>
#include <string>

#include "core/Error.h"
#include "io/SweepSpec.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)wiggle::parseSweepSpec(text, "fuzz-sweep.toml");
  } catch (const wiggle::Error&) {
  }
  return 0;
}
