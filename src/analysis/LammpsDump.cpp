#include "analysis/LammpsDump.h"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace wiggle {

namespace {

// Forces and torques of the particles the step does not sum: the frozen base (its contacts with
// grains and with the intruder) and the intruder's atoms (their contacts with particles). Each
// pair's slot holds the force on its grain; the other side gets the opposite force and its own
// radius times the torque arm (ContactLaw.h), summed in list order.
struct ContactSums {
  std::vector<double> baseFx, baseFy, baseTorque;  // index i - grainCount
  std::vector<double> atomFx, atomFy, atomTorque;  // index: the atom
};

ContactSums contactSums(const World& world, std::size_t atoms) {
  const ParticleStore& s = world.particles();
  const std::uint32_t n = s.grainCount;
  const std::size_t base = s.size() - n;
  ContactSums sums{std::vector<double>(base, 0.0), std::vector<double>(base, 0.0), std::vector<double>(base, 0.0),
                   std::vector<double>(atoms, 0.0), std::vector<double>(atoms, 0.0), std::vector<double>(atoms, 0.0)};
  const NeighbourList& list = world.neighbours();
  for (std::size_t k = 0; k < list.partner.size() && k < list.forceX.size(); ++k) {
    const std::uint32_t j = list.partner[k];
    if (j < n) continue;  // a grain: its total is in the store
    sums.baseFx[j - n] -= list.forceX[k];
    sums.baseFy[j - n] -= list.forceY[k];
    sums.baseTorque[j - n] -= s.radius[j] * list.torqueArm[k];
  }
  const IntruderPairs& pairs = world.intruderPairs();
  const double atomRadius = world.clump().atomRadius;
  for (std::uint32_t p = 0; p < pairs.size() && atoms > 0; ++p) {
    const std::uint32_t g = pairs.grain[p], a = pairs.atom[p];
    sums.atomFx[a] -= pairs.forceX[p];
    sums.atomFy[a] -= pairs.forceY[p];
    sums.atomTorque[a] -= atomRadius * pairs.torqueArm[p];
    if (g >= n) {
      sums.baseFx[g - n] += pairs.forceX[p];
      sums.baseFy[g - n] += pairs.forceY[p];
      sums.baseTorque[g - n] -= s.radius[g] * pairs.torqueArm[p];
    }
  }
  return sums;
}

}  // namespace

std::string lammpsDumpFrame(const World& world) {
  const ParticleStore& s = world.particles();
  const std::size_t atoms = world.hasIntruder() ? world.clump().offsetX.size() : 0;
  const ContactSums sums = contactSums(world, atoms);
  double yLo = 0.0, yHi = 1.0;
  for (double y : s.y) {
    yLo = std::min(yLo, y - 1.0);
    yHi = std::max(yHi, y + 1.0);
  }
  std::string out;
  out.reserve((s.size() + atoms) * 110 + 256);
  char line[320];
  std::snprintf(line, sizeof line,
                "ITEM: TIMESTEP\n%llu\nITEM: NUMBER OF ATOMS\n%zu\nITEM: BOX BOUNDS pp ff pp\n"
                "0 %.17g\n%.17g %.17g\n-0.5 0.5\nITEM: ATOMS id type x y z radius vx vy fx fy tqz\n",
                static_cast<unsigned long long>(world.stepCount()), s.size() + atoms, world.def().boxWidth, yLo, yHi);
  out += line;
  std::uint32_t maxTag = 0;
  for (std::uint32_t i = 0; i < s.size(); ++i) {
    maxTag = std::max(maxTag, s.tag[i]);
    const bool grain = i < s.grainCount;
    const double fx = grain ? s.fx[i] : sums.baseFx[i - s.grainCount];
    const double fy = grain ? s.fy[i] : sums.baseFy[i - s.grainCount];
    const double torque = grain ? s.torque[i] : sums.baseTorque[i - s.grainCount];
    std::snprintf(line, sizeof line, "%u %d %.9g %.9g 0 %.9g %.6g %.6g %.6g %.6g %.6g\n", s.tag[i] + 1, grain ? 1 : 2,
                  s.x[i], s.y[i], s.radius[i], s.vx[i], s.vy[i], fx, fy, torque);
    out += line;
  }
  const ClumpState& c = world.intruder();
  for (std::size_t a = 0; a < atoms; ++a) {
    std::snprintf(line, sizeof line, "%zu 3 %.9g %.9g 0 %.9g %.6g %.6g %.6g %.6g %.6g\n", maxTag + 2 + a,
                  c.x + world.clump().offsetX[a], c.y + world.clump().offsetY[a], world.clump().atomRadius, c.vx, c.vy,
                  sums.atomFx[a], sums.atomFy[a], sums.atomTorque[a]);
    out += line;
  }
  return out;
}

}  // namespace wiggle
