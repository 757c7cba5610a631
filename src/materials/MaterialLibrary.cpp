#include "materials/MaterialLibrary.h"

#include <algorithm>

namespace sphcast {

namespace {

// "constant/physicalProperties" of ".../case/constant/physicalProperties", for messages that
// name the file as the user knows it (the error's location holds the full path).
std::string caseRelativeName(const std::filesystem::path& file) {
  const std::filesystem::path folder = file.parent_path().filename();
  return folder.empty() ? file.filename().string() : (folder / file.filename()).string();
}

}  // namespace

MaterialLibrary MaterialLibrary::read(const std::filesystem::path& physicalProperties) {
  MaterialLibrary library =
      fromDictionary(Dictionary::read(physicalProperties), caseRelativeName(physicalProperties));
  library.file_ = physicalProperties.string();
  return library;
}

MaterialLibrary MaterialLibrary::fromDictionary(const Dictionary& properties,
                                                const std::string& file) {
  MaterialLibrary library;
  library.file_ = properties.location().file;
  for (const std::string& key : properties.keys()) {
    if (!properties.isDict(key)) continue;
    library.materials_.push_back(Material::read(properties.subDict(key), key, file));
  }
  return library;
}

bool MaterialLibrary::has(const std::string& name) const {
  return std::any_of(materials_.begin(), materials_.end(),
                     [&](const Material& material) { return material.name == name; });
}

std::vector<std::string> MaterialLibrary::names() const {
  std::vector<std::string> names;
  for (const Material& material : materials_) names.push_back(material.name);
  return names;
}

const Material& MaterialLibrary::get(const std::string& name, const SourceLocation& namedAt,
                                     std::string_view key) const {
  for (const Material& material : materials_) {
    if (material.name == name) return material;
  }
  const std::vector<std::string> materials = names();
  std::string listed;
  for (const std::string& material : materials) listed += (listed.empty() ? "" : " ") + material;
  const std::string nearest = nearestWord(name, materials);
  throw DictionaryError(
      namedAt, "'" + std::string(key) + "' names the material '" + name + "', which is not in " +
                   file_ + (nearest.empty() ? "" : "; did you mean '" + nearest + "'?") +
                   (nearest.empty() ? "; " : " ") + "materials there: (" + listed + ")");
}

}  // namespace sphcast
