#include "physics/ForceKernels.h"

#include <cstdlib>
#include <string_view>

#include "core/Error.h"

namespace wiggle {

// One table per variant built (ForceKernelVariant.cpp); the x86 variants only on x86-64.
const ForceKernels& forceKernels_scalar(ContactLaw law);
#if WIGGLE_X86_KERNELS
const ForceKernels& forceKernels_avx2(ContactLaw law);
const ForceKernels& forceKernels_avx512(ContactLaw law);
#endif

namespace {

bool cpuRuns(SimdLevel level) {
#if WIGGLE_X86_KERNELS
  __builtin_cpu_init();
  // The variants are built for the x86-64 micro-architecture levels v3 and v4 (CMakeLists.txt), so
  // the CPU must have the features of the level that code can use, not only AVX2 or AVX-512F.
  // Named one by one: GCC 12 knows "x86-64-v3" as a name, clang 14 (the fuzz build) does not.
  const bool v3 = __builtin_cpu_supports("sse4.2") && __builtin_cpu_supports("popcnt") &&
                  __builtin_cpu_supports("avx") && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
                  __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2");
  const bool v4 = v3 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
                  __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512vl") &&
                  __builtin_cpu_supports("avx512cd");
  switch (level) {
    case SimdLevel::Scalar: return true;
    case SimdLevel::Avx2: return v3;
    case SimdLevel::Avx512: return v4;
  }
  return false;
#else
  return level == SimdLevel::Scalar;
#endif
}

SimdLevel widestLevel() {
  for (const SimdLevel level : {SimdLevel::Avx512, SimdLevel::Avx2})
    if (cpuRuns(level)) return level;
  return SimdLevel::Scalar;
}

}  // namespace

std::string simdLevelName(SimdLevel level) {
  switch (level) {
    case SimdLevel::Scalar: return "scalar";
    case SimdLevel::Avx2: return "avx2";
    case SimdLevel::Avx512: return "avx512";
  }
  return "unknown";
}

const ForceKernels& forceKernels(SimdLevel level, ContactLaw law) {
  if (!cpuRuns(level)) throw Error("this CPU cannot run the " + simdLevelName(level) + " force kernels");
  if (!isChoice<ContactLaw>(law)) throw Error("no force kernels for an unknown contact law");
  switch (level) {
#if WIGGLE_X86_KERNELS
    case SimdLevel::Avx512: return forceKernels_avx512(law);
    case SimdLevel::Avx2: return forceKernels_avx2(law);
#endif
    default: return forceKernels_scalar(law);
  }
}

SimdLevel defaultSimdLevel() {
  const SimdLevel widest = widestLevel();
  const char* cap = std::getenv("WIGGLE_SIMD");
  if (cap == nullptr || *cap == '\0') return widest;
  for (const SimdLevel level : {SimdLevel::Scalar, SimdLevel::Avx2, SimdLevel::Avx512})
    if (std::string_view(cap) == simdLevelName(level)) {
      if (!cpuRuns(level))
        throw Error("WIGGLE_SIMD=" + simdLevelName(level) + ": this CPU's widest force kernels are " +
                    simdLevelName(widest));
      return level;
    }
  throw Error("WIGGLE_SIMD=" + std::string(cap) + " is not one of scalar, avx2, avx512");
}

}  // namespace wiggle
