#include "parallel/DecompositionSettings.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"

namespace sphcast {

namespace {

// OpenFOAM's graph partitioners of a mesh's cells: for particles, recursive bisection.
const std::vector<std::string> graphPartitioners{"scotch", "ptscotch", "metis", "parMetis",
                                                 "kahip"};
// Methods that need what particles do not have (a cell-to-rank file, a mesh's structure).
const std::vector<std::string> refusedMethods{"manual", "multiLevel", "structured", "none",
                                              "random"};

bool among(const std::string& word, const std::vector<std::string>& words) {
  return std::find(words.begin(), words.end(), word) != words.end();
}

// The keys a decomposeParDict may carry: ours, and OpenFOAM's for a mesh (every method's
// coeffs, the distributed case's roots, the face constraints), which particles ignore.
std::vector<std::string> validKeys() {
  std::vector<std::string> keys{"numberOfSubdomains",
                                "method",
                                "maxImbalance",
                                "coeffs",
                                "distributed",
                                "roots",
                                "constraints",
                                "preservePatches",
                                "preserveFaceZones",
                                "preserveBaffles",
                                "singleProcessorFaceSets",
                                "weightField"};
  for (const auto& methods : {graphPartitioners, refusedMethods}) {
    for (const std::string& method : methods) keys.push_back(method + "Coeffs");
  }
  for (const char* method : {"simple", "hierarchical"})
    keys.push_back(std::string(method) + "Coeffs");
  return keys;
}

// hierarchical's and simple's n (and order) from <method>Coeffs, or from OpenFOAM's generic
// `coeffs` when the method's own is absent.
void readCuts(const Dictionary& dict, const std::string& method, int dimension,
              DecompositionSettings& settings) {
  const std::string coeffsKey = dict.isDict(method + "Coeffs") ? method + "Coeffs"
                                : dict.isDict("coeffs")        ? "coeffs"
                                                               : "";
  if (coeffsKey.empty()) {
    throw DictionaryError(dict.location("method"),
                          "method " + method + " in decomposeParDict needs " + method +
                              "Coeffs { n (" + std::to_string(settings.subdomains) +
                              " 1 1); } (the subdomains along x, y and z)");
  }
  const Dictionary& coeffs = dict.subDict(coeffsKey);
  if (method == "hierarchical") {
    coeffs.checkKeys({"n", "order", "delta"});
  } else {
    coeffs.checkKeys({"n", "delta"});
  }
  const auto n = coeffs.get<std::vector<long>>("n");
  const SourceLocation nAt = coeffs.location("n");
  if (n.size() != 3) {
    throw DictionaryError(nAt, "n in decomposeParDict's " + coeffsKey +
                                   " needs three counts, the subdomains along x, y and z: (" +
                                   std::to_string(settings.subdomains) + " 1 1)");
  }
  long product = 1;
  for (int a = 0; a < 3; ++a) {
    if (n[a] < 1 || n[a] > 1'000'000) {
      throw DictionaryError(nAt, "n in decomposeParDict's " + coeffsKey +
                                     " must count at least one subdomain along each axis");
    }
    product *= n[a];
    settings.counts[a] = static_cast<int>(n[a]);
  }
  const std::string written =
      "(" + std::to_string(n[0]) + " " + std::to_string(n[1]) + " " + std::to_string(n[2]) + ")";
  if (product != settings.subdomains) {
    throw DictionaryError(nAt, "n " + written + " in decomposeParDict's " + coeffsKey + " makes " +
                                   std::to_string(product) +
                                   " subdomains, but numberOfSubdomains is " +
                                   std::to_string(settings.subdomains));
  }
  if (dimension == 2 && n[2] != 1) {
    throw DictionaryError(nAt,
                          "n " + written + " in decomposeParDict's " + coeffsKey +
                              " cuts z, which a 2D case does not have: make its third count 1");
  }
  if (method == "hierarchical" && coeffs.found("order")) {
    const auto order = coeffs.get<std::string>("order");
    std::string sorted = order;
    std::sort(sorted.begin(), sorted.end());
    if (sorted != "xyz") {
      throw DictionaryError(coeffs.location("order"),
                            "order '" + order + "' in decomposeParDict's " + coeffsKey +
                                " must name x, y and z once each, as xyz or zxy");
    }
    for (int k = 0; k < 3; ++k) settings.order[k] = order[k] - 'x';
  }
}

}  // namespace

DecompositionSettings readDecompositionSettings(const CaseFolder& caseFolder, int ranks,
                                                int dimension) {
  const auto file = caseFolder.systemFile("decomposeParDict");
  if (!std::filesystem::exists(file)) {
    throw Error("-parallel needs " + file.string() + " (numberOfSubdomains " +
                std::to_string(ranks) + ";), as OpenFOAM's decomposePar reads it");
  }
  const Dictionary dict = Dictionary::read(file);
  dict.checkKeys(validKeys());
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
  std::vector<std::string> methods{"recursiveBisection", "hierarchical", "simple"};
  methods.insert(methods.end(), graphPartitioners.begin(), graphPartitioners.end());
  methods.insert(methods.end(), refusedMethods.begin(), refusedMethods.end());
  if (dict.found("method")) settings.requested = dict.getChoice("method", methods);
  const std::string& requested = settings.requested;
  if (among(requested, refusedMethods)) {
    throw DictionaryError(dict.location("method"),
                          "method " + requested +
                              " in decomposeParDict needs a mesh's cells, which particles do "
                              "not have: use recursiveBisection (the default), hierarchical, "
                              "simple or scotch");
  }
  if (requested == "hierarchical" || requested == "simple") {
    settings.method = "hierarchical";
    readCuts(dict, requested, dimension, settings);
    if (requested == "simple") {
      settings.note =
          "method simple: its n cut as hierarchical's in order xyz, each slab at its "
          "own particles' quantiles (simple's planes through the whole domain would "
          "leave the ranks unbalanced where the metal is not a box)";
    }
  } else if (among(requested, graphPartitioners)) {
    settings.note = "method " + requested +
                    " (a partitioner of a mesh's cells): recursive bisection of the particles, "
                    "balanced compact subdomains re-cut as the metal moves";
    if (dict.isDict(requested + "Coeffs")) settings.note += "; " + requested + "Coeffs ignored";
  } else if (requested.empty()) {
    settings.note = "no method given: recursive bisection";
  }
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

std::string describeMethod(const DecompositionSettings& settings) {
  if (settings.method != "hierarchical") return "recursive bisection";
  std::string order;
  for (int axis : settings.order) order += static_cast<char>('x' + axis);
  return "hierarchical cuts n (" + std::to_string(settings.counts[0]) + " " +
         std::to_string(settings.counts[1]) + " " + std::to_string(settings.counts[2]) +
         "), order " + order;
}

}  // namespace sphcast
