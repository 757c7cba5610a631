#pragma once

// Lattice blocks of particles and a thermal run without the solver: the same EnergyEquation,
// paths and neighbourhood the solver steps, in the order its evolve() calls them when nothing
// flows (halfKick, computeRates, halfKick).

#include <cmath>
#include <deque>
#include <functional>
#include <memory>
#include <string>

#include "core/dictionary/Dictionary.h"
#include "materials/MaterialLibrary.h"
#include "particles/FieldNames.h"
#include "particles/Neighbourhood.h"
#include "sph/ExposedArea.h"
#include "thermal/EnergyEquation.h"

namespace sphcast::testing {

// A block of nx x ny x nz particles on the lattice (lower + (i + 1/2) dx), nz = 1 in 2D (then
// at z = 0), each with volume dx^d, temperature T, and the attribute spacing.
inline ParticleCloud latticeBlock(const std::string& name, const Vector& lower, int nx, int ny,
                                  int nz, Real dx, int dimension, Real T) {
  ParticleCloud cloud(name);
  cloud.resize(static_cast<std::size_t>(nx) * ny * nz);
  auto& volume = cloud.addScalarField(field::volume);
  auto& temperature = cloud.addScalarField(field::T);
  std::size_t n = 0;
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i, ++n) {
        cloud.positions()[n] =
            lower + dx * Vector(i + Real(0.5), j + Real(0.5), dimension == 3 ? k + Real(0.5) : 0);
        volume[n] = std::pow(dx, dimension);
        temperature[n] = T;
      }
    }
  }
  cloud.attributes()["spacing"] = dx;
  return cloud;
}

// A held mold with a surface, as particleizeMold writes one, for a 2D strip `across` particles
// wide: `layers` columns of the lattice behind the surface x = x0 (to the left when left is
// true), the first centred dx/2 behind it, each with its depth (wallDistance) and the normal out
// of the mold. Without the two fields (withSurface false: a box of setCastFields) the solver
// places the same surface at the start.
inline ParticleCloud heldSurfaceColumns(const std::string& name, Real x0, bool left, int layers,
                                        int across, Real dx, Real T, bool withSurface = true) {
  ParticleCloud cloud =
      latticeBlock(name, Vector(left ? x0 - layers * dx : x0, 0, 0), layers, across, 1, dx, 2, T);
  if (!withSurface) return cloud;
  auto& depth = cloud.addScalarField(field::wallDistance);
  auto& normal = cloud.addVectorField(field::normal);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    depth[i] = std::abs(cloud.positions()[i][0] - x0);
    normal[i] = Vector(left ? 1 : -1, 0, 0);
  }
  return cloud;
}

// Keeps only the particles for which keep(x) holds.
inline void keepWhere(ParticleCloud& cloud, const std::function<bool(const Vector&)>& keep) {
  std::vector<std::size_t> order, dropped;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    (keep(cloud.positions()[i]) ? order : dropped).push_back(i);
  }
  const std::size_t keptCount = order.size();
  order.insert(order.end(), dropped.begin(), dropped.end());
  cloud.reorder(order);  // the kept first, in their order
  cloud.resize(keptCount);
}

inline MaterialLibrary materials(const std::string& text) {
  return MaterialLibrary::fromDictionary(Dictionary::parse(text, "physicalProperties"),
                                         "physicalProperties");
}

// Clouds (stable addresses), their materials, a neighbourhood and the energy equation.
struct ThermalRun {
  int dimension;
  Real supportRadius;
  Real spacing;
  MaterialLibrary library;
  std::deque<ParticleCloud> clouds;
  std::vector<HeatCloud> heat;
  PeriodicBox periodic;
  std::unique_ptr<Neighbourhood> neighbourhood;
  std::unique_ptr<EnergyEquation> energy;
  std::unique_ptr<ExposedArea> exposedArea;
  double time = 0;
  long steps = 0;
  double maxDi = 0.1;  // controlDict's, the conduction step maxDi dx^2 / alpha_max

  ThermalRun(int dimension_, Real supportRadius_, Real spacing_, MaterialLibrary library_)
      : dimension(dimension_),
        supportRadius(supportRadius_),
        spacing(spacing_),
        library(std::move(library_)) {}

  ParticleCloud& add(ParticleCloud cloud, const std::string& material, bool held = false,
                     double heldTemperature = 0) {
    clouds.push_back(std::move(cloud));
    heat.push_back({&clouds.back(),
                    &library.get(material, SourceLocation(), "material"),
                    held,
                    heldTemperature,
                    {}});
    return clouds.back();
  }

  // Builds the paths heatTransfer (the text of the sub-dictionary) switches on and starts.
  void start(const std::string& heatTransfer) {
    neighbourhood = std::make_unique<Neighbourhood>(supportRadius, periodic);
    for (ParticleCloud& cloud : clouds)
      neighbourhood->addCloud(cloud, Neighbourhood::Motion::fixed);
    HeatTransferContext context;
    context.dimension = dimension;
    context.supportRadius = supportRadius;
    context.spacing = spacing;
    context.maxDi = maxDi;
    context.clouds = heat;
    context.neighbourhood = neighbourhood.get();
    const Dictionary dict =
        Dictionary::parse("heatTransfer {" + heatTransfer + "}", "physicsModels");
    energy = std::make_unique<EnergyEquation>(context, dict.subDict("heatTransfer"));
    if (energy->needsExposedArea()) {
      std::vector<ParticleCloud*> exposed;
      std::vector<const ParticleCloud*> covering;
      for (ParticleCloud& cloud : clouds) {
        exposed.push_back(&cloud);
        covering.push_back(&cloud);
      }
      exposedArea =
          std::make_unique<ExposedArea>(energy->exposedAreaForm(), dimension, supportRadius,
                                        spacing, exposed, covering, *neighbourhood);
    }
    neighbourhood->update(CloudOrder::keep);
    if (exposedArea) exposedArea->compute();
    energy->start();
  }

  double stableDeltaT() const {
    std::string limiter;
    return energy->stableDeltaT(limiter);
  }

  // Steps to `end` with the stable step times `fraction`, the last step shortened to land on it.
  void advanceTo(double end, double fraction = 1.0) {
    const double stable = fraction * stableDeltaT();
    while (time < end * (1 - 1e-12)) {
      const double dt = std::min(stable, end - time);
      energy->halfKick(dt);
      energy->computeRates();
      energy->halfKick(dt);
      time += dt;
      ++steps;
    }
  }

  double internalEnergy(const ParticleCloud& cloud) const {
    const auto& mass = cloud.scalarField(field::mass);
    const auto& u = cloud.scalarField(field::u);
    double total = 0;
    for (std::size_t i = 0; i < u.size(); ++i) total += double(mass[i]) * double(u[i]);
    return total;
  }
};

}  // namespace sphcast::testing
