#include "rheology/RheologyModel.h"

#include <cmath>
#include <string>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"
#include "rheology/ElastoViscoplastic.h"
#include "rheology/HerschelBulkley.h"
#include "rheology/ThixotropicSemiSolid.h"

namespace sphcast {

NewtonianViscosity::NewtonianViscosity(const RheologyContext&, const Dictionary& settings) {
  settings.checkKeys({"model"});
}

Real lawCoefficient(const Dictionary& coeffs, const char* key, bool zeroAllowed) {
  const Real value = coeffs.get<Real>(key);
  if (!(value > 0 || (zeroAllowed && value == 0)) || !std::isfinite(value)) {
    throw DictionaryError(coeffs.location(key),
                          std::string("'") + key + "' must be " +
                              (zeroAllowed ? "zero or positive" : "positive") + " in " +
                              coeffs.name());
  }
  return value;
}

RheologyModels& rheologyModels() {
  static RheologyModels models = [] {
    RheologyModels registry("rheology");
    registry.add<NewtonianViscosity>("newtonian");  // the default
    registry.add<ThixotropicSemiSolid>("thixotropicSemiSolid");
    registry.add<HerschelBulkley>("herschelBulkley");
    registry.add<ElastoViscoplastic>("elastoViscoplastic");
    return registry;
  }();
  return models;
}

}  // namespace sphcast
