// Particles as bytes between ranks: a header (count, field counts, a hash of the field names),
// then each field's values for all the particles, contiguous.
#include "parallel/ParticleTransfer.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string_view>

#include "core/Error.h"

namespace sphcast {

namespace {

struct Header {
  std::int64_t count = 0;
  std::uint64_t layout = 0;  // the field names, hashed
};

// FNV-1a over the kinds and names of the fields: two clouds with the same fields agree.
std::uint64_t layoutHash(const ParticleCloud& cloud) {
  std::uint64_t hash = 1469598103934665603ull;
  auto add = [&](const std::string& text) {
    for (unsigned char c : text) hash = (hash ^ c) * 1099511628211ull;
    hash = (hash ^ 0xff) * 1099511628211ull;
  };
  for (const auto& [name, field] : cloud.scalarFields()) add("s" + name);
  for (const auto& [name, field] : cloud.vectorFields()) add("v" + name);
  for (const auto& [name, field] : cloud.idFields()) add("i" + name);
  return hash;
}

// buffer: a std::vector<char> (particles) or a std::string (a layout)
template <class Buffer, class T>
void put(Buffer& buffer, const T& value) {
  const std::size_t at = buffer.size();
  buffer.resize(at + sizeof(T));
  std::memcpy(buffer.data() + at, &value, sizeof(T));
}

template <class T>
void putField(std::vector<char>& buffer, const std::vector<T>& field,
              const std::vector<std::size_t>& indices) {
  const std::size_t at = buffer.size();
  buffer.resize(at + indices.size() * sizeof(T));
  char* out = buffer.data() + at;
  for (std::size_t k = 0; k < indices.size(); ++k) {
    std::memcpy(out + k * sizeof(T), &field[indices[k]], sizeof(T));
  }
}

// Reads the buffer from `offset` on; throws when it runs short (a corrupt message).
class Reader {
 public:
  explicit Reader(const std::vector<char>& buffer) : buffer_(buffer.data(), buffer.size()) {}
  explicit Reader(std::string_view buffer) : buffer_(buffer) {}
  template <class T>
  T get() {
    T value;
    need(sizeof(T));
    std::memcpy(&value, buffer_.data() + offset_, sizeof(T));
    offset_ += sizeof(T);
    return value;
  }
  template <class T>
  void getField(std::vector<T>& field, std::size_t start, std::size_t count) {
    need(count * sizeof(T));
    if (count > 0) {  // the fields are arrays of plain values (Real, int64, Eigen's 3 Reals)
      std::memcpy(static_cast<void*>(&field[start]), buffer_.data() + offset_, count * sizeof(T));
    }
    offset_ += count * sizeof(T);
  }
  // a text putText wrote: its length, then its characters
  std::string text() {
    const auto length = get<std::int64_t>();
    if (length < 0) throw Error("particle transfer: a corrupt message");
    need(static_cast<std::size_t>(length));
    std::string value(buffer_.substr(offset_, static_cast<std::size_t>(length)));
    offset_ += static_cast<std::size_t>(length);
    return value;
  }
  bool atEnd() const { return offset_ == buffer_.size(); }

