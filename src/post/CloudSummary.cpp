#include "post/CloudSummary.h"

#include <algorithm>
#include <cstdio>

namespace sphcast {

CloudSummary summarize(const ParticleCloud& cloud) {
  CloudSummary summary;
  summary.particles = cloud.size();
  if (cloud.size() == 0) return summary;
  const auto& position = cloud.positions();
  summary.lower = summary.upper = position.front();
  // Sums in double whatever Real is: a centroid of 10^6 particles must not lose digits.
  Eigen::Vector3d positionSum = Eigen::Vector3d::Zero();
  for (const Vector& x : position) {
    positionSum += x.cast<double>();
    summary.lower = summary.lower.cwiseMin(x);
    summary.upper = summary.upper.cwiseMax(x);
  }
  const double count = static_cast<double>(cloud.size());
  summary.centroid = (positionSum / count).cast<Real>();
  if (cloud.hasVectorField("U")) {
    Eigen::Vector3d velocitySum = Eigen::Vector3d::Zero();
    for (const Vector& u : cloud.vectorField("U")) {
      velocitySum += u.cast<double>();
      summary.maxSpeed = std::max(summary.maxSpeed, static_cast<double>(u.norm()));
    }
    summary.meanVelocity = (velocitySum / count).cast<Real>();
  }
  return summary;
}

std::string cloudSummaryCsvHeader() {
  return "time,particles,centroidX,centroidY,centroidZ,meanUx,meanUy,meanUz,maxSpeed,"
         "minX,minY,minZ,maxX,maxY,maxZ\n";
}

std::string cloudSummaryCsvRow(double time, const CloudSummary& s) {
  char row[512];
  std::snprintf(row, sizeof row,
                "%.17g,%zu,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,"
                "%.17g,%.17g\n",
                time, s.particles, double(s.centroid.x()), double(s.centroid.y()),
                double(s.centroid.z()), double(s.meanVelocity.x()), double(s.meanVelocity.y()),
                double(s.meanVelocity.z()), s.maxSpeed, double(s.lower.x()), double(s.lower.y()),
                double(s.lower.z()), double(s.upper.x()), double(s.upper.y()),
                double(s.upper.z()));
  return row;
}

}  // namespace sphcast
