// A mold particleized at graded spacing (geometry/GradedVolume.h). Conduction
// (thermal/GradedConduction.h): a linear profile exact across a change of spacing, the books
// closed to round-off, and the slab between two held faces against its series solution with the
// spacing doubled twice across it (doc/validation.md §3); 2D strips, periodic across, at
// h = 3 l for every spacing l. The exposed area (sph/ExposedArea.h): the faces of a graded block
// against their areas.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <numbers>

#include "ThermalTestCases.h"
#include "geometry/GradedVolume.h"
#include "particles/FieldNames.h"
#include "particles/GradedPairs.h"
#include "sph/ExposedArea.h"
#include "thermal/GradedConduction.h"

namespace sphcast::testing {
namespace {

constexpr Real dx = Real(1e-3);
constexpr Real h = 3 * dx;
constexpr int across = 32;  // fine particles across the period in y (> 2 x the coarsest h, 24 dx)

// A run of columns x0 <= x < x1 at spacing l (in dx).
struct Band {
  int x0, x1, l;
};

// A 2D strip of columns at the bands' spacings (each band's width a multiple of its spacing),
// periodic in y over `across` dx, its free faces at x = 0 and the far end: each particle has
// its spacing (localSpacing) and its depth from those faces (wallDistance), as particleizeMold
// writes a graded volume.
ParticleCloud gradedStrip(const std::vector<Band>& bands, Real T) {
  ParticleCloud cloud("body");
  const int length = bands.back().x1;
  std::vector<Vector> x;
  std::vector<Real> l;
  for (const Band& band : bands) {
    for (int i = 0; i < (band.x1 - band.x0) / band.l; ++i) {
      for (int j = 0; j < across / band.l; ++j) {
        x.push_back(dx * Vector(band.x0 + (i + Real(0.5)) * band.l, (j + Real(0.5)) * band.l, 0));
        l.push_back(band.l * dx);
      }
    }
  }
  cloud.resize(x.size());
  auto& volume = cloud.addScalarField(field::volume);
  auto& temperature = cloud.addScalarField(field::T);
  auto& spacing = cloud.addScalarField(field::localSpacing);
  auto& depth = cloud.addScalarField(field::wallDistance);
  for (std::size_t i = 0; i < x.size(); ++i) {
    cloud.positions()[i] = x[i];
    volume[i] = l[i] * l[i];
    temperature[i] = T;
    spacing[i] = l[i];
    depth[i] = std::min(x[i][0], length * dx - x[i][0]);
  }
  cloud.attributes()["spacing"] = dx;
  return cloud;
}

// Fine at both faces, doubled twice towards the middle: 16 dx at dx, 8 at 2 dx, 16 at 4 dx.
const std::vector<Band> twiceDoubled{
    {0, 16, 1}, {16, 24, 2}, {24, 40, 4}, {40, 48, 2}, {48, 64, 1}};

// The pairs of the strip alone, with mass and rho = 1 per unit volume.
GradedConduction pairsOf(ParticleCloud& cloud, bool corrected) {
  auto& mass = cloud.addScalarField(field::mass);
  auto& rho = cloud.addScalarField(field::rho);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    rho[i] = 1;
    mass[i] = cloud.scalarField(field::volume)[i];
  }
  PeriodicBox periodic;
  periodic.setPeriodic(1, 0, across * dx);
  return GradedConduction(cloud, 2, h, dx, periodic, corrected);
}

// Largest |m_i du_i/dt| over the interior particles for phi = x (a linear profile), over the
// largest pair flux of the strip's mean gradient across a fine spacing.
double linearProfileResidual(bool corrected) {
  ParticleCloud cloud = gradedStrip(twiceDoubled, 300);
  const GradedConduction pairs = pairsOf(cloud, corrected);
  std::vector<Real> phi(cloud.size()), rate(cloud.size(), 0);
  for (std::size_t i = 0; i < cloud.size(); ++i) phi[i] = cloud.positions()[i][0];
  pairs.addEnergyRates(phi.data(), cloud.scalarField(field::mass).data(), rate.data());
  // the scale: one fine particle's heat flow for a unit gradient through its face, kappa dx
  const double scale = dx;
  double largest = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const double x = cloud.positions()[i][0];
    if (std::min(x, 64 * dx - x) < 2 * h) continue;  // the free faces' own moment
    largest = std::max(largest, std::abs(rate[i] * cloud.scalarField(field::mass)[i]) / scale);
  }
  return largest;
}

