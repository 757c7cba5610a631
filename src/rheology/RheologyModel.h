#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/Registry.h"
#include "materials/Material.h"
#include "particles/Neighbourhood.h"
#include "particles/ParticleCloud.h"
#include "rheology/ShearRate.h"

namespace sphcast {

class Dictionary;
class FluidForceModel;

// What a rheology is built on: the flow's fluid (with T and solidFraction where the metal
// solidifies), its material, the neighbourhood whose fluid and wall pairs give the velocity
// gradient, the flow's walls (shearWalls), the dimension and h.
struct RheologyContext {
  ParticleCloud& fluid;
  const Material& material;
  const Neighbourhood& neighbourhood;
  std::vector<ShearWall> walls;
  int dimension;
  Real supportRadius;
};

// A law for the fluid's dynamic viscosity (the field `viscosity`, Pa s) beyond the material's
// mu(T): before the rates of every flow step it writes the viscosity of the state the step
// starts from (after the search), and whatever state it keeps (a restart reads it back). The
// flow's viscous term then takes that field, explicitly or implicitly (sph/ImplicitViscosity.h).
class RheologyModel {
 public:
  virtual ~RheologyModel() = default;

  // The viscosity for a flow step of dt about to be taken (its state integrated over dt).
  virtual void update(double dt) = 0;
  // The fields it writes (restart state beside `viscosity`).
  virtual std::vector<std::string> fields() const = 0;
  // What the model is, with its constants, for the log (one or more lines, no trailing newline).
  virtual std::string description() const = 0;
  // The solid fraction at which the mush stops flowing and a particle freezes, or a negative
  // value where the model sets none (solidification's frozenSolidFraction then holds).
  virtual Real coherentSolidFraction() const { return Real(-1); }
  // Whether update writes the viscosity (the solidification then leaves it alone); the
  // Newtonian mu(T) is the solidification's to write.
  virtual bool writesViscosity() const { return true; }
  // A law with a stress of its own (ElastoViscoplastic.h) returns the force the flow adds at
  // every evaluation of the rates; a viscosity law returns null.
  virtual FluidForceModel* force() { return nullptr; }
};

// A law's coefficient `key` from its <model>Coeffs dictionary: positive, or zero where
// zeroAllowed; anything else (negative, not finite) is an error naming the entry.
Real lawCoefficient(const Dictionary& coeffs, const char* key, bool zeroAllowed);

// The models by the names physicsModels gives them (rheology { model NAME; <NAME>Coeffs {} }),
// each built from the context and the rheology dictionary; registered in RheologyModel.cpp, the
// first the default.
using RheologyModels = Registry<RheologyModel, const RheologyContext&, const Dictionary&>;
RheologyModels& rheologyModels();

// The paper's: mu(T) of the material's table, as the solidification (and the flow's start)
// write it; nothing to do per step.
class NewtonianViscosity : public RheologyModel {
 public:
  NewtonianViscosity(const RheologyContext& context, const Dictionary& settings);
  void update(double) override {}
  std::vector<std::string> fields() const override { return {}; }
  bool writesViscosity() const override { return false; }
  std::string description() const override {
    return "Newtonian: mu(T) of the material's table (the paper's)";
  }
};

}  // namespace sphcast
