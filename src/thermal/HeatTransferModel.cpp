#include "thermal/HeatTransferModel.h"

#include "core/Error.h"

namespace sphcast {

std::vector<std::size_t> cloudsOfMaterial(const HeatTransferContext& context,
                                          const std::string& material, const Dictionary& dict,
                                          const std::string& key) {
  std::vector<std::size_t> found;
  std::string present;
  for (std::size_t c = 0; c < context.clouds.size(); ++c) {
    if (context.clouds[c].material->name == material) found.push_back(c);
    present += " " + context.clouds[c].material->name;
  }
  if (found.empty()) {
    throw DictionaryError(dict.location(key),
                          "'" + key + "' in " + dict.name() + " names the material '" + material +
                              "', which no heat cloud has; they have (" + present + " )");
  }
  return found;
}

}  // namespace sphcast