// Without the correction a linear profile is not steady where the spacing doubles; with it,
// it is to round-off. Measured: 0.45 of kappa dx (the heat flow through one fine particle's face
// for a unit gradient) without, 1.2e-14 with.
TEST(GradedConductionTest, LinearProfileIsExactAcrossAChangeOfSpacing) {
  const double plain = linearProfileResidual(false);
  const double corrected = linearProfileResidual(true);
  RecordProperty("plainResidual", std::to_string(plain));
  RecordProperty("correctedResidual", std::to_string(corrected));
  std::printf("linear profile: plain %.3e, corrected %.3e\n", plain, corrected);
  EXPECT_GT(plain, 1e-3) << "the plain pair sum should miss a linear profile at a change";
  EXPECT_LT(corrected, 1e-10);
  ParticleCloud cloud = gradedStrip(twiceDoubled, 300);
  const GradedConduction pairs = pairsOf(cloud, true);
  EXPECT_GT(pairs.leastWeightRatio(), 0.5);
  EXPECT_LT(pairs.largestFirstMoment(), 1e-12);
}

// Heat only moves: sum_i m_i du_i/dt = 0 for any phi.
TEST(GradedConductionTest, PairsMoveHeatWithoutMakingAny) {
  ParticleCloud cloud = gradedStrip(twiceDoubled, 300);
  const GradedConduction pairs = pairsOf(cloud, true);
  std::vector<Real> phi(cloud.size()), rate(cloud.size(), 0);
  double magnitude = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Vector& x = cloud.positions()[i];
    phi[i] = Real(1e5 * std::sin(400 * x[0]) * std::cos(300 * x[1]) + 3e4 * x[0] / dx);
  }
  pairs.addEnergyRates(phi.data(), cloud.scalarField(field::mass).data(), rate.data());
  double total = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const double flow = rate[i] * cloud.scalarField(field::mass)[i];
    total += flow;
    magnitude += std::abs(flow);
  }
  EXPECT_LT(std::abs(total), 1e-13 * magnitude);
}

// The pairs, their corrected weights and the rates they give are the same bits on 1 and 2
// threads (the correction's sums are taken in index order).
TEST(GradedConductionTest, SameBitsOnOneAndTwoThreads) {
  const int before = omp_get_max_threads();
  std::vector<std::vector<Real>> rates;
  for (const int threads : {1, 2}) {
    omp_set_num_threads(threads);
    ParticleCloud cloud = gradedStrip(twiceDoubled, 300);
    const GradedConduction pairs = pairsOf(cloud, true);
    std::vector<Real> phi(cloud.size()), rate(cloud.size(), 0);
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      const Vector& x = cloud.positions()[i];
      phi[i] = Real(1e5 * std::sin(400 * x[0]) * std::cos(300 * x[1]));
    }
    pairs.addEnergyRates(phi.data(), cloud.scalarField(field::mass).data(), rate.data());
    rates.push_back(rate);
  }
  omp_set_num_threads(before);
  EXPECT_EQ(rates[0], rates[1]);
}

const char* const water = "body { density 1000; conductivity 1; specificHeat 1000; }";

// A held face of 4 fine columns beside x0, as in ConductionValidationTest.
ParticleCloud heldFace(const std::string& name, Real x0, bool left, Real T) {
  return heldSurfaceColumns(name, x0, left, 4, across, dx, T);
}

