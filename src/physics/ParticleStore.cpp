#include "physics/ParticleStore.h"

#include <numbers>

#include "core/Assert.h"

namespace wiggle {

double particleMass(MassModel model, double density, double radius) {
  if (model == MassModel::Sphere) return density * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  return density * std::numbers::pi * radius * radius;
}

double inertiaCoefficient(MassModel model) { return model == MassModel::Sphere ? 0.4 : 0.5; }

void ParticleStore::append(double px, double py, double pvx, double pvy, double pomega,
                           double pradius, double pmass, double pinvMass, double pinvInertia,
                           std::uint32_t ptag) {
  x.push_back(px);
  y.push_back(py);
  vx.push_back(pvx);
  vy.push_back(pvy);
  omega.push_back(pomega);
  fx.push_back(0.0);
  fy.push_back(0.0);
  torque.push_back(0.0);
  radius.push_back(pradius);
  invMass.push_back(pinvMass);
  invInertia.push_back(pinvInertia);
  mass.push_back(pmass);
  tag.push_back(ptag);
}

namespace {
template <class T>
void applyOrder(std::vector<T>& values, const std::vector<std::uint32_t>& order) {
  std::vector<T> result(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) result[k] = values[order[k]];
  values.swap(result);
}
}  // namespace

void ParticleStore::permute(const std::vector<std::uint32_t>& order) {
  WIGGLE_ASSERT(order.size() <= x.size());
  forEachArray([&order](auto& values, Hashed) { applyOrder(values, order); });
}

}  // namespace wiggle
