// The run's health checks (solver/RunHealth.h): what they find, that two threads find the same,
// and how their thresholds are read; the metal spilled out of the domain (solver/MetalSpill.h).
#include "solver/RunHealth.h"

#include <omp.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"
#include "particles/FieldNames.h"
#include "solver/MetalSpill.h"

namespace sphcast {
namespace {

ParticleCloud fluidWithDeviations(std::size_t count) {
  ParticleCloud cloud("metal");
  cloud.resize(count);
  auto& u = cloud.addVectorField(field::U);
  auto& rho = cloud.addScalarField(field::rho);
  auto& rest = cloud.addScalarField(field::restDensity);
  for (std::size_t i = 0; i < count; ++i) {
    cloud.positions()[i] = Vector(Real(i) * Real(1e-6), 0, 0);
    u[i] = Vector::Zero();
    rest[i] = 2400;
    rho[i] = 2400 * (1 + Real(0.01) * std::sin(Real(i)));  // within 1 %
  }
  return cloud;
}

const Domain box{Vector::Constant(-1), Vector::Constant(1)};

TEST(RunHealth, FindsTheLargestDensityDeviationAndWhereItIs) {
  ParticleCloud cloud = fluidWithDeviations(1000);
  cloud.scalarField(field::rho)[617] = 2400 * 1.07;
  const CloudHealth health = measureCloudHealth(cloud, box);
  EXPECT_TRUE(health.finiteAndInside());
  EXPECT_NEAR(health.largestDensityDeviation, 0.07, 1e-12);
  EXPECT_EQ(health.mostDeviating, 617u);
  EXPECT_EQ(health.mostDeviatingPosition, cloud.positions()[617]);
}

TEST(RunHealth, CountsNonFiniteAndOutsideParticlesAndNamesTheFirst) {
  ParticleCloud cloud = fluidWithDeviations(1000);
  cloud.positions()[700] = Vector(2, 0, 0);  // outside
  cloud.vectorField(field::U)[300][1] = std::numeric_limits<Real>::quiet_NaN();
  cloud.scalarField(field::rho)[900] = std::numeric_limits<Real>::infinity();
  const CloudHealth health = measureCloudHealth(cloud, box);
  EXPECT_EQ(health.nonFinite, 2u);
  EXPECT_EQ(health.outside, 1u);
  EXPECT_EQ(health.firstBad, 300u);
}

TEST(RunHealth, OneAndTwoThreadsFindTheSame) {
  ParticleCloud cloud = fluidWithDeviations(100000);
  cloud.scalarField(field::rho)[4242] = 2400 * 1.1;
  cloud.scalarField(field::rho)[77777] = 2400 * 1.1;  // the same deviation: the first one is named
  cloud.positions()[5000] = Vector(0, 5, 0);
  const int previous = omp_get_max_threads();
  omp_set_num_threads(1);
  const CloudHealth one = measureCloudHealth(cloud, box);
  omp_set_num_threads(2);
  const CloudHealth two = measureCloudHealth(cloud, box);
  omp_set_num_threads(previous);
  EXPECT_EQ(one.outside, two.outside);
  EXPECT_EQ(one.firstBad, two.firstBad);
  EXPECT_EQ(one.largestDensityDeviation, two.largestDensityDeviation);
  EXPECT_EQ(one.mostDeviating, two.mostDeviating);
  EXPECT_EQ(two.mostDeviating, 4242u);
}

TEST(RunHealth, WarningsArePrintedFirstThenOnlyWhenHalfAsBadAgain) {
  HealthWarnings warnings;
  EXPECT_TRUE(warnings.shouldPrint("density", 0.04));
  EXPECT_FALSE(warnings.shouldPrint("density", 0.05));
  EXPECT_TRUE(warnings.shouldPrint("density", 0.06));
  EXPECT_TRUE(warnings.shouldPrint("wall", 0.1));
  EXPECT_EQ(warnings.summary(), "warnings: 3 step(s) with density, 1 step(s) with wall");
}

TEST(RunHealth, ThresholdsAreReadFromControlDictAndChecked) {
  const HealthSettings defaults = HealthSettings::read(Dictionary::parse("endTime 1;"));
  EXPECT_EQ(defaults.maxDensityDeviation, 0.2);
  const HealthSettings set = HealthSettings::read(
      Dictionary::parse("healthChecks { maxDensityDeviation 0.1; minDeltaTFraction 1e-4; }"));
  EXPECT_EQ(set.maxDensityDeviation, 0.1);
  EXPECT_EQ(set.minDeltaTFraction, 1e-4);
  EXPECT_THROW(HealthSettings::read(Dictionary::parse("healthChecks { maxDensityDeviaton 0.1; }")),
               Error);
  EXPECT_THROW(HealthSettings::read(Dictionary::parse("healthChecks { maxWallPenetration -1; }")),
               Error);
  EXPECT_THROW(HealthSettings::read(Dictionary::parse(
                   "healthChecks { warnDensityDeviation 0.3; maxDensityDeviation 0.2; }")),
               Error);
  EXPECT_EQ(defaults.maxSpilledFraction, 0.05);
  EXPECT_FALSE(defaults.domain.has_value());
  const HealthSettings floor = HealthSettings::read(Dictionary::parse(
      "healthChecks { maxSpilledFraction 0.2; domain { lower (-1 -2 -0.5); upper (1 2 3); } }"));
  EXPECT_EQ(floor.maxSpilledFraction, 0.2);
  ASSERT_TRUE(floor.domain.has_value());
  EXPECT_EQ(floor.domain->lower.z(), Real(-0.5));
  EXPECT_EQ(floor.domain->upper.y(), Real(2));
  // upside down, a key misspelt, a fraction not positive: each names its key
  EXPECT_THROW(HealthSettings::read(Dictionary::parse(
                   "healthChecks { domain { lower (0 0 1); upper (1 1 0.5); } }")),
               Error);
  EXPECT_THROW(HealthSettings::read(
                   Dictionary::parse("healthChecks { domain { lower (0 0 0); uper (1 1 1); } }")),
               Error);
  EXPECT_THROW(HealthSettings::read(Dictionary::parse("healthChecks { maxSpilledFraction 0; }")),
               Error);
}

// Metal outside the domain is removed and booked: mass, count and heat (sum m u) exactly those
// of the removed particles, added to what spilled before; a second call with nothing outside
// changes nothing; the domain kept with the cloud reads back bit for bit.
TEST(MetalSpill, RemovesTheMetalOutsideAndBooksItsMassAndHeat) {
  ParticleCloud metal("metal");
  metal.resize(6);
  auto& mass = metal.addScalarField(field::mass);
  auto& u = metal.addScalarField(field::u);
  metal.addIdField(field::id);
  for (std::size_t i = 0; i < 6; ++i) {
    metal.positions()[i] = Vector(0, 0, Real(0.3) * Real(i) - Real(0.2));  // z -0.2 .. 1.3
    mass[i] = Real(0.001) * Real(i + 1);
    u[i] = Real(1e5) * Real(i + 2);
    metal.idField(field::id)[i] = static_cast<std::int64_t>(100 + i);
  }
  const Domain domain{Vector::Constant(-1), Vector(1, 1, Real(0.5))};  // z 0.7 .. 1.3 outside
  const Communicator serial = Communicator::self();
  const Spill first = spillOutside(metal, domain, nullptr, serial);
  EXPECT_EQ(first.particles, 3);
  const double massOut = 0.004 + 0.005 + 0.006;
  EXPECT_NEAR(first.mass, massOut, 1e-15);
  EXPECT_NEAR(first.energy, 0.004 * 5e5 + 0.005 * 6e5 + 0.006 * 7e5, 1e-9);
  EXPECT_NE(first.first.find("particle id 103"), std::string::npos) << first.first;
  ASSERT_EQ(metal.size(), 3u);
  EXPECT_EQ(metal.idField(field::id)[2], 102);
  EXPECT_EQ(metal.attributes().at("spilledParticles"), 3);
  EXPECT_NEAR(metal.attributes().at("spilledMass"), massOut, 1e-15);
  EXPECT_NEAR(metal.attributes().at("heatLost.spilled"), first.energy, 1e-12);
  EXPECT_NEAR(spilledFraction(metal, serial), massOut / 0.021, 1e-12);
  const Spill none = spillOutside(metal, domain, nullptr, serial);
  EXPECT_EQ(none.particles, 0);
  EXPECT_EQ(metal.size(), 3u);
  metal.positions()[0].x() = Real(-2);  // a second spill adds to the first
  EXPECT_EQ(spillOutside(metal, domain, nullptr, serial).particles, 1);
  EXPECT_EQ(metal.attributes().at("spilledParticles"), 4);
  EXPECT_NEAR(metal.attributes().at("spilledMass"), massOut + 0.001, 1e-15);

  EXPECT_FALSE(storedDomain(metal).has_value());
  storeDomain(metal, domain);
  const std::optional<Domain> kept = storedDomain(metal);
  ASSERT_TRUE(kept.has_value());
  EXPECT_EQ(kept->lower, domain.lower);
  EXPECT_EQ(kept->upper, domain.upper);
}

// A step that falls below a thousandth of its running mean is a collapse; one that only halves
// is not; a step that is not finite or not positive stops at once; restart() forgets the mean.
TEST(StepCollapseWatch, StopsWhenTheStableStepFallsFarBelowItsRunningMean) {
  StepCollapseWatch watch;
  for (int k = 0; k < 200; ++k) EXPECT_EQ(watch.check(1e-4, "acoustic CFL", 1e-3), "");
  EXPECT_EQ(watch.check(0.5e-4, "acoustic CFL", 1e-3), "");
  const std::string collapse = watch.check(5e-8, "viscous", 1e-3);
  EXPECT_NE(collapse.find("collapsed to 5e-08 s (viscous), below 0.001 of its running mean"),
            std::string::npos)
      << collapse;
  EXPECT_NE(watch.check(std::nan(""), "density rate", 1e-3).find("(density rate) is nan"),
            std::string::npos);
  EXPECT_NE(watch.check(0, "acoustic CFL", 1e-3), "");
  watch.restart();  // the cooling mode's steps are longer by design
  EXPECT_EQ(watch.check(5e-8, "heat", 1e-3), "");
  EXPECT_EQ(watch.check(1e-2, "heat", 1e-3), "");
}

}  // namespace
}  // namespace sphcast