 private:
  void need(std::size_t bytes) const {
    if (offset_ + bytes > buffer_.size()) throw Error("particle transfer: a message ran short");
  }
  std::string_view buffer_;
  std::size_t offset_ = 0;
};

// Overwrites particles [start, start + count) of cloud from the reader (all fields).
void readParticles(Reader& in, ParticleCloud& cloud, std::size_t start, std::size_t count) {
  in.getField(cloud.positions(), start, count);
  for (const auto& [name, field] : cloud.scalarFields()) {
    in.getField(cloud.scalarField(name), start, count);
  }
  for (const auto& [name, field] : cloud.vectorFields()) {
    in.getField(cloud.vectorField(name), start, count);
  }
  for (const auto& [name, field] : cloud.idFields()) in.getField(cloud.idField(name), start, count);
}

Header readHeader(Reader& in, const ParticleCloud& cloud) {
  Header header;
  header.count = in.get<std::int64_t>();
  header.layout = in.get<std::uint64_t>();
  if (header.layout != layoutHash(cloud) || header.count < 0) {
    throw Error("particle transfer: cloud '" + cloud.name() +
                "' has other fields on another rank (every rank must add the same fields)");
  }
  return header;
}

}  // namespace

void packParticles(const ParticleCloud& cloud, const std::vector<std::size_t>& indices,
                   std::vector<char>& buffer) {
  put(buffer, static_cast<std::int64_t>(indices.size()));
  put(buffer, layoutHash(cloud));
  putField(buffer, cloud.positions(), indices);
  for (const auto& [name, field] : cloud.scalarFields()) putField(buffer, field, indices);
  for (const auto& [name, field] : cloud.vectorFields()) putField(buffer, field, indices);
  for (const auto& [name, field] : cloud.idFields()) putField(buffer, field, indices);
}

void unpackParticles(const std::vector<char>& buffer, ParticleCloud& cloud) {
  if (buffer.empty()) return;
  Reader in(buffer);
  const Header header = readHeader(in, cloud);
  const std::size_t start = cloud.size();
  cloud.resize(start + static_cast<std::size_t>(header.count));
  readParticles(in, cloud, start, static_cast<std::size_t>(header.count));
  if (!in.atEnd()) throw Error("particle transfer: a message is longer than its particles");
}

namespace {

void putText(std::string& bytes, const std::string& text) {
  put(bytes, static_cast<std::int64_t>(text.size()));
  bytes += text;
}

template <class Fields>
void putNames(std::string& bytes, const Fields& fields) {
  put(bytes, static_cast<std::int64_t>(fields.size()));
  for (const auto& [name, field] : fields) putText(bytes, name);
}

}  // namespace

std::string packLayout(const ParticleCloud& cloud) {
  std::string bytes;
  putText(bytes, cloud.name());
  put(bytes, static_cast<std::int64_t>(cloud.attributes().size()));
  for (const auto& [name, value] : cloud.attributes()) {
    putText(bytes, name);
    put(bytes, value);
  }
  putNames(bytes, cloud.scalarFields());
  putNames(bytes, cloud.vectorFields());
  putNames(bytes, cloud.idFields());
  return bytes;
}

ParticleCloud unpackLayout(const std::string& bytes) {
  Reader in(bytes);
  ParticleCloud cloud(in.text());
  const auto attributes = in.get<std::int64_t>();
  for (std::int64_t k = 0; k < attributes; ++k) {
    std::string name = in.text();
    cloud.attributes()[name] = in.get<double>();
  }
  for (std::int64_t k = 0, count = in.get<std::int64_t>(); k < count; ++k) {
    cloud.addScalarField(in.text());
  }
  for (std::int64_t k = 0, count = in.get<std::int64_t>(); k < count; ++k) {
    cloud.addVectorField(in.text());
  }
  for (std::int64_t k = 0, count = in.get<std::int64_t>(); k < count; ++k) {
    cloud.addIdField(in.text());
  }
  if (!in.atEnd()) throw Error("particle transfer: a cloud layout is longer than its fields");
  return cloud;
}

ParticleCloud readOnMaster(const std::function<ParticleCloud()>& read, const Communicator& comm) {
  if (comm.size() == 1) return read();
  std::optional<ParticleCloud> cloud;
  std::string message;  // rank 0's: 'c' and the cloud's layout, or 'e' and its error
  if (comm.master()) {
    try {
      cloud = read();
      message = 'c' + packLayout(*cloud);
    } catch (const std::exception& error) {
      message = std::string("e") + error.what();
    }
  }
  message = comm.broadcast(message);
  if (message.empty() || message.front() != 'c') {
    throw CollectiveError(message.empty() ? "rank 0 read no cloud" : message.substr(1));
  }
  if (cloud) return std::move(*cloud);
  return unpackLayout(message.substr(1));
}

std::size_t migrateParticles(ParticleCloud& cloud, const RecursiveBisection& decomposition,
                             const Communicator& comm) {
  if (decomposition.parts() != comm.size()) {
    throw Error("particle migration: " + std::to_string(decomposition.parts()) +
                " subdomains for " + std::to_string(comm.size()) + " ranks");
  }
  if (cloud.haloSize() != 0) {
    throw Error("particle migration: cloud '" + cloud.name() + "' still holds its halo");
  }
  std::vector<std::vector<std::size_t>> leaving(static_cast<std::size_t>(comm.size()));
  std::vector<std::size_t> staying;
  staying.reserve(cloud.size());
  const auto& x = cloud.positions();
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const int owner = decomposition.owner(x[i]);
    if (owner == comm.rank()) {
      staying.push_back(i);
    } else {
      leaving[static_cast<std::size_t>(owner)].push_back(i);
    }
  }
  const std::size_t left = cloud.size() - staying.size();
  // every rank takes part in the exchange, even one with nothing to send
  std::vector<std::vector<char>> outgoing(static_cast<std::size_t>(comm.size()));
  for (int r = 0; r < comm.size(); ++r) {
    if (r != comm.rank() && !leaving[static_cast<std::size_t>(r)].empty()) {
      packParticles(cloud, leaving[static_cast<std::size_t>(r)],
                    outgoing[static_cast<std::size_t>(r)]);
    }
  }
  if (left > 0) {  // keeps the stayers in their order (a reorder of the first staying.size())
    std::vector<std::size_t> order = staying;
    for (const auto& gone : leaving) order.insert(order.end(), gone.begin(), gone.end());
    cloud.reorder(order);
    cloud.resize(staying.size());
  }
  const auto incoming = comm.exchange(std::move(outgoing));
  for (int r = 0; r < comm.size(); ++r) {
    if (r != comm.rank()) unpackParticles(incoming[static_cast<std::size_t>(r)], cloud);
  }
  return left;
}

