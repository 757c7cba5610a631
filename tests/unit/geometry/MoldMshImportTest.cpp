// particleizeMold reads gmsh .msh files (2.2 and 4.1) written here through the gmsh API, and
// makes the same particles from them as from the .geo that describes the same solid.
#include <gmsh.h>
#include <gtest/gtest.h>

#include <numbers>
#include <sstream>

#include "core/Error.h"
#include "geometry/GmshGeometry.h"
#include "geometry/MoldParticleization.h"
#include "particles/FieldNames.h"
#include "support/TemporaryCase.h"

namespace sphcast {
namespace {

using testing::TemporaryCase;

constexpr double dx = 0.005;

std::string moldDict(const std::string& file, const std::string& patch = "walls") {
  std::ostringstream dict;
  dict << "FoamFile { version 2.0; format ascii; class dictionary; object particleizeMoldDict; }\n"
       << "geometry (\"" << file << "\");\nspacing " << dx << ";\nwallLayers 2;\n"
       << "patches\n{\n    " << patch << " { cloud mold; type fixedWall; }\n}\n";
  return dict.str();
}

// The solids of the tests, each with its walls (all faces but one) and its volume. The cylinder
// lies along x, so that its open end, which gmsh does not save in the .msh (it is in no physical
// group), is crossed by the lattice lines that tell the cavity's inside.
enum class Solid { box, cylinder };

std::string geoText(Solid solid) {
  return solid == Solid::box
             ? "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 0.04, 0.03, 0.03};\n"
               "Physical Surface(\"walls\") = {1, 2, 3, 4, 5};\nPhysical Volume(\"cavity\") = "
               "{1};\n"
             : "SetFactory(\"OpenCASCADE\");\nCylinder(1) = {0, 0, 0, 0.03, 0, 0, 0.02};\n"
               "Physical Surface(\"walls\") = {1, 3};\nPhysical Volume(\"cavity\") = {1};\n";
}

// Builds the same solid through the gmsh API, meshes its surfaces as particleizeMold meshes a
// .geo (triangles of at most dx/2 where curved), and its volume too unless surfacesOnly, and
// writes it in the given MSH version.
void writeMsh(Solid solid, const std::filesystem::path& file, double version,
              bool surfacesOnly = false) {
  std::filesystem::create_directories(file.parent_path());
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::model::add("mold");
  if (solid == Solid::box) {
    gmsh::model::occ::addBox(0, 0, 0, 0.04, 0.03, 0.03, 1);
  } else {
    gmsh::model::occ::addCylinder(0, 0, 0, 0.03, 0, 0, 0.02, 1);
  }
  gmsh::model::occ::synchronize();
  const std::vector<int> walls =
      solid == Solid::box ? std::vector<int>{1, 2, 3, 4, 5} : std::vector<int>{1, 3};
  gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, walls), "walls");
  gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {1}), "cavity");
  meshSurfacesForParticles(0.5 * dx);
  if (!surfacesOnly) gmsh::model::mesh::generate(3);
  gmsh::option::setNumber("Mesh.MshFileVersion", version);
  gmsh::write(file.string());
  gmsh::finalize();
}

ParticleizedMold particleizeFile(const TemporaryCase& mold, const std::string& file,
                                 const std::string& patch = "walls") {
  mold.write("system/particleizeMoldDict", moldDict(file, patch));
  return particleizeMold(CaseFolder(mold.root()));
}

// Every particle of `a` has one of `b` at the same place with the same fields, and the counts
// agree.
void expectSameParticles(const ParticleCloud& a, const ParticleCloud& b) {
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a.size(), 100u);
  double worstPosition = 0.0, worstDistance = 0.0, worstNormal = 0.0, worstVolume = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    std::size_t match = 0;
    double nearest = 1e300;
    for (std::size_t j = 0; j < b.size(); ++j) {
      const double d = (a.positions()[i] - b.positions()[j]).norm();
      if (d < nearest) {
        nearest = d;
        match = j;
      }
    }
    worstPosition = std::max(worstPosition, nearest);
    worstDistance = std::max(worstDistance, std::abs(a.scalarField(field::wallDistance)[i] -
                                                     b.scalarField(field::wallDistance)[match]));
    worstNormal =
        std::max(worstNormal,
                 (a.vectorField(field::normal)[i] - b.vectorField(field::normal)[match]).norm());
    worstVolume = std::max(worstVolume, std::abs(a.scalarField(field::volume)[i] -
                                                 b.scalarField(field::volume)[match]));
  }
  // Node coordinates go through the file in 16 significant digits: the same to round-off.
  EXPECT_LT(worstPosition, 1e-9 * dx);
  EXPECT_LT(worstDistance, 1e-9 * dx);
  EXPECT_LT(worstNormal, 1e-9);
  EXPECT_LT(worstVolume, 1e-9 * dx * dx * dx);
}

