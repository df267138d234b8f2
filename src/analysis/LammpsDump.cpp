#include "analysis/LammpsDump.h"

#include <algorithm>
#include <cstdio>

namespace wiggle {

std::string lammpsDumpFrame(const World& world) {
  const ParticleStore& s = world.particles();
  const std::size_t atoms = world.hasIntruder() ? world.clump().offsetX.size() : 0;
  double yLo = 0.0, yHi = 1.0;
  for (double y : s.y) {
    yLo = std::min(yLo, y - 1.0);
    yHi = std::max(yHi, y + 1.0);
  }
  std::string out;
  out.reserve((s.size() + atoms) * 80 + 256);
  char line[256];
  std::snprintf(line, sizeof line,
                "ITEM: TIMESTEP\n%llu\nITEM: NUMBER OF ATOMS\n%zu\nITEM: BOX BOUNDS pp ff pp\n"
                "0 %.17g\n%.17g %.17g\n-0.5 0.5\nITEM: ATOMS id type x y z radius vx vy\n",
                static_cast<unsigned long long>(world.stepCount()), s.size() + atoms, world.def().boxWidth, yLo, yHi);
  out += line;
  std::uint32_t maxTag = 0;
  for (std::uint32_t i = 0; i < s.size(); ++i) {
    maxTag = std::max(maxTag, s.tag[i]);
    std::snprintf(line, sizeof line, "%u %d %.9g %.9g 0 %.9g %.6g %.6g\n", s.tag[i] + 1, i < s.grainCount ? 1 : 2,
                  s.x[i], s.y[i], s.radius[i], s.vx[i], s.vy[i]);
    out += line;
  }
  const ClumpState& c = world.intruder();
  for (std::size_t a = 0; a < atoms; ++a) {
    std::snprintf(line, sizeof line, "%zu 3 %.9g %.9g 0 %.9g %.6g %.6g\n", maxTag + 2 + a,
                  c.x + world.clump().offsetX[a], c.y + world.clump().offsetY[a], world.clump().atomRadius, c.vx, c.vy);
    out += line;
  }
  return out;
}

}  // namespace wiggle
