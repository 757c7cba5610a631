// u(T) from an internalEnergy table and from the integral of cp(T): against hand values and the
// analytic integral, its inverse T(u), the specific heat and its smallest value.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "materials/InternalEnergyTable.h"

namespace sphcast {
namespace {

const Dimensions energyDimensions{{0, 2, -2, 0, 0, 0, 0}};
const Dimensions specificHeatDimensions{{0, 2, -2, -1, 0, 0, 0}};

PropertyEntry readEntry(const std::string& text, const std::string& key,
                        const Dimensions& dimensions) {
  const Dictionary dict = Dictionary::parse(text, "physicalProperties");
  return readPropertyEntry(dict.subDict("metal"), key, dimensions);
}

InternalEnergyTable fromEnergy(const std::string& rows) {
  return InternalEnergyTable::fromInternalEnergy(readEntry(
      "metal { internalEnergy table (" + rows + "); }", "internalEnergy", energyDimensions));
}

InternalEnergyTable fromSpecificHeat(const std::string& value) {
  return InternalEnergyTable::fromSpecificHeat(
      readEntry("metal { specificHeat " + value + "; }", "specificHeat", specificHeatDimensions));
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

// Three rows: slopes 2000 J/kg/K on [800, 830], 10000 on [830, 890]; extrapolated with them.
TEST(InternalEnergyTable, TableIsPiecewiseLinearAndExtrapolatedWithTheEndSlopes) {
  const auto u = fromEnergy("(800 8e5) (830 8.6e5) (890 1.46e6)");
  EXPECT_DOUBLE_EQ(u.energy(815), 8.3e5);
  EXPECT_DOUBLE_EQ(u.energy(860), 1.16e6);
  EXPECT_DOUBLE_EQ(u.energy(790), 7.8e5);   // 10 K below at 2000 J/kg/K
  EXPECT_DOUBLE_EQ(u.energy(900), 1.56e6);  // 10 K above at 10000 J/kg/K
  EXPECT_DOUBLE_EQ(u.specificHeat(700), 2000);
  EXPECT_DOUBLE_EQ(u.specificHeat(815), 2000);
  EXPECT_DOUBLE_EQ(u.specificHeat(830), 10000);  // a node belongs to the segment above it
  EXPECT_DOUBLE_EQ(u.specificHeat(1500), 10000);
  EXPECT_DOUBLE_EQ(u.smallestSpecificHeat(), 2000);
  // the smallest slope may be an end segment's, which the extrapolation keeps
  EXPECT_DOUBLE_EQ(fromEnergy("(800 8e5) (830 1.1e6) (890 1.16e6)").smallestSpecificHeat(), 1000);
}

TEST(InternalEnergyTable, TemperatureIsTheInverseOfEnergyOverAndBeyondTheTable) {
  const auto u = fromEnergy(
      "(803 7.89e5) (830.44 8.44e5) (848 1.11e6) (888.64 1.33e6) "
      "(973 1.431e6)");
  for (double temperature = 300; temperature <= 1500; temperature += 0.37) {
    EXPECT_NEAR(u.temperature(u.energy(temperature)), temperature, 1e-12 * temperature);
  }
  for (double energy = 1e5; energy <= 2e6; energy += 1234.5) {
    EXPECT_NEAR(u.energy(u.temperature(energy)), energy, 1e-12 * energy);
  }
}

// cp linear in T between the rows (773.15 K, 640) and (973.15 K, 800), clamped outside:
//   u(T) = 640 T                                       below 773.15 K
//        = 640 T0 + 640 (T - T0) + s/2 (T - T0)^2      s = 160/200 = 0.8 J/kg/K^2
//        = u(T1) + 800 (T - T1)                        above 973.15 K
TEST(InternalEnergyTable, EnergyFromSpecificHeatIsItsIntegralFromZeroKelvin) {
  const auto u = fromSpecificHeat("table ((773.15 640) (973.15 800))");
  const double t0 = 773.15, t1 = 973.15, s = 0.8;
  auto exact = [&](double t) {
    if (t <= t0) return 640 * t;
    if (t <= t1) return 640 * t0 + 640 * (t - t0) + 0.5 * s * (t - t0) * (t - t0);
    return 640 * t0 + 640 * (t1 - t0) + 0.5 * s * (t1 - t0) * (t1 - t0) + 800 * (t - t1);
  };
  for (const double t : {1.0, 300.0, 773.15, 800.0, 850.3, 900.0, 911.7, 973.15, 1000.0, 1500.0}) {
    EXPECT_NEAR(u.energy(t), exact(t), 1e-6 * exact(t)) << "T = " << t;
  }
  // the worst point: midway between two nodes of the subdivision
  for (double t = 773.15; t < 973.15; t += 0.0731) {
    ASSERT_NEAR(u.energy(t), exact(t), 1e-6 * exact(t)) << "T = " << t;
  }
  EXPECT_NEAR(u.specificHeat(500), 640, 1e-9);
  EXPECT_NEAR(u.specificHeat(1200), 800, 1e-9);
  EXPECT_NEAR(u.specificHeat(873.15), 720, 1.5);  // the mean cp of one piece (< 2 K wide)
  EXPECT_NEAR(u.smallestSpecificHeat(), 640, 1e-9);
  for (double t = 10; t < 2000; t += 3.3) {
    EXPECT_NEAR(u.temperature(u.energy(t)), t, 1e-12 * t);
  }
}

TEST(InternalEnergyTable, ConstantSpecificHeatGivesULinearThroughZero) {
  const auto u = fromSpecificHeat("900");
  EXPECT_DOUBLE_EQ(u.energy(1000), 9e5);
  EXPECT_DOUBLE_EQ(u.energy(250), 2.25e5);
  EXPECT_DOUBLE_EQ(u.temperature(9e5), 1000);
  EXPECT_DOUBLE_EQ(u.specificHeat(5000), 900);
  EXPECT_DOUBLE_EQ(u.smallestSpecificHeat(), 900);
}

TEST(InternalEnergyTable, EnergyThatDoesNotIncreaseIsAnErrorAtItsRow) {
  const std::string message = errorOf([] {
    InternalEnergyTable::fromInternalEnergy(readEntry(
        "metal\n{\n    internalEnergy table\n    (\n        (800 8e5)\n        (830 7.9e5)\n"
        "    );\n}\n",
        "internalEnergy", energyDimensions));
  });
  EXPECT_NE(message.find("physicalProperties:6:9:"), std::string::npos) << message;
  EXPECT_NE(message.find("'internalEnergy' must increase with T in physicalProperties/metal"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("row 2 has u = 790000 J/kg at T = 830 K"), std::string::npos) << message;
  const std::string constant = errorOf([] {
    InternalEnergyTable::fromInternalEnergy(
        readEntry("metal { internalEnergy 8e5; }", "internalEnergy", energyDimensions));
  });
  EXPECT_NE(constant.find("at least 2 rows"), std::string::npos) << constant;
  const std::string zeroHeat = errorOf([] { fromSpecificHeat("table ((300 500) (400 0))"); });
  EXPECT_NE(zeroHeat.find("'specificHeat' must be positive in physicalProperties/metal; row 2"),
            std::string::npos)
      << zeroHeat;
}

}  // namespace
}  // namespace sphcast
