#pragma once

#include <string>

#include "core/Real.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// One line of postProcessing/cloudSummary/<cloud>.csv: the bulk motion of a cloud at one time.
struct CloudSummary {
  std::size_t particles = 0;
  Vector centroid = Vector::Zero();  // mean particle position (centre of mass for equal masses)
  Vector meanVelocity = Vector::Zero();
  double maxSpeed = 0.0;
  Vector lower = Vector::Zero();  // bounding box
  Vector upper = Vector::Zero();
};

CloudSummary summarize(const ParticleCloud& cloud);

// "time,particles,centroidX,...": the CSV header and one row, full precision.
std::string cloudSummaryCsvHeader();
std::string cloudSummaryCsvRow(double time, const CloudSummary& summary);

}  // namespace sphcast
