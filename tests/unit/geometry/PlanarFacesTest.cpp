// findPlanarFaces: which faces of a wall are flat, which way they face, and the frame of the
// lattice their particles sit on.
#include "geometry/PlanarFaces.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <numbers>

#include "geometry/GmshGeometry.h"
#include "support/TemporaryCase.h"

namespace sphcast {
namespace {

constexpr double dx = 0.01;

// The flat faces of the walls of a 0.1 x 0.08 x 0.06 box (all faces but z = 0.06) rotated by
// `angle` about `axis`.
std::vector<PlanarFace> boxFaces(const Eigen::Vector3d& axis, double angle) {
  testing::TemporaryCase box;
  std::ostringstream geo;
  geo.precision(17);
  geo << "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 0.1, 0.08, 0.06};\n"
      << "Rotate {{" << axis.x() << ", " << axis.y() << ", " << axis.z() << "}, {0, 0, 0}, "
      << angle << "} { Volume{1}; }\n"
      << "Physical Surface(\"walls\") = {1, 2, 3, 4, 5};\nPhysical Volume(\"cavity\") = {1};\n";
  box.write("box.geo", geo.str());
  const GmshGeometry geometry(box.root() / "box.geo", 0.5 * dx);
  const TriangleMesh wall = geometry.surfacesOf({{geometry.findGroup("walls"), 0}});
  const TriangleMesh cavity =
      geometry.boundaryOfVolumes(geometry.volumesOf(*geometry.findGroup("cavity")));
  return findPlanarFaces(wall, cavity, dx);
}

TEST(PlanarFaces, AxisAlignedBoxFacesUseTheGlobalLattice) {
  const auto faces = boxFaces(Eigen::Vector3d::UnitZ(), 0.0);
  ASSERT_EQ(faces.size(), 5u);
  for (const auto& face : faces) {
    EXPECT_TRUE(face.globalLattice);
    EXPECT_EQ(face.normal.cwiseAbs().maxCoeff(), 1.0);
    // Into the cavity: from the face towards the box's centre.
    const Eigen::Vector3d centre(0.05, 0.04, 0.03);
    EXPECT_GT(face.normal.dot(centre - face.origin), 0.0);
    EXPECT_EQ(face.origin.cwiseAbs().sum(), std::abs(face.normal.dot(face.origin)));
  }
}

TEST(PlanarFaces, RotatedBoxFacesTakeTheirEdgesAsAxesAndACornerAsOrigin) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, 3).normalized();
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(std::numbers::pi / 6, axis).toRotationMatrix();
  const auto faces = boxFaces(axis, std::numbers::pi / 6);
  ASSERT_EQ(faces.size(), 5u);
  const Eigen::Vector3d size(0.1, 0.08, 0.06);
  for (const auto& face : faces) {
    EXPECT_FALSE(face.globalLattice);
    const Eigen::Vector3d localNormal = rotation.transpose() * face.normal;
    const Eigen::Vector3d localAxis1 = rotation.transpose() * face.axis1;
    const Eigen::Vector3d localAxis2 = rotation.transpose() * face.axis2;
    const Eigen::Vector3d localOrigin = rotation.transpose() * face.origin;
    // Normal, axes: the box's own axes, to round-off.
    EXPECT_NEAR(localNormal.cwiseAbs().maxCoeff(), 1.0, 1e-12);
    EXPECT_NEAR(localAxis1.cwiseAbs().maxCoeff(), 1.0, 1e-12);
    EXPECT_NEAR(localAxis2.cwiseAbs().maxCoeff(), 1.0, 1e-12);
    // Into the cavity.
    EXPECT_GT(face.normal.dot(rotation * (0.5 * size) - face.origin), 0.0);
    // The origin is a corner of the box, the extent the face's sides; axis1 along the longer.
    for (int i = 0; i < 3; ++i) {
      EXPECT_TRUE(std::abs(localOrigin[i]) < 1e-12 || std::abs(localOrigin[i] - size[i]) < 1e-12)
          << localOrigin.transpose();
    }
    Eigen::Index a1 = 0, a2 = 0;
    localAxis1.cwiseAbs().maxCoeff(&a1);
    localAxis2.cwiseAbs().maxCoeff(&a2);
    EXPECT_NEAR(face.upper.x(), size[a1], 1e-12);
    EXPECT_NEAR(face.upper.y(), size[a2], 1e-12);
    EXPECT_GE(face.upper.x(), face.upper.y());
    EXPECT_EQ(face.lower, Eigen::Vector2d::Zero());
  }
}

}  // namespace
}  // namespace sphcast
