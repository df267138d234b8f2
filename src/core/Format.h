#pragma once
// Numbers and durations as text, one way each, for messages, logs and CSV cells.
#include <cmath>
#include <cstdio>
#include <string>

namespace wiggle {

// printf's %.Ng: `digits` significant digits, the shortest of fixed and exponent notation. 6 for
// messages, 10 for CSV cells (a round trip to about 1e-10), 17 where the bits must survive.
inline std::string formatNumber(double v, int digits = 6) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", digits, v);
  return text;
}

// A wall-clock duration for people: "42s", "3m05s", "1h02m", "2d03h"; "?" when unknown (negative or
// not finite).
inline std::string formatDuration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  char text[32];
  const long s = std::lround(seconds);
  if (s >= 86400) std::snprintf(text, sizeof text, "%ldd%02ldh", s / 86400, (s % 86400) / 3600);
  else if (s >= 3600) std::snprintf(text, sizeof text, "%ldh%02ldm", s / 3600, (s % 3600) / 60);
  else if (s >= 60) std::snprintf(text, sizeof text, "%ldm%02lds", s / 60, s % 60);
  else std::snprintf(text, sizeof text, "%lds", s);
  return text;
}

}  // namespace wiggle
