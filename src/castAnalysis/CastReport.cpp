#include "castAnalysis/CastReport.h"

#include <sstream>

#include "core/AtomicFile.h"
#include "core/Log.h"

namespace sphcast {

void writeCastReport(const AnalysisContext& context, const std::string& command,
                     const std::vector<std::pair<const CastAnalysis*, ReportSection>>& sections) {
  std::ostringstream page;
  page << "# Casting report: " << context.caseRoot.filename().string() << "\n\n"
       << "Case `" << context.caseRoot.string() << "`; " << context.times.size()
       << " written time(s) from " << context.times.front().name << " to "
       << context.times.back().name << " s" << (context.allTimes ? "" : " (a selection)")
       << "; written by `" << command << "`.\n";
  for (const auto& [analysis, section] : sections) {
    page << "\n## " << analysis->name() << " (" << analysis->type() << ")\n\n" << section.markdown;
    for (const std::string& image : section.images) {
      page << "\n![" << image << "](" << image << ")\n";
    }
  }
  const auto file = context.caseRoot / "postProcessing" / "castReport.md";
  std::filesystem::create_directories(file.parent_path());
  writeFileAtomically(file, page.str());
  info() << "Wrote " << file.string() << '\n';
}

}  // namespace sphcast
