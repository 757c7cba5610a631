#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "materials/Material.h"

namespace sphcast {

// The materials of constant/physicalProperties, one sub-dictionary each (Material.h), read and
// checked in full when the file is read: a mistake in a material no model uses yet is still
// reported at once. A material's body may come from the sphCast etc folder:
//
//   AC4CH { #includeEtc "materials/AC4CH" }
//   mold  { #includeEtc "materials/iron"  emissivity 0.5; }   // a key given after overrides
class MaterialLibrary {
 public:
  static MaterialLibrary read(const std::filesystem::path& physicalProperties);
  // From a dictionary already read; `file` names it in messages.
  static MaterialLibrary fromDictionary(const Dictionary& properties, const std::string& file);

  bool has(const std::string& name) const;
  // In file order.
  std::vector<std::string> names() const;
  // The file as given to read(), for messages.
  const std::string& file() const { return file_; }

  // The material `name`, which the entry `key` names at `namedAt`; else a DictionaryError
  // there: "'fluid' names the material 'steel', which is not in constant/physicalProperties;
  // did you mean 'steal'? materials there: (water steal)".
  const Material& get(const std::string& name, const SourceLocation& namedAt,
                      std::string_view key) const;

 private:
  std::vector<Material> materials_;
  std::string file_;
};

}  // namespace sphcast
