#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "castAnalysis/CastAnalysis.h"

namespace sphcast {

// postProcessing/castReport.md: one page a casting engineer reads first. A header (the case,
// the times processed, the command), then each analysis' section in castPostProcessDict order
// under its name and type, with its pictures. Written whole at every castPostProcess run.
void writeCastReport(const AnalysisContext& context, const std::string& command,
                     const std::vector<std::pair<const CastAnalysis*, ReportSection>>& sections);

}  // namespace sphcast
