// controlDict `functions`: reading (errors name file, line and key), the files written, and
// restarts joined without duplicated rows.
#include <gtest/gtest.h>

#include <cmath>

#include "core/dictionary/Dictionary.h"
#include "particles/FieldNames.h"
#include "post/FunctionObject.h"
#include "sph/FlowTestCases.h"
#include "support/TemporaryFolder.h"

namespace sphcast {
namespace {

class FunctionObjectTest : public testing::TemporaryFolderTest {
 protected:
  FunctionObjectContext context(const std::string& startTime) {
    FunctionObjectContext c;
    c.caseRoot = folder_;
    c.startTimeName = startTime;
    c.startTime = std::stod(startTime);
    c.supportRadius = 0.03;
    c.gravity = Vector(0, -9.81, 0);
    c.clouds = {&water_};
    return c;
  }
  std::string errorOf(const std::string& functions) {
    try {
      FunctionObjectList list(Dictionary::parse("functions {" + functions + "}", "controlDict"),
                              context("0"));
    } catch (const Error& error) {
      return error.what();
    }
    return "no error";
  }
  ParticleCloud water_ = [] {
    auto fluid = testing::fluidBlock2D(10, 5, 0.01, Vector::Zero(), 1000, 1e-3);
    fluid.attributes().clear();  // no spacing: heights and front are particle centres
    auto& p = fluid.addScalarField(field::p);
    for (std::size_t i = 0; i < p.size(); ++i) p[i] = 100;
    return fluid;
  }();
};

TEST_F(FunctionObjectTest, BadEntriesAreErrorsAtTheirKey) {
  EXPECT_EQ(errorOf("P1 { type probe; cloud fluid; }"),
            "controlDict:1:22: unknown type 'probe'; did you mean 'probes'? valid type are: "
            "(probes surfaceHeights front fieldMinMax massAverage energyBalance bodyHistory)");
  // energyBalance spans clouds: `clouds`, each carrying heat
  const std::string noHeat = errorOf("E { type energyBalance; clouds (fluid); }");
  EXPECT_NE(noHeat.find("controlDict:1:36: cloud 'fluid'"), std::string::npos) << noHeat;
  EXPECT_NE(noHeat.find("carries no heat"), std::string::npos) << noHeat;
  EXPECT_NE(errorOf("E { type energyBalance; cloud fluid; }").find("unknown key 'cloud'"),
            std::string::npos);
  EXPECT_NE(
      errorOf("P1 { type probes; fields (p); probeLocations ((0 0 0)); }").find("controlDict:1:"),
      std::string::npos);
  EXPECT_NE(errorOf("P1 { type probes; fields (p); probeLocations ((0 0 0)); }").find("'cloud'"),
            std::string::npos);
  const std::string unknownCloud =
      errorOf("P1 { type probes; cloud metal; fields (p); probeLocations ((0 0 0)); }");
  EXPECT_NE(unknownCloud.find("controlDict:1:30: unknown cloud 'metal'"), std::string::npos)
      << unknownCloud;
  const std::string unknownField =
      errorOf("P1 { type probes; cloud fluid; fields (T); probeLocations ((0 0 0)); }");
  EXPECT_NE(unknownField.find("unknown field 'T' of cloud 'fluid'"), std::string::npos)
      << unknownField;
  EXPECT_NE(unknownField.find("controlDict:1:"), std::string::npos) << unknownField;
  const std::string unknownKey =
      errorOf("H { type surfaceHeights; cloud fluid; locations ((0 0 0)); radus 1; }");
  EXPECT_NE(unknownKey.find("unknown key 'radus'"), std::string::npos) << unknownKey;
  const std::string badControl =
      errorOf("F { type front; cloud fluid; direction (1 0 0); writeControl clockTime; }");
  EXPECT_NE(badControl.find("writeControl"), std::string::npos) << badControl;
}

TEST_F(FunctionObjectTest, WritesOpenFoamStyleFilesUnderTheStartTime) {
  FunctionObjectList list(
      Dictionary::parse(
          "functions {\n"
          "  P { type probes; cloud fluid; fields (p U);\n"
          "      probeLocations ((0.05 0.02 0) (1 1 0)); }\n"
          "  H { type surfaceHeights; cloud fluid; locations ((0.05 0.3 0));\n"
          "      writeControl timeStep; writeInterval 2; }\n"
          "  F { type front; cloud fluid; direction (2 0 0); writeControl writeTime; }\n"
          "}",
          "controlDict"),
      context("0"));
  ASSERT_EQ(list.size(), 3u);
  for (long index = 0; index <= 4; ++index) {
    const TimeState time{0.1 * double(index), "", index, 0.1};
    list.execute(time, index == 3);
  }
  const auto probes = testing::readWholeFile(folder_ / "postProcessing/P/0/p");
  EXPECT_EQ(probes.substr(0, probes.find("\n#        Probe")),
            "# startTime 0\n# Probe 0 (0.05 0.02 0)\n# Probe 1 (1 1 0)\n"
            "# Shepard interpolation over particles of cloud fluid within h = 0.03 m; nan: no "
            "particle within h");
  const auto p = readFunctionObjectSeries(folder_, "P", "p");
  ASSERT_EQ(p.size(), 5u);
  EXPECT_DOUBLE_EQ(p[4][0], 0.4);
  EXPECT_DOUBLE_EQ(p[4][1], 100);
  EXPECT_TRUE(std::isnan(p[4][2]));
  const auto velocity = readFunctionObjectSeries(folder_, "P", "U");
  ASSERT_EQ(velocity.size(), 5u);
  EXPECT_EQ(velocity[0].size(), 7u);  // time and two vectors
  const auto height = readFunctionObjectSeries(folder_, "H", "height");
  ASSERT_EQ(height.size(), 3u);  // the start, steps 2 and 4
  EXPECT_DOUBLE_EQ(height[1][0], 0.2);
  EXPECT_NEAR(height[1][1], 0.045, 1e-12);  // top particle centre
  const auto front = readFunctionObjectSeries(folder_, "F", "front");
  ASSERT_EQ(front.size(), 2u);  // the start and the write time
  EXPECT_NEAR(front[1][0], 0.3, 1e-12);
  EXPECT_NEAR(front[1][1], 0.095, 1e-12);
}

TEST_F(FunctionObjectTest, FieldMinMaxGivesTheExtremesAndWhereTheyAre) {
  auto& p = water_.scalarField(field::p);
  p[7] = -5;  // the lowest, at particle 7
  p[23] = 250;
  water_.vectorField(field::U)[11] = Vector(3, 4, 0);  // |U| = 5, the rest are at rest
  FunctionObjectList list(
      Dictionary::parse("functions { R { type fieldMinMax; cloud fluid; fields (p U); } }",
                        "controlDict"),
      context("0"));
  list.execute(TimeState{0, "", 0, 0.1}, false);
  const auto pressure = readFunctionObjectSeries(folder_, "R", "p");
  ASSERT_EQ(pressure.size(), 1u);
  ASSERT_EQ(pressure[0].size(), 9u);  // time, min, max, two positions
  EXPECT_DOUBLE_EQ(pressure[0][1], -5);
  EXPECT_DOUBLE_EQ(pressure[0][2], 250);
  const auto& x = water_.positions();
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(pressure[0][3 + k], x[7][k], 1e-9);
    EXPECT_NEAR(pressure[0][6 + k], x[23][k], 1e-9);
  }
  const auto speed = readFunctionObjectSeries(folder_, "R", "U");
  ASSERT_EQ(speed.size(), 1u);
  EXPECT_DOUBLE_EQ(speed[0][1], 0);
  EXPECT_DOUBLE_EQ(speed[0][2], 5);
  const std::string unknownField = errorOf("R { type fieldMinMax; cloud fluid; fields (T); }");
  EXPECT_NE(unknownField.find("controlDict:1:"), std::string::npos) << unknownField;
  EXPECT_NE(unknownField.find("unknown field 'T' of cloud 'fluid'"), std::string::npos)
      << unknownField;
}

// massAverage: sum m f / sum m, here of p with two heavy particles: the mean moves toward them
// as their mass says; a vector field is an error at its key.
TEST_F(FunctionObjectTest, MassAverageWeighsByMass) {
  auto& mass = water_.scalarField(field::mass);
  auto& p = water_.scalarField(field::p);
  for (std::size_t i = 0; i < mass.size(); ++i) mass[i] = 1;
  mass[3] = mass[5] = 10;
  p[3] = p[5] = 1000;  // the rest stay at 100
  const double n = double(mass.size());
  const double expected = (100 * (n - 2) + 2 * 10 * 1000) / (n - 2 + 20);
  FunctionObjectList list(
      Dictionary::parse("functions { A { type massAverage; cloud fluid; fields (p); } }",
                        "controlDict"),
      context("0"));
  list.execute(TimeState{0, "", 0, 0.1}, false);
  const auto rows = readFunctionObjectSeries(folder_, "A", "p");
  ASSERT_EQ(rows.size(), 1u);
  ASSERT_EQ(rows[0].size(), 2u);  // time, mean
  EXPECT_NEAR(rows[0][1], expected, 1e-9 * expected);
  const std::string vector = errorOf("A { type massAverage; cloud fluid; fields (U); }");
  EXPECT_NE(vector.find("unknown scalar field 'U'"), std::string::npos) << vector;
}

TEST_F(FunctionObjectTest, ARestartedRunContinuesWithoutDuplicatedRows) {
  const auto functions = Dictionary::parse(
      "functions { F { type front; cloud fluid; direction (1 0 0); }\n"
      "            G { type front; cloud fluid; direction (1 0 0); writeInterval 2; }\n"
      "            R { type front; cloud fluid; direction (1 0 0); writeControl runTime;\n"
      "                writeInterval 0.2; } }",
      "controlDict");
  {
    // The first run goes to step 6 and is killed there; time 0.3 (step 3) was its last write.
    FunctionObjectList first(functions, context("0"));
    for (long index = 0; index <= 6; ++index) {
      first.execute({0.1 * double(index), "", index, index > 0 ? 0.1 : 0.0}, false);
    }
  }
  {
    FunctionObjectList restarted(functions, context("0.3"));
    for (long index = 3; index <= 8; ++index) {
      restarted.execute({0.1 * double(index), "", index, 0.1}, false);
    }
  }
  // Every step once; every second step once; every 0.2 s once; and no row at the restart's
  // start (0.3) where the uninterrupted run has none.
  const std::vector<std::pair<std::string, std::vector<long>>> expected = {
      {"F", {0, 1, 2, 3, 4, 5, 6, 7, 8}}, {"G", {0, 2, 4, 6, 8}}, {"R", {0, 2, 4, 6, 8}}};
  for (const auto& [name, steps] : expected) {
    const auto rows = readFunctionObjectSeries(folder_, name, "front");
    ASSERT_EQ(rows.size(), steps.size()) << name;
    for (std::size_t k = 0; k < rows.size(); ++k) {
      EXPECT_NEAR(rows[k][0], 0.1 * double(steps[k]), 1e-12) << name;
    }
  }
  // Started again from 0.3: that folder is replaced, not appended to.
  {
    FunctionObjectList again(functions, context("0.3"));
    again.execute({0.3, "", 3, 0.1}, false);
  }
  EXPECT_EQ(readFunctionObjectSeries(folder_, "F", "front").size(), 4u);
}

TEST_F(FunctionObjectTest, ARestartFromATimeOfManyDigitsJoinsWithoutItsRowTwice) {
  // Rows print 12 significant digits; the start time has 15.
  const double restart = 0.0194031221304117;
  const auto functions = Dictionary::parse(
      "functions { F { type front; cloud fluid; direction (1 0 0); } }", "controlDict");
  {
    FunctionObjectList first(functions, context("0"));
    first.execute({0, "", 0, 0}, false);
    first.execute({restart, "", 1, restart}, false);
    first.execute({2 * restart, "", 2, restart}, false);
  }
  {
    auto restarted = context("0.0194031");
    restarted.startTime = restart;
    FunctionObjectList second(functions, restarted);
    second.execute({restart, "", 1, restart}, false);
  }
  const auto rows = readFunctionObjectSeries(folder_, "F", "front");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_NEAR(rows[1][0], restart, 1e-12);
}

}  // namespace
}  // namespace sphcast
