#pragma once
// Grains and frozen base particles, one array per property (struct of arrays).
//
// Layout: indices [0, grainCount) are mobile grains, [grainCount, size()) frozen base particles.
// The grain range is re-sorted spatially for locality; `tag` keeps each particle's stable id.
// Units: lengths in d, time in sqrt(d/g), mass in rho d^3 (sphere model) or rho d^2 (disc).
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "core/Choice.h"

namespace wiggle {

enum class MassModel : std::uint8_t { Sphere, Disc };  // grains.mass_model
template <>
struct ChoiceNames<MassModel> {
  static constexpr std::array<std::string_view, 2> names{"sphere", "disc"};
};

// Mass and rotational inertia coefficient of a grain of radius r and density rho (docs/PHYSICS.md §3).
double particleMass(MassModel model, double density, double radius);
double inertiaCoefficient(MassModel model);  // I = c m r^2: 2/5 sphere, 1/2 disc

struct ParticleStore {
  // Hot, read and written every step.
  std::vector<double> x, y;      // centre [d]; x wrapped into [0, W) at each neighbour rebuild
  std::vector<double> vx, vy;    // velocity [sqrt(g d)]
  std::vector<double> omega;     // spin about z [sqrt(g/d)]
  std::vector<double> fx, fy;    // total force, contacts plus gravity [m g]
  std::vector<double> torque;    // torque about z [m g d]
  std::vector<double> radius;    // [d]
  std::vector<double> invMass;   // 1 / mass; 0 for frozen particles (infinite mass in meff)
  std::vector<double> invInertia;  // 1 / (c m r^2); 0 for frozen particles
  // Cold.
  std::vector<double> mass;      // [rho d^3]; frozen particles keep their nominal mass here
  std::vector<std::uint32_t> tag;  // stable id, unique, survives re-sorting

  std::uint32_t grainCount = 0;

  std::uint32_t size() const { return static_cast<std::uint32_t>(x.size()); }
  std::uint32_t baseCount() const { return size() - grainCount; }

  // Appends a particle at the end; the caller keeps the grains-then-base order.
  void append(double px, double py, double pvx, double pvy, double pomega, double pradius,
              double pmass, double pinvMass, double pinvInertia, std::uint32_t ptag);
  // Reorders all arrays: new index k holds old particle order[k] (order is a permutation).
  void permute(const std::vector<std::uint32_t>& order);

  // Whether an array enters the state hash: the dynamic state and the radii do; the masses, which
  // follow from the radii, do not (World::stateHash).
  enum class Hashed : bool { No, Yes };
  // Every per-particle array, in one fixed order (the state file's): visit(array, hashed). Saving,
  // loading, re-sorting, the state hash and the byte count all go through it, so an array added
  // here is saved, loaded, re-sorted, hashed and counted with no other list to keep in step (only
  // append, which gives each array its value, names them again).
  template <class Visit>
  void forEachArray(Visit&& visit) {
    forEachArrayOf(*this, visit);
  }
  template <class Visit>
  void forEachArray(Visit&& visit) const {
    forEachArrayOf(*this, visit);
  }

 private:
  template <class Store, class Visit>
  static void forEachArrayOf(Store& s, Visit& visit) {
    for (auto* v : {&s.x, &s.y, &s.vx, &s.vy, &s.omega, &s.fx, &s.fy, &s.torque, &s.radius}) visit(*v, Hashed::Yes);
    for (auto* v : {&s.invMass, &s.invInertia, &s.mass}) visit(*v, Hashed::No);
    visit(s.tag, Hashed::Yes);
  }
};

}  // namespace wiggle
