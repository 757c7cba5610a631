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

// The CSV `existing` updated by the CSV `updated` (both a header and rows, as written above):
// rows at the times of `updated` replace those at the same times, the other rows stay, all in
// time order. castPostProcess -time/-latestTime thus updates the times it processed only. An
// `existing` with another header (an older format) is replaced whole.
std::string mergeCloudSummaryCsv(const std::string& existing, const std::string& updated);

}  // namespace sphcast
