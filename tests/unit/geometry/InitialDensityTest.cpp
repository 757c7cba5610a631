// Initial density of setCastFields: rho_s(T) tables of constant/physicalProperties and the
// hydrostatic start, checked against the formulas and against the weight of the column.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "geometry/CastFieldsSetup.h"
#include "geometry/InitialDensity.h"
#include "materials/TemperatureTable.h"
#include "particles/FieldNames.h"
#include "support/TemporaryCase.h"

namespace sphcast {
namespace {

using testing::TemporaryCase;

const Dimensions densityDimensions{{1, -3, 0, 0, 0, 0, 0}};
const std::string header = "FoamFile { version 2.0; format ascii; class dictionary; object x; }\n";

TemperatureTable readDensity(const std::string& text) {
  const Dictionary dict = Dictionary::parse(text, "physicalProperties");
  return TemperatureTable::read(dict.subDict("metal"), "density", densityDimensions);
}

TEST(TemperatureTable, InterpolatesLinearlyAndClampsAtTheEnds) {
  const auto rhoS = readDensity(
      "metal\n{\n    density [1 -3 0 0 0 0 0] table ((300 2700) (900 2400) (1000 2350));\n}\n");
  EXPECT_FALSE(rhoS.isConstant());
  EXPECT_DOUBLE_EQ(rhoS(300.0), 2700.0);
  EXPECT_DOUBLE_EQ(rhoS(600.0), 2550.0);  // half-way between the first two rows
  EXPECT_DOUBLE_EQ(rhoS(975.0), 2362.5);  // three quarters between the last two
  EXPECT_DOUBLE_EQ(rhoS(1000.0), 2350.0);
  EXPECT_DOUBLE_EQ(rhoS(200.0), 2700.0);   // clamped below
  EXPECT_DOUBLE_EQ(rhoS(1500.0), 2350.0);  // clamped above
}

TEST(TemperatureTable, ReadsTheSolversConstantFormatAndTablesWithoutTheWord) {
  // constant/physicalProperties as src/sph/FlowSetup.cpp reads it today.
  const auto constant =
      readDensity("metal { density [1 -3 0 0 0 0 0] 2400; viscosity [1 -1 -1 0 0 0 0] 1e-3; }");
  EXPECT_TRUE(constant.isConstant());
  EXPECT_DOUBLE_EQ(constant(10.0), 2400.0);
  EXPECT_DOUBLE_EQ(constant(5000.0), 2400.0);
  EXPECT_NO_THROW(constant.checkCovers(1e6, {}));
  EXPECT_DOUBLE_EQ(readDensity("metal { density table ((300 2700) (900 2400)); }")(450.0), 2625.0);
  // The dictionary drops a word before a dimension set (old style), leaving the bare list.
  EXPECT_DOUBLE_EQ(
      readDensity("metal { density table [1 -3 0 0 0 0 0] ((300 2700) (900 2400)); }")(900.0),
      2400.0);
}

// The message of the DictionaryError that `read` throws, or "" when none.
template <class Read>
std::string errorOf(const Read& read) {
  try {
    read();
  } catch (const DictionaryError& error) {
    return error.what();
  }
  return "";
}

TEST(TemperatureTable, TemperaturesThatDoNotIncreaseAreAnErrorAtTheirRow) {
  const std::string message = errorOf([] {
    readDensity(
        "metal\n{\n    density table\n    (\n        (300 2700)\n        (900 2400)\n"
        "        (800 2380)\n    );\n}\n");
  });
  EXPECT_NE(message.find("physicalProperties:7:9:"), std::string::npos) << message;
  EXPECT_NE(message.find("'density'"), std::string::npos) << message;
  EXPECT_NE(message.find("row 3 has T = 800 K after 900 K"), std::string::npos) << message;
  const std::string equal =
      errorOf([] { readDensity("metal { density table ((300 2700) (300 2600)); }"); });
  EXPECT_NE(equal.find("must increase"), std::string::npos) << equal;
}

TEST(TemperatureTable, BadValuesAreErrorsAtTheirKey) {
  const std::string negative =
      errorOf([] { readDensity("metal\n{\n    density table ((300 2700) (900 -1));\n}\n"); });
  EXPECT_NE(negative.find("physicalProperties:3:"), std::string::npos) << negative;
  EXPECT_NE(negative.find("must be positive"), std::string::npos) << negative;
  const std::string wrongDimensions =
      errorOf([] { readDensity("metal\n{\n    density [0 1 0 0 0 0 0] 2400;\n}\n"); });
  EXPECT_NE(wrongDimensions.find("physicalProperties:3:"), std::string::npos) << wrongDimensions;
  const std::string word = errorOf([] { readDensity("metal\n{\n    density lots;\n}\n"); });
  EXPECT_NE(word.find("expected a number or table"), std::string::npos) << word;
  const std::string empty = errorOf([] { readDensity("metal\n{\n    density table ();\n}\n"); });
  EXPECT_NE(empty.find("at least one row"), std::string::npos) << empty;
}

TEST(InitialDensity, DepthIsMeasuredAlongGravityFromTheHighestParticle) {
  // Gravity along (3, 0, -4)/5: "up" is (-0.6, 0, 0.8).
  const std::vector<Vector> x{{0, 0, 0}, {0, 0, 1}, {-1, 0, 1}, {2, 5, 0}};
  const auto depths = depthsBelowFreeSurface(x, Vector(3, 0, -4), 0.1);
  // heights: 0, 0.8, 1.4, -1.2; surface at 1.4 + 0.05
  EXPECT_NEAR(depths[0], 1.45, 1e-14);
  EXPECT_NEAR(depths[1], 0.65, 1e-14);
  EXPECT_NEAR(depths[2], 0.05, 1e-14);
  EXPECT_NEAR(depths[3], 2.65, 1e-14);
  for (const double d : depthsBelowFreeSurface(x, Vector::Zero(), 0.1)) EXPECT_EQ(d, 0.0);
}

// A case with a tall box of metal: dx = 5 mm, 0.05 x 0.05 x 0.2 m, c = 20 m/s.
struct ColumnCase {
  TemporaryCase folder;
  explicit ColumnCase(const std::string& rho, const std::string& density = "2400",
                      const std::string& temperature = "953") {
    folder.write("system/setCastFieldsDict",
                 header +
                     "spacing 0.005;\nclouds\n{\n    metal\n    {\n"
                     "        regions { column { type box; min (0 0 0); max (0.05 0.05 0.2); } }\n"
                     "        fields { T " +
                     temperature + "; rho " + rho + "; }\n    }\n}\n");
    folder.write("constant/physicalProperties",
                 header + "metal\n{\n    density [1 -3 0 0 0 0 0] " + density +
                     ";\n    viscosity [1 -1 -1 0 0 0 0] 1e-3;\n}\n");
    folder.write("constant/g", header + "dimensions [0 1 -2 0 0 0 0];\nvalue (0 0 -9.81);\n");
    folder.write("system/sphSchemes",
                 header +
                     "densityScheme riemann;\nviscousForm Morris;\nsupportRadius 0.0125;\n"
                     "soundSpeed [0 1 -1 0 0 0 0] 20;\n");
  }
  ParticleCloud metal() const {
    return buildCastClouds(CaseDescription(CaseFolder(folder.root())), {}).at(0);
  }
};

TEST(InitialDensity, HydrostaticColumnStartsWithThePressureOfItsWeight) {
  const double g = 9.81, c = 20.0, rhoS = 2400.0, height = 0.2, dx = 0.005;
  const ParticleCloud metal = ColumnCase("hydrostatic").metal();
  ASSERT_EQ(metal.size(), 10u * 10u * 40u);
  const auto& rho = metal.scalarField(field::rho);
  // rho of the formula: rho_s (1 + |g| d / c^2), d = H - z (the top layer sits at H - dx/2).
  for (std::size_t i = 0; i < metal.size(); ++i) {
    const double depth = height - static_cast<double>(metal.positions()[i].z());
    EXPECT_NEAR(rho[i], rhoS * (1.0 + g * depth / (c * c)), 1e-12 * rhoS);
  }
  // p = c^2 (rho - rho_s) against rho g (H - z) and against the weight of the column above each
  // particle per unit area, g dx (sum of rho above + rho_i / 2). The linear start is first order
  // in g d / c^2: it misses the exact weight by (g d / c^2) / 2 relative, at most 0.25 % at the
  // bottom here (g H / c^2 = 0.0049); uniform density would start with p = 0 everywhere.
  std::map<std::pair<long, long>, std::map<double, double>> columns;  // (x, y) -> z -> rho
  for (std::size_t i = 0; i < metal.size(); ++i) {
    const Vector& x = metal.positions()[i];
    columns[{std::lround(x.x() / dx), std::lround(x.y() / dx)}][x.z()] = rho[i];
  }
  double worstAgainstRhoGh = 0.0, worstAgainstWeight = 0.0;
  for (const auto& [xy, column] : columns) {
    double above = 0.0;  // sum of rho of the particles above, walking down
    for (auto it = column.rbegin(); it != column.rend(); ++it) {
      const double z = it->first, rhoI = it->second;
      const double p = c * c * (rhoI - rhoS);
      const double rhoGh = rhoI * g * (height - z);
      const double weight = g * dx * (above + 0.5 * rhoI);
      worstAgainstRhoGh = std::max(worstAgainstRhoGh, std::abs(p - rhoGh) / rhoGh);
      worstAgainstWeight = std::max(worstAgainstWeight, std::abs(p - weight) / weight);
      above += rhoI;
    }
  }
  EXPECT_LT(worstAgainstRhoGh, 0.0050);  // g H / c^2 = 0.0049
  EXPECT_LT(worstAgainstWeight, 0.0026);
  std::printf(
      "hydrostatic column: p against rho g (H - z) within %.4f %%, against the column's "
      "weight within %.4f %%\n",
      100 * worstAgainstRhoGh, 100 * worstAgainstWeight);
}

TEST(InitialDensity, StandardAndHydrostaticUseRhoSAtTheInitialTemperature) {
  const std::string table = "table ((300 2700) (900 2400) (1000 2350))";
  const ParticleCloud standard = ColumnCase("standard", table, "950").metal();
  for (const Real r : standard.scalarField(field::rho)) EXPECT_DOUBLE_EQ(r, 2375.0);
  const ParticleCloud hydrostatic = ColumnCase("hydrostatic", table, "950").metal();
  for (std::size_t i = 0; i < hydrostatic.size(); ++i) {
    const double depth = 0.2 - static_cast<double>(hydrostatic.positions()[i].z());
    EXPECT_NEAR(hydrostatic.scalarField(field::rho)[i], 2375.0 * (1.0 + 9.81 * depth / 400.0),
                1e-9);
  }
  // A number keeps working and is written as given.
  const ParticleCloud given = ColumnCase("2500").metal();
  for (const Real r : given.scalarField(field::rho)) EXPECT_EQ(r, 2500.0);
}

TEST(InitialDensity, MistakesNameTheFileLineAndKey) {
  // T in deg C where the table is in K: the error points at T in setCastFieldsDict.
  const std::string celsius =
      errorOf([] { ColumnCase("standard", "table ((300 2700) (900 2400))", "25").metal(); });
  EXPECT_NE(celsius.find("setCastFieldsDict:8:"), std::string::npos) << celsius;
  EXPECT_NE(celsius.find("T = 25 K lies outside the table 'density'"), std::string::npos)
      << celsius;
  const std::string word = errorOf([] { ColumnCase("hydrostatik").metal(); });
  EXPECT_NE(word.find("setCastFieldsDict:8:"), std::string::npos) << word;
  EXPECT_NE(word.find("standard or hydrostatic"), std::string::npos) << word;
  ColumnCase noMaterial("standard");
  noMaterial.folder.write("constant/physicalProperties", header + "water { density 1000; }\n");
  const std::string missing = errorOf([&] { noMaterial.metal(); });
  EXPECT_NE(missing.find("setCastFieldsDict:8:"), std::string::npos) << missing;
  EXPECT_NE(missing.find("needs the material 'metal'"), std::string::npos) << missing;
  EXPECT_NE(missing.find("( water )"), std::string::npos) << missing;
}

}  // namespace
}  // namespace sphcast
