// castPostProcess: the analyses of system/castPostProcessDict (castAnalysis/CastAnalysis.h,
// doc/castPostProcess.md) over the written times, each into postProcessing/<name>/, and the
// one-page postProcessing/castReport.md. Without the dictionary: the cloud summary of every cloud.
#include <filesystem>
#include <memory>
#include <utility>

#include "case/CaseDescription.h"
#include "castAnalysis/CastAnalysis.h"
#include "castAnalysis/CastReport.h"
#include "core/CaseFolder.h"
#include "core/CommandLine.h"
#include "core/Error.h"
#include "core/Log.h"
#include "io/TimeFolders.h"

namespace {

// h and the dimension where the case gives them, and the materials of its heat clouds.
void readCaseSetup(const sphcast::CaseDescription& description, sphcast::AnalysisContext& context) {
  context.dimension = description.dimension();
  if (description.hasHeat() ||
      (description.hasSchemes() && description.schemes().found("supportRadius"))) {
    context.supportRadius = description.supportRadius();
  }
  for (const std::string& cloud : description.heatClouds()) {
    context.materials.emplace(cloud, description.heatCloudMaterial(cloud));
  }
}

int castPostProcess(int argc, const char* const argv[]) {
  sphcast::CommandLine args(
      "castPostProcess",
      "Runs the analyses named in system/castPostProcessDict (types: " +
          sphcast::castAnalysisTypes().listed() +
          "; doc/castPostProcess.md) over the written times, each into "
          "postProcessing/<name>/, and writes postProcessing/castReport.md. Without that file: "
          "the cloud summary of every cloud (postProcessing/cloudSummary/<cloud>.csv). With "
          "-time or -latestTime the time series replace or add the rows of those times only.");
  args.options()("latestTime", "only the latest time")(
      "time", boost::program_options::value<std::string>()->value_name("LIST"),
      "times to process: 0.1,0.2 or 0.1:0.5 (ranges), comma-separated");
  if (!args.parse(argc, argv)) return 0;
  const sphcast::CaseFolder caseFolder(args.casePath());
  sphcast::printBanner(args.application(), caseFolder.root().string());

  auto times = caseFolder.times();
  if (args.has("time")) times = sphcast::selectTimes(times, args.get<std::string>("time"));
  if (args.has("latestTime") && !times.empty()) times.erase(times.begin(), times.end() - 1);
  if (times.empty()) {
    throw sphcast::Error("no time folder " +
                         (args.has("time") ? "matches -time " + args.get<std::string>("time")
                                           : std::string("to process")) +
                         " in " + caseFolder.root().string());
  }

  sphcast::AnalysisContext context;
  context.caseRoot = caseFolder.root();
  context.times = times;
  context.allTimes = !args.has("time") && !args.has("latestTime");
  context.clouds = sphcast::timeFolderCloudNames(caseFolder, times.front().name);
  readCaseSetup(sphcast::CaseDescription(caseFolder), context);

  const auto dictFile = caseFolder.systemFile("castPostProcessDict");
  const bool haveDict = std::filesystem::exists(dictFile);
  const sphcast::Dictionary dict =
      haveDict ? sphcast::Dictionary::read(dictFile)
               : sphcast::Dictionary::parse("cloudSummary { type cloudSummary; }",
                                            "castPostProcess's default");
  if (!haveDict) {
    sphcast::info() << "No system/castPostProcessDict: the cloud summary of every cloud\n";
  }
  const auto analyses = sphcast::readCastAnalyses(dict, context);
  sphcast::info() << "Analyses:";
  for (const auto& analysis : analyses) {
    sphcast::info() << ' ' << analysis->name() << " (" << analysis->type() << ')';
  }
  sphcast::info() << "\n\n";

  for (const sphcast::TimeFolder& time : times) {
    sphcast::info() << "Time = " << time.name << '\n';
    const sphcast::WrittenTime written{time, sphcast::readTimeFolderClouds(caseFolder, time.name)};
    for (const auto& analysis : analyses) analysis->add(written);
  }
  sphcast::info() << '\n';
  std::vector<std::pair<const sphcast::CastAnalysis*, sphcast::ReportSection>> sections;
  for (const auto& analysis : analyses) sections.emplace_back(analysis.get(), analysis->finish());
  if (haveDict) {
    std::string command = "castPostProcess";
    for (int k = 1; k < argc; ++k) command += std::string(" ") + argv[k];
    sphcast::writeCastReport(context, command, sections);
  }
  sphcast::info() << "\nEnd\n";
  return 0;
}

}  // namespace

int main(int argc, char* argv[]) {
  return sphcast::runApplication("castPostProcess", castPostProcess, argc, argv);
}
