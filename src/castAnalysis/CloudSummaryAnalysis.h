#pragma once

#include <map>
#include <string>
#include <vector>

#include "castAnalysis/CastAnalysis.h"

namespace sphcast {

// type cloudSummary: per cloud and written time, the particle count, centroid, mean velocity,
// largest speed and bounding box (post/CloudSummary.h), in postProcessing/<name>/<cloud>.csv;
// under -time / -latestTime the rows of those times are replaced or added. Without a
// castPostProcessDict castPostProcess runs this alone, as `cloudSummary`, on every cloud.
// Keys: clouds (optional; every cloud by default).
class CloudSummaryAnalysis : public CastAnalysis {
 public:
  CloudSummaryAnalysis(const std::string& name, const Dictionary& dict,
                       const AnalysisContext& context);

  void add(const WrittenTime& time) override;
  ReportSection finish() override;

 private:
  std::vector<std::string> clouds_;
  std::map<std::string, std::string> csv_;
};

}  // namespace sphcast
