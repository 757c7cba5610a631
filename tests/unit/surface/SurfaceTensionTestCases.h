#pragma once

// Droplets and a flow with surface tension without the solver: the same flow, force model and
// shared neighbourhood the solver steps, in the order its evolve() calls them.

#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "core/dictionary/Dictionary.h"
#include "materials/MaterialLibrary.h"
#include "particles/FieldNames.h"
#include "particles/Neighbourhood.h"
#include "sph/FlowTestCases.h"
#include "sph/WeaklyCompressibleFlow.h"
#include "surface/ContinuumSurfaceForce.h"
#include "surface/SurfaceEnergyTension.h"

namespace sphcast::testing {

// Gamma_g as the solver reads it: a constant of a material in physicalProperties.
inline TemperatureTable constantTension(double gamma) {
  const MaterialLibrary library = MaterialLibrary::fromDictionary(
      Dictionary::parse("liquid { surfaceTension " + std::to_string(gamma) + "; }",
                        "physicalProperties"),
      "physicalProperties");
  return *library.get("liquid", SourceLocation{}, "test").surfaceTension;
}

// The surface tension's settings for a fluid of spacing dx: the dimension, h, dx and a constant
// Gamma_g (N/m); the rest as the model defaults them.
inline SurfaceTensionSettings tensionSettings(int dimension, Real supportRadius, Real dx,
                                              double gamma) {
  SurfaceTensionSettings settings;
  settings.dimension = dimension;
  settings.supportRadius = supportRadius;
  settings.spacing = dx;
  settings.gasTension = constantTension(gamma);
  return settings;
}

// The speed of sound for which the surface layer's pull, R_d Gamma / dx, is `compression` of
// rho c^2 (the tutorials choose 1 %: doc/physics.md §10.1).
inline Real capillarySoundSpeed(Real energyFactor, Real gamma, Real dx, Real rho,
                                Real compression) {
  return std::sqrt(energyFactor * gamma / (dx * rho * compression));
}

// A fluid at rest of density rho and dynamic viscosity mu on the given positions, each particle
// carrying rho dx^d, with the fields the flow and the surface tension read.
inline ParticleCloud fluidAtRest(int dimension, Real dx, const std::vector<Vector>& positions,
                                 Real rho, Real mu) {
  ParticleCloud fluid("fluid");
  fluid.resize(positions.size());
  auto& U = fluid.addVectorField(field::U);
  auto& density = fluid.addScalarField(field::rho);
  auto& mass = fluid.addScalarField(field::mass);
  auto& viscosity = fluid.addScalarField(field::viscosity);
  auto& rest = fluid.addScalarField(field::restDensity);
  fluid.addVectorField(field::acceleration);
  fluid.addScalarField(field::densityRate);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    fluid.positions()[i] = positions[i];
    U[i] = Vector::Zero();
    density[i] = rest[i] = rho;
    mass[i] = rho * std::pow(dx, dimension);
    viscosity[i] = mu;
  }
  fluid.attributes()["spacing"] = dx;
  return fluid;
}

// The lattice particles (spacing dx, cell centres on (i + 1/2) dx, z = 0 in 2D) for which
// inside(x) holds, as a fluid at rest of density rho and dynamic viscosity mu; each particle
// moved by up to `jitter` dx along each axis when jitter > 0.
inline ParticleCloud latticeFluid(int dimension, Real dx, const Vector& lower, const Vector& upper,
                                  const std::function<bool(const Vector&)>& inside, Real rho,
                                  Real mu, Real jitter = 0, unsigned seed = 1) {
  std::vector<Vector> positions;
  const int nx = static_cast<int>(std::ceil((upper[0] - lower[0]) / dx));
  const int ny = static_cast<int>(std::ceil((upper[1] - lower[1]) / dx));
  const int nz = dimension == 3 ? static_cast<int>(std::ceil((upper[2] - lower[2]) / dx)) : 1;
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const Vector x = lower + dx * Vector(i + Real(0.5), j + Real(0.5),
                                             dimension == 3 ? k + Real(0.5) : Real(0));
        if (dimension == 2) {
          Vector planar = x;
          planar[2] = 0;
          if (inside(planar)) positions.push_back(planar);
        } else if (inside(x)) {
          positions.push_back(x);
        }
      }
    }
  }
  if (jitter > 0) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<Real> offset(-jitter * dx, jitter * dx);
    for (Vector& x : positions) {
      x[0] += offset(random);
      x[1] += offset(random);
      if (dimension == 3) x[2] += offset(random);
    }
  }
  return fluidAtRest(dimension, dx, positions, rho, mu);
}

// The radius of the disk (2D) or ball (3D) that `count` particles of dx^d each fill: a drop's
// radius from its volume.
inline double dropRadius(int dimension, std::size_t count, double dx) {
  const double n = static_cast<double>(count);
  return dimension == 2 ? std::sqrt(n * dx * dx / std::numbers::pi)
                        : std::cbrt(3 * n * dx * dx * dx / (4 * std::numbers::pi));
}

