// The families' registries (core/Registry.h): a model added through the registry alone is built
// from its dictionary entry; an unknown name is an error listing the valid ones; every
// registered name is documented (doc/design.md §3 "Adding a model"; castPostProcess's -help
// lists its registry: castPostProcessUpdatesOnlyTheSelectedTimes.sh).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "castAnalysis/CastAnalysis.h"
#include "core/Error.h"
#include "core/Registry.h"
#include "core/dictionary/Dictionary.h"
#include "particles/ParticleCloud.h"
#include "post/FunctionObject.h"
#include "rheology/RheologyModel.h"
#include "support/TemporaryCase.h"
#include "surface/SurfaceTensionModel.h"
#include "thermal/HeatTransferRegistration.h"

namespace sphcast {
namespace {

// A function object of a test build: counts its samples.
class CountingObject : public FunctionObject {
 public:
  CountingObject(const std::string& name, const Dictionary& dict,
                 const FunctionObjectContext& context)
      : FunctionObject(name, dict, context, {}) {}
  static int samples;

 protected:
  void sample(double) override { ++samples; }
};
int CountingObject::samples = 0;

TEST(ModelRegistry, AModelAddedThroughTheRegistryAloneIsBuiltFromItsEntry) {
  if (!functionObjectTypes().has("countSamples")) {
    functionObjectTypes().add<CountingObject>("countSamples");
  }
  const testing::TemporaryCase folder;
  ParticleCloud water("water");
  water.resize(3);
  FunctionObjectContext context;
  context.caseRoot = folder.root();
  context.clouds = {&water};
  const Dictionary controlDict = Dictionary::parse(
      "functions { counter { type countSamples; cloud water; writeControl timeStep; "
      "writeInterval 1; } }",
      "controlDict");
  FunctionObjectList functions(controlDict, context);
  ASSERT_EQ(functions.size(), 1u);
  CountingObject::samples = 0;
  TimeState time;
  functions.execute(time, false);
  EXPECT_EQ(CountingObject::samples, 1);
}

TEST(ModelRegistry, AnUnknownNameIsAnErrorAtItsEntryListingTheValidOnes) {
  const Dictionary controlDict =
      Dictionary::parse("functions\n{\n  p { type probs; cloud water; }\n}\n", "controlDict");
  try {
    FunctionObjectList(controlDict, FunctionObjectContext{});
    FAIL() << "an unknown type accepted";
  } catch (const DictionaryError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("controlDict:3:"), std::string::npos) << message;
    EXPECT_NE(message.find("did you mean 'probes'"), std::string::npos) << message;
    for (const std::string& name : functionObjectTypes().names()) {
      EXPECT_NE(message.find(name), std::string::npos) << name << " not listed: " << message;
    }
  }
  Registry<FunctionObject, const std::string&, const Dictionary&, const FunctionObjectContext&>
      family("function object");
  family.add<CountingObject>("countSamples");
  EXPECT_THROW(family.add<CountingObject>("countSamples"), Error);  // twice
  EXPECT_EQ(family.listed(), "countSamples");
}

std::string documentText(const std::string& relative) {
  std::ifstream file(std::filesystem::path(SPHCAST_SOURCE_DIR) / relative);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

// Every registered name of a family appears, as a word, on the family's page of doc/.
void expectDocumented(const std::vector<std::string>& names, const std::string& page) {
  const std::string text = documentText(page);
  ASSERT_FALSE(text.empty()) << page;
  for (const std::string& name : names) {
    EXPECT_TRUE(std::regex_search(text, std::regex("\\b" + name + "\\b")))
        << "'" << name << "' is registered but not in " << page;
  }
}

TEST(ModelRegistry, EveryRegisteredNameIsDocumented) {
  expectDocumented(castAnalysisTypes().names(), "doc/castPostProcess.md");
  std::vector<std::string> functionObjects = functionObjectTypes().names();
  std::erase(functionObjects, "countSamples");  // the test build's own, when registered
  expectDocumented(functionObjects, "doc/design.md");
  expectDocumented(surfaceTensionModels().names(), "doc/physics.md");
  expectDocumented(heatTransferPaths().names(), "doc/physics.md");
  expectDocumented(rheologyModels().names(), "doc/physics.md");
}

}  // namespace
}  // namespace sphcast
