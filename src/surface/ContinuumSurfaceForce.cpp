#include "surface/ContinuumSurfaceForce.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <sstream>

#include "core/Error.h"
#include "core/Smoothstep.h"
#include "particles/FieldNames.h"
#include "particles/WallSurfaceDistance.h"
#include "particles/WendlandKernel.h"
#include "sph/ParticleVolumes.h"

namespace sphcast {

namespace {

constexpr int profileIntervals = 256;

// Above this (degrees) the turned normal threw particles off a free drop on a wall (2D sessile
// drops at 30 and 44 across, 165 and 180 set); the angle set is imposed as this one.
constexpr double largestContactAngle = 150;

// P(t) of the Wendland C2 kernel: the kernel integrated over the plane at distance t.
template <int Dim>
double planarProfile(const WendlandC2Kernel<Dim>& kernel, double h, double t) {
  t = std::abs(t);
  if (t >= h) return 0;
  // Simpson on [t, h] in r: 3D: 2 pi int W(r) r dr; 2D: 2 int W(r) r / sqrt(r^2 - t^2) dr, in
  // the variable y = sqrt(r^2 - t^2) instead (no singularity): 2 int_0^Y W(sqrt(t^2 + y^2)) dy.
  constexpr int n = 512;
  double sum = 0;
  if constexpr (Dim == 3) {
    const double step = (h - t) / n;
    for (int k = 0; k <= n; ++k) {
      const double r = t + k * step;
      const double weight = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
      sum += weight * kernel.value(static_cast<Real>(r)) * r;
    }
    return 2 * std::numbers::pi * sum * step / 3;
  } else {
    const double top = std::sqrt(h * h - t * t);
    const double step = top / n;
    for (int k = 0; k <= n; ++k) {
      const double y = k * step;
      const double weight = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
      sum += weight * kernel.value(static_cast<Real>(std::sqrt(t * t + y * y)));
    }
    return 2 * sum * step / 3;
  }
}

// P(0): the largest colour gradient of a half space (at its surface).
Real planarProfileAtSurface(int dimension, Real h) {
  return static_cast<Real>(dimension == 2 ? planarProfile(WendlandC2Kernel<2>(h), h, 0.0)
                                          : planarProfile(WendlandC2Kernel<3>(h), h, 0.0));
}

}  // namespace

SurfaceDepthProfile::SurfaceDepthProfile(int dimension, Real supportRadius) : h_(supportRadius) {
  const double h = supportRadius;
  std::vector<double> p(profileIntervals + 1);
  for (int k = 0; k <= profileIntervals; ++k) {
    const double t = h * k / profileIntervals;
    p[k] = dimension == 2 ? planarProfile(WendlandC2Kernel<2>(supportRadius), h, t)
                          : planarProfile(WendlandC2Kernel<3>(supportRadius), h, t);
  }
  // C(z_k) = 1/2 + int_0^z_k P by the trapezoidal rule on the fine table, then scaled so that
  // C(h) is exactly 1 (the table's integral of P over [0, h] is 1/2 to about 1e-6)
  std::vector<double> c(profileIntervals + 1, 0);
  for (int k = 1; k <= profileIntervals; ++k) {
    c[k] = c[k - 1] + 0.5 * (p[k - 1] + p[k]) * h / profileIntervals;
  }
  colour_.resize(profileIntervals + 1);
  for (int k = 0; k <= profileIntervals; ++k) {
    colour_[k] = static_cast<Real>(0.5 + 0.5 * c[k] / c.back());
  }
}

Real SurfaceDepthProfile::depth(Real colour) const {
  if (!(colour > colour_.front())) return 0;
  if (colour >= colour_.back()) return h_;
  const auto upper = std::upper_bound(colour_.begin(), colour_.end(), colour);
  const std::size_t k = static_cast<std::size_t>(upper - colour_.begin());  // colour_[k-1] <= c
  const Real fraction = (colour - colour_[k - 1]) / (colour_[k] - colour_[k - 1]);
  return h_ * (Real(k - 1) + fraction) / Real(profileIntervals);
}

Real SurfaceDepthProfile::colour(Real depth) const {
  if (!(depth > 0)) return colour_.front();
  if (!(depth < h_)) return colour_.back();
  const Real position = depth / h_ * Real(profileIntervals);
  const std::size_t k =
      std::min(static_cast<std::size_t>(position), static_cast<std::size_t>(profileIntervals - 1));
  const Real fraction = position - Real(k);
  return colour_[k] + fraction * (colour_[k + 1] - colour_[k]);
}

ContinuumSurfaceForce::ContinuumSurfaceForce(SurfaceTensionSettings settings, ParticleCloud& fluid,
                                             std::vector<const ParticleCloud*> walls,
                                             Neighbourhood& neighbourhood)
    : settings_(std::move(settings)),
      cosTheta_(
          std::max(settings_.cosContactAngle ? *settings_.cosContactAngle : Real(-1),
                   static_cast<Real>(std::cos(largestContactAngle * std::numbers::pi / 180)))),
      sinTheta_(std::sqrt(std::max(Real(0), Real(1) - cosTheta_ * cosTheta_))),
      profile_(settings_.dimension, settings_.supportRadius),
      bulkColour_(
          latticeKernelSum(settings_.dimension, settings_.supportRadius, settings_.spacing)),
      surfaceGradient_(planarProfileAtSurface(settings_.dimension, settings_.supportRadius)),
      fluid_(fluid),
      walls_(std::move(walls)),
      neighbourhood_(neighbourhood) {
  if (!settings_.gasTension) throw Error("surface tension: no sigma given");
  if (settings_.solidTension) {
    throw Error(
        "surface tension: the continuum surface force takes the contact angle, not "
        "Gamma_s");
  }
  requireTemperatureFor(*settings_.gasTension, fluid_);
  if (!fluid_.hasScalarField(field::curvature)) fluid_.addScalarField(field::curvature);
  neighbourhood_.requestPairs(fluid_, fluid_);
  for (const ParticleCloud* wall : walls_) neighbourhood_.requestPairs(fluid_, *wall);
}

std::string ContinuumSurfaceForce::settingsWarning(double soundSpeed) const {
  (void)soundSpeed;
  if (walls_.empty() || !settings_.cosContactAngle) return {};
  const double asked =
      std::acos(static_cast<double>(*settings_.cosContactAngle)) * 180 / std::numbers::pi;
  if (!(asked > largestContactAngle + 1e-9)) return {};
  std::ostringstream text;
  text << "surfaceTension: contactAngle " << asked << " is imposed as " << largestContactAngle
       << " degrees: above it the turned normal throws particles off a free drop on a wall; "
          "a wall set to 150 degrees reads 109-114 on a sessile drop (doc/validation.md 2.2)";
  return text.str();
}

std::string ContinuumSurfaceForce::summary(double soundSpeed) const {
  (void)soundSpeed;
  const TemperatureTable& sigma = *settings_.gasTension;
  std::ostringstream text;
  text << "continuum surface force (Brackbill et al. 1992, corrected curvature), sigma "
       << sigma.description()
       << (sigma.isConstant() ? " = " + std::to_string(sigma(0)) + " N/m" : " (a table in T)");
  if (!walls_.empty()) {
    text << "\n    at the walls: contact angle " << std::acos(cosTheta_) * 180 / std::numbers::pi
         << " degrees, the surface's normal turned towards it within h = "
         << settings_.supportRadius << " m";
    if (settings_.gapMeniscus) {
      text << "; in gaps between facing walls narrower than 2 h the meniscus's curvature "
              "-2 cos(theta) / w, in full up to h (gapMeniscus on)";
    }
  }
  return text.str();
}

double ContinuumSurfaceForce::stableDeltaT() const {
  return capillaryStepLimit(*settings_.gasTension, tension_, fluid_, settings_.spacing);
}

// The colour gradient g_i, then c_i and z_i where i can be a surface particle, then the normal
// smoothed over the fluid and made unit.
template <int Dim>
void ContinuumSurfaceForce::computeColourAndNormal() {
  const WendlandC2Kernel<Dim> kernel(settings_.supportRadius);
  const Real self = kernel.value(0);
  const std::size_t n = fluid_.size();
  volume_ = particleVolumes(fluid_, Dim);
  const std::vector<std::vector<Real>>& wallVolume = wallVolumes_.of(walls_, Dim);
  colour_.resize(n);
  depth_.resize(n);
  gradient_.resize(n);
  unitNormal_.resize(n);
  onSurface_.assign(n, 0);
  surfaceWeight_.assign(n, 0);
  const auto& x = fluid_.positions();
  const NeighbourList& pairs = neighbourhood_.pairs(fluid_, fluid_);
  std::vector<const NeighbourList*> wallPairs;
  for (const ParticleCloud* wall : walls_)
    wallPairs.push_back(&neighbourhood_.pairs(fluid_, *wall));
  const PeriodicBox periodic = neighbourhood_.periodicBox();
  const Real bulk = bulkColour_;
  const Real threshold = Real(0.1) * surfaceGradient_;
  const Real h = settings_.supportRadius;
  // g from the flow's pair loop when it summed it for these positions (colourGradientBuffer:
  // the same sum, where every grad W was at hand), else here; the particles the flow skipped
  // (frozen metal away from the melt) it left NaN
  const bool fromFlow = flowGradient_.size() == n;
  if (fromFlow) ++passesWithFlowsGradient_;
  // a decomposed run's halo: its owners' values of what a pass reads at neighbours (the halo's
  // own sums lack the neighbours beyond it)
  if (fromFlow) neighbourhood_.syncHalo(fluid_, flowGradient_);
  auto gradientPass = [&](auto separation) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      if (fromFlow) {
        if (flowGradient_[i].allFinite()) {
          gradient_[i] = flowGradient_[i] / bulk;
          continue;
        }
        // skipped by the flow (no melt within two hops): summed here only within a hop of one
        // it summed. A melt particle's curvature reads normals two hops out, each smoothed over
        // a third hop's g; farther frozen metal reaches no melt particle's force, and its own
        // force is held: g = 0 there (most of a casting in the cooling mode)
        bool nearSummed = false;
        for (const std::uint32_t j : pairs.of(i)) {
          if (flowGradient_[j].allFinite()) {
            nearSummed = true;
            break;
          }
        }
        if (!nearSummed) {
          gradient_[i] = Vector::Zero();
          continue;
        }
      }
      Vector g = Vector::Zero();
      for (const std::uint32_t j : pairs.of(i)) {
        const Vector xij = separation(x[i], x[j]);
        g -= (volume_[j] * kernel.derivativeOverDistance(xij.norm())) * xij;
      }
      for (std::size_t w = 0; w < walls_.size(); ++w) {
        const auto& y = walls_[w]->positions();
        const auto& v = wallVolume[w];
        for (const std::uint32_t k : wallPairs[w]->of(i)) {
          const Vector xik = separation(x[i], y[k]);
          g -= (v[k] * kernel.derivativeOverDistance(xik.norm())) * xik;
        }
      }
      gradient_[i] = g / bulk;
    }
  };
  withSeparation(periodic, gradientPass);
  neighbourhood_.syncHalo(fluid_, gradient_);
  flowGradient_.clear();  // used: the next pass asks the flow again
  // c and z only where the surface weight can be above 0: |g| above the threshold (most of the
  // liquid lies deeper; there colour and depth are not computed, NaN)
  auto colourPass = [&](auto separation) {
#pragma omp parallel for schedule(dynamic, 256)
    for (std::size_t i = 0; i < n; ++i) {
      const Real length = gradient_[i].norm();
      if (!(length > threshold)) {
        colour_[i] = depth_[i] = std::numeric_limits<Real>::quiet_NaN();
        continue;
      }
      Real c = volume_[i] * self;
      for (const std::uint32_t j : pairs.of(i)) {
        c += volume_[j] * kernel.value(separation(x[i], x[j]).norm());
      }
      for (std::size_t w = 0; w < walls_.size(); ++w) {
        const auto& y = walls_[w]->positions();
        const auto& v = wallVolume[w];
        for (const std::uint32_t k : wallPairs[w]->of(i)) {
          c += v[k] * kernel.value(separation(x[i], y[k]).norm());
        }
      }
      colour_[i] = c / bulk;
      depth_[i] = profile_.depth(colour_[i]);
      // from a tenth to a fifth of a flat face's largest gradient the weight rises smoothly:
      // a particle that crossed a sharp threshold would be kicked
      surfaceWeight_[i] = depth_[i] < h ? smoothstep(length / threshold - Real(1)) : Real(0);
      onSurface_[i] = surfaceWeight_[i] > 0 ? 1 : 0;
    }
  };
  withSeparation(periodic, colourPass);
  auto smoothingPass = [&](auto separation) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      if (!onSurface_[i]) {
        unitNormal_[i] = Vector::Zero();
        continue;
      }
      Real weight = volume_[i] * self;
      Vector sum = weight * gradient_[i];
      for (const std::uint32_t j : pairs.of(i)) {
        const Real w = volume_[j] * kernel.value(separation(x[i], x[j]).norm());
        weight += w;
        sum += w * gradient_[j];
      }
      const Real length = sum.norm();
      unitNormal_[i] = length > 0 ? Vector(sum / length) : Vector::Zero();
      if (!(length > 0)) {
        onSurface_[i] = 0;
        surfaceWeight_[i] = 0;
      }
    }
  };
  withSeparation(periodic, smoothingPass);
}

