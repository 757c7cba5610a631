#pragma once

#include <map>
#include <vector>

#include "bodies/RigidBody.h"
#include "case/CaseDescription.h"
#include "core/dictionary/Dictionary.h"

namespace sphcast {

// constant/dynamicBodies (optional): the mold clouds that move as rigid bodies, one
// sub-dictionary per body (bodies/RigidBody.h says how they move):
//
//   upperMold
//   {
//       cloud           upperMold;       // optional: the body's name
//       mass            0.8;             // kg; or density 7850; (kg/m^3, x the particles' volume)
//       centreOfMass    (0 0 0.023);     // optional: from the particles
//       momentOfInertia (1e-3 1e-3 2e-3);// optional: principal, along x y z; from the particles
//       translation     (0 0 1);         // free | locked | an axis it slides along
//       rotation        locked;          // free | locked
//       releaseTime     0.2;             // s, optional: held where it is until then
//       endStop         (0 0 -0.01875);  // optional: the centre's travel at which it stops
//       appliedForce    (0 0 -50);       // N, optional: a press cylinder's; or against time,
//                                        // ((0 (0 0 0)) (0.1 (0 0 -500)))
//       appliedPressure ((0 0) (0.2 1e7)); // Pa, optional: a press's curve (or a constant),
//       pressedArea     0.0195;          //   m^2, on this area
//       pressDirection  (0 0 -1);        //   the way it pushes the body
//   }
// The loads' tables are linear between their points and held at their ends; the force and the
// pressure's force add up.
//   punch
//   {
//       motion          prescribed;      // dynamic (the default) | prescribed
//       displacement    ((0 (0 0 0)) (0.5 (0 0 -0.01)));  // s, m: the centre's travel
//   }
//
// A body's cloud must be one of the flow's walls (constant/physicsModels, flow/walls).
struct BodySetup {
  std::vector<RigidBodySettings> bodies;
  std::map<std::string, SourceLocation> declaredAt;  // body name -> its sub-dictionary
};

BodySetup readBodySetup(const CaseDescription& description);

// The text of <time>/uniform/dynamicBodies for the bodies' state.
std::string bodyStateFile(const std::string& timeName, const std::vector<const RigidBody*>& bodies);

}  // namespace sphcast
