#include "rheology/ThixotropicSemiSolid.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"
#include "particles/FieldNames.h"
#include "rheology/ShearRate.h"

namespace sphcast {
namespace {

ThixotropicSemiSolidSettings readSettings(const Dictionary& rheology) {
  rheology.checkKeys({"model", "thixotropicSemiSolidCoeffs"});
  ThixotropicSemiSolidSettings settings;
  if (!rheology.found("thixotropicSemiSolidCoeffs")) return settings;
  const Dictionary& coeffs = rheology.subDict("thixotropicSemiSolidCoeffs");
  coeffs.checkKeys({"a", "b", "m", "maxPacking"});
  auto positive = [&](const char* key, Real fallback) {
    const Real value = coeffs.getOrDefault<Real>(key, fallback);
    if (!(value > 0)) {
      throw DictionaryError(coeffs.location(key),
                            std::string("'") + key + "' must be positive in " + coeffs.name());
    }
    return value;
  };
  settings.buildUp = positive("a", settings.buildUp);
  settings.breakDown = positive("b", settings.breakDown);
  settings.exponent = positive("m", settings.exponent);
  settings.maxPacking = positive("maxPacking", settings.maxPacking);
  if (!(settings.maxPacking < 1)) {
    throw DictionaryError(coeffs.location("maxPacking"),
                          "'maxPacking' (a solid fraction) must lie in (0, 1) in " + coeffs.name());
  }
  return settings;
}

}  // namespace

ThixotropicSemiSolid::ThixotropicSemiSolid(const RheologyContext& context,
                                           const Dictionary& settings)
    : ThixotropicSemiSolid(context, readSettings(settings)) {}

ThixotropicSemiSolid::ThixotropicSemiSolid(const RheologyContext& context,
                                           ThixotropicSemiSolidSettings settings)
    : fluid_(context.fluid),
      neighbourhood_(context.neighbourhood),
      walls_(context.walls),
      dimension_(context.dimension),
      supportRadius_(context.supportRadius),
      mu_(context.material.requireViscosity("rheology thixotropicSemiSolid")),
      liquidViscosity_(0),
      settings_(settings) {
  if (!context.material.freezingRange) {
    throw Error("rheology thixotropicSemiSolid: material '" + context.material.name +
                "' has no liquidus and solidus (the semi-solid range) in "
                "constant/physicalProperties");
  }
  liquidViscosity_ = static_cast<Real>(mu_(context.material.freezingRange->liquidus));
  for (const char* needed : {field::T, field::solidFraction}) {
    if (!fluid_.hasScalarField(needed)) {
      throw Error(std::string("rheology thixotropicSemiSolid: the fluid cloud '") + fluid_.name() +
                  "' has no field '" + needed +
                  "'; the model needs the metal's temperature and solid fraction (heatTransfer "
                  "and solidification in constant/physicsModels)");
    }
  }
  // a fresh mush starts fully built (at rest); a restart reads its structure back
  if (!fluid_.hasScalarField(field::structure)) {
    fluid_.addScalarField(field::structure).assign(fluid_.size(), Real(1));
  }
  if (!fluid_.hasScalarField(field::shearRate)) {
    fluid_.addScalarField(field::shearRate).assign(fluid_.size(), Real(0));
  }
}

std::vector<std::string> ThixotropicSemiSolid::fields() const {
  return {field::structure, field::shearRate};
}

std::string ThixotropicSemiSolid::description() const {
  std::ostringstream text;
  text << "thixotropic semi-solid: d lambda/dt = " << settings_.buildUp << " (1 - lambda) - "
       << settings_.breakDown << " lambda gammaDot^" << settings_.exponent
       << "; mu = mu_inf / (1 - K lambda)^2 between mu(T) at rest and the broken suspension "
       << "mu_l (1 - f_s/" << settings_.maxPacking << ")^(-2.5 x " << settings_.maxPacking
       << "), mu_l = " << liquidViscosity_ << " Pa s; the mush freezes at f_s "
       << settings_.maxPacking;
  return text.str();
}

Real ThixotropicSemiSolid::equilibriumStructure(Real shearRate) const {
  const Real k = settings_.buildUp + settings_.breakDown * std::pow(shearRate, settings_.exponent);
  return settings_.buildUp / k;
}

Real ThixotropicSemiSolid::viscosity(Real solidFraction, Real temperature, Real structure) const {
  const Real atRest = static_cast<Real>(mu_(static_cast<double>(temperature)));
  if (solidFraction <= 0) return atRest;
  const Real packed = std::min(solidFraction / settings_.maxPacking, Real(0.999999));
  const Real broken = std::min(
      atRest, liquidViscosity_ * std::pow(Real(1) - packed, Real(-2.5) * settings_.maxPacking));
  const Real k = Real(1) - std::sqrt(broken / atRest);
  const Real denominator = Real(1) - k * std::clamp(structure, Real(0), Real(1));
  return broken / (denominator * denominator);
}

void ThixotropicSemiSolid::update(double dt) {
  computeShearRates(fluid_, neighbourhood_, walls_, dimension_, supportRadius_,
                    fluid_.scalarField(field::shearRate));
  const auto& temperature = fluid_.scalarField(field::T);
  const auto& solidFraction = fluid_.scalarField(field::solidFraction);
  const Real* frozen =
      fluid_.hasScalarField(field::frozen) ? fluid_.scalarField(field::frozen).data() : nullptr;
  const auto& shearRate = fluid_.scalarField(field::shearRate);
  auto& structure = fluid_.scalarField(field::structure);
  auto& mu = fluid_.scalarField(field::viscosity);
  const std::size_t owned = fluid_.ownedSize();
  const Real step = static_cast<Real>(dt);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < owned; ++i) {
    // exact over the step at its shear rate (a frozen particle rests: it rebuilds)
    const Real rate = frozen && frozen[i] != 0 ? Real(0) : shearRate[i];
    const Real k = settings_.buildUp + settings_.breakDown * std::pow(rate, settings_.exponent);
    const Real equilibrium = settings_.buildUp / k;
    structure[i] = equilibrium + (structure[i] - equilibrium) * std::exp(-k * step);
    mu[i] = frozen && frozen[i] != 0 ? static_cast<Real>(mu_(static_cast<double>(temperature[i])))
                                     : viscosity(solidFraction[i], temperature[i], structure[i]);
  }
  neighbourhood_.syncHalo(fluid_, mu);  // the pair terms read the neighbours' mu
}

}  // namespace sphcast
