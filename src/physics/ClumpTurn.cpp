#include "physics/ClumpTurn.h"

#include <algorithm>
#include <cmath>

namespace wiggle {

void turnedOffsets(const std::vector<double>& bodyX, const std::vector<double>& bodyY, double angle,
                   std::vector<double>& x, std::vector<double>& y) {
  const double c = std::cos(angle), s = std::sin(angle);
  x.resize(bodyX.size());
  y.resize(bodyY.size());
  for (std::size_t a = 0; a < bodyX.size(); ++a) {
    x[a] = c * bodyX[a] - s * bodyY[a];
    y[a] = s * bodyX[a] + c * bodyY[a];
  }
}

double clumpContactTorque(const ClumpDef& clump, const IntruderPairs& pairs) {
  double torque = 0.0;
  for (std::uint32_t p = 0; p < pairs.size(); ++p) {
    const std::uint32_t a = pairs.atom[p];
    // forceX/Y are the grain's; the atom gets their opposite.
    torque += clump.offsetY[a] * pairs.forceX[p] - clump.offsetX[a] * pairs.forceY[p] -
              clump.atomRadius * pairs.torqueArm[p];
  }
  return torque;
}

double clumpReach(const ClumpDef& clump) {
  double reach = 0.0;
  for (std::size_t a = 0; a < clump.offsetX.size(); ++a)
    reach = std::max(reach, std::hypot(clump.offsetX[a], clump.offsetY[a]));
  return reach;
}

}  // namespace wiggle