// L2 over the body's particles of (T - series) / (T_0 - T_s) for the slab 0 < x < L with both
// faces held at T_s = 300 K from T_0 = 400 K, at Fourier numbers 0.02, 0.1 and 0.3.
std::vector<double> slabErrors(const std::vector<Band>& bands) {
  const double L = bands.back().x1 * dx, alpha = 1e-6;
  ThermalRun run(2, h, dx, materials(water));
  run.periodic.setPeriodic(1, 0, across * dx);
  run.add(gradedStrip(bands, 400), "body");
  run.add(heldFace("left", 0, true, 300), "body", true, 300);
  run.add(heldFace("right", Real(L), false, 300), "body", true, 300);
  run.start("clouds (body left right); conduction on;");
  const auto series = [&](double x, double t) {
    double sum = 0;
    for (int k = 1; k < 400; k += 2) {
      sum += 4 / (k * std::numbers::pi) * std::sin(k * std::numbers::pi * x / L) *
             std::exp(-k * k * std::numbers::pi * std::numbers::pi * alpha * t / (L * L));
    }
    return 300 + 100 * sum;
  };
  std::vector<double> errors;
  for (const double fourier : {0.02, 0.1, 0.3}) {
    const double t = fourier * L * L / alpha;
    run.advanceTo(t);
    const ParticleCloud& body = run.clouds.front();
    double sum = 0;
    for (std::size_t i = 0; i < body.size(); ++i) {
      const double error =
          (body.scalarField(field::T)[i] - series(body.positions()[i][0], t)) / 100;
      sum += error * error;
    }
    errors.push_back(std::sqrt(sum / double(body.size())));
  }
  return errors;
}

// The slab of 64 dx with the spacing doubled twice towards its middle against the uniform slab
// at dx, both against the series solution. Measured (L2 of the jump at Fo 0.02 / 0.1 / 0.3):
// uniform 0.166 / 0.286 / 0.119 %, graded 0.173 / 0.269 / 0.142 % (without the first-moment
// correction 0.244 / 0.193 / 0.086 %: a transient this symmetric hides what a steady gradient
// across a change shows, LinearProfileIsExact... above).
TEST(GradedConductionTest, SlabAcrossTwoChangesOfSpacingFollowsTheSeriesSolution) {
  const std::vector<double> uniform = slabErrors({{0, 64, 1}});
  const std::vector<double> graded = slabErrors(twiceDoubled);
  for (std::size_t k = 0; k < graded.size(); ++k) {
    RecordProperty("uniform" + std::to_string(k), std::to_string(uniform[k]));
    RecordProperty("graded" + std::to_string(k), std::to_string(graded[k]));
    std::printf("Fo step %zu: uniform %.4f %%, graded %.4f %%\n", k, 100 * uniform[k],
                100 * graded[k]);
    EXPECT_LT(graded[k], 0.005) << "Fourier step " << k;
  }
}

// A block of side n dx (the lattice's cells from 0 to n dx on each axis), graded as
// particleizeMold grades a volume whose only fine surface is its top face: dx within 6 dx of it,
// coarser below up to maxSpacing (in dx).
ParticleCloud gradedBlock(int n, int maxSpacing) {
  const double d = dx, side = n * d;
  WallParticles fine;
  std::vector<double> depth;
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d p((i + 0.5) * d, (j + 0.5) * d, (k + 0.5) * d);
        fine.positions.push_back(p);
        // the nearest face: its distance and outward normal
        const double toFaces[6] = {p.x(), side - p.x(), p.y(), side - p.y(), p.z(), side - p.z()};
        const auto nearest = static_cast<int>(std::min_element(toFaces, toFaces + 6) - toFaces);
        Eigen::Vector3d outward = Eigen::Vector3d::Zero();
        outward[nearest / 2] = nearest % 2 == 0 ? -1 : 1;
        fine.normals.push_back(outward);
        fine.wallDistances.push_back(toFaces[nearest]);
        fine.volumes.push_back(d * d * d);
        fine.owners.push_back(0);
        depth.push_back(side - p.z());
      }
    }
  }
  TriangleMesh box;
  for (int corner = 0; corner < 8; ++corner) {
    box.vertices.emplace_back(corner & 1 ? side : 0, corner & 2 ? side : 0, corner & 4 ? side : 0);
  }
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    box.triangles.push_back({q[0], q[1], q[2]});
    box.triangles.push_back({q[0], q[2], q[3]});
  }
  VolumeGrading grading;
  grading.maxSpacing = maxSpacing * d;
  grading.fineDepth = 6 * d;
  grading.layersPerLevel = 3;
  const WallParticles graded = gradeVolumeParticles(fine, depth, box, d, d * d * d, grading);
  ParticleCloud cloud("block");
  cloud.resize(graded.size());
  auto& volume = cloud.addScalarField(field::volume);
  auto& spacing = cloud.addScalarField(field::localSpacing);
  auto& wallDistance = cloud.addScalarField(field::wallDistance);
  auto& normal = cloud.addVectorField(field::normal);
  for (std::size_t i = 0; i < graded.size(); ++i) {
    cloud.positions()[i] = graded.positions[i].cast<Real>();
    wallDistance[i] = static_cast<Real>(graded.wallDistances[i]);
    normal[i] = graded.normals[i].cast<Real>();
    volume[i] = static_cast<Real>(graded.volumes[i]);
    spacing[i] = static_cast<Real>(graded.spacings[i]);
  }
  cloud.attributes()["spacing"] = dx;
  return cloud;
}

