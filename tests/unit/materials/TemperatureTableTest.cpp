// Temperature tables of constant/physicalProperties: interpolation (linear, log-linear),
// clamping, the column form beside `temperatures`, and the value rules.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "materials/TemperatureTable.h"

namespace sphcast {
namespace {

const Dimensions viscosityDimensions{{1, -1, -1, 0, 0, 0, 0}};
const Dimensions surfaceTensionDimensions{{1, 0, -2, 0, 0, 0, 0}};

TemperatureTable readProperty(const std::string& text, const std::string& key,
                              const Dimensions& dimensions, Interpolation interpolation,
                              ValueRule rule = ValueRule::positive) {
  const Dictionary dict = Dictionary::parse(text, "physicalProperties");
  const Dictionary& metal = dict.subDict("metal");
  std::optional<TemperatureColumn> columns;
  if (metal.found("temperatures")) columns = readTemperatureColumn(metal, "temperatures");
  return TemperatureTable::read(metal, key, dimensions, interpolation, rule,
                                columns ? &*columns : nullptr);
}

template <class Read>
std::string errorOf(const Read& read) {
  try {
    read();
  } catch (const DictionaryError& error) {
    return error.what();
  }
  return "";
}

// mu of Table 1 between 888.64 K (1.57e-3 Pa s) and 873 K (186 Pa s): log-linear puts the
// midpoint at the geometric mean, sqrt(1.57e-3 * 186) = 0.54039 Pa s; linear at 93 Pa s.
TEST(TemperatureTable, LogLinearInterpolatesTheLogarithmAndLinearTheValue) {
  const std::string text = "metal { viscosity table ((873 186) (888.64 1.57e-3)); }";
  const auto logLinear =
      readProperty(text, "viscosity", viscosityDimensions, Interpolation::logLinear);
  const auto linear = readProperty(text, "viscosity", viscosityDimensions, Interpolation::linear);
  const double midpoint = 0.5 * (873 + 888.64);
  EXPECT_NEAR(logLinear(midpoint), std::sqrt(1.57e-3 * 186), 1e-12);
  EXPECT_NEAR(linear(midpoint), 0.5 * (186 + 1.57e-3), 1e-12);
  // a quarter of the way: 186^(3/4) (1.57e-3)^(1/4)
  EXPECT_NEAR(logLinear(873 + 0.25 * 15.64), std::pow(186, 0.75) * std::pow(1.57e-3, 0.25), 1e-12);
  // clamped at both ends, to the values as written
  EXPECT_EQ(logLinear(800), 186);
  EXPECT_EQ(logLinear(873), 186);
  EXPECT_EQ(logLinear(2000), 1.57e-3);
  EXPECT_EQ(logLinear.interpolation(), Interpolation::logLinear);
}

// integral(T) = int from the lowest temperature to T (the Kirchhoff transform of a
// conductivity): against the trapezoid rule on a fine grid (exact for the linear table, and to
// 1e-9 for the log-linear one), below the table (negative, the first value) and above it (the
// last value), and a constant.
TEST(TemperatureTable, IntegralIsTheAreaUnderTheTableClampedAtTheEnds) {
  const Dimensions conductivity{{1, 1, -3, -1, 0, 0, 0}};
  const std::string text =
      "metal { conductivity table ((803 174.35) (830.44 175.34) (848 114.78) (888.64 83.3)); "
      "viscosity table ((873 186) (888.64 1.57e-3)); c 20; }";
  const auto kappa = readProperty(text, "conductivity", conductivity, Interpolation::linear);
  const auto mu = readProperty(text, "viscosity", viscosityDimensions, Interpolation::logLinear);
  auto trapezoid = [](const TemperatureTable& table, double from, double to) {
    const int steps = 200000;
    double sum = 0;
    for (int k = 0; k < steps; ++k) {
      const double a = from + (to - from) * k / steps, b = from + (to - from) * (k + 1) / steps;
      sum += 0.5 * (table(a) + table(b)) * (b - a);
    }
    return sum;
  };
  for (const double T : {803.0, 820.0, 830.44, 840.0, 870.0, 888.64, 950.0}) {
    EXPECT_NEAR(kappa.integral(T), trapezoid(kappa, 803, T), 1e-6) << T;
  }
  EXPECT_DOUBLE_EQ(kappa.integral(300), 174.35 * (300 - 803));
  EXPECT_NEAR(kappa.integral(1000) - kappa.integral(888.64), 83.3 * (1000 - 888.64), 1e-8);
  for (const double T : {873.0, 875.0, 880.0, 888.64, 900.0}) {
    EXPECT_NEAR(mu.integral(T), trapezoid(mu, 873, T), 1e-9 * 186 * 16) << T;
  }
  const auto constant = readProperty(text, "c", conductivity, Interpolation::linear);
  EXPECT_NEAR(constant.integral(500) - constant.integral(300), 20 * 200, 1e-9);
}

TEST(TemperatureTable, ColumnsReadBesideTheMaterialsTemperatures) {
  const auto density =
      readProperty("metal { temperatures (300 900 1000); density (2700 2400 2350); }", "density",
                   Dimensions{{1, -3, 0, 0, 0, 0, 0}}, Interpolation::linear);
  EXPECT_DOUBLE_EQ(density(600), 2550);
  EXPECT_DOUBLE_EQ(density(975), 2362.5);
  EXPECT_DOUBLE_EQ(density(100), 2700);
  EXPECT_DOUBLE_EQ(density(1100), 2350);
}

TEST(TemperatureTable, SurfaceTensionMayBeZeroWhereOtherPropertiesMustBePositive) {
  const std::string text = "metal { surfaceTension table ((803 0) (848 0.932)); }";
  const auto gamma = readProperty(text, "surfaceTension", surfaceTensionDimensions,
                                  Interpolation::linear, ValueRule::nonNegative);
  EXPECT_DOUBLE_EQ(gamma(825.5), 0.466);
  const std::string positive = errorOf([&] {
    readProperty(text, "surfaceTension", surfaceTensionDimensions, Interpolation::linear);
  });
  EXPECT_NE(positive.find("physicalProperties:1:"), std::string::npos) << positive;
  EXPECT_NE(positive.find("'surfaceTension' must be positive in physicalProperties/metal; row 1 "
                          "has 0"),
            std::string::npos)
      << positive;
  const std::string negative = errorOf([] {
    readProperty("metal\n{\n    surfaceTension table ((803 0) (848 -0.1));\n}\n", "surfaceTension",
                 surfaceTensionDimensions, Interpolation::linear, ValueRule::nonNegative);
  });
  EXPECT_NE(negative.find("physicalProperties:3:"), std::string::npos) << negative;
  EXPECT_NE(negative.find("must not be negative"), std::string::npos) << negative;
  EXPECT_NE(negative.find("row 2 has -0.1"), std::string::npos) << negative;
}

// A column as long as `temperatures` is needed: the error names both lengths and both keys.
TEST(TemperatureTable, AColumnOfAnotherLengthThanTheTemperaturesIsAnError) {
  const std::string message = errorOf([] {
    readProperty("metal\n{\n    temperatures (300 900 1000);\n    density (2700 2400);\n}\n",
                 "density", Dimensions{{1, -3, 0, 0, 0, 0, 0}}, Interpolation::linear);
  });
  EXPECT_NE(message.find("physicalProperties:4:5:"), std::string::npos) << message;
  EXPECT_NE(message.find("'density' in physicalProperties/metal is a column of 2 values"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("'temperatures' in physicalProperties/metal (physicalProperties:3:5) "
                         "has 3 rows"),
            std::string::npos)
      << message;
  const std::string withoutTemperatures = errorOf([] {
    readProperty("metal { density (2700 2400); }", "density", Dimensions{{1, -3, 0, 0, 0, 0, 0}},
                 Interpolation::linear);
  });
  EXPECT_NE(withoutTemperatures.find("needs the material's 'temperatures'"), std::string::npos)
      << withoutTemperatures;
}

TEST(TemperatureTable, TemperaturesColumnOutOfOrderIsAnErrorAtItsRow) {
  const std::string message = errorOf([] {
    readProperty("metal\n{\n    temperatures (300\n    900\n    800);\n    density (1 2 3);\n}\n",
                 "density", Dimensions{{1, -3, 0, 0, 0, 0, 0}}, Interpolation::linear);
  });
  EXPECT_NE(message.find("physicalProperties:5:5:"), std::string::npos) << message;
  EXPECT_NE(message.find("'temperatures' in physicalProperties/metal must increase: row 3 has "
                         "T = 800 K after 900 K"),
            std::string::npos)
      << message;
}

}  // namespace
}  // namespace sphcast
