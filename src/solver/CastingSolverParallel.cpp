// The solver's decomposed run (-parallel): which clouds are cut among the ranks, what each
// particle weighs, how far each cloud's halo reaches, and the search through the decomposition.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/Error.h"
#include "parallel/DecompositionSettings.h"
#include "particles/FieldNames.h"
#include "particles/GradedPairs.h"
#include "solver/CastingSolver.h"

namespace sphcast {

namespace {
// the cloud attribute that says for which h / dx its supportReach was made
constexpr const char* supportReachHOverDx = "supportReachHOverDx";
}  // namespace

// -parallel decomposes the flow's fluid and walls (every model of a casting runs on them), or,
// without a flow, the heat clouds. A case with neither (ballistic clouds alone), or with heat
// in a cloud that is neither the fluid nor a wall, is refused. Every rank refuses alike (a
// CollectiveError: rank 0 says it).
void CastingSolver::checkParallelSupport() const {
  auto refuse = [&](const std::string& what) {
    throw CollectiveError("-parallel: " + what +
                          " does not run decomposed in this version; run the case serial "
                          "(without mpirun and -parallel). Decomposed runs take the flow's fluid "
                          "and walls with every model on them, or the heat clouds without a flow.");
  };
  if (!flowSetup_.enabled && !heatSetup_.enabled) {
    refuse("a case without a flow or heat (constant/physicsModels: flow, heatTransfer)");
  }
  if (!flowSetup_.enabled) return;
  // the heat clouds must be decomposed: the flow's fluid or its walls
  for (const std::string& name : heatSetup_.clouds) {
    const auto& walls = flowSetup_.wallClouds;
    const bool wall = std::find(walls.begin(), walls.end(), name) != walls.end();
    if (name != flowSetup_.fluidCloud && !wall) {
      refuse("heat cloud '" + name + "', neither the flow's fluid nor one of its walls,");
    }
  }
}

// Cuts space among the ranks by system/decomposeParDict, and leaves each rank the fluid and
// wall particles of its subdomain with their halos (the neighbour search's reach, h + skin; a
// graded mold's coarsest support plus the skin);
// without a flow, the heat clouds' particles, every one of equal weight (each costs its
// conduction pairs), none migrating (nothing moves).
void CastingSolver::decompose() {
  DecompositionSettings decomposeParDict;
  try {
    decomposeParDict =
        readDecompositionSettings(caseFolder_, comm_.size(), description_.dimension());
  } catch (const Error& error) {
    throw CollectiveError(error.what());  // every rank read the same file
  }
  models_.decomposition = std::make_unique<DomainDecomposition>(
      comm_, decomposeParDict,
      static_cast<double>(models_.neighbourhood->radius() + models_.neighbourhood->skin()),
      models_.neighbourhood->periodicBox(), description_.dimension());
  std::vector<DomainDecomposition::Cloud> decomposed;
  if (!flowSetup_.enabled) {
    for (const std::string& name : heatSetup_.clouds) decomposed.push_back({&cloudNamed(name)});
  } else {
    auto writable = [&](const ParticleCloud* cloud) -> ParticleCloud* {
      for (ParticleCloud& c : clouds_) {
        if (&c == cloud) return &c;
      }
      for (ParticleCloud& c : staticClouds_) {
        if (&c == cloud) return &c;
      }
      throw Error("internal: a wall cloud the solver does not hold");
    };
    // The weights: what a particle costs a step. A wall particle costs only where fluid is
    // within h of it (its extrapolated pressure, its place in the fluid's lists), most of a
    // mold's particles nothing. Measured on the 3D dam break (10,850 water, 24,682 wall
    // particles, 2 ranks): fluid 3 : wall 1 left nearly all the water on one rank (17.8 s),
    // 30 : 1 and 1 : 0 split it (14.5 and 14.7 s).
    constexpr std::int64_t fluidWeight = 30, wallWeight = 1;
    decomposed.push_back({&cloudNamed(flowSetup_.fluidCloud), true, fluidWeight});
    // a moving mold's particles migrate as the fluid's do
    for (const ParticleCloud* wall : models_.walls) {
      bool moving = false;
      for (const RigidBodySettings& body : bodySetup_.bodies) moving |= body.cloud == wall->name();
      decomposed.push_back({writable(wall), moving, wallWeight});
    }
  }
  // a mold particleized at graded spacing: its halo reaches at most its coarsest particles'
  // support h l_max / dx (their pairs within it, thermal/GradedConduction.h, sph/ExposedArea.h),
  // each particle its supportReach (GradedPairs.h): made where one rank holds the whole cloud
  // (a serial start), read back with the cloud at a restart (written with it)
  double smallestSpacing = 0;
  for (const auto& entry : decomposed) {
    const auto attribute = entry.cloud->attributes().find("spacing");
    if (attribute == entry.cloud->attributes().end()) continue;
    smallestSpacing =
        smallestSpacing == 0 ? attribute->second : std::min(smallestSpacing, attribute->second);
  }
  for (auto& entry : decomposed) {
    double coarsest = 0;
    if (entry.cloud->hasScalarField(field::localSpacing)) {
      for (const Real l : entry.cloud->scalarField(field::localSpacing)) {
        coarsest = std::max(coarsest, static_cast<double>(l));
      }
    }
    coarsest = comm_.max(coarsest);  // a serial start's particles are all on rank 0
    if (coarsest > smallestSpacing && smallestSpacing > 0) {
      const double hOverDx = models_.neighbourhood->radius() / smallestSpacing;
      entry.haloRadius = hOverDx * coarsest + models_.neighbourhood->skin();
      entry.skin = models_.neighbourhood->skin();
      ParticleCloud& cloud = *entry.cloud;
      // the reaches hold for the h / dx they were made with (the cloud's attribute)
      const auto made = cloud.attributes().find(supportReachHOverDx);
      const bool current = cloud.hasScalarField(field::supportReach) &&
                           made != cloud.attributes().end() &&
                           std::abs(made->second - hOverDx) <= 1e-9 * hOverDx;
      const auto owned = static_cast<std::int64_t>(cloud.ownedSize());
      const bool whole = comm_.max(owned == comm_.sum(owned) ? 1.0 : 0.0) > 0;
      if (!current && whole) {
        auto& reach = cloud.hasScalarField(field::supportReach)
                          ? cloud.scalarField(field::supportReach)
                          : cloud.addScalarField(field::supportReach);
        if (cloud.size() > 0) {
          const auto& placed = cloud.hasVectorField(field::restPosition)
                                   ? cloud.vectorField(field::restPosition)
                                   : cloud.positions();
          reach =
              gradedSupportReach(placed, cloud.scalarField(field::localSpacing),
                                 static_cast<Real>(hOverDx), models_.neighbourhood->periodicBox());
        }
        cloud.attributes()[supportReachHOverDx] = hOverDx;
      }
      // else, a restart's pieces without current reaches: every particle sent within the
      // coarsest support
      entry.perParticleReach = current || whole;
    }
  }
  models_.decomposition->distribute(decomposed);
  models_.neighbourhood->setHaloSync(models_.decomposition.get());
  info() << "Decomposition: " << models_.decomposition->describe() << '\n';
  if (!decomposeParDict.note.empty())
    info() << "  (decomposeParDict: " << decomposeParDict.note << ")\n";
}

void CastingSolver::searchNeighbours(CloudOrder order, bool rebuild) {
  if (models_.decomposition) {
    models_.decomposition->update(*models_.neighbourhood, rebuild);
  } else {
    models_.neighbourhood->update(order, rebuild);
  }
}

}  // namespace sphcast