void ContinuumSurfaceForce::turnNormalsAtWalls() {
  if (walls_.empty()) return;
  const std::size_t n = fluid_.size();
  const std::vector<WallSurfaceView> views = wallSurfaceViews(fluid_, walls_, neighbourhood_);
  const PeriodicBox periodic = neighbourhood_.periodicBox();
  const auto& x = fluid_.positions();
  const Real h = settings_.supportRadius;
  const Real dx = settings_.spacing;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (!onSurface_[i]) continue;
    const WallSurfaceDistance wall = wallSurfaceDistance(x[i], i, views, periodic, dx);
    if (!wall.found || !(wall.distance < h)) continue;
    const Vector& wallNormal = wall.normal;  // out of the wall, into the liquid
    const Vector& normal = unitNormal_[i];
    Vector along = normal - normal.dot(wallNormal) * wallNormal;
    const Real alongLength = along.norm();
    // A surface parallel to the wall (a film, the underside of a drop) meets it nowhere: its
    // direction along the wall is noise, and turned by it the normals scattered (a 150-degree
    // drop threw particles out). The turn fades as the surface comes within 15 degrees of
    // parallel to the wall, in full from 30.
    const Real meets = smoothstep(Real(4) * alongLength - Real(1));
    if (!(meets > 0)) continue;
    along /= alongLength;
    const Vector contact = cosTheta_ * wallNormal + sinTheta_ * along;
    const Real turned = meets * (Real(1) - smoothstep(wall.distance / h));
    const Vector blended = (Real(1) - turned) * normal + turned * contact;
    const Real length = blended.norm();
    if (length > 0) unitNormal_[i] = blended / length;
  }
}

