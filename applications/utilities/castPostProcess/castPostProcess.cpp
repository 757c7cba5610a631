// castPostProcess: analyses of the written times. For now the cloud summary (particle count,
// centroid, mean velocity, top speed, bounding box per cloud and time) as CSV; the casting maps
// (solidification time, Niyama, cavities) join as their physics lands.
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/AtomicFile.h"
#include "core/CaseFolder.h"
#include "core/CommandLine.h"
#include "core/Error.h"
#include "core/Log.h"
#include "io/TimeFolders.h"
#include "post/CloudSummary.h"

namespace {

int castPostProcess(int argc, const char* const argv[]) {
  sphcast::CommandLine args(
      "castPostProcess",
      "Writes postProcessing/cloudSummary/<cloud>.csv: per written time, the particle count, "
      "centroid, mean velocity, maximum speed and bounding box of every cloud. With -time or "
      "-latestTime only the rows of those times are replaced or added; the others stay.");
  args.options()("latestTime", "only the latest time")(
      "time", boost::program_options::value<std::string>()->value_name("LIST"),
      "times to process: 0.1,0.2 or 0.1:0.5 (ranges), comma-separated");
  if (!args.parse(argc, argv)) return 0;
  const sphcast::CaseFolder caseFolder(args.casePath());
  sphcast::printBanner(args.application(), caseFolder.root().string());

  auto times = caseFolder.times();
  if (args.has("time")) times = sphcast::selectTimes(times, args.get<std::string>("time"));
  if (args.has("latestTime") && !times.empty()) times.erase(times.begin(), times.end() - 1);
  if (times.empty()) throw sphcast::Error("no time folder selected in " + caseFolder.root().string());

  std::map<std::string, std::string> csvByCloud;
  for (const sphcast::TimeFolder& time : times) {
    sphcast::info() << "Time = " << time.name << '\n';
    for (const auto& cloud : sphcast::readTimeFolderClouds(caseFolder, time.name)) {
      std::string& csv = csvByCloud[cloud.name()];
      if (csv.empty()) csv = sphcast::cloudSummaryCsvHeader();
      csv += sphcast::cloudSummaryCsvRow(time.value, sphcast::summarize(cloud));
    }
  }
  const auto folder = caseFolder.root() / "postProcessing" / "cloudSummary";
  std::filesystem::create_directories(folder);
  // All times: the files are written afresh. Some times: merged into the rows already there.
  const bool someTimes = args.has("time") || args.has("latestTime");
  for (const auto& [cloudName, csv] : csvByCloud) {
    const auto file = folder / (cloudName + ".csv");
    if (someTimes && std::filesystem::exists(file)) {
      std::ostringstream existing;
      existing << std::ifstream(file).rdbuf();
      sphcast::writeFileAtomically(file, sphcast::mergeCloudSummaryCsv(existing.str(), csv));
      sphcast::info() << "Updated " << file.string() << '\n';
    } else {
      sphcast::writeFileAtomically(file, csv);
      sphcast::info() << "Wrote " << file.string() << '\n';
    }
  }
  sphcast::info() << "\nEnd\n";
  return 0;
}

}  // namespace

int main(int argc, char* argv[]) {
  return sphcast::runApplication("castPostProcess", castPostProcess, argc, argv);
}
