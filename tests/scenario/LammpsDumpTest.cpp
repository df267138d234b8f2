// The dump frame (scenario/lammps/LammpsDump.h): its rows are the particles in store order with the dump's
// ids and types, then the intruder's atoms; its text holds those numbers; and its forces obey
// Newton's third law: every contact appears twice with opposite signs, so over all rows the forces
// add up to gravity on the grains alone.
#include "scenario/lammps/LammpsDump.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <sstream>
#include <string>

#include "physics/World.h"

namespace wiggle {
namespace {

// A few grains dropped onto a base row around a held ring-shaped intruder (one right above it),
// stepped until they touch each other, the base and the intruder.
World touchingWorld() {
  WorldDef def;
  def.boxWidth = 12.0;
  World w(def);
  for (int i = 0; i < 12; ++i) w.addFrozen(i + 0.5, 0.0, 0.5);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 10; ++c) {
      const double x = 0.6 + 1.15 * c, y = 1.05 + 1.05 * r;
      if (std::hypot(x - 6.0, y - 3.0) > 1.6) w.addGrain(x, y, 0.5, 0.0);
    }
  w.addGrain(6.0, 4.52, 0.5, 0.0);  // 0.02 d above the ring's top atom: it lands on the intruder
  ClumpDef clump;
  for (int a = 0; a < 8; ++a) {
    clump.offsetX.push_back(0.75 * std::cos(a * 0.785398));
    clump.offsetY.push_back(0.75 * std::sin(a * 0.785398));
  }
  clump.mass = 3.0;
  w.setIntruder(clump, 6.0, 3.0);
  w.setIntruderMotion({HorizontalMotion::Held, 6.0, 0.0, 1.0, 0.0, false});
  // t = 2: the bottom row has fallen into the base's hollows. One thread: a few dozen grains gain
  // nothing from two, and a second thread on a busy core makes every step wait for it.
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  w.run(20000);
  omp_set_num_threads(saved);
  return w;
}

TEST(LammpsDump, RowsAreTheParticlesThenTheIntrudersAtoms) {
  const World w = touchingWorld();
  const ParticleFrame f = particleFrame(w);
  const ParticleStore& s = w.particles();
  const std::size_t atoms = w.clump().offsetX.size();
  ASSERT_EQ(f.id.size(), s.size() + atoms);
  EXPECT_EQ(f.step, w.stepCount());
  std::uint32_t maxTag = 0;
  for (std::uint32_t i = 0; i < s.size(); ++i) {
    EXPECT_EQ(f.id[i], s.tag[i] + 1u);
    EXPECT_EQ(f.type[i], i < s.grainCount ? 1 : 2);
    EXPECT_EQ(f.x[i], s.x[i]);
    EXPECT_EQ(f.vy[i], s.vy[i]);
    maxTag = std::max(maxTag, s.tag[i]);
  }
  for (std::size_t a = 0; a < atoms; ++a) {
    const std::size_t row = s.size() + a;
    EXPECT_EQ(f.id[row], maxTag + 2u + a);  // after every particle's id
    EXPECT_EQ(f.type[row], 3);
    EXPECT_EQ(f.x[row], w.intruder().x + w.clump().offsetX[a]);
    EXPECT_EQ(f.radius[row], w.clump().atomRadius);
  }
  // The text: its header, then one line per row with the same numbers (9 significant digits).
  std::istringstream text(lammpsDumpFrame(w));
  std::string line;
  std::getline(text, line);
  EXPECT_EQ(line, "ITEM: TIMESTEP");
  for (int k = 0; k < 8; ++k) std::getline(text, line);
  EXPECT_EQ(line, "ITEM: ATOMS id type x y z radius vx vy fx fy tqz");
  for (std::size_t row = 0; row < f.id.size(); ++row) {
    std::uint64_t id;
    int type;
    double x, y, z, radius;
    text >> id >> type >> x >> y >> z >> radius;
    std::getline(text, line);
    EXPECT_EQ(id, f.id[row]);
    EXPECT_EQ(type, f.type[row]);
    EXPECT_NEAR(x, f.x[row], 1e-8 * std::max(1.0, std::fabs(f.x[row])));
    EXPECT_NEAR(y, f.y[row], 1e-8 * std::max(1.0, std::fabs(f.y[row])));
  }
}

TEST(LammpsDump, ForcesOverAllRowsAddUpToTheGrainsWeight) {
  const World w = touchingWorld();
  const ParticleFrame f = particleFrame(w);
  const ParticleStore& s = w.particles();
  double fx = 0.0, fy = 0.0, scale = 0.0, weight = 0.0;
  int baseTouched = 0, atomsTouched = 0;
  for (std::size_t row = 0; row < f.id.size(); ++row) {
    fx += f.fx[row];
    fy += f.fy[row];
    scale += std::hypot(f.fx[row], f.fy[row]);
    baseTouched += f.type[row] == 2 && f.fy[row] != 0.0;
    atomsTouched += f.type[row] == 3 && std::hypot(f.fx[row], f.fy[row]) > 0.0;
  }
  for (std::uint32_t i = 0; i < s.grainCount; ++i) weight += s.mass[i] * w.def().gravity;
  ASSERT_GT(baseTouched, 0);  // the test means something only if contacts of every kind are there
  ASSERT_GT(atomsTouched, 0);
  EXPECT_NEAR(fx, 0.0, 1e-12 * scale);
  EXPECT_NEAR(fy, -weight, 1e-12 * scale);
}

}  // namespace
}  // namespace wiggle