void HaloExchange::build(ParticleCloud& cloud, const RecursiveBisection& decomposition,
                         double radius, const PeriodicBox& periodic, const Communicator& comm,
                         const std::vector<Real>* reach, double skin) {
  remove(cloud);
  if (decomposition.parts() != comm.size()) {
    throw Error("halo exchange: " + std::to_string(decomposition.parts()) + " subdomains for " +
                std::to_string(comm.size()) + " ranks");
  }
  const auto ranks = static_cast<std::size_t>(comm.size());
  owned_ = cloud.size();
  partners_ = decomposition.neighbours(comm.rank(), radius, periodic);
  sendIndices_.assign(ranks, {});
  std::vector<int> near;
  const auto& x = cloud.positions();
  for (std::size_t i = 0; i < owned_; ++i) {
    near.clear();
    const double own = reach ? std::min(radius, double((*reach)[i]) + skin) : radius;
    decomposition.partsNear(x[i], own, periodic, comm.rank(), near);
    for (int r : near) sendIndices_[static_cast<std::size_t>(r)].push_back(i);
  }
  std::vector<std::vector<char>> outgoing(ranks);
  for (int r : partners_) {
    packParticles(cloud, sendIndices_[static_cast<std::size_t>(r)],
                  outgoing[static_cast<std::size_t>(r)]);
  }
  const auto incoming = comm.exchange(std::move(outgoing), partners_);
  haloStart_.assign(ranks, owned_);
  haloSize_.assign(ranks, 0);
  for (int r : partners_) {
    haloStart_[static_cast<std::size_t>(r)] = cloud.size();
    unpackParticles(incoming[static_cast<std::size_t>(r)], cloud);
    haloSize_[static_cast<std::size_t>(r)] = cloud.size() - haloStart_[static_cast<std::size_t>(r)];
  }
  halo_ = cloud.size() - owned_;
  cloud.setHaloSize(halo_);
  built_ = true;
}

void HaloExchange::checkLayout(const ParticleCloud& cloud) const {
  if (cloud.size() != owned_ + halo_ || cloud.haloSize() != halo_) {
    throw Error("halo exchange: cloud '" + cloud.name() +
                "' changed its particle count since its halo was built");
  }
}

void HaloExchange::refresh(ParticleCloud& cloud, const Communicator& comm) const {
  if (!built_) return;  // dropped on every rank alike: nothing to refresh until the build
  checkLayout(cloud);
  std::vector<std::vector<char>> outgoing(static_cast<std::size_t>(comm.size()));
  for (int r : partners_) {
    packParticles(cloud, sendIndices_[static_cast<std::size_t>(r)],
                  outgoing[static_cast<std::size_t>(r)]);
  }
  const auto incoming = comm.exchange(std::move(outgoing), partners_);
  for (int r : partners_) {
    const auto& buffer = incoming[static_cast<std::size_t>(r)];
    Reader in(buffer);
    const Header header = readHeader(in, cloud);
    if (static_cast<std::size_t>(header.count) != haloSize_[static_cast<std::size_t>(r)]) {
      throw Error("halo exchange: rank " + std::to_string(r) + " sent " +
                  std::to_string(header.count) + " particles of cloud '" + cloud.name() +
                  "' for a halo of " + std::to_string(haloSize_[static_cast<std::size_t>(r)]));
    }
    readParticles(in, cloud, haloStart_[static_cast<std::size_t>(r)],
                  static_cast<std::size_t>(header.count));
  }
}

