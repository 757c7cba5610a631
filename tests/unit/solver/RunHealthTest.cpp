// The run's health checks (solver/RunHealth.h): what they find, that two threads find the same,
// and how their thresholds are read.
#include "solver/RunHealth.h"

#include <omp.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"
#include "particles/FieldNames.h"

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