// A drop of radius R = layers dx centred on the origin, built of rings (2D) or shells (3D) of
// radius (k + 1/2) dx, k < layers, each with as many evenly spread particles as it has spacings
// of circumference (2D) or squared spacings of area (3D, on a Fibonacci spiral): a round drop
// without a lattice's staircase, every particle carrying about dx^d, at rest at density rho.
inline ParticleCloud ringFluid(int dimension, Real dx, int layers, Real rho, Real mu) {
  std::vector<Vector> positions;
  const double pi = std::numbers::pi;
  const double golden = pi * (3 - std::sqrt(5.0));
  for (int k = 0; k < layers; ++k) {
    const double r = (k + 0.5) * dx;
    if (dimension == 2) {
      const int count = std::max(1, static_cast<int>(std::lround(2 * pi * r / dx)));
      const double offset = 0.5 * (k % 2);  // alternate rings half a step apart
      for (int m = 0; m < count; ++m) {
        const double angle = 2 * pi * (m + offset) / count;
        positions.emplace_back(r * std::cos(angle), r * std::sin(angle), 0);
      }
    } else {
      const int count = std::max(1, static_cast<int>(std::lround(4 * pi * r * r / (dx * dx))));
      for (int m = 0; m < count; ++m) {
        const double z = count == 1 ? 0 : 1 - 2 * (m + 0.5) / count;
        const double ring = std::sqrt(std::max(0.0, 1 - z * z));
        const double angle = golden * m + k;  // each shell turned
        positions.emplace_back(r * ring * std::cos(angle), r * ring * std::sin(angle), r * z);
      }
    }
  }
  return fluidAtRest(dimension, dx, positions, rho, mu);
}

// A 3D floor of three wall layers in z < 0 (its surface z = 0, normals +z), 2 reach spacings a
// side about the origin, for a half ball resting on it.
inline ParticleCloud floorInZ(int reach, Real dx) {
  ParticleCloud wall = emptyWall();
  for (int k = -reach; k < reach; ++k) {
    addWallCells(
        wall, -reach, reach, -3, 0, dx, Vector(0, 0, (k + Real(0.5)) * dx),
        [](int, int) { return Vector(0, 1, 0); },
        [dx](int, int row) { return (-row - Real(0.5)) * dx; });
  }
  for (Vector& x : wall.positions()) x = Vector(x[0], x[2], x[1]);
  for (Vector& n : wall.vectorField(field::normal)) n = Vector(0, 0, 1);
  for (Real& v : wall.scalarField(field::volume)) v = dx * dx * dx;  // addWallCells gives 2D's dx^2
  return wall;
}

// A drop's mode read from the history of its moment (times, moments): the period from the zero
// crossings about the moment's mean over the run (a relaxed drop is not quite round, so its
// moment keeps an offset), the amplitude's decay rate from successive extremes (half a period
// apart); 0 where there are too few crossings or extremes.
struct ModeReading {
  double period = 0, decay = 0, mean = 0;
  std::vector<double> crossings, extremes;  // times; |moment - mean|
};

inline ModeReading readMode(const std::vector<double>& times, const std::vector<double>& moments) {
  ModeReading mode;
  for (const double m : moments) mode.mean += m;
  mode.mean /= static_cast<double>(moments.size());
  for (std::size_t k = 1; k < moments.size(); ++k) {
    const double previous = moments[k - 1] - mode.mean, now = moments[k] - mode.mean;
    if ((previous > 0) != (now > 0)) {
      mode.crossings.push_back(times[k - 1] +
                               (times[k] - times[k - 1]) * previous / (previous - now));
    }
    if (k >= 2) {
      const double before = moments[k - 2] - mode.mean;
      if (std::abs(previous) > std::abs(before) && std::abs(previous) >= std::abs(now)) {
        mode.extremes.push_back(std::abs(previous));
      }
    }
  }
  const std::size_t crossings = mode.crossings.size(), extremes = mode.extremes.size();
  if (crossings >= 3) {
    mode.period = (mode.crossings.back() - mode.crossings.front()) /
                  (0.5 * static_cast<double>(crossings - 1));
  }
  if (extremes >= 2 && mode.period > 0) {
    mode.decay = std::log(mode.extremes.front() / mode.extremes.back()) /
                 (0.5 * mode.period * static_cast<double>(extremes - 1));
  }
  return mode;
}

// A flow with surface tension (the model Tension: SurfaceEnergyTension or
// ContinuumSurfaceForce) over one shared neighbourhood, stepped as the solver's evolve() steps
// it: kick and drift, search, wall clearance, rates (the flow's, then the surface tension's) and
// kick.
template <class Tension = SurfaceEnergyTension>
struct CapillaryRun {
  CapillaryRun(const FlowSettings& flowSettings, const SurfaceTensionSettings& tensionSettings,
               ParticleCloud& fluid, std::vector<const ParticleCloud*> walls)
      : neighbourhood(flowSettings.supportRadius, flowSettings.periodic),
        flow(flowSettings, fluid, walls, registered(fluid, walls)),
        tension(tensionSettings, fluid, walls, neighbourhood) {
    flow.addForceModel(tension);
    neighbourhood.update();
    flow.start();
  }

  void step(double dt) {
    flow.kickAndDrift(dt);
    neighbourhood.update();
    flow.keepClearOfWalls();
    flow.computeRatesAndKick(dt);
    time += dt;
  }

  double stableDeltaT(double maxCo = 0.25) const {
    std::string limiter;
    return flow.stepLimits(maxCo).smallest(limiter);
  }

  Neighbourhood neighbourhood;
  WeaklyCompressibleFlow flow;
  Tension tension;
  double time = 0;

 private:
  Neighbourhood& registered(ParticleCloud& fluid, const std::vector<const ParticleCloud*>& walls) {
    neighbourhood.addCloud(fluid, Neighbourhood::Motion::moving);
    for (const ParticleCloud* wall : walls) neighbourhood.addFixedCloud(*wall);
    return neighbourhood;
  }
};

}  // namespace sphcast::testing
