#include "solver/FlowSetup.h"

#include <filesystem>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"

namespace sphcast {

namespace {

const Dimensions length{{0, 1, 0, 0, 0, 0, 0}};
const Dimensions speed{{0, 1, -1, 0, 0, 0, 0}};
const Dimensions density{{1, -3, 0, 0, 0, 0, 0}};
const Dimensions dynamicViscosity{{1, -1, -1, 0, 0, 0, 0}};

template <class Value>
Value positive(const Dictionary& dict, const std::string& key, const Dimensions& dimensions) {
  const Value value = dict.get<Value>(key, dimensions);
  if (!(value > 0)) {
    throw DictionaryError(dict.location(key), "'" + key + "' must be positive in " + dict.name());
  }
  return value;
}

}  // namespace

FlowSetup readFlowSetup(const CaseFolder& caseFolder, const Vector& gravity) {
  FlowSetup setup;
  const auto modelsFile = caseFolder.constantFile("physicsModels");
  if (!std::filesystem::exists(modelsFile)) return setup;
  const Dictionary models = Dictionary::read(modelsFile);
  models.checkKeys({"flow"});
  if (!models.found("flow")) return setup;
  const Dictionary& flow = models.subDict("flow");
  flow.checkKeys({"model", "fluid", "walls"});
  if (flow.getChoice("model", {"none", "weaklyCompressible"}) == "none") return setup;
  setup.enabled = true;
  setup.fluidCloud = flow.get<std::string>("fluid");
  setup.wallClouds = flow.getOrDefault<std::vector<std::string>>("walls", {});

  const Dictionary schemes = Dictionary::read(caseFolder.systemFile("sphSchemes"));
  schemes.checkKeys({"densityScheme", "viscousForm", "supportRadius", "soundSpeed"});
  setup.settings.densityScheme = schemes.getChoice("densityScheme", {"riemann", "standard"});
  setup.settings.viscousForm = schemes.getChoice("viscousForm", {"Morris", "Cleary"});
  setup.settings.supportRadius = positive<Real>(schemes, "supportRadius", length);
  setup.settings.soundSpeed = positive<Real>(schemes, "soundSpeed", speed);
  setup.settings.gravity = gravity;
  setup.settings.dimension = 3;

  const Dictionary properties = Dictionary::read(caseFolder.constantFile("physicalProperties"));
  properties.checkKeys({setup.fluidCloud});
  const Dictionary& material = properties.subDict(setup.fluidCloud);
  material.checkKeys({"density", "viscosity"});
  setup.restDensity = positive<Real>(material, "density", density);
  setup.viscosity = positive<Real>(material, "viscosity", dynamicViscosity);
  return setup;
}

std::vector<std::string> prepareFluidFields(const FlowSetup& setup, ParticleCloud& fluid) {
  std::vector<std::string> added;
  auto fill = [&](const char* name, Real value) {
    if (fluid.hasScalarField(name)) return;
    for (Real& x : fluid.addScalarField(name)) x = value;
    added.emplace_back(name);
  };
  fill("restDensity", setup.restDensity);
  fill("viscosity", setup.viscosity);
  fill("rho", setup.restDensity);
  if (!fluid.hasScalarField("mass")) {
    if (!fluid.hasScalarField("volume")) {
      throw Error("cloud '" + fluid.name() +
                  "' has neither 'mass' nor 'volume' (setCastFields writes volume)");
    }
    const auto& volume = fluid.scalarField("volume");
    const auto& rho = fluid.scalarField("rho");
    auto& mass = fluid.addScalarField("mass");
    for (std::size_t i = 0; i < mass.size(); ++i) mass[i] = rho[i] * volume[i];
    added.emplace_back("mass");
  }
  if (!fluid.hasVectorField("U")) {
    fluid.addVectorField("U");
    added.emplace_back("U");
  }
  return added;
}

}  // namespace sphcast
