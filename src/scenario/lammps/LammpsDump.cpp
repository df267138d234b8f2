#include "scenario/lammps/LammpsDump.h"

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

ParticleFrame particleFrame(const World& world) {
  const ParticleStore& s = world.particles();
  const std::size_t atoms = world.hasIntruder() ? world.clump().offsetX.size() : 0;
  const ContactSums sums = contactSums(world, atoms);
  ParticleFrame f;
  f.step = world.stepCount();
  f.time = world.time();
  f.boxWidth = world.def().boxWidth;
  for (double y : s.y) {
    f.yLo = std::min(f.yLo, y - 1.0);
    f.yHi = std::max(f.yHi, y + 1.0);
  }
  auto add = [&f](std::uint64_t id, int type, double x, double y, double radius, double vx, double vy, double fx,
                  double fy, double tqz) {
    f.id.push_back(id);
    f.type.push_back(type);
    f.x.push_back(x);
    f.y.push_back(y);
    f.radius.push_back(radius);
    f.vx.push_back(vx);
    f.vy.push_back(vy);
    f.fx.push_back(fx);
    f.fy.push_back(fy);
    f.tqz.push_back(tqz);
  };
  std::uint32_t maxTag = 0;
  for (std::uint32_t i = 0; i < s.size(); ++i) {
    maxTag = std::max(maxTag, s.tag[i]);
    if (i < s.grainCount) {
      add(s.tag[i] + 1, 1, s.x[i], s.y[i], s.radius[i], s.vx[i], s.vy[i], s.fx[i], s.fy[i], s.torque[i]);
    } else {
      const std::size_t b = i - s.grainCount;
      add(s.tag[i] + 1, 2, s.x[i], s.y[i], s.radius[i], s.vx[i], s.vy[i], sums.baseFx[b], sums.baseFy[b],
          sums.baseTorque[b]);
    }
  }
  const ClumpState& c = world.intruder();
  for (std::size_t a = 0; a < atoms; ++a)
    add(maxTag + 2 + a, 3, c.x + world.clump().offsetX[a], c.y + world.clump().offsetY[a], world.clump().atomRadius,
        c.vx, c.vy, sums.atomFx[a], sums.atomFy[a], sums.atomTorque[a]);
  return f;
}

std::string lammpsDumpFrame(const World& world) {
  const ParticleFrame f = particleFrame(world);
  std::string out;
  out.reserve(f.id.size() * 110 + 256);
  char line[320];
  std::snprintf(line, sizeof line,
                "ITEM: TIMESTEP\n%llu\nITEM: NUMBER OF ATOMS\n%zu\nITEM: BOX BOUNDS pp ff pp\n"
                "0 %.17g\n%.17g %.17g\n-0.5 0.5\nITEM: ATOMS id type x y z radius vx vy fx fy tqz\n",
                static_cast<unsigned long long>(f.step), f.id.size(), f.boxWidth, f.yLo, f.yHi);
  out += line;
  for (std::size_t i = 0; i < f.id.size(); ++i) {
    std::snprintf(line, sizeof line, "%llu %d %.9g %.9g 0 %.9g %.6g %.6g %.6g %.6g %.6g\n",
                  static_cast<unsigned long long>(f.id[i]), f.type[i], f.x[i], f.y[i], f.radius[i], f.vx[i], f.vy[i],
                  f.fx[i], f.fy[i], f.tqz[i]);
    out += line;
  }
  return out;
}

}  // namespace wiggle
