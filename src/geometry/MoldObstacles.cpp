#include "geometry/MoldObstacles.h"
#include "particles/FieldNames.h"

namespace sphcast {

MoldObstacles::MoldObstacles(const std::vector<ParticleCloud>& moldClouds, double spacing,
                             double clearance)
    : spacing_(spacing), clearance_(clearance), clearanceGrid_(static_cast<Real>(clearance)) {
  bool sided = true;
  for (const ParticleCloud& cloud : moldClouds) {
    sided =
        sided && cloud.hasVectorField(field::normal) && cloud.hasScalarField(field::wallDistance);
  }
  for (const ParticleCloud& cloud : moldClouds) {
    particles_.positions.insert(particles_.positions.end(), cloud.positions().begin(),
                                cloud.positions().end());
    if (cloud.hasScalarField(field::volume)) {
      const auto& volume = cloud.scalarField(field::volume);
      particles_.volumes.insert(particles_.volumes.end(), volume.begin(), volume.end());
    } else {
      particles_.volumes.insert(particles_.volumes.end(), cloud.size(),
                                static_cast<Real>(spacing * spacing * spacing));
    }
    if (sided) {
      const auto& normal = cloud.vectorField(field::normal);
      const auto& distance = cloud.scalarField(field::wallDistance);
      normals_.insert(normals_.end(), normal.begin(), normal.end());
      wallDistances_.insert(wallDistances_.end(), distance.begin(), distance.end());
      // a cloud without the patches particleizeMold works out has 0.75 dx each and no second
      // feet (particles/WallSurfaceDistance.h)
      if (cloud.hasScalarField(field::wallPatchRadius)) {
        const auto& radius = cloud.scalarField(field::wallPatchRadius);
        patchRadii_.insert(patchRadii_.end(), radius.begin(), radius.end());
      } else {
        patchRadii_.insert(patchRadii_.end(), cloud.size(), static_cast<Real>(0.75 * spacing));
      }
      if (cloud.hasScalarField(field::wallPatchAtRim)) {
        const auto& atRim = cloud.scalarField(field::wallPatchAtRim);
        patchesAtRim_.insert(patchesAtRim_.end(), atRim.begin(), atRim.end());
      } else {
        // a cloud without patch radii takes the rim rule everywhere (WallSurfaceDistance.h)
        patchesAtRim_.insert(patchesAtRim_.end(), cloud.size(),
                             cloud.hasScalarField(field::wallPatchRadius) ? Real(0) : Real(1));
      }
      if (cloud.hasScalarField(field::secondWallPatchRadius)) {
        const auto& normal2 = cloud.vectorField(field::secondNormal);
        const auto& depth2 = cloud.scalarField(field::secondWallDistance);
        const auto& radius2 = cloud.scalarField(field::secondWallPatchRadius);
        secondNormals_.insert(secondNormals_.end(), normal2.begin(), normal2.end());
        secondDepths_.insert(secondDepths_.end(), depth2.begin(), depth2.end());
        secondPatchRadii_.insert(secondPatchRadii_.end(), radius2.begin(), radius2.end());
      } else {
        secondNormals_.insert(secondNormals_.end(), cloud.size(), Vector::Zero());
        secondDepths_.insert(secondDepths_.end(), cloud.size(), Real(0));
        secondPatchRadii_.insert(secondPatchRadii_.end(), cloud.size(), Real(0));
      }
    }
  }
  if (!empty()) clearanceGrid_.build(particles_.positions);
}

std::vector<bool> MoldObstacles::clear(const std::vector<Vector>& points) const {
  std::vector<bool> result(points.size(), true);
  if (empty() || points.empty()) return result;
  NeighbourList list;
  list.buildBetween(points, particles_.positions, clearanceGrid_);
  for (std::size_t i = 0; i < points.size(); ++i) result[i] = list.of(i).empty();
  return result;
}

std::vector<bool> MoldObstacles::behindWall(const std::vector<Vector>& points,
                                            double radius) const {
  std::vector<bool> behind(points.size(), false);
  if (normals_.empty() || points.empty()) return behind;
  const auto& walls = particles_.positions;
  CellGrid grid(static_cast<Real>(radius));
  grid.build(walls);
  NeighbourList list;
  list.buildBetween(points, walls, grid);
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (const std::uint32_t j : list.of(i)) {
      if (wallDistances_[j] - (points[i] - walls[j]).dot(normals_[j]) > Real(0)) {
        behind[i] = true;
        break;
      }
    }
  }
  return behind;
}

std::vector<WallSurfaceDistance> MoldObstacles::wallSurfaceDistances(
    const std::vector<Vector>& points, double radius) const {
  std::vector<WallSurfaceDistance> distances(points.size());
  if (normals_.empty() || points.empty()) return distances;
  CellGrid grid(static_cast<Real>(radius));
  grid.build(particles_.positions);
  NeighbourList list;
  list.buildBetween(points, particles_.positions, grid);
  const std::vector<WallSurfaceView> walls{{particles_.positions,
                                            normals_,
                                            wallDistances_,
                                            &list,
                                            {},
                                            patchRadii_,
                                            secondNormals_,
                                            secondDepths_,
                                            secondPatchRadii_,
                                            patchesAtRim_}};
  for (std::size_t i = 0; i < points.size(); ++i) {
    distances[i] =
        wallSurfaceDistance(points[i], i, walls, PeriodicBox{}, static_cast<Real>(spacing_));
  }
  return distances;
}

FixedNeighbours MoldObstacles::within(const Vector& lower, const Vector& upper) const {
  FixedNeighbours near;
  for (std::size_t j = 0; j < particles_.positions.size(); ++j) {
    const Vector& p = particles_.positions[j];
    if ((p.array() >= lower.array()).all() && (p.array() <= upper.array()).all()) {
      near.positions.push_back(p);
      near.volumes.push_back(particles_.volumes[j]);
    }
  }
  return near;
}

}  // namespace sphcast
