// libFuzzer target: a run config, through everything `wiggle run` does with it before it makes a
// bed (parse, validate, outline, clump, geometry). Any wiggle::Error is a clean refusal; anything
// else (another exception, a crash, a sanitizer report, a hang, memory past -rss_limit_mb) is a
// finding.
#include <cstdint>
#include <string>

#include "core/Error.h"
#include "io/Config.h"
#include "scenario/run/Experiment.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const wiggle::RunConfig config = wiggle::parseRunConfig(text, "fuzz.toml");
    wiggle::prepareCase(config);
    (void)wiggle::toToml(config);
  } catch (const wiggle::Error&) {
  }
  return 0;
}
