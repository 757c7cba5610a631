// system/decomposeParDict: the settings read as written, and every mistake a user makes named
// with the file, the line and the key.
#include "parallel/DecompositionSettings.h"

#include <gtest/gtest.h>

#include <array>
#include <string>

#include "core/Error.h"
#include "support/TemporaryCase.h"

namespace sphcast {
namespace {

const std::string header =
    "FoamFile { version 2.0; format ascii; class dictionary; "
    "object decomposeParDict; }\n";

// The message of the Error reading the dictionary throws ("" when it reads).
std::string errorOf(const std::string& body, int ranks, int dimension = 3) {
  testing::TemporaryCase dir;
  dir.write("system/decomposeParDict", header + body);
  try {
    readDecompositionSettings(CaseFolder(dir.root()), ranks, dimension);
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
  const std::string method = errorOf("numberOfSubdomains 2;\nmethod manual;\n", 2);
  EXPECT_NE(method.find("decomposeParDict:3"), std::string::npos) << method;
  EXPECT_NE(method.find("recursiveBisection"), std::string::npos) << method;
  const std::string typo = errorOf("numberOfSubdomains 2;\nmethod hierarchicl;\n", 2);
  EXPECT_NE(typo.find("did you mean 'hierarchical'"), std::string::npos) << typo;
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

// OpenFOAM's damBreak decomposeParDict as a user copies it: method simple with its n, the other
// methods' coeffs, distributed and roots. It runs as hierarchical cuts in order xyz, and the
// note for the log says so.
TEST(DecompositionSettingsTest, AnOpenFoamDictionaryIsReadAndItsMethodMapped) {
  const std::string openFoam =
      "numberOfSubdomains 4;\n"
      "method          simple;\n"
      "simpleCoeffs\n{\n    n               (2 2 1);\n    delta           0.001;\n}\n"
      "hierarchicalCoeffs\n{\n    n               (1 1 1);\n    delta           0.001;\n"
      "    order           xyz;\n}\n"
      "manualCoeffs\n{\n    dataFile        \"\";\n}\n"
      "scotchCoeffs\n{\n}\n"
      "distributed     no;\n"
      "roots           ( );\n";
  testing::TemporaryCase dir;
  dir.write("system/decomposeParDict", header + openFoam);
  const auto simple = readDecompositionSettings(CaseFolder(dir.root()), 4, 2);
  EXPECT_EQ(simple.method, "hierarchical");
  EXPECT_EQ(simple.requested, "simple");
  EXPECT_EQ(simple.counts, (std::array<int, 3>{2, 2, 1}));
  EXPECT_EQ(simple.order, (std::array<int, 3>{0, 1, 2}));
  EXPECT_NE(simple.note.find("simple"), std::string::npos) << simple.note;
  EXPECT_EQ(describeMethod(simple), "hierarchical cuts n (2 2 1), order xyz");

  auto read = [&](const std::string& body, int ranks) {
    dir.write("system/decomposeParDict", header + body);
    return readDecompositionSettings(CaseFolder(dir.root()), ranks);
  };
  const auto hierarchical = read(
      "numberOfSubdomains 6;\nmethod hierarchical;\n"
      "hierarchicalCoeffs { n (3 1 2); order zxy; }\n",
      6);
  EXPECT_EQ(hierarchical.counts, (std::array<int, 3>{3, 1, 2}));
  EXPECT_EQ(hierarchical.order, (std::array<int, 3>{2, 0, 1}));
  EXPECT_EQ(hierarchical.note, "");
  // OpenFOAM's generic `coeffs`
  EXPECT_EQ(read("numberOfSubdomains 2;\nmethod hierarchical;\ncoeffs { n (1 2 1); }\n", 2).counts,
            (std::array<int, 3>{1, 2, 1}));
  // a graph partitioner: recursive bisection, said in the note
  const auto scotch = read("numberOfSubdomains 2;\nmethod scotch;\nscotchCoeffs { }\n", 2);
  EXPECT_EQ(scotch.method, "recursiveBisection");
  EXPECT_NE(scotch.note.find("scotch"), std::string::npos) << scotch.note;
  EXPECT_EQ(describeMethod(scotch), "recursive bisection");
  // no method: recursive bisection
  const auto none = read("numberOfSubdomains 2;\n", 2);
  EXPECT_EQ(none.method, "recursiveBisection");
  EXPECT_EQ(none.requested, "");
  EXPECT_NE(none.note.find("no method"), std::string::npos) << none.note;
}

TEST(DecompositionSettingsTest, CutsThatDoNotFitAreNamedWithTheirLine) {
  const std::string product =
      errorOf("numberOfSubdomains 4;\nmethod simple;\nsimpleCoeffs\n{\n  n (2 1 1);\n}\n", 4);
  EXPECT_NE(product.find("decomposeParDict:6"), std::string::npos) << product;
  EXPECT_NE(product.find("n (2 1 1)"), std::string::npos) << product;
  EXPECT_NE(product.find("makes 2 subdomains"), std::string::npos) << product;
  const std::string acrossZ =
      errorOf("numberOfSubdomains 2;\nmethod simple;\nsimpleCoeffs { n (1 1 2); }\n", 2, 2);
  EXPECT_NE(acrossZ.find("2D"), std::string::npos) << acrossZ;
  const std::string noCoeffs = errorOf("numberOfSubdomains 2;\nmethod hierarchical;\n", 2);
  EXPECT_NE(noCoeffs.find("hierarchicalCoeffs { n (2 1 1); }"), std::string::npos) << noCoeffs;
  const std::string order = errorOf(
      "numberOfSubdomains 2;\nmethod hierarchical;\nhierarchicalCoeffs { n (2 1 1); order xxz; }\n",
      2);
  EXPECT_NE(order.find("order 'xxz'"), std::string::npos) << order;
  const std::string twoCounts =
      errorOf("numberOfSubdomains 2;\nmethod simple;\nsimpleCoeffs { n (2 1); }\n", 2);
  EXPECT_NE(twoCounts.find("three counts"), std::string::npos) << twoCounts;
  const std::string coeffsKey =
      errorOf("numberOfSubdomains 2;\nmethod simple;\nsimpleCoeffs { n (2 1 1); ordr xyz; }\n", 2);
  EXPECT_NE(coeffsKey.find("ordr"), std::string::npos) << coeffsKey;
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