void HaloExchange::refresh(ParticleCloud& cloud, const std::vector<std::string>& fields,
                           const Communicator& comm, std::source_location where) const {
  if (!built_) return;  // dropped on every rank alike: nothing to refresh until the build
  checkLayout(cloud);
  std::vector<std::vector<char>> outgoing(static_cast<std::size_t>(comm.size()));
  for (int r : partners_) {
    auto& buffer = outgoing[static_cast<std::size_t>(r)];
    const auto& indices = sendIndices_[static_cast<std::size_t>(r)];
    for (const std::string& name : fields) {
      if (name == "position") {
        putField(buffer, cloud.positions(), indices);
      } else if (cloud.hasScalarField(name)) {
        putField(buffer, cloud.scalarField(name), indices);
      } else {
        putField(buffer, cloud.vectorField(name), indices);  // throws, naming the fields
      }
    }
  }
  const auto incoming = comm.exchange(std::move(outgoing), partners_, where);
  for (int r : partners_) {
    Reader in(incoming[static_cast<std::size_t>(r)]);
    const std::size_t start = haloStart_[static_cast<std::size_t>(r)];
    const std::size_t count = haloSize_[static_cast<std::size_t>(r)];
    for (const std::string& name : fields) {
      if (name == "position") {
        in.getField(cloud.positions(), start, count);
      } else if (cloud.hasScalarField(name)) {
        in.getField(cloud.scalarField(name), start, count);
      } else {
        in.getField(cloud.vectorField(name), start, count);
      }
    }
    if (!in.atEnd()) throw Error("halo exchange: a refresh message does not match its halo");
  }
}

void HaloExchange::refresh(const ParticleCloud& cloud, void* values, std::size_t bytesPerParticle,
                           const Communicator& comm, std::source_location where) const {
  if (!built_) return;  // dropped on every rank alike: nothing to refresh until the build
  checkLayout(cloud);
  auto* bytes = static_cast<char*>(values);
  std::vector<std::vector<char>> outgoing(static_cast<std::size_t>(comm.size()));
  for (int r : partners_) {
    const auto& indices = sendIndices_[static_cast<std::size_t>(r)];
    auto& buffer = outgoing[static_cast<std::size_t>(r)];
    buffer.resize(indices.size() * bytesPerParticle);
    for (std::size_t k = 0; k < indices.size(); ++k) {
      std::memcpy(buffer.data() + k * bytesPerParticle, bytes + indices[k] * bytesPerParticle,
                  bytesPerParticle);
    }
  }
  const auto incoming = comm.exchange(std::move(outgoing), partners_, where);
  for (int r : partners_) {
    const auto& buffer = incoming[static_cast<std::size_t>(r)];
    if (buffer.size() != haloSize_[static_cast<std::size_t>(r)] * bytesPerParticle) {
      throw Error("halo exchange: a refresh of cloud '" + cloud.name() +
                  "' does not match its halo");
    }
    if (!buffer.empty()) {
      std::memcpy(bytes + haloStart_[static_cast<std::size_t>(r)] * bytesPerParticle, buffer.data(),
                  buffer.size());
    }
  }
}

void HaloExchange::remove(ParticleCloud& cloud) {
  if (built_ && halo_ > 0) {
    checkLayout(cloud);
    cloud.resize(owned_);
  }
  built_ = false;
  halo_ = 0;
  owned_ = cloud.size();
  partners_.clear();
  sendIndices_.clear();
  haloStart_.clear();
  haloSize_.clear();
}

std::size_t HaloExchange::sentCount() const {
  std::size_t sent = 0;
  for (const auto& indices : sendIndices_) sent += indices.size();
  return sent;
}

}  // namespace sphcast
