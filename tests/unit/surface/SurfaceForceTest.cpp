// The surface-tension force is the exact gradient of the surface energy (8): against central
// differences of the energy, with and without a wetting wall; its pair part conserves momentum;
// a flat free surface carries Gamma_g per unit area with the calibrated R_d.

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

#include <omp.h>

#include "SurfaceTensionTestCases.h"
#include "particles/FieldNames.h"
#include "sph/ExposedArea.h"
#include "sph/FlowTestCases.h"

namespace sphcast {
namespace {

using testing::latticeFluid;
using testing::tensionSettings;

// The force of the model on every particle (m a, acceleration zeroed first).
std::vector<Vector> forces(SurfaceEnergyTension& tension, ParticleCloud& fluid) {
  auto& a = fluid.vectorField(field::acceleration);
  std::fill(a.begin(), a.end(), Vector::Zero());
  tension.addAcceleration();
  std::vector<Vector> f(fluid.size());
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = fluid.scalarField(field::mass)[i] * a[i];
  return f;
}

// -dE/dx_k by central differences, the neighbourhood searched again at every displaced state
// (the fluid's order kept).
Vector energyGradientByDifferences(SurfaceEnergyTension& tension, ParticleCloud& fluid,
                                   Neighbourhood& neighbourhood, std::size_t k, int dimension,
                                   Real delta) {
  Vector gradient = Vector::Zero();
  for (int axis = 0; axis < dimension; ++axis) {
    Vector& x = fluid.positions()[k];
    const Real x0 = x[axis];
    x[axis] = x0 + delta;
    neighbourhood.update(CloudOrder::keep);
    const double plus = tension.energy();
    x[axis] = x0 - delta;
    neighbourhood.update(CloudOrder::keep);
    const double minus = tension.energy();
    x[axis] = x0;
    gradient[axis] = static_cast<Real>((plus - minus) / (2 * delta));
  }
  neighbourhood.update(CloudOrder::keep);
  return -gradient;
}

struct Blob {
  int dimension;
  Real jitter;
};

class SurfaceForceIsTheEnergyGradient : public ::testing::TestWithParam<Blob> {};

TEST_P(SurfaceForceIsTheEnergyGradient, ForEveryParticleOfAJitteredDroplet) {
  const Blob blob = GetParam();
  const int d = blob.dimension;
  const Real dx = 1e-3, h = 3 * dx, radius = (d == 2 ? 6 : 3.6) * dx;
  ParticleCloud fluid = latticeFluid(
      d, dx, Vector::Constant(-radius - dx), Vector::Constant(radius + dx),
      [&](const Vector& x) { return x.norm() < radius; }, 1000, 1e-3, blob.jitter);
  Neighbourhood neighbourhood(h, PeriodicBox());
  neighbourhood.addCloud(fluid, Neighbourhood::Motion::moving);
  SurfaceTensionSettings settings = tensionSettings(d, h, dx, 0.07);
  settings.densityCoupling = false;  // -dE/dx at fixed densities (the coupling: below)
  SurfaceEnergyTension tension(settings, fluid, {}, neighbourhood);
  neighbourhood.update(CloudOrder::keep);
  const std::vector<Vector> f = forces(tension, fluid);
  Real largest = 0;
  for (const Vector& fk : f) largest = std::max(largest, fk.norm());
  ASSERT_GT(largest, 0);
  Real worst = 0;
  int interior = 0;
  for (std::size_t k = 0; k < fluid.size(); ++k) {
    const Vector expected =
        energyGradientByDifferences(tension, fluid, neighbourhood, k, d, Real(1e-6) * dx);
    worst = std::max(worst, (f[k] - expected).norm());
    if (fluid.positions()[k].norm() < radius - h && expected.norm() < 1e-12 * largest) ++interior;
  }
  EXPECT_LT(worst, 1e-6 * largest) << fluid.size() << " particles";
  // particles deeper than h carry no force: g is zero around them
  if (blob.jitter == 0) {
    EXPECT_GT(interior, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(Droplets, SurfaceForceIsTheEnergyGradient,
                         ::testing::Values(Blob{2, 0}, Blob{2, 0.15}, Blob{3, 0.15}),
                         [](const auto& parameter) {
                           return std::to_string(parameter.param.dimension) + "D" +
                                  (parameter.param.jitter > 0 ? "Jittered" : "Lattice");
                         });

// A 2D drop on a flat wall, contact angle 60 degrees: the wall term (chi of the wall distance)
// is the gradient too; the wall normal is the same everywhere, so l is smooth.
TEST(SurfaceForce, IsTheEnergyGradientBesideAWettingWall) {
  const Real dx = 1e-3, h = 3 * dx;
  ParticleCloud fluid = latticeFluid(
      2, dx, Vector(-8 * dx, 0, 0), Vector(8 * dx, 8 * dx, 0),
      [&](const Vector& x) { return (x - Vector(0, 0, 0)).norm() < 7 * dx; }, 1000, 1e-3, 0.1);
  ParticleCloud wall = testing::emptyWall();
  testing::addWallCells(
      wall, -12, 12, -3, 0, dx, Vector::Zero(), [](int, int) { return Vector(0, 1, 0); },
      [dx](int, int row) { return (-row - Real(0.5)) * dx; });
  Neighbourhood neighbourhood(h, PeriodicBox());
  neighbourhood.addCloud(fluid, Neighbourhood::Motion::moving);
  neighbourhood.addFixedCloud(wall);
  SurfaceTensionSettings settings = tensionSettings(2, h, dx, 0.07);
  settings.densityCoupling = false;  // -dE/dx at fixed densities (the coupling: below)
  settings.cosContactAngle = Real(0.5);
  SurfaceEnergyTension tension(settings, fluid, {&wall}, neighbourhood);
  neighbourhood.update(CloudOrder::keep);
  const std::vector<Vector> f = forces(tension, fluid);
  Real largest = 0;
  for (const Vector& fk : f) largest = std::max(largest, fk.norm());
  Real worst = 0;
  Real wallPull = 0;  // the net force towards the wall: the wall's part, pair parts cancel
  for (std::size_t k = 0; k < fluid.size(); ++k) {
    const Vector expected =
        energyGradientByDifferences(tension, fluid, neighbourhood, k, 2, Real(1e-6) * dx);
    worst = std::max(worst, (f[k] - expected).norm());
    wallPull += f[k][1];
  }
  EXPECT_LT(worst, 1e-6 * largest);
  EXPECT_LT(wallPull, -1e-3 * largest);  // a wetting wall pulls the drop onto it
}

// dE/drho_j, which the density coupling turns into a pressure, against central differences of
// the energy in rho_j, for every particle of a jittered 3D drop and of a 2D drop on a wall.
TEST(SurfaceEnergy, DensityDerivativeIsTheDerivativeOfTheEnergy) {
  const Real dx = 1e-3, h = 3 * dx;
  for (const int d : {2, 3}) {
    const Real radius = (d == 2 ? 6 : 3.6) * dx;
    ParticleCloud fluid = latticeFluid(
        d, dx, Vector::Constant(-radius - dx), Vector::Constant(radius + dx),
        [&](const Vector& x) { return x.norm() < radius; }, 1000, 1e-3, 0.15);
    for (std::size_t i = 0; i < fluid.size(); ++i) {  // densities a few per cent apart
      fluid.scalarField(field::rho)[i] = 1000 * (1 + Real(0.03) * std::sin(Real(i)));
    }
    Neighbourhood neighbourhood(h, PeriodicBox());
    neighbourhood.addCloud(fluid, Neighbourhood::Motion::moving);
    const SurfaceTensionSettings settings = tensionSettings(d, h, dx, 0.07);
    SurfaceEnergyTension tension(settings, fluid, {}, neighbourhood);
    neighbourhood.update(CloudOrder::keep);
    const std::vector<Real> psi = tension.densityDerivative();
    Real largest = 0, worst = 0;
    for (const Real value : psi) largest = std::max(largest, std::abs(value));
    ASSERT_GT(largest, 0);
    for (std::size_t j = 0; j < fluid.size(); ++j) {
      Real& rho = fluid.scalarField(field::rho)[j];
      const Real rho0 = rho, delta = Real(1e-6) * rho0;
      rho = rho0 + delta;
      const double plus = tension.energy();
      rho = rho0 - delta;
      const double minus = tension.energy();
      rho = rho0;
      worst = std::max(worst, std::abs(static_cast<Real>((plus - minus) / (2 * delta)) - psi[j]));
    }
    EXPECT_LT(worst, 1e-6 * largest) << d << "D";
  }
}

// Without walls the forces are pair forces, equal and opposite, along x_kj (the density
// coupling's too): the total force and torque are zero to round-off.
TEST(SurfaceForce, ConservesMomentumPairByPair) {
  const Real dx = 1e-3, h = 3 * dx, radius = 8 * dx;
  ParticleCloud fluid = latticeFluid(
      3, dx, Vector::Constant(-radius), Vector::Constant(radius),
      [&](const Vector& x) { return x.cwiseProduct(Vector(1, 1.4, 0.8)).norm() < radius; }, 1000,
      1e-3, 0.2);
  Neighbourhood neighbourhood(h, PeriodicBox());
  neighbourhood.addCloud(fluid, Neighbourhood::Motion::moving);
  const SurfaceTensionSettings settings = tensionSettings(3, h, dx, 0.07);
  SurfaceEnergyTension tension(settings, fluid, {}, neighbourhood);
  neighbourhood.update();
  const std::vector<Vector> f = forces(tension, fluid);
  Vector total = Vector::Zero();
  Real sumOfMagnitudes = 0;
  for (const Vector& fk : f) {
    total += fk;
    sumOfMagnitudes += fk.norm();
  }
  EXPECT_LT(total.norm(), 1e-13 * sumOfMagnitudes);
  // angular momentum too: each pair force lies along x_kj
  Vector torque = Vector::Zero();
  for (std::size_t k = 0; k < f.size(); ++k) torque += fluid.positions()[k].cross(f[k]);
  EXPECT_LT(torque.norm(), 1e-13 * sumOfMagnitudes * radius);
}

// Skipping the pairs inside the fluid changes nothing: their terms are exactly zero.
TEST(SurfaceForce, SkippingInteriorPairsGivesTheSameBits) {
  const Real dx = 1e-3, h = 3 * dx, radius = 10 * dx;
  ParticleCloud fluid = latticeFluid(
      3, dx, Vector::Constant(-radius), Vector::Constant(radius),
      [&](const Vector& x) { return x.norm() < radius; }, 1000, 1e-3, 0.1);
  ParticleCloud copy = fluid;
  auto forcesWith = [&](ParticleCloud& cloud, bool surfaceOnly, std::size_t& pairs) {
    Neighbourhood neighbourhood(h, PeriodicBox());
    neighbourhood.addCloud(cloud, Neighbourhood::Motion::moving);
    SurfaceTensionSettings settings = tensionSettings(3, h, dx, 0.07);
    settings.surfaceParticlesOnly = surfaceOnly;
    SurfaceEnergyTension tension(settings, cloud, {}, neighbourhood);
    neighbourhood.update(CloudOrder::keep);
    pairs = neighbourhood.pairCount();
    return forces(tension, cloud);
  };
  std::size_t pairs = 0;
  const std::vector<Vector> all = forcesWith(fluid, false, pairs);
  const std::vector<Vector> surface = forcesWith(copy, true, pairs);
  for (std::size_t k = 0; k < all.size(); ++k) {
    ASSERT_EQ(all[k], surface[k]) << "particle " << k;
  }
}

// Both passes (s_i and the energy; the pair forces), beside a wetting wall, give the same bits
// on one and two threads: each particle gathers over its own neighbours in a fixed order.
TEST(SurfaceForce, SameBitsOnOneAndTwoThreads) {
  const Real dx = 1e-3, h = 3 * dx;
  auto forcesOn = [&](int threads) {
    omp_set_num_threads(threads);
    ParticleCloud fluid = latticeFluid(
        3, dx, Vector(-8 * dx, -8 * dx, 0), Vector(8 * dx, 8 * dx, 8 * dx),
        [&](const Vector& x) { return x.norm() < 7 * dx; }, 1000, 1e-3, 0.1);
    ParticleCloud wall = testing::floorInZ(10, dx);  // three layers under the half ball
    Neighbourhood neighbourhood(h, PeriodicBox());
    neighbourhood.addCloud(fluid, Neighbourhood::Motion::moving);
    neighbourhood.addFixedCloud(wall);
    SurfaceTensionSettings settings = tensionSettings(3, h, dx, 0.07);
    settings.cosContactAngle = Real(0.5);
    SurfaceEnergyTension tension(settings, fluid, {&wall}, neighbourhood);
    neighbourhood.update(CloudOrder::keep);
    return forces(tension, fluid);
  };
  const std::vector<Vector> one = forcesOn(1);
  const std::vector<Vector> two = forcesOn(2);
  omp_set_num_threads(1);
  Real wallPull = 0;
  for (std::size_t k = 0; k < one.size(); ++k) {
    ASSERT_EQ(one[k], two[k]) << "particle " << k;
    wallPull += one[k][2];
  }
  EXPECT_LT(wallPull, 0);  // the wall term ran: a wetting floor pulls the drop down
}

// A flat free surface of the lattice (a periodic slab, two faces) carries Gamma_g per unit length
// with the lattice's R_d, and 1 / relaxedTensionRatio times that with the calibrated one.
TEST(SurfaceEnergy, OfALatticeFaceIsGammaTimesItsLengthWithTheLatticeFactor) {
  const Real dx = 1e-3, h = 3 * dx, width = 30 * dx, thickness = 12 * dx;
  ParticleCloud fluid = latticeFluid(
      2, dx, Vector(0, 0, 0), Vector(width, thickness, 0), [](const Vector&) { return true; }, 1000,
      1e-3);
  PeriodicBox periodic;
  periodic.setPeriodic(0, 0, width);
  const Real gamma = 0.07;
  const Real lattice = SurfaceEnergyTension::latticeEnergyFactor(2, h, dx, 1);
  for (const Real factor : {lattice, Real(0), Real(41.4)}) {
    Neighbourhood neighbourhood(h, periodic);
    neighbourhood.addCloud(fluid, Neighbourhood::Motion::moving);
    SurfaceTensionSettings settings = tensionSettings(2, h, dx, gamma);
    settings.energyFactor = factor;
    SurfaceEnergyTension tension(settings, fluid, {}, neighbourhood);
    neighbourhood.update(CloudOrder::keep);
    const double ratio = tension.energy() / (2 * width * gamma);
    // the calibration sums a half lattice on its own; here the slab's particles do
    const double expected =
        (factor == 0 ? SurfaceEnergyTension::calibratedEnergyFactor(2, h, dx, 1) : factor) /
        lattice;
    EXPECT_NEAR(ratio, expected, 1e-12);
  }
}

}  // namespace
}  // namespace sphcast
