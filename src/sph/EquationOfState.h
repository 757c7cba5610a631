#pragma once

#include "core/Real.h"

namespace sphcast {

// Paper eq. (3): the linear (weakly compressible) equation of state p = c^2 (rho - rho_s), with
// rho_s the density at zero pressure (the material's rho_s(T) once the thermal models exist).
struct LinearEquationOfState {
  Real soundSpeed;

  Real pressure(Real density, Real restDensity) const {
    return soundSpeed * soundSpeed * (density - restDensity);
  }
  Real density(Real pressure, Real restDensity) const {
    return restDensity + pressure / (soundSpeed * soundSpeed);
  }
};

}  // namespace sphcast
