#include "post/FluidSampling.h"
#include "particles/FieldNames.h"

#include <algorithm>
#include <cmath>

namespace sphcast {

namespace {

// The Wendland C2 shape (1 - q)^4 (4 q + 1) without its normalisation, which Shepard cancels.
Real kernelShape(Real r, Real inverseH) {
  const Real q = r * inverseH;
  if (q >= Real(1)) return Real(0);
  const Real oneMinusQ = Real(1) - q;
  const Real square = oneMinusQ * oneMinusQ;
  return square * square * (Real(4) * q + Real(1));
}

Real halfSpacing(const ParticleCloud& fluid) {
  const auto at = fluid.attributes().find("spacing");
  return at == fluid.attributes().end() ? Real(0) : Real(0.5 * at->second);
}

}  // namespace

ShepardInterpolation::ShepardInterpolation(const ParticleCloud& fluid, Real supportRadius,
                                           const Communicator& comm)
    : fluid_(fluid), supportRadius_(supportRadius), comm_(comm) {
  if (fluid.hasScalarField(field::mass) && fluid.hasScalarField(field::rho)) {
    mass_ = &fluid.scalarField(field::mass);
    density_ = &fluid.scalarField(field::rho);
  }
}

template <class Accumulate>
bool ShepardInterpolation::accumulate(const Vector& point, Accumulate add) const {
  const auto& x = fluid_.positions();
  const Real hSquared = supportRadius_ * supportRadius_;
  const Real inverseH = Real(1) / supportRadius_;
  Real weightSum = 0;
  for (std::size_t j = 0; j < fluid_.ownedSize(); ++j) {
    const Real rSquared = (x[j] - point).squaredNorm();
    if (rSquared >= hSquared) continue;
    const Real volume = mass_ ? (*mass_)[j] / (*density_)[j] : Real(1);
    const Real weight = volume * kernelShape(std::sqrt(rSquared), inverseH);
    add(j, weight);
    weightSum += weight;
  }
  return weightSum > 0;
}

double ShepardInterpolation::scalar(const std::vector<Real>& field, const Vector& point) const {
  Real weighted = 0;
  Real weights = 0;
  accumulate(point, [&](std::size_t j, Real weight) {
    weighted += weight * field[j];
    weights += weight;
  });
  if (comm_.size() > 1) {  // the other ranks' particles within h
    std::vector<double> sums{double(weighted), double(weights)};
    comm_.sum(sums);
    weighted = static_cast<Real>(sums[0]);
    weights = static_cast<Real>(sums[1]);
  }
  return weights > 0 ? double(weighted / weights) : noFluid;
}

Vector ShepardInterpolation::vector(const std::vector<Vector>& field, const Vector& point) const {
  Vector weighted = Vector::Zero();
  Real weights = 0;
  accumulate(point, [&](std::size_t j, Real weight) {
    weighted += weight * field[j];
    weights += weight;
  });
  if (comm_.size() > 1) {
    std::vector<double> sums{double(weighted[0]), double(weighted[1]), double(weighted[2]),
                             double(weights)};
    comm_.sum(sums);
    weighted =
        Vector(static_cast<Real>(sums[0]), static_cast<Real>(sums[1]), static_cast<Real>(sums[2]));
    weights = static_cast<Real>(sums[3]);
  }
  return weights > 0 ? Vector(weighted / weights) : Vector::Constant(Real(noFluid));
}

double surfaceHeight(const ParticleCloud& fluid, const Vector& up, const Vector& point, Real radius,
                     const Communicator& comm) {
  const Real radiusSquared = radius * radius;
  double highest = -std::numeric_limits<double>::infinity();
  const auto& positions = fluid.positions();
  for (std::size_t i = 0; i < fluid.ownedSize(); ++i) {
    const Vector& x = positions[i];
    const Vector offset = x - point;
    const Real height = offset.dot(up);
    const Real across = (offset - height * up).squaredNorm();
    if (across < radiusSquared) highest = std::max(highest, double(x.dot(up)));
  }
  highest = comm.max(highest);
  return std::isfinite(highest) ? highest + double(halfSpacing(fluid)) : noFluid;
}

double fluidFront(const ParticleCloud& fluid, const Vector& direction, const Communicator& comm) {
  double front = -std::numeric_limits<double>::infinity();
  const auto& x = fluid.positions();
  for (std::size_t i = 0; i < fluid.ownedSize(); ++i) {
    front = std::max(front, double(x[i].dot(direction)));
  }
  front = comm.max(front);
  return std::isfinite(front) ? front + double(halfSpacing(fluid)) : noFluid;
}

}  // namespace sphcast
