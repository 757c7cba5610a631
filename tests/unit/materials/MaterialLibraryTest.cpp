// Materials of constant/physicalProperties: the library, the etc/materials files through
// #includeEtc, and the errors a user can make in a material.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "materials/MaterialLibrary.h"
#include "support/TemporaryCase.h"

namespace sphcast {
namespace {

using testing::TemporaryCase;

const std::string header =
    "FoamFile { version 2.0; format ascii; class dictionary; object physicalProperties; }\n";

MaterialLibrary readLibrary(const TemporaryCase& folder, const std::string& body) {
  folder.write("constant/physicalProperties", header + body);
  return MaterialLibrary::read(folder.root() / "constant/physicalProperties");
}

std::string errorOf(const TemporaryCase& folder, const std::string& body) {
  try {
    readLibrary(folder, body);
  } catch (const DictionaryError& error) {
    return error.what();
  }
  return "";
}

// Table 1 of the paper as shipped in etc/materials/AC4CH: the latent heat between the solidus
// 830.44 K and the liquidus 888.64 K is 1.33e6 - 8.44e5 = 4.86e5 J/kg.
TEST(MaterialLibrary, AC4CHFromTheEtcFolderCarriesTable1) {
  const TemporaryCase folder;
  const auto library = readLibrary(folder,
                                   "AC4CH { #includeEtc \"materials/AC4CH\" }\n"
                                   "mold { #includeEtc \"materials/iron\" }\n");
  EXPECT_EQ(library.names(), (std::vector<std::string>{"AC4CH", "mold"}));
  const Material& alloy = library.get("AC4CH", {}, "fluid");
  const InternalEnergyTable& u = alloy.requireInternalEnergy("the test");
  EXPECT_NEAR(u.energy(888.64) - u.energy(830.44), 4.86e5, 1e3);
  EXPECT_DOUBLE_EQ(alloy.requireDensity("the test")(973), 2398.8);
  EXPECT_DOUBLE_EQ(alloy.requireDensity("the test")(803), 2571.9);
  EXPECT_DOUBLE_EQ(alloy.requireConductivity("the test")(888.64), 83.3);
  EXPECT_EQ(alloy.requireSurfaceTension("the test")(803), 0.0);
  EXPECT_DOUBLE_EQ(alloy.requireViscosity("the test")(973), 1.28e-3);
  // log-linear between 873 K and 888.64 K: the geometric mean at the midpoint
  EXPECT_NEAR(alloy.requireViscosity("the test")(880.82), std::sqrt(186 * 1.57e-3), 1e-9);
  EXPECT_FALSE(alloy.emissivity);  // the paper gives none
  EXPECT_DOUBLE_EQ(alloy.requireFreezingRange("the test").liquidus, 888.64);
  EXPECT_DOUBLE_EQ(alloy.requireFreezingRange("the test").solidus, 830.44);

  const Material& iron = library.get("mold", {}, "mold");
  EXPECT_DOUBLE_EQ(iron.requireEmissivity("radiation"), 0.3);
  EXPECT_DOUBLE_EQ(iron.requireDensity("the test")(300), 7874);
  EXPECT_DOUBLE_EQ(iron.requireInternalEnergy("the test").specificHeat(500), 640);
  EXPECT_FALSE(iron.viscosity);
}

// A key written after the #includeEtc line overrides the file's.
TEST(MaterialLibrary, KeysAfterTheIncludeOverrideTheEtcFile) {
  const TemporaryCase folder;
  const auto library =
      readLibrary(folder, "mold { #includeEtc \"materials/iron\" emissivity 0.5; }\n");
  EXPECT_DOUBLE_EQ(library.get("mold", {}, "mold").requireEmissivity("radiation"), 0.5);
}

TEST(MaterialLibrary, MissingPropertyIsAnErrorAtTheMaterialNamingWhoNeedsIt) {
  const TemporaryCase folder;
  const auto library = readLibrary(folder, "\nAC4CH\n{\n    density 2400;\n}\n");
  try {
    library.get("AC4CH", {}, "fluid").requireConductivity("heatTransfer conduction");
    FAIL() << "a missing conductivity was not reported";
  } catch (const DictionaryError& error) {
    EXPECT_EQ(std::string(error.what()),
              (folder.root() / "constant/physicalProperties").string() +
                  ":3:1: material 'AC4CH' in constant/physicalProperties has no 'conductivity', "
                  "which heatTransfer conduction needs");
  }
  EXPECT_THROW(library.get("AC4CH", {}, "fluid").requireEmissivity("radiation"), DictionaryError);
  EXPECT_THROW(library.get("AC4CH", {}, "fluid").requireInternalEnergy("heat"), DictionaryError);
}

TEST(MaterialLibrary, UnknownMaterialIsReportedWhereItIsNamedWithTheNearestOne) {
  const TemporaryCase folder;
  const auto library = readLibrary(folder, "water { density 1000; }\nsteel { density 7800; }\n");
  try {
    library.get("watr", SourceLocation{"constant/physicsModels", 2, 34}, "fluid");
    FAIL() << "an unknown material was accepted";
  } catch (const DictionaryError& error) {
    EXPECT_EQ(std::string(error.what()),
              "constant/physicsModels:2:34: 'fluid' names the material 'watr', which is not in " +
                  (folder.root() / "constant/physicalProperties").string() +
                  "; did you mean 'water'? materials there: (water steel)");
  }
  EXPECT_TRUE(library.has("steel"));
  EXPECT_FALSE(library.has("iron"));
}

TEST(MaterialLibrary, ErrorsNameFileLineKeyAndRow) {
  const TemporaryCase folder;
  const std::string file = (folder.root() / "constant/physicalProperties").string();
  auto expectError = [&](const std::string& body, const std::string& place,
                         const std::string& what) {
    const std::string message = errorOf(folder, body);
    EXPECT_NE(message.find(file + place), std::string::npos) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
  };
  // rows out of order
  expectError("metal\n{\n    conductivity table ((800 100)\n        (700 90));\n}\n", ":5:9:",
              "'conductivity' in physicalProperties/metal must increase: row 2 has T = 700 K "
              "after 800 K");
  // a column of another length than `temperatures`
  expectError("metal\n{\n    temperatures (800 900);\n    viscosity (1 2 3);\n}\n", ":5:5:",
              "'viscosity' in physicalProperties/metal is a column of 3 values, but "
              "'temperatures' in physicalProperties/metal (" +
                  file + ":4:5) has 2 rows");
  // u not increasing, in a column
  expectError("metal\n{\n    temperatures (800 900);\n    internalEnergy (8e5\n    7e5);\n}\n",
              ":6:5:", "'internalEnergy' must increase with T in physicalProperties/metal");
  // both u and cp
  expectError(
      "metal\n{\n    internalEnergy table ((800 8e5) (900 9e5));\n    specificHeat "
      "900;\n}\n",
      ":5:5:",
      "material 'metal' in constant/physicalProperties gives both 'internalEnergy' (line "
      "4) and 'specificHeat'");
  // a value that must be positive
  expectError("metal\n{\n    density table ((300 2700) (900 0));\n}\n",
              ":4:", "'density' must be positive in physicalProperties/metal; row 2 has 0");
  expectError("metal\n{\n    emissivity 1.2;\n}\n", ":4:5:", "must lie in [0, 1]");
  // an unknown key, with the nearest valid one
  expectError("metal\n{\n    densty 2400;\n}\n", ":4:5:", "did you mean 'density'?");
  // wrong dimensions
  expectError("metal\n{\n    conductivity [1 1 -3 0 0 0 0] 26;\n}\n", ":4:", "conductivity");
  // a freezing range: both ends, in order
  expectError("metal\n{\n    liquidus 888;\n}\n", ":4:5:",
              "material 'metal' in constant/physicalProperties gives 'liquidus' but not "
              "'solidus'");
  expectError("metal\n{\n    liquidus 830;\n    solidus 888;\n}\n", ":5:5:",
              "'solidus' 888 K of material 'metal' in constant/physicalProperties must be "
              "positive and below its 'liquidus' 830 K");
  // lambda_2 = A t_f^n: two positive numbers, n at most 1
  expectError("metal\n{\n    dendriteArmSpacing (1e-5);\n}\n", ":4:5:",
              "'dendriteArmSpacing' of material 'metal' in constant/physicalProperties must be "
              "(A n)");
  expectError("metal\n{\n    dendriteArmSpacing (1e-5 1.5);\n}\n", ":4:5:", "n in (0, 1]");
}

}  // namespace
}  // namespace sphcast
