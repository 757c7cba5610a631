#include "particles/Domain.h"

#include <string>

namespace sphcast {

Domain boundingBox(const std::vector<const ParticleCloud*>& clouds) {
  Domain box{Vector::Constant(std::numeric_limits<Real>::max()),
             Vector::Constant(std::numeric_limits<Real>::lowest())};
  for (const ParticleCloud* cloud : clouds) {
    const auto& x = cloud->positions();
    for (std::size_t i = 0; i < cloud->ownedSize(); ++i) {
      box.lower = box.lower.cwiseMin(x[i]);
      box.upper = box.upper.cwiseMax(x[i]);
    }
  }
  return box;
}

Domain withMargin(Domain box) {
  const Vector margin = Real(0.5) * (box.upper - box.lower);
  box.lower -= margin;
  box.upper += margin;
  return box;
}

Domain defaultDomain(const std::vector<const ParticleCloud*>& clouds) {
  return withMargin(boundingBox(clouds));
}

bool inside(const Domain& domain, const Vector& x) {
  return (x.array() >= domain.lower.array()).all() && (x.array() <= domain.upper.array()).all();
}

std::vector<std::size_t> particlesOutside(const ParticleCloud& cloud, const Domain& domain) {
  std::vector<std::size_t> outside;
  const auto& x = cloud.positions();
  for (std::size_t i = 0; i < cloud.ownedSize(); ++i) {
    if (x[i].allFinite() && !inside(domain, x[i])) outside.push_back(i);
  }
  return outside;
}

namespace {
std::string domainKey(const char* side, int axis) {
  return std::string("domain.") + side + '.' + "xyz"[axis];
}
}  // namespace

void storeDomain(ParticleCloud& cloud, const Domain& domain) {
  for (int a = 0; a < 3; ++a) {
    cloud.attributes()[domainKey("lower", a)] = static_cast<double>(domain.lower[a]);
    cloud.attributes()[domainKey("upper", a)] = static_cast<double>(domain.upper[a]);
  }
}

std::optional<Domain> storedDomain(const ParticleCloud& cloud) {
  Domain domain;
  for (int a = 0; a < 3; ++a) {
    const auto lower = cloud.attributes().find(domainKey("lower", a));
    const auto upper = cloud.attributes().find(domainKey("upper", a));
    if (lower == cloud.attributes().end() || upper == cloud.attributes().end()) {
      return std::nullopt;
    }
    domain.lower[a] = static_cast<Real>(lower->second);
    domain.upper[a] = static_cast<Real>(upper->second);
  }
  return domain;
}

}  // namespace sphcast
