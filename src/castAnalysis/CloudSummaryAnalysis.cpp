#include "castAnalysis/CloudSummaryAnalysis.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "core/AtomicFile.h"
#include "core/Log.h"
#include "post/CloudSummary.h"

namespace sphcast {

CloudSummaryAnalysis::CloudSummaryAnalysis(const std::string& name, const Dictionary& dict,
                                           const AnalysisContext& context)
    : CastAnalysis(name, dict, context, {"clouds"}),
      clouds_(dict.getOrDefault<std::vector<std::string>>("clouds", context.clouds)) {}

void CloudSummaryAnalysis::add(const WrittenTime& time) {
  for (const ParticleCloud& cloud : time.clouds) {
    if (std::find(clouds_.begin(), clouds_.end(), cloud.name()) == clouds_.end()) continue;
    std::string& csv = csv_[cloud.name()];
    if (csv.empty()) csv = cloudSummaryCsvHeader();
    csv += cloudSummaryCsvRow(time.folder.value, summarize(cloud));
  }
}

ReportSection CloudSummaryAnalysis::finish() {
  for (const auto& [cloudName, csv] : csv_) writeRowsByTime(cloudName + ".csv", csv);
  ReportSection section;
  section.markdown = "Particle counts, centroids, velocities and bounding boxes by time in " +
                     name_ + "/<cloud>.csv.\n";
  return section;
}

}  // namespace sphcast