class MshImport : public ::testing::TestWithParam<std::tuple<Solid, double>> {};

TEST_P(MshImport, GivesTheSameParticlesAsTheGeo) {
  const auto [solid, version] = GetParam();
  TemporaryCase mold;
  mold.write("constant/geometry/mold.geo", geoText(solid));
  writeMsh(solid, mold.root() / "constant/geometry/mold.msh", version);
  {
    // The cavity's boundary read back from the .msh is closed (the open end, in no physical
    // group, is not in the file: the tetrahedra's faces stand in) and the walls bound it.
    const GmshGeometry geometry(mold.root() / "constant/geometry/mold.msh", 0.5 * dx);
    const auto cavity = geometry.volumesOf(*geometry.findGroup("cavity"));
    EXPECT_EQ(geometry.volumesBoundedBy(*geometry.findGroup("walls")), cavity);
    const TriangleMesh boundary = geometry.boundaryOfVolumes(cavity);
    EXPECT_EQ(boundary.freeEdgeCount(), 0u);
    const double exactVolume =
        solid == Solid::box ? 0.04 * 0.03 * 0.03 : std::numbers::pi * 0.02 * 0.02 * 0.03;
    // The inscribed polygon of a circle with chords <= dx/2 = R/16 misses 0.2% of the area.
    EXPECT_NEAR(boundary.enclosedVolume() / exactVolume, 1.0, solid == Solid::box ? 1e-12 : 3e-3);
  }
  const ParticleizedMold fromGeo = particleizeFile(mold, "mold.geo");
  const ParticleizedMold fromMsh = particleizeFile(mold, "mold.msh");
  ASSERT_EQ(fromMsh.clouds.size(), 1u);
  expectSameParticles(fromGeo.clouds[0], fromMsh.clouds[0]);
}

INSTANTIATE_TEST_SUITE_P(
    BoxAndCylinderInMsh22And41, MshImport,
    ::testing::Combine(::testing::Values(Solid::box, Solid::cylinder), ::testing::Values(2.2, 4.1)),
    [](const auto& instance) {
      return std::string(std::get<0>(instance.param) == Solid::box ? "box" : "cylinder") +
             (std::get<1>(instance.param) < 3.0 ? "Msh22" : "Msh41");
    });

class MshMissingGroup : public ::testing::TestWithParam<double> {};

TEST_P(MshMissingGroup, IsNamedWithTheGroupsPresent) {
  TemporaryCase mold;
  writeMsh(Solid::box, mold.root() / "constant/geometry/mold.msh", GetParam());
  std::string message = "no error";
  try {
    particleizeFile(mold, "mold.msh", "lowerMold");
  } catch (const Error& error) {
    message = error.what();
    message = message.substr(message.find("system/particleizeMoldDict"));
  }
  EXPECT_EQ(message,
            "system/particleizeMoldDict:7:5: patch 'lowerMold' is not a physical group of the "
            "geometry; the groups present are ( walls cavity )");
  EXPECT_FALSE(std::filesystem::exists(mold.root() / "constant/particles"));
}

TEST(MshImport, SurfaceMeshWithoutItsVolumeIsRefusedWithAReason) {
  TemporaryCase mold;
  writeMsh(Solid::box, mold.root() / "constant/geometry/mold.msh", 2.2, true);
  std::string message = "no error";
  try {
    particleizeFile(mold, "mold.msh");
  } catch (const Error& error) {
    message = error.what();
  }
  EXPECT_NE(message.find("system/particleizeMoldDict:7:5: cannot tell which side of physical "
                         "group 'walls' is the cavity"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("mold.msh' bounds 0 volumes"), std::string::npos) << message;
  EXPECT_NE(message.find("(a .msh must hold that volume's tetrahedra: mesh it in 3D, or give the "
                         ".geo)"),
            std::string::npos)
      << message;
  EXPECT_FALSE(std::filesystem::exists(mold.root() / "constant/particles"));
}

INSTANTIATE_TEST_SUITE_P(Msh22And41, MshMissingGroup, ::testing::Values(2.2, 4.1),
                         [](const auto& instance) {
                           return std::string(instance.param < 3.0 ? "Msh22" : "Msh41");
                         });

}  // namespace
}  // namespace sphcast