// kappa_i over the surface particles, then taken to the surface (depth z_i above i).
template <int Dim>
void ContinuumSurfaceForce::computeCurvature() {
  const WendlandC2Kernel<Dim> kernel(settings_.supportRadius);
  const std::size_t n = fluid_.size();
  kappa_.assign(n, 0);
  const auto& x = fluid_.positions();
  const NeighbourList& pairs = neighbourhood_.pairs(fluid_, fluid_);
  const PeriodicBox periodic = neighbourhood_.periodicBox();
  constexpr Real tangential = Real(Dim - 1);
  // The tangential normalisation's value for half a kernel's support filled with surface
  // particles is about (d - 1) / 2; below a tenth of it i has too few surface neighbours
  // (a lone particle, a thread of spray) for a curvature.
  constexpr Real fewest = Real(0.05) * tangential;
  const Real self = kernel.value(0);
  // a twentieth of the kernel's sum over a full neighbourhood (1)
  constexpr Real fewestWeight = Real(0.05);
  std::vector<Real> levelKappa(n, 0);
  // the surface particles and their neighbours (marked by the first pass; a flag set to 1 by
  // any thread, so the set does not depend on the order)
  std::vector<std::uint8_t> nearSurface(n, 0);
  std::vector<Real> kappaWeight(n, 0);  // the surface weight, times a ramp for few neighbours
  const Real* weightOf = surfaceWeight_.data();
  auto pass = [&](auto separation) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      if (!onSurface_[i]) continue;
      std::atomic_ref<std::uint8_t>(nearSurface[i]).store(1, std::memory_order_relaxed);
      const Vector& ni = unitNormal_[i];
      Real numerator = 0, denominator = 0;
      for (const std::uint32_t j : pairs.of(i)) {
        std::atomic_ref<std::uint8_t>(nearSurface[j]).store(1, std::memory_order_relaxed);
        if (!onSurface_[j]) continue;
        const Vector xij = separation(x[i], x[j]);
        const Real r = xij.norm();
        const Real slope = weightOf[j] * volume_[j] * kernel.derivativeOverDistance(r);  // -F
        const Real along = ni.dot(xij);
        numerator += slope * (unitNormal_[j] - ni).dot(xij);
        denominator -= slope * (r * r - along * along);
      }
      if (!(denominator > fewest)) continue;
      const Real kappa = tangential * numerator / denominator;
      // from the level surface through i to the surface z_i above it
      const Real reach = std::max(tangential + kappa * depth_[i], Real(0.5) * tangential);
      levelKappa[i] = kappa * tangential / reach;
      kappaWeight[i] = weightOf[i] * smoothstep(denominator / fewest - Real(1));
    }
  };
  withSeparation(periodic, pass);
  neighbourhood_.syncHalo(fluid_, levelKappa);  // the smoothing reads them at neighbours
  neighbourhood_.syncHalo(fluid_, kappaWeight);
  // Smoothed over the surface particles that have one (Shepard): a particle's curvature comes
  // from differences of neighbouring normals and carries their noise; without the smoothing
  // the oscillating drop's amplitude grew and its period came out 8 % long. (Smoothing the
  // numerators and denominators apart instead did no better on a lattice's staircase.)
  // (only where the force will act: a colour gradient from 0.2 % of a face's on, in full from
  // 0.4 %; a lattice's bulk has 0. At 1 % the 2D drop's period at 30 across was 0.7 % longer)
  const Real smallest = Real(0.002) * surfaceGradient_;
  // A surface curved more tightly than a sphere of radius h (a drop of fewer than 6 particles
  // across, a hole of a spacing in the liquid) is not resolved: its curvature is read as that
  // sphere's. Unbounded, the holes a ring-built drop's cut base left read 4 / dx and threw
  // particles out.
  const Real largest = tangential / settings_.supportRadius;
  // A gap between facing walls narrower than 2 h (both walls within the kernel's reach): its
  // meniscus, of radius w / (2 |cos theta|) (1.15 dx in a 2 dx slot at 150 degrees), is tighter
  // than the kernel resolves, so the surface there takes Young-Laplace's curvature
  // -2 cos(theta) / w (one principal curvature: a slot; a round hole's is twice that), in full
  // up to w = h, blended into the kernel's own over h < w < 2 h. Without it a non-wetting melt
  // entered a 2 dx slot at half its entry pressure (doc/validation.md §2.2).
  const Real h = settings_.supportRadius;
  const Real dx = settings_.spacing;
  const bool gaps = settings_.gapMeniscus && !walls_.empty();
  const std::vector<WallSurfaceView> views =
      gaps ? wallSurfaceViews(fluid_, walls_, neighbourhood_) : std::vector<WallSurfaceView>();
  auto smoothing = [&](auto separation) {
#pragma omp parallel for schedule(dynamic, 256)
    for (std::size_t i = 0; i < n; ++i) {
      // no surface particle within h: no curvature to take (most of the bulk)
      if (!nearSurface[i] || !(gradient_[i].squaredNorm() > smallest * smallest)) continue;
      Real weight = kappaWeight[i] * volume_[i] * self;
      Real sum = weight * levelKappa[i];
      for (const std::uint32_t j : pairs.of(i)) {
        if (!(kappaWeight[j] > 0)) continue;
        const Real w = kappaWeight[j] * volume_[j] * kernel.value(separation(x[i], x[j]).norm());
        weight += w;
        sum += w * levelKappa[j];
      }
      // a particle with few surface particles near it takes a share of their curvature: the
      // force fades to 0 as it moves away from the surface instead of switching off
      Real kappa = std::clamp(sum / std::max(weight, fewestWeight), -largest, largest);
      if (gaps) {
        // in full up to w = h, fading to none at 2 h, where the facing wall leaves the
        // neighbours (a gap under a spacing holds no more than a row: its curvature is a
        // spacing's)
        const WallGap gap = wallGapAcross(x[i], i, views, periodic, dx, h);
        const Real inGap = gap.cover * (Real(1) - smoothstep(gap.width / h - Real(1)));
        if (inGap > 0) {
          kappa += inGap * (-Real(2) * cosTheta_ / std::max(gap.width, dx) - kappa);
        }
      }
      kappa_[i] = kappa * smoothstep(gradient_[i].norm() / smallest - Real(1));
    }
  };
  withSeparation(periodic, smoothing);
}