// The exposed area (gradient form, h = 3 dx, 3D) summed over the particles of the block nearest
// to its bottom face (all 4 dx particles there) and to two side faces (below the changes to 2 dx
// and 4 dx, within the reach of the second), within the middle of each (whole 4 dx columns, 16 dx
// or more from the edges, more than a 4 dx particle's support), against those pieces' areas;
// and none inside. Measured at 64 dx: the bottom +0.000 %, the sides +0.40 % (+4.08 % with the
// pairs' mean kernels, before the particles deeper than their support were given none), inside 0
// (0.73 of a face before); the whole block -9.2 % of 6 L^2, its edges rounded over each face's
// own support (a lattice cube of 16 across, the 4 dx faces', is about -14 %). At 62 dx: the
// bottom +0.000 %, the sides +0.46 and +0.76 % (the second of blocks cut by the face), the whole
// block -9.0 %.
void checkFacesOfAGradedBlock(int n) {
  ParticleCloud block = gradedBlock(n, 4);
  std::size_t coarse = 0;
  for (const Real l : block.scalarField(field::localSpacing)) coarse += l > dx ? 1 : 0;
  EXPECT_GT(coarse, 0u);
  Neighbourhood neighbourhood(h, PeriodicBox());
  neighbourhood.addCloud(block, Neighbourhood::Motion::fixed);
  ExposedArea area(ExposedAreaForm::gradient, 3, h, dx, {&block}, {&block}, neighbourhood,
                   {&block});
  neighbourhood.update(CloudOrder::keep);
  area.compute();
  const auto& A = block.scalarField(field::exposedArea);
  // the middle: whole columns of 4 dx particles, 16 dx or more from the edges
  const double side = n * dx, margin = 16 * dx, span = 4 * dx * std::floor((n - 32) / 4);
  double bottom = 0, wall = 0, farWall = 0, inside = 0, total = 0;
  for (std::size_t i = 0; i < block.size(); ++i) {
    const Vector& p = block.positions()[i];
    total += A[i];
    if (block.scalarField(field::wallDistance)[i] > 3 * block.scalarField(field::localSpacing)[i]) {
      inside += A[i];
    }
    const bool middleX = p.x() > margin && p.x() < margin + span;
    const bool middleY = p.y() > margin && p.y() < margin + span;
    const double toBottom = p.z(), toWall = p.y();
    if (middleX && middleY && toBottom < std::min({toWall, side - p.y(), p.x(), side - p.x()})) {
      bottom += A[i];
    }
    if (middleX && p.z() > margin && p.z() < margin + span &&
        toWall < std::min({toBottom, side - p.z(), p.x(), side - p.x()})) {
      wall += A[i];
    }
    if (middleY && p.z() > margin && p.z() < margin + span &&
        side - p.x() < std::min({toBottom, side - p.z(), p.y(), side - p.y()})) {
      farWall += A[i];
    }
  }
  const double piece = span * span;
  const double bottomError = bottom / piece - 1, wallError = wall / piece - 1,
               farWallError = farWall / piece - 1;
  std::printf(
      "graded block, %zu particles (%zu coarser than dx): bottom face %+.3f %%, side face "
      "across the changes of spacing %+.3f %%, the face at x = L %+.3f %%, inside %.3e of a face, "
      "all %+.3f %% of 6 L^2\n",
      block.size(), coarse, 100 * bottomError, 100 * wallError, 100 * farWallError,
      inside / (side * side), 100 * (total / (6 * side * side) - 1));
  ::testing::Test::RecordProperty("bottomError_" + std::to_string(n), std::to_string(bottomError));
  ::testing::Test::RecordProperty("wallError_" + std::to_string(n), std::to_string(wallError));
  EXPECT_LT(std::abs(bottomError), 0.005);  // a flat face of 4 dx particles: R_A is exact there
  // faces crossed by changes of spacing: measured +0.40 to +0.76 % (the particles near a change
  // read a little of its gradient; cut blocks at the face x = L of the 62 dx block add 0.3 points)
  EXPECT_LT(std::abs(wallError), 0.015);
  EXPECT_LT(std::abs(farWallError), 0.015);
  EXPECT_LT(inside, 1e-9 * side * side);  // nothing deeper than a particle's support
}

