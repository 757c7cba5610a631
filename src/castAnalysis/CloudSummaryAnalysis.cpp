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
  const auto out = folder();
  for (const auto& [cloudName, csv] : csv_) {
    const auto file = out / (cloudName + ".csv");
    if (!context_.allTimes && std::filesystem::exists(file)) {
      std::ostringstream existing;
      existing << std::ifstream(file).rdbuf();
      writeFileAtomically(file, mergeCloudSummaryCsv(existing.str(), csv));
      info() << "    " << name_ << ": updated " << file.string() << '\n';
    } else {
      writeFileAtomically(file, csv);
      info() << "    " << name_ << ": wrote " << file.string() << '\n';
    }
  }
  ReportSection section;
  section.markdown = "Particle counts, centroids, velocities and bounding boxes by time in " +
                     name_ + "/<cloud>.csv.\n";
  return section;
}

}  // namespace sphcast
