#include "rheology/HerschelBulkley.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"
#include "particles/FieldNames.h"
#include "rheology/ShearRate.h"

namespace sphcast {
namespace {

HerschelBulkleySettings readSettings(const Dictionary& rheology) {
  rheology.checkKeys({"model", "herschelBulkleyCoeffs"});
  if (!rheology.found("herschelBulkleyCoeffs")) {
    throw DictionaryError(rheology.location(),
                          "rheology herschelBulkley needs herschelBulkleyCoeffs { tau0 (Pa); k "
                          "(Pa s^n); n; mu0 (Pa s, the viscosity at rest); } in " +
                              rheology.name());
  }
  const Dictionary& coeffs = rheology.subDict("herschelBulkleyCoeffs");
  coeffs.checkKeys({"tau0", "k", "n", "mu0"});
  HerschelBulkleySettings settings;
  settings.yieldStress = lawCoefficient(coeffs, "tau0", true);
  settings.consistency = lawCoefficient(coeffs, "k", true);
  settings.exponent = lawCoefficient(coeffs, "n", false);
  settings.restViscosity = lawCoefficient(coeffs, "mu0", false);
  if (settings.yieldStress == 0 && settings.consistency == 0) {
    throw DictionaryError(coeffs.location("k"),
                          "'tau0' and 'k' are both zero in " + coeffs.name() +
                              ": the fluid would have no viscosity but mu0 at rest");
  }
  return settings;
}

}  // namespace

HerschelBulkley::HerschelBulkley(const RheologyContext& context, const Dictionary& settings)
    : HerschelBulkley(context, readSettings(settings)) {}

HerschelBulkley::HerschelBulkley(const RheologyContext& context, HerschelBulkleySettings settings)
    : fluid_(context.fluid),
      neighbourhood_(context.neighbourhood),
      walls_(context.walls),
      dimension_(context.dimension),
      supportRadius_(context.supportRadius),
      settings_(settings) {
  if (!fluid_.hasScalarField(field::shearRate)) {
    fluid_.addScalarField(field::shearRate).assign(fluid_.size(), Real(0));
  }
}

std::vector<std::string> HerschelBulkley::fields() const { return {field::shearRate}; }

std::string HerschelBulkley::description() const {
  std::ostringstream text;
  text << "Herschel-Bulkley: mu = min(mu0, (tau0 + k gammaDot^n) / gammaDot), tau0 = "
       << settings_.yieldStress << " Pa, k = " << settings_.consistency
       << " Pa s^n, n = " << settings_.exponent << ", mu0 = " << settings_.restViscosity << " Pa s";
  return text.str();
}

Real HerschelBulkley::viscosity(Real shearRate) const {
  if (!(shearRate > 0)) return settings_.restViscosity;
  const Real stress =
      settings_.yieldStress + settings_.consistency * std::pow(shearRate, settings_.exponent);
  return std::min(settings_.restViscosity, stress / shearRate);
}

void HerschelBulkley::update(double) {
  auto& shearRate = fluid_.scalarField(field::shearRate);
  computeShearRates(fluid_, neighbourhood_, walls_, dimension_, supportRadius_, shearRate);
  const Real* frozen =
      fluid_.hasScalarField(field::frozen) ? fluid_.scalarField(field::frozen).data() : nullptr;
  auto& mu = fluid_.scalarField(field::viscosity);
  const std::size_t owned = fluid_.ownedSize();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < owned; ++i) {
    mu[i] = frozen && frozen[i] != 0 ? settings_.restViscosity : viscosity(shearRate[i]);
  }
  neighbourhood_.syncHalo(fluid_, mu);  // the pair terms read the neighbours' mu
}

}  // namespace sphcast