void ContinuumSurfaceForce::computeSurface() {
  if (settings_.dimension == 2) {
    computeColourAndNormal<2>();
  } else {
    computeColourAndNormal<3>();
  }
  turnNormalsAtWalls();
  // the curvature reads the surface's marks, weights and normals at neighbours
  neighbourhood_.syncHalo(fluid_, onSurface_);
  neighbourhood_.syncHalo(fluid_, surfaceWeight_);
  neighbourhood_.syncHalo(fluid_, unitNormal_);
  if (settings_.dimension == 2) {
    computeCurvature<2>();
  } else {
    computeCurvature<3>();
  }
}

void ContinuumSurfaceForce::addAcceleration() {
  const auto start = std::chrono::steady_clock::now();
  tensionAtParticles(*settings_.gasTension, fluid_, tension_);
  computeSurface();
  const std::size_t n = fluid_.size();
  const auto& rho = fluid_.scalarField(field::rho);
  auto& acceleration = fluid_.vectorField(field::acceleration);
  auto& curvature = fluid_.scalarField(field::curvature);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    curvature[i] = kappa_[i];
    if (kappa_[i] == Real(0) || tension_[i] == Real(0)) continue;
    acceleration[i] -= (Real(2) * tension_[i] * kappa_[i] / rho[i]) * gradient_[i];
  }
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace sphcast
