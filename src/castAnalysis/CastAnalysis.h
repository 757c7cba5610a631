#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/CaseFolder.h"
#include "core/Real.h"
#include "core/Registry.h"
#include "core/dictionary/Dictionary.h"
#include "materials/Material.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

// castPostProcess's analyses (doc/castPostProcess.md). system/castPostProcessDict names each
// one, OpenFOAM style; only the entries written there run:
//
//   cooling   { type timeSeries; }                      // every cloud of the case
//   TC        { type thermocouples; cloud metal; locations { centre (0 0 0.03); } }
//   maps      { type solidificationMaps; cloud metal; }
//
// Each writes to postProcessing/<name>/ and gives a section of the case's report,
// postProcessing/castReport.md, which castPostProcess writes (CastReport.h).
// They see the selected time folders one at a time, in time order, so memory holds one time
// (plus what an analysis keeps per particle), whatever the number of writes.

// One written time and the clouds stored in it.
struct WrittenTime {
  TimeFolder folder;
  std::vector<ParticleCloud> clouds;
  // nullptr when the time has no such cloud
  const ParticleCloud* find(const std::string& cloudName) const;
};

// What an analysis may know of the case besides its own entry.
struct AnalysisContext {
  std::filesystem::path caseRoot;
  std::vector<TimeFolder> times;    // selected, ascending
  bool allTimes = true;             // false under -time / -latestTime
  std::vector<std::string> clouds;  // the clouds of the first selected time
  Real supportRadius = 0;           // h of system/sphSchemes (0 when the case has none)
  int dimension = 3;
  std::map<std::string, Material> materials;  // of the heat clouds (constant/physicsModels)
};

// What an analysis adds to the case's report (CastReport.h): markdown, and PNGs relative to
// postProcessing/.
struct ReportSection {
  std::string markdown;
  std::vector<std::string> images;
};

class CastAnalysis {
 public:
  virtual ~CastAnalysis() = default;
  CastAnalysis(const CastAnalysis&) = delete;
  CastAnalysis& operator=(const CastAnalysis&) = delete;

  const std::string& name() const { return name_; }
  const std::string& type() const { return type_; }

  // Called once per selected time, in time order.
  virtual void add(const WrittenTime& time) = 0;
  // After the last time: writes the results and returns the report's section.
  virtual ReportSection finish() = 0;

 protected:
  // Checks the entry's keys against `keys` (plus type); errors name file, line and key.
  CastAnalysis(const std::string& name, const Dictionary& dict, const AnalysisContext& context,
               const std::vector<std::string>& keys);

  // postProcessing/<name>/, created on first use.
  std::filesystem::path folder() const;
  // Writes a CSV of rows by time (first column) to postProcessing/<name>/<fileName>: whole when
  // every time was processed, else merged into the file's rows (the selected times' replaced or
  // added, the others kept: post/CloudSummary.h's mergeCloudSummaryCsv).
  void writeRowsByTime(const std::string& fileName, const std::string& csv) const;
  // The entry's `cloud`, which must be a cloud of the case (an error at the key otherwise).
  std::string readCloud(const std::string& key = "cloud") const;
  // The material of a cloud, or an error at `key` naming what needs it.
  const Material& materialOf(const std::string& cloud, const std::string& neededBy) const;
  // A cloud of the time, or else of constant/particles (a mold that the solver does not write
  // into the time folders; read once); nullptr when neither has it.
  const ParticleCloud* cloudAt(const WrittenTime& time, const std::string& cloudName);
  // The clouds of the time and those of constant/particles that it lacks, sorted.
  std::vector<std::string> cloudsAt(const WrittenTime& time) const;
  // The clouds of constant/particles (the molds particleizeMold wrote), sorted.
  std::vector<std::string> constantCloudNames() const;
  // The entry's `range (low high)` of a picture's colours: false without one; an error at the
  // key unless low < high.
  bool readRange(double& low, double& high) const;
  // The entry's `times latest|all` (true: all) and `show (t1 t2 ...)`, the times whose pictures
  // the report shows, which needs `times all` (an error at the key otherwise).
  bool readPictureTimes(std::vector<double>& show) const;
  // The pictures a report shows of those drawn at `drawnTimes` (ascending, not empty): the one
  // nearest each time of `show`, once each, then the last.
  static std::vector<std::size_t> shownPictures(const std::vector<double>& drawnTimes,
                                                const std::vector<double>& show);

  std::string name_;
  std::string type_;
  Dictionary dict_;
  const AnalysisContext& context_;

 private:
  std::map<std::string, ParticleCloud> constantClouds_;
};

// The analyses of castPostProcessDict in file order. An entry that is not a sub-dictionary, an
// unknown type, an unknown key or a bad value: DictionaryError naming file, line and key.
std::vector<std::unique_ptr<CastAnalysis>> readCastAnalyses(const Dictionary& dict,
                                                            const AnalysisContext& context);

// A number for a report or a CSV, printf's %.<digits>g ("nan" where not finite), and a point
// as "(x y z) m" with 4 digits each.
std::string formatNumber(double value, int digits);
std::string formatPoint(const Vector& x);
// " (K)" for T, " (s)" for a ...Time field, ...: the unit a picture's colour bar names ("" where
// sphCast does not know it).
std::string fieldUnit(const std::string& field);

// The analyses by the type names castPostProcessDict gives them, each built from its name, its
// sub-dictionary and the context; registered in CastAnalysis.cpp (castPostProcess -help lists
// them).
using CastAnalysisTypes =
    Registry<CastAnalysis, const std::string&, const Dictionary&, const AnalysisContext&>;
CastAnalysisTypes& castAnalysisTypes();

}  // namespace sphcast