TEST(GradedMoldTest, FacesOfAGradedBlockShowTheirArea) { checkFacesOfAGradedBlock(64); }

// The exposed area of a graded block is the same bits on 1 and 2 threads.
TEST(GradedMoldTest, ExposedAreaSameBitsOnOneAndTwoThreads) {
  const int before = omp_get_max_threads();
  std::vector<std::vector<Real>> areas;
  for (const int threads : {1, 2}) {
    omp_set_num_threads(threads);
    ParticleCloud block = gradedBlock(40, 4);
    Neighbourhood neighbourhood(h, PeriodicBox());
    neighbourhood.addCloud(block, Neighbourhood::Motion::fixed);
    ExposedArea area(ExposedAreaForm::gradient, 3, h, dx, {&block}, {&block}, neighbourhood);
    neighbourhood.update(CloudOrder::keep);
    area.compute();
    areas.push_back(block.scalarField(field::exposedArea));
  }
  omp_set_num_threads(before);
  EXPECT_EQ(areas[0], areas[1]);
}

// 62 dx: the coarser blocks cut by the faces (at least half inside: a particle at the centre
// of its points), as off the lattice of 4 dx a mold's faces to the air are.
TEST(GradedMoldTest, FacesOfAGradedBlockOffTheCoarseLatticesShowTheirArea) {
  checkFacesOfAGradedBlock(62);
}

// A decomposed run sends each particle of a graded cloud as far as its reach (particles/
// GradedPairs.h, gradedSupportReach): every pair of the block, of either support (conduction's
// mean, the exposed area's row), no longer than the reach of both its particles; and the reach
// is well short of the coarsest support for the particles far from the coarse ones. Measured on
// the 32 dx block graded to 4 dx: the mean reach 0.82 of the coarsest support.
TEST(GradedMoldTest, EveryPairLiesWithinTheReachOfBoth) {
  const ParticleCloud block = gradedBlock(32, 4);
  const auto& spacing = block.scalarField(field::localSpacing);
  const Real hOverDx = 3;
  const std::vector<Real> reach =
      gradedSupportReach(block.positions(), spacing, hOverDx, PeriodicBox());
  ASSERT_EQ(reach.size(), block.size());
  for (const PairSupport support : {PairSupport::mean, PairSupport::row}) {
    const GradedPairs pairs =
        findGradedPairs(block.positions(), spacing, hOverDx, PeriodicBox(), nullptr, support);
    for (std::size_t i = 0; i < block.size(); ++i) {
      for (std::size_t s = pairs.rowStart[i]; s < pairs.rowStart[i + 1]; ++s) {
        const std::size_t j = pairs.neighbours[s];
        const Real r = (block.positions()[i] - block.positions()[j]).norm();
        ASSERT_LT(r, reach[i] * (1 + 1e-12)) << i << " " << j;
        ASSERT_LT(r, reach[j] * (1 + 1e-12)) << i << " " << j;
      }
    }
  }
  double mean = 0;
  Real coarsest = 0;
  for (std::size_t i = 0; i < block.size(); ++i) {
    mean += reach[i];
    coarsest = std::max(coarsest, hOverDx * spacing[i]);
    EXPECT_GE(reach[i], hOverDx * spacing[i]);
  }
  mean /= double(block.size());
  std::printf("reach: mean %.3f of the coarsest support\n", mean / coarsest);
  EXPECT_LT(mean, 0.9 * coarsest);
}

}  // namespace
}  // namespace sphcast::testing
