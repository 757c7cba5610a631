#pragma once

#include "particles/FieldNames.h"
#include "particles/Neighbourhood.h"
#include "sph/FlowTestCases.h"

namespace sphcast::testing {

// A 2D block of fluid (periodic in x, 24 rows: the middle rows have a full support) for the
// rheologies' tests, sheared simply about its middle, v_x = rate (y - its middle).
struct ShearedBlock {
  static constexpr int columns = 12, rows = 24;
  static constexpr Real dx = Real(1e-3);
  ParticleCloud fluid;
  Neighbourhood neighbourhood;

  ShearedBlock(Real density, Real viscosity)
      : fluid(fluidBlock2D(columns, rows, dx, Vector::Zero(), density, viscosity)),
        neighbourhood(3 * dx, periodicX()) {
    fluid.addVectorField(field::acceleration).assign(fluid.size(), Vector::Zero());
    neighbourhood.addCloud(fluid, Neighbourhood::Motion::moving);
    neighbourhood.requestPairs(fluid, fluid);
    neighbourhood.update();
  }
  static PeriodicBox periodicX() {
    PeriodicBox box;
    box.setPeriodic(0, 0, columns * dx);
    return box;
  }
  void shear(Real rate) {
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      const Real y = fluid.positions()[i].y() - Real(rows / 2) * dx;
      fluid.vectorField(field::U)[i] = Vector(rate * y, 0, 0);
    }
  }
  // the particles a full support away from the top and bottom
  bool interior(std::size_t i) const {
    const Real y = fluid.positions()[i].y();
    return y > Real(3.5) * dx && y < (rows - Real(3.5)) * dx;
  }
};

}  // namespace sphcast::testing
