#include "solver/ParticleCheck.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace sphcast {

namespace {

bool isBad(const Vector& x, const Vector& u, Real rho, const Domain& domain) {
  return !x.allFinite() || !u.allFinite() || !std::isfinite(rho) ||
         (x.array() < domain.lower.array()).any() || (x.array() > domain.upper.array()).any();
}

}  // namespace

Domain defaultDomain(const std::vector<const ParticleCloud*>& clouds) {
  Domain box{Vector::Constant(std::numeric_limits<Real>::max()),
             Vector::Constant(std::numeric_limits<Real>::lowest())};
  for (const ParticleCloud* cloud : clouds) {
    for (const Vector& x : cloud->positions()) {
      box.lower = box.lower.cwiseMin(x);
      box.upper = box.upper.cwiseMax(x);
    }
  }
  const Vector margin = Real(0.5) * (box.upper - box.lower);
  box.lower -= margin;
  box.upper += margin;
  return box;
}

ParticleCheck checkParticles(const ParticleCloud& cloud, const Domain& domain) {
  const auto& x = cloud.positions();
  const auto& u = cloud.vectorField("U");
  const auto& rho = cloud.scalarField("rho");
  ParticleCheck check;
  check.first = x.size();
  // Counted in one pass; the first bad one is found again only when there is one.
  std::size_t nonFinite = 0;
  std::size_t outside = 0;
#pragma omp parallel for reduction(+ : nonFinite, outside)
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!x[i].allFinite() || !u[i].allFinite() || !std::isfinite(rho[i])) {
      ++nonFinite;
    } else if ((x[i].array() < domain.lower.array()).any() ||
               (x[i].array() > domain.upper.array()).any()) {
      ++outside;
    }
  }
  check.nonFinite = nonFinite;
  check.outside = outside;
  if (!check.good()) {
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (isBad(x[i], u[i], rho[i], domain)) {
        check.first = i;
        check.firstPosition = x[i];
        break;
      }
    }
  }
  return check;
}

std::string ParticleCheck::describe(const ParticleCloud& cloud, const Domain& domain) const {
  const Eigen::IOFormat plain(Eigen::StreamPrecision, Eigen::DontAlignCols, " ", " ");
  std::ostringstream text;
  text.precision(6);
  text << outside << " particle(s) of cloud '" << cloud.name() << "' left the domain ("
       << domain.lower.transpose().format(plain) << ") ("
       << domain.upper.transpose().format(plain) << "), " << nonFinite
       << " went non-finite; the first, particle " << first;
  if (cloud.hasIdField("id") && first < cloud.size()) text << " (id " << cloud.idField("id")[first] << ")";
  text << ", at (" << firstPosition.transpose().format(plain) << ")";
  return text.str();
}

}  // namespace sphcast
