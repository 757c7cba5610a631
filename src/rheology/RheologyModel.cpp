#include "rheology/RheologyModel.h"

#include "core/dictionary/Dictionary.h"
#include "rheology/ElastoViscoplastic.h"
#include "rheology/HerschelBulkley.h"
#include "rheology/ThixotropicSemiSolid.h"

namespace sphcast {

NewtonianViscosity::NewtonianViscosity(const RheologyContext&, const Dictionary& settings) {
  settings.checkKeys({"model"});
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
