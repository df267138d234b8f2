#pragma once
// Counter-based random numbers: a value is a pure function of (seed, stream, index, draw), so a
// bed is the same whatever the thread count or the order in which grains are made, and any grain's
// draws can be recomputed alone. The mixer is SplitMix64's finaliser (Steele, Lea, Flood 2014),
// applied to a combination of the four keys.
//
// Every stream id used by wiggle is listed here, so that two uses never share a stream.
#include <cstdint>

namespace wiggle {

enum class RngStream : std::uint64_t {
  GrainDiameter = 1,   // index: grain serial number in the pour; draw 0
  PourPosition = 2,    // index: grain serial number; draws 0 (x), 1 (y jitter)
  PourVelocity = 3,    // index: grain serial number; draws 0, 1
  RandomPourDiameter = 4,  // bed.pour = "random"; index: attempt serial number in the pour; draw 0
  RandomPourPosition = 5,  // bed.pour = "random"; index: attempt serial number; draws 0 (x), 1 (y)
};

inline std::uint64_t mix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

inline std::uint64_t randomBits(std::uint64_t seed, RngStream stream, std::uint64_t index,
                                std::uint64_t draw = 0) {
  std::uint64_t h = mix64(seed);
  h = mix64(h ^ static_cast<std::uint64_t>(stream));
  h = mix64(h ^ index);
  return mix64(h ^ draw);
}

// Uniform in [0, 1) with 53 random bits.
inline double uniform01(std::uint64_t seed, RngStream stream, std::uint64_t index,
                        std::uint64_t draw = 0) {
  return static_cast<double>(randomBits(seed, stream, index, draw) >> 11) * 0x1.0p-53;
}

}  // namespace wiggle
