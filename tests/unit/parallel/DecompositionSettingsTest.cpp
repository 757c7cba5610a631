// system/decomposeParDict: the settings read as written, and every mistake a user makes named
// with the file, the line and the key.
#include "parallel/DecompositionSettings.h"

#include <gtest/gtest.h>

#include <string>

#include "core/Error.h"
#include "support/TemporaryCase.h"

namespace sphcast {
namespace {

const std::string header =
    "FoamFile { version 2.0; format ascii; class dictionary; "
    "object decomposeParDict; }\n";

// The message of the Error reading the dictionary throws ("" when it reads).
std::string errorOf(const std::string& body, int ranks) {
  testing::TemporaryCase dir;
  dir.write("system/decomposeParDict", header + body);
  try {
    readDecompositionSettings(CaseFolder(dir.root()), ranks);
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

TEST(DecompositionSettingsTest, ReadsTheSubdomainsTheMethodAndTheImbalance) {
  testing::TemporaryCase dir;
  dir.write("system/decomposeParDict",
            header + "numberOfSubdomains 4;\nmethod recursiveBisection;\nmaxImbalance 0.2;\n");
  const auto settings = readDecompositionSettings(CaseFolder(dir.root()), 4);
  EXPECT_EQ(settings.subdomains, 4);
  EXPECT_EQ(settings.method, "recursiveBisection");
  EXPECT_DOUBLE_EQ(settings.maxImbalance, 0.2);
  EXPECT_EQ(settings.subdomainsAt.line, 2);
}

TEST(DecompositionSettingsTest, MistakesNameTheFileTheLineAndTheKey) {
  const std::string good = "numberOfSubdomains 2;\nmethod recursiveBisection;\n";
  EXPECT_EQ(errorOf(good, 2), "");
  const std::string ranks = errorOf(good, 4);
  EXPECT_NE(ranks.find("decomposeParDict:2"), std::string::npos) << ranks;
  EXPECT_NE(ranks.find("mpirun started 4 ranks"), std::string::npos) << ranks;
  const std::string method = errorOf("numberOfSubdomains 2;\nmethod scotch;\n", 2);
  EXPECT_NE(method.find("decomposeParDict:3"), std::string::npos) << method;
  EXPECT_NE(method.find("recursiveBisection"), std::string::npos) << method;
  const std::string key = errorOf(good + "maxImbalanse 0.1;\n", 2);
  EXPECT_NE(key.find("maxImbalanse"), std::string::npos) << key;
  EXPECT_NE(key.find("maxImbalance"), std::string::npos) << key;  // the suggestion
  EXPECT_NE(errorOf("numberOfSubdomains 0;\nmethod recursiveBisection;\n", 1)
                .find("numberOfSubdomains 0"),
            std::string::npos);
  EXPECT_NE(errorOf("numberOfSubdomains two;\nmethod recursiveBisection;\n", 2)
                .find("numberOfSubdomains"),
            std::string::npos);
  EXPECT_NE(errorOf(good + "maxImbalance -1;\n", 2).find("maxImbalance"), std::string::npos);
  EXPECT_NE(errorOf("method recursiveBisection;\n", 2).find("numberOfSubdomains"),
            std::string::npos);
}

TEST(DecompositionSettingsTest, AMissingDictionarySaysWhatToWrite) {
  testing::TemporaryCase dir;
  try {
    readDecompositionSettings(CaseFolder(dir.root()), 2);
    FAIL() << "no error";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("system/decomposeParDict"), std::string::npos) << message;
    EXPECT_NE(message.find("numberOfSubdomains 2"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace sphcast
