// libFuzzer target for the FoamFile dictionary parser: any bytes must either parse or raise a
// DictionaryError; a crash, hang, sanitizer report or any other exception is a bug.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "core/Real.h"
#include "core/dictionary/Dictionary.h"

namespace {

using sphcast::Dictionary;
using sphcast::DictionaryError;

template <class T>
void tryGet(const Dictionary& dict, const std::string& key) {
  try {
    (void)dict.get<T>(key);
  } catch (const DictionaryError&) {
  }
}

// Reads every entry as each kind of value a solver asks for, recursing into sub-dictionaries.
void readEverything(const Dictionary& dict, int depth) {
  const sphcast::Dimensions viscosity{{0, 2, -1, 0, 0, 0, 0}};
  for (const std::string& key : dict.keys()) {
    (void)dict.location(key);
    if (dict.isDict(key)) {
      if (depth < 8) readEverything(dict.subDict(key), depth + 1);
      continue;
    }
    tryGet<double>(dict, key);
    tryGet<float>(dict, key);
    tryGet<int>(dict, key);
    tryGet<std::size_t>(dict, key);
    tryGet<bool>(dict, key);
    tryGet<std::string>(dict, key);
    tryGet<sphcast::Vector>(dict, key);
    tryGet<std::vector<std::string>>(dict, key);
    tryGet<std::vector<std::vector<int>>>(dict, key);
    tryGet<std::vector<std::tuple<double, sphcast::Vector>>>(dict, key);
    try {
      (void)dict.get<double>(key, viscosity);
    } catch (const DictionaryError&) {
    }
    try {
      (void)dict.getChoice(key, {"endTime", "writeNow"});
    } catch (const DictionaryError&) {
    }
  }
  try {
    dict.checkKeys({"endTime", "deltaT", "functions"});
  } catch (const DictionaryError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const Dictionary dict = Dictionary::parse(text, "fuzz/controlDict");
    readEverything(dict, 0);
    if (dict.header()) readEverything(*dict.header(), 1);
  } catch (const DictionaryError&) {
  }
  return 0;
}
