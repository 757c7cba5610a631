#include "particles/ParticleCloud.h"

#include <cstring>
#include <sstream>

#include "core/Error.h"

namespace sphcast {

namespace {

// Permutes through a scratch array of the same kind and swaps: the scratch then holds the old
// buffer, so a reorder every step allocates nothing after the first.
template <class Field>
void permute(Field& field, const std::vector<std::size_t>& newOrder, Field& scratch) {
  scratch.resize(field.size());
  for (std::size_t k = 0; k < newOrder.size(); ++k) scratch[k] = field[newOrder[k]];
  field.swap(scratch);
}

// Bit-for-bit, so that -0.0 != 0.0 and NaN payloads count: restart checks must be exact.
template <class Field>
bool bitwiseEqual(const Field& a, const Field& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0);
}

template <class FieldMap>
bool sameFieldsBitwise(const FieldMap& a, const FieldMap& b) {
  if (a.size() != b.size()) return false;
  for (auto itA = a.begin(), itB = b.begin(); itA != a.end(); ++itA, ++itB) {
    if (itA->first != itB->first || !bitwiseEqual(itA->second, itB->second)) return false;
  }
  return true;
}

template <class FieldMap>
void appendFields(FieldMap& mine, const FieldMap& theirs) {
  for (auto& [fieldName, field] : mine) {
    const auto& other = theirs.at(fieldName);
    field.insert(field.end(), other.begin(), other.end());
  }
}

template <class FieldMap>
bool sameNames(const FieldMap& a, const FieldMap& b) {
  if (a.size() != b.size()) return false;
  for (auto itA = a.begin(), itB = b.begin(); itA != a.end(); ++itA, ++itB) {
    if (itA->first != itB->first) return false;
  }
  return true;
}

}  // namespace

ParticleCloud::ParticleCloud(std::string name) : name_(std::move(name)) {}

void ParticleCloud::setHaloSize(std::size_t count) {
  if (count > size()) {
    throw Error("cloud '" + name_ + "': a halo of " + std::to_string(count) + " particles in " +
                std::to_string(size()));
  }
  haloSize_ = count;
}

void ParticleCloud::resize(std::size_t count) {
  ++layoutVersion_;
  haloSize_ = 0;
  positions_.resize(count, Vector::Zero());
  for (auto& [fieldName, field] : scalars_) field.resize(count, Real(0));
  for (auto& [fieldName, field] : vectors_) field.resize(count, Vector::Zero());
  for (auto& [fieldName, field] : ids_) field.resize(count, 0);
}

void ParticleCloud::remove(const std::vector<std::size_t>& indices) {
  if (indices.empty()) return;
  if (haloSize_ > 0) {
    throw Error("cloud '" + name_ + "': particles removed while it holds a halo of " +
                std::to_string(haloSize_));
  }
  std::vector<char> removed(size(), 0);
  for (const std::size_t i : indices) {
    if (i >= size() || removed[i]) {
      throw Error("cloud '" + name_ + "': cannot remove particle " + std::to_string(i) + " of " +
                  std::to_string(size()) + " (out of range or named twice)");
    }
    removed[i] = 1;
  }
  // the kept particles first, in their order, then the removed ones, cut off
  std::vector<std::size_t> order;
  order.reserve(size());
  for (std::size_t i = 0; i < size(); ++i) {
    if (!removed[i]) order.push_back(i);
  }
  const std::size_t kept = order.size();
  for (const std::size_t i : indices) order.push_back(i);
  reorder(order);
  resize(kept);
}

void ParticleCloud::checkNameFree(const std::string& fieldName, const char* kind) const {
  const bool taken = fieldName == "position" ||
                     (scalars_.count(fieldName) && std::strcmp(kind, "scalar") != 0) ||
                     (vectors_.count(fieldName) && std::strcmp(kind, "vector") != 0) ||
                     (ids_.count(fieldName) && std::strcmp(kind, "id") != 0);
  if (taken) {
    throw Error("cloud '" + name_ + "': cannot add " + kind + " field '" + fieldName +
                "': the name is already used by another field (fields: " + fieldList() + ")");
  }
}

ParticleCloud::ScalarField& ParticleCloud::addScalarField(const std::string& fieldName) {
  checkNameFree(fieldName, "scalar");
  auto [it, added] = scalars_.try_emplace(fieldName, size(), Real(0));
  return it->second;
}

ParticleCloud::VectorField& ParticleCloud::addVectorField(const std::string& fieldName) {
  checkNameFree(fieldName, "vector");
  auto [it, added] = vectors_.try_emplace(fieldName, size(), Vector::Zero());
  return it->second;
}

