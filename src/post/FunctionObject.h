#pragma once

#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/Real.h"
#include "core/Registry.h"
#include "core/TimeControl.h"
#include "core/dictionary/Dictionary.h"
#include "parallel/Communicator.h"
#include "particles/ParticleCloud.h"

namespace sphcast {

class RigidBody;

// What a function object may look at, handed over by the solver once the clouds are set up.
struct FunctionObjectContext {
  std::filesystem::path caseRoot;
  std::string startTimeName;  // output goes to postProcessing/<name>/<startTimeName>/
  double startTime = 0;       // its exact value
  Real supportRadius = 0;     // h of the flow (0 without one: a probe must then say)
  Vector gravity = Vector::Zero();
  std::vector<const ParticleCloud*> clouds;  // that the run steps; addresses stay valid
  std::vector<const RigidBody*> bodies;      // of constant/dynamicBodies (every rank holds all)
  // A decomposed run's ranks: each samples its own particles, rank 0 writes the rows.
  Communicator comm = Communicator::self();
};

// A function object of system/controlDict's `functions` dictionary, as in OpenFOAM:
//
//   functions
//   {
//       P1 { type probes; cloud water; fields (p); probeLocations ((2.4 0.5 0.02));
//            writeControl timeStep; writeInterval 1; }
//   }
//
// Each samples one cloud after the steps its writeControl picks (timeStep: every writeInterval
// steps, counted by the time index; writeTime: when the case writes; runTime: every
// writeInterval seconds), and at the start time where the uninterrupted run samples it too
// (time 0 always), and appends a row `time value...` to
// postProcessing/<name>/<startTime>/<file>, after a header whose first line is
// `# startTime <exact value>`. A run restarted from time T writes a new folder T, as OpenFOAM
// does, and leaves the old one as it was: to join them, take each folder's rows before the next
// folder's startTime (readFunctionObjectSeries does this); the result is the uninterrupted
// run's rows. A run started again from the same time replaces that folder's files.
class FunctionObject {
 public:
  virtual ~FunctionObject() = default;
  FunctionObject(const FunctionObject&) = delete;
  FunctionObject& operator=(const FunctionObject&) = delete;

  const std::string& name() const { return name_; }

  // Samples and writes a row when the writeControl asks for this time.
  void execute(const TimeState& time, bool caseWriteTime);

 protected:
  // Reads the keys every function object has (type, cloud, writeControl, writeInterval) and
  // checks the cloud exists; extraKeys are the type's own, for the unknown-key check. A type
  // that spans several clouds (Clouds::many) reads its own `clouds` instead of `cloud`.
  enum class Clouds { one, many };
  FunctionObject(const std::string& name, const Dictionary& dict,
                 const FunctionObjectContext& context, const std::vector<std::string>& extraKeys,
                 Clouds clouds = Clouds::one);

  const ParticleCloud& cloud() const { return *cloud_; }
  const Communicator& communicator() const { return comm_; }

  // The output file postProcessing/<name>/<startTime>/<fileName>, opened (replaced) on first
  // use, with the header lines given.
  std::ofstream& openOutput(const std::string& fileName, const std::string& header);
  // Writes the row and flushes it, so a killed run keeps every row it sampled.
  static void writeRow(std::ofstream& file, double time, const std::string& values);

  virtual void sample(double time) = 0;

  std::filesystem::path outputFolder_;  // postProcessing/<name>/<startTime>

 private:
  enum class Control { timeStep, writeTime, runTime };
  void readWriteControl(const Dictionary& dict);
  bool wanted(const TimeState& time, bool caseWriteTime);

  std::string name_;
  Communicator comm_;
  double startTime_ = 0;
  const ParticleCloud* cloud_ = nullptr;
  Control control_ = Control::timeStep;
  double interval_ = 1;
  bool started_ = false;
  long lastRunTimeIndex_ = 0;
  std::map<std::string, std::unique_ptr<std::ofstream>> files_;
};

// Formats a value for a row: 10 significant digits, "nan" where no fluid was within reach.
std::string formatSample(double value);
std::string formatSample(const Vector& value);  // "(x y z)"

// The function objects by the type names controlDict's `functions` give them, each built from
// its name, its sub-dictionary and the run's context; registered in FunctionObject.cpp.
using FunctionObjectTypes =
    Registry<FunctionObject, const std::string&, const Dictionary&, const FunctionObjectContext&>;
FunctionObjectTypes& functionObjectTypes();

// Every object of controlDict's `functions`, built in file order, in one list.
class FunctionObjectList {
 public:
  FunctionObjectList() = default;
  // Types: those of functionObjectTypes(). An unknown type (listing the valid ones), a missing or
  // unknown cloud or field, a bad location: DictionaryError naming file, line and key. In a
  // decomposed run (context.comm of more than one rank) each sums over the ranks.
  FunctionObjectList(const Dictionary& controlDict, const FunctionObjectContext& context);

  // One more, after those of controlDict (the solver's bodies' history).
  void add(std::unique_ptr<FunctionObject> object) { objects_.push_back(std::move(object)); }

  void execute(const TimeState& time, bool caseWriteTime);
  std::size_t size() const { return objects_.size(); }
  const std::vector<std::unique_ptr<FunctionObject>>& objects() const { return objects_; }

 private:
  std::vector<std::unique_ptr<FunctionObject>> objects_;
};

// One output file of a function object over a whole run, restarts joined: the rows of every
// postProcessing/<name>/<startTime>/<fileName>, each folder's rows taken before the next
// folder's startTime (its header's exact value). Rows are the whitespace-separated numbers of a
// line ('#' lines skipped); an unfinished last line (a killed run) is left out.
std::vector<std::vector<double>> readFunctionObjectSeries(const std::filesystem::path& caseRoot,
                                                          const std::string& name,
                                                          const std::string& fileName);

}  // namespace sphcast
