#include "geometry/InitialDensity.h"

#include <algorithm>
#include <limits>

namespace sphcast {

std::vector<double> depthsBelowFreeSurface(const std::vector<Vector>& positions,
                                           const Vector& gravity, double spacing) {
  std::vector<double> depths(positions.size(), 0.0);
  const double gravityMagnitude = gravity.cast<double>().norm();
  if (gravityMagnitude == 0.0 || positions.empty()) return depths;
  const Eigen::Vector3d up = -gravity.cast<double>() / gravityMagnitude;
  double highest = -std::numeric_limits<double>::infinity();
  for (const Vector& x : positions) highest = std::max(highest, up.dot(x.cast<double>()));
  const double surface = highest + 0.5 * spacing;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    depths[i] = surface - up.dot(positions[i].cast<double>());
  }
  return depths;
}

}  // namespace sphcast
