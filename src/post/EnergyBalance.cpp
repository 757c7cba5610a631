#include "post/EnergyBalance.h"

#include <cmath>

#include "core/Error.h"
#include "particles/FieldNames.h"

namespace sphcast {

namespace {
// heat that left: through the air, by radiation, into held patches, with spilled metal
const char* const paths[] = {"atmosphere", "radiation", "fixedTemperature", "spilled"};
}  // namespace

EnergyBalance::EnergyBalance(const std::string& name, const Dictionary& dict,
                             const FunctionObjectContext& context)
    : FunctionObject(name, dict, context, {"clouds"}, Clouds::many) {
  const auto names = dict.get<std::vector<std::string>>("clouds");
  std::string present;
  for (const ParticleCloud* cloud : context.clouds) present += " " + cloud->name();
  for (const std::string& cloudName : names) {
    const ParticleCloud* found = nullptr;
    for (const ParticleCloud* cloud : context.clouds) {
      if (cloud->name() == cloudName) found = cloud;
    }
    if (!found) {
      throw DictionaryError(dict.location("clouds"), "unknown cloud '" + cloudName + "' in " +
                                                         dict.name() + "; the run has: (" +
                                                         present + " )");
    }
    if (!found->hasScalarField(field::u) ||
        !found->attributes().contains("internalEnergyAtStart")) {
      throw DictionaryError(dict.location("clouds"),
                            "cloud '" + cloudName + "' in " + dict.name() +
                                " carries no heat (name it in heatTransfer's clouds in "
                                "constant/physicsModels)");
    }
    clouds_.push_back(found);
  }
  if (clouds_.empty()) {
    throw DictionaryError(dict.location("clouds"), "'clouds' in " + dict.name() + " is empty");
  }
  header_ = "# Time";
  for (const ParticleCloud* cloud : clouds_) header_ += "  E_" + cloud->name();
  for (const char* path : paths) header_ += std::string("  lost_") + path;
  header_ += "  imbalance  relativeImbalance\n# energies in J\n";
}

void EnergyBalance::sample(double time) {
  std::string row;
  double change = 0, content = 0;
  double lost[4] = {0, 0, 0, 0};
  for (const ParticleCloud* cloud : clouds_) {
    const auto& mass = cloud->scalarField(field::mass);
    const auto& u = cloud->scalarField(field::u);
    double energy = 0;  // every rank's own particles (the heat attributes are the whole's)
    for (std::size_t i = 0; i < cloud->ownedSize(); ++i) energy += double(mass[i]) * double(u[i]);
    energy = communicator().sum(energy);
    // a pouring inlet's metal brings its energy (inflowEnergy, PouringInlet.h)
    const auto inflow = cloud->attributes().find("inflowEnergy");
    const double brought = inflow == cloud->attributes().end() ? 0.0 : inflow->second;
    const double delta = energy - cloud->attributes().at("internalEnergyAtStart") - brought;
    change += delta;
    content += std::abs(cloud->attributes().at("internalEnergyAtStart")) + brought;
    row += formatSample(energy) + ' ';
    for (int p = 0; p < 4; ++p) {
      const auto found = cloud->attributes().find(std::string("heatLost.") + paths[p]);
      if (found != cloud->attributes().end()) lost[p] += found->second;
    }
  }
  double totalLost = 0;
  for (const double value : lost) {
    row += formatSample(value) + ' ';
    totalLost += value;
  }
  const double imbalance = change + totalLost;
  row += formatSample(imbalance) + ' ' + formatSample(content > 0 ? imbalance / content : 0.0);
  writeRow(openOutput("energyBalance", header_), time, row);
}

}  // namespace sphcast
