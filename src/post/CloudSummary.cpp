#include "post/CloudSummary.h"
#include "particles/FieldNames.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <utility>
#include <vector>

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
  if (cloud.hasVectorField(field::U)) {
    Eigen::Vector3d velocitySum = Eigen::Vector3d::Zero();
    for (const Vector& u : cloud.vectorField(field::U)) {
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
                double(s.lower.z()), double(s.upper.x()), double(s.upper.y()), double(s.upper.z()));
  return row;
}

namespace {

struct CsvRow {
  double time;
  std::string text;  // with its newline
};

// The header line and the rows of a CSV written by cloudSummaryCsvHeader and cloudSummaryCsvRow.
std::pair<std::string, std::vector<CsvRow>> splitCsv(const std::string& csv) {
  std::istringstream lines(csv);
  std::string header;
  std::getline(lines, header);
  std::vector<CsvRow> rows;
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty()) rows.push_back({std::strtod(line.c_str(), nullptr), line + '\n'});
  }
  return {header, rows};
}

}  // namespace

std::string mergeCloudSummaryCsv(const std::string& existing, const std::string& updated) {
  auto [header, rows] = splitCsv(updated);
  const auto [oldHeader, oldRows] = splitCsv(existing);
  if (oldHeader == header) {
    for (const CsvRow& row : oldRows) {
      const bool replaced = std::any_of(
          rows.begin(), rows.end(), [&](const CsvRow& fresh) { return fresh.time == row.time; });
      if (!replaced) rows.push_back(row);
    }
  }
  std::stable_sort(rows.begin(), rows.end(),
                   [](const CsvRow& a, const CsvRow& b) { return a.time < b.time; });
  std::string csv = header + '\n';
  for (const CsvRow& row : rows) csv += row.text;
  return csv;
}

}  // namespace sphcast
