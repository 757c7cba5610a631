#include "parallel/DecompositionSettings.h"

#include <cmath>
#include <filesystem>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"

namespace sphcast {

DecompositionSettings readDecompositionSettings(const CaseFolder& caseFolder, int ranks) {
  const auto file = caseFolder.systemFile("decomposeParDict");
  if (!std::filesystem::exists(file)) {
    throw Error("-parallel needs " + file.string() + " (numberOfSubdomains " +
                std::to_string(ranks) +
                "; method recursiveBisection;), as OpenFOAM's decomposePar reads it");
  }
  const Dictionary dict = Dictionary::read(file);
  dict.checkKeys({"numberOfSubdomains", "method", "maxImbalance"});
  DecompositionSettings settings;
  settings.subdomainsAt = dict.location("numberOfSubdomains");
  const auto subdomains = dict.get<long>("numberOfSubdomains");
  if (subdomains < 1 || subdomains > 1'000'000) {
    throw DictionaryError(settings.subdomainsAt,
                          "numberOfSubdomains " + std::to_string(subdomains) +
                              " in decomposeParDict must be between 1 and 1000000");
  }
  settings.subdomains = static_cast<int>(subdomains);
  if (settings.subdomains != ranks) {
    throw DictionaryError(settings.subdomainsAt,
                          "numberOfSubdomains " + std::to_string(settings.subdomains) +
                              " in decomposeParDict, but mpirun started " + std::to_string(ranks) +
                              (ranks == 1 ? " rank" : " ranks") + ": run mpirun -np " +
                              std::to_string(settings.subdomains) + ", or change the dictionary");
  }
  // OpenFOAM's other methods (simple, hierarchical, scotch, metis) are not offered: recursive
  // bisection re-balances as the metal moves, which a graph partitioner of a mesh does not
  settings.method = dict.getChoice("method", {"recursiveBisection"});
  if (dict.found("maxImbalance")) {
    settings.maxImbalance = dict.get<double>("maxImbalance");
    if (!(settings.maxImbalance > 0) || !std::isfinite(settings.maxImbalance)) {
      throw DictionaryError(dict.location("maxImbalance"),
                            "maxImbalance in decomposeParDict must be positive (0.1: re-balance "
                            "when a rank carries 10 % more than the mean)");
    }
  }
  return settings;
}

}  // namespace sphcast
