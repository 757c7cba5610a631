#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/Real.h"

namespace sphcast {

// A set of particles of one kind (the metal, a mold part) as a structure of arrays: positions
// plus any number of named per-particle fields. Each field is one contiguous array, so a pass
// over the cloud touches only the fields it needs, and the whole cloud can be reordered along
// the neighbour grid. Cloud-wide constants (e.g. the lattice spacing) are attributes.
class ParticleCloud {
 public:
  using ScalarField = std::vector<Real>;
  using VectorField = std::vector<Vector>;
  using IdField = std::vector<std::int64_t>;

  explicit ParticleCloud(std::string name);

  const std::string& name() const { return name_; }
  std::size_t size() const { return positions_.size(); }

  // In a decomposed run (src/parallel) the last haloSize() particles are copies of other
  // ranks' particles, there for the pair loops of the first ownedSize(): sums, books, checks
  // and output count the owned particles only. Serial runs have no halo.
  std::size_t ownedSize() const { return positions_.size() - haloSize_; }
  std::size_t haloSize() const { return haloSize_; }
  // Marks the last `count` particles as the halo (HaloExchange, after appending them).
  void setHaloSize(std::size_t count);

  // Changes the particle count of every field at once; new entries are zero. The halo is
  // dropped from the count (its particles, if kept, become owned ones).
  void resize(std::size_t count);

  VectorField& positions() { return positions_; }
  const VectorField& positions() const { return positions_; }

  // Adds a field of size() zeros, or returns the existing one of that name and kind. A name is
  // used by one kind of field only; "position" is reserved.
  ScalarField& addScalarField(const std::string& fieldName);
  VectorField& addVectorField(const std::string& fieldName);
  IdField& addIdField(const std::string& fieldName);

  bool hasScalarField(const std::string& fieldName) const;
  bool hasVectorField(const std::string& fieldName) const;
  bool hasIdField(const std::string& fieldName) const;

  // Look-ups throw an Error naming the cloud and listing the fields it has.
  ScalarField& scalarField(const std::string& fieldName);
  const ScalarField& scalarField(const std::string& fieldName) const;
  VectorField& vectorField(const std::string& fieldName);
  const VectorField& vectorField(const std::string& fieldName) const;
  IdField& idField(const std::string& fieldName);
  const IdField& idField(const std::string& fieldName) const;

  // All fields by name (sorted, so output is deterministic).
  const std::map<std::string, ScalarField>& scalarFields() const { return scalars_; }
  const std::map<std::string, VectorField>& vectorFields() const { return vectors_; }
  const std::map<std::string, IdField>& idFields() const { return ids_; }

  // Cloud-wide constants, written with the cloud (VTK field data).
  std::map<std::string, double>& attributes() { return attributes_; }
  const std::map<std::string, double>& attributes() const { return attributes_; }

  // Applies newOrder to every field: particle k of the result is particle newOrder[k] of now.
  // A cloud with a halo keeps it last: newOrder must map the halo's places onto themselves.
  void reorder(const std::vector<std::size_t>& newOrder);

  // Removes the particles at `indices` (in any order, each once) from every field, the others
  // keeping their order. Only a cloud without a halo: a decomposed run drops it first.
  void remove(const std::vector<std::size_t>& indices);

  // Appends the particles of another cloud with the same fields (throws if they differ); the
  // halo is dropped from the count, as by resize().
  void append(const ParticleCloud& other);

  // Counts the changes of which particle is where in the arrays (resize, reorder, append), so
  // that a neighbour list kept over several steps knows when its indices went stale.
  std::uint64_t layoutVersion() const { return layoutVersion_; }

  // Bit-for-bit equality of positions, fields and attributes (restart and I/O checks).
  bool identicalTo(const ParticleCloud& other) const;

 private:
  void checkNameFree(const std::string& fieldName, const char* kind) const;
  std::string fieldList() const;

  std::string name_;
  VectorField positions_;
  std::map<std::string, ScalarField> scalars_;
  std::map<std::string, VectorField> vectors_;
  std::map<std::string, IdField> ids_;
  std::map<std::string, double> attributes_;
  std::size_t haloSize_ = 0;
  std::uint64_t layoutVersion_ = 0;
  // Buffers reorder() permutes through, kept so that a reorder every step allocates nothing.
  // Not part of the cloud's state: copying a cloud does not copy them.
  struct ReorderScratch {
    ScalarField scalars;
    VectorField vectors;
    IdField ids;
    ReorderScratch() = default;
    ReorderScratch(const ReorderScratch&) {}
    ReorderScratch(ReorderScratch&&) = default;
    ReorderScratch& operator=(const ReorderScratch&) { return *this; }
    ReorderScratch& operator=(ReorderScratch&&) = default;
  };
  ReorderScratch scratch_;
};

}  // namespace sphcast