ParticleCloud::IdField& ParticleCloud::addIdField(const std::string& fieldName) {
  checkNameFree(fieldName, "id");
  auto [it, added] = ids_.try_emplace(fieldName, size(), 0);
  return it->second;
}

bool ParticleCloud::hasScalarField(const std::string& n) const { return scalars_.count(n) > 0; }
bool ParticleCloud::hasVectorField(const std::string& n) const { return vectors_.count(n) > 0; }
bool ParticleCloud::hasIdField(const std::string& n) const { return ids_.count(n) > 0; }

std::string ParticleCloud::fieldList() const {
  std::ostringstream list;
  list << "(position";
  for (const auto& entry : scalars_) list << ' ' << entry.first;
  for (const auto& entry : vectors_) list << ' ' << entry.first;
  for (const auto& entry : ids_) list << ' ' << entry.first;
  list << ')';
  return list.str();
}

namespace {
// available() lists the cloud's fields for the error only: built on every look-up, the list
// cost more than a dam break's step where a function object looked a field up per particle.
template <class FieldMap, class Available>
auto& findField(FieldMap& fields, const std::string& fieldName, const std::string& cloudName,
                const char* kind, Available available) {
  auto it = fields.find(fieldName);
  if (it == fields.end()) {
    throw Error("cloud '" + cloudName + "' has no " + kind + " field '" + fieldName +
                "'; its fields are " + available());
  }
  return it->second;
}
}  // namespace

ParticleCloud::ScalarField& ParticleCloud::scalarField(const std::string& n) {
  return findField(scalars_, n, name_, "scalar", [this] { return fieldList(); });
}
const ParticleCloud::ScalarField& ParticleCloud::scalarField(const std::string& n) const {
  return findField(scalars_, n, name_, "scalar", [this] { return fieldList(); });
}
ParticleCloud::VectorField& ParticleCloud::vectorField(const std::string& n) {
  return findField(vectors_, n, name_, "vector", [this] { return fieldList(); });
}
const ParticleCloud::VectorField& ParticleCloud::vectorField(const std::string& n) const {
  return findField(vectors_, n, name_, "vector", [this] { return fieldList(); });
}
ParticleCloud::IdField& ParticleCloud::idField(const std::string& n) {
  return findField(ids_, n, name_, "id", [this] { return fieldList(); });
}
const ParticleCloud::IdField& ParticleCloud::idField(const std::string& n) const {
  return findField(ids_, n, name_, "id", [this] { return fieldList(); });
}

void ParticleCloud::reorder(const std::vector<std::size_t>& newOrder) {
  if (newOrder.size() != size()) {
    throw Error("cloud '" + name_ + "': reorder with " + std::to_string(newOrder.size()) +
                " indices for " + std::to_string(size()) + " particles");
  }
  for (std::size_t k = ownedSize(); k < size(); ++k) {
    if (newOrder[k] != k) throw Error("cloud '" + name_ + "': a reorder would move its halo");
  }
  ++layoutVersion_;
  permute(positions_, newOrder, scratch_.vectors);
  for (auto& entry : scalars_) permute(entry.second, newOrder, scratch_.scalars);
  for (auto& entry : vectors_) permute(entry.second, newOrder, scratch_.vectors);
  for (auto& entry : ids_) permute(entry.second, newOrder, scratch_.ids);
}

void ParticleCloud::append(const ParticleCloud& other) {
  if (!sameNames(scalars_, other.scalars_) || !sameNames(vectors_, other.vectors_) ||
      !sameNames(ids_, other.ids_)) {
    throw Error("cannot append cloud '" + other.name_ + "' " + other.fieldList() + " to cloud '" +
                name_ + "' " + fieldList() + ": their fields differ");
  }
  ++layoutVersion_;
  haloSize_ = 0;
  positions_.insert(positions_.end(), other.positions_.begin(), other.positions_.end());
  appendFields(scalars_, other.scalars_);
  appendFields(vectors_, other.vectors_);
  appendFields(ids_, other.ids_);
}

bool ParticleCloud::identicalTo(const ParticleCloud& other) const {
  return bitwiseEqual(positions_, other.positions_) &&
         sameFieldsBitwise(scalars_, other.scalars_) &&
         sameFieldsBitwise(vectors_, other.vectors_) && sameFieldsBitwise(ids_, other.ids_) &&
         attributes_ == other.attributes_;
}

}  // namespace sphcast
