#pragma once

#include <memory>
#include <vector>

#include "parallel/DomainDecomposition.h"
#include "particles/Neighbourhood.h"
#include "particles/ParticleCloud.h"
#include "rheology/RheologyModel.h"
#include "solidification/Solidification.h"
#include "solver/MovingMolds.h"
#include "solver/PouringInlets.h"
#include "sph/ExposedArea.h"
#include "sph/FillTime.h"
#include "sph/WeaklyCompressibleFlow.h"
#include "surface/SurfaceTensionModel.h"
#include "thermal/EnergyEquation.h"

namespace sphcast {

// The models a run built from the case (CastingSolverSetup.cpp), over one neighbourhood: what
// the step (CastingSolver.cpp) steps and the monitor (RunMonitor.h) watches. A model the case
// does not name is absent (null, or empty for the bodies and inlets).
struct CastingModels {
  // The cell grids and pair lists of every model, built once per step (with flow or heat).
  std::unique_ptr<Neighbourhood> neighbourhood;
  std::unique_ptr<DomainDecomposition> decomposition;  // a parallel run's
  std::unique_ptr<WeaklyCompressibleFlow> flow;
  std::unique_ptr<SurfaceTensionModel> surfaceTension;  // a force model of the flow
  std::unique_ptr<RheologyModel> rheology;              // the fluid's viscosity beyond mu(T)
  ParticleCloud* fluid = nullptr;                       // the flow's
  std::vector<const ParticleCloud*> walls;              // the flow's walls
  std::unique_ptr<EnergyEquation> energy;
  std::unique_ptr<Solidification> solidification;  // follows the fluid's T after heat steps
  std::unique_ptr<ExposedArea> exposedArea;        // A_i, when a model reads it
  std::unique_ptr<FillTime> fillTime;              // the fluid's first wall contact
  MovingMolds movingMolds;                         // the rigid bodies: moving walls of the flow
  PouringInlets pouringInlets;                     // feed the fluid
};

}  // namespace sphcast
