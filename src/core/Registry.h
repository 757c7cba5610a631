#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"

namespace sphcast {

// The models of one family by the names the dictionaries give them (doc/design.md §3, "Adding
// a model"): surface-tension models, function objects, castPostProcess's analyses, heat paths.
// Each family keeps one registry, filled in its registration file in the order its help lists
// them; nothing registers itself from a static initialiser. An unknown name is the dictionary's
// error at the entry, listing the valid names and the nearest one. A test build may add a
// model through add() alone.
template <class Base, class... Args>
class Registry {
 public:
  using Constructor = std::function<std::unique_ptr<Base>(Args...)>;

  // `family` names the registry in messages: "surface-tension model", "function object".
  explicit Registry(std::string family) : family_(std::move(family)) {}

  // Registers Model, built from the family's arguments.
  template <class Model>
  void add(const std::string& name) {
    add(name, [](Args... args) { return std::make_unique<Model>(std::forward<Args>(args)...); });
  }
  void add(const std::string& name, Constructor constructor) {
    if (has(name)) throw Error("internal: the " + family_ + " '" + name + "' is registered twice");
    entries_.emplace_back(name, std::move(constructor));
  }

  bool has(std::string_view name) const {
    for (const auto& entry : entries_) {
      if (entry.first == name) return true;
    }
    return false;
  }
  // In the order of registration.
  std::vector<std::string> names() const {
    std::vector<std::string> names;
    for (const auto& entry : entries_) names.push_back(entry.first);
    return names;
  }
  // "a, b and c", for a tool's -help.
  std::string listed() const {
    std::string text;
    for (std::size_t k = 0; k < entries_.size(); ++k) {
      if (k > 0) text += k + 1 == entries_.size() ? " and " : ", ";
      text += entries_[k].first;
    }
    return text;
  }

  // The name `key` of `dict` gives (before `extra`, words that mean no model, such as none);
  // else the dictionary's error at the key, listing them all.
  std::string choose(const Dictionary& dict, std::string_view key,
                     const std::vector<std::string>& extra = {}) const {
    std::vector<std::string> choices = extra;
    for (const auto& entry : entries_) choices.push_back(entry.first);
    return dict.getChoice(key, choices);
  }

  // The model `name` (a name choose() gave, or has() found), built from `args`.
  std::unique_ptr<Base> build(std::string_view name, Args... args) const {
    for (const auto& entry : entries_) {
      if (entry.first == name) return entry.second(std::forward<Args>(args)...);
    }
    throw Error("internal: no " + family_ + " '" + std::string(name) + "' is registered");
  }

 private:
  std::string family_;
  std::vector<std::pair<std::string, Constructor>> entries_;
};

}  // namespace sphcast
