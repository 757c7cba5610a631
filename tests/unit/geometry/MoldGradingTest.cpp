// particleizeMold's graded volumes (geometry/GradedVolume.h): a die with a pocket, graded with
// its pocket's faces kept fine, against the same die at the uniform spacing, in 3D and in 2D;
// and the errors a user meets in `grading`.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Error.h"
#include "geometry/MoldParticleization.h"
#include "particles/FieldNames.h"
#include "support/TemporaryCase.h"

namespace sphcast {
namespace {

using testing::TemporaryCase;

// A die 100 x 100 x 60 mm with a pocket 60 x 60 x 20 mm in its top, its pocket's five faces the
// Physical Surface "pocket"; the die's lower corner off the coarser lattices (-0.0487 m).
const std::string dieGeo = R"(SetFactory("OpenCASCADE");
Box(1) = {-0.0487, -0.0487, -0.0487, 0.1, 0.1, 0.06};
Box(2) = {-0.0287, -0.0287, -0.0087, 0.06, 0.06, 0.02};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Physical Volume("die") = {3};
e = 1e-6;
Physical Surface("pocket") = Surface In BoundingBox{-0.0287 - e, -0.0287 - e, -0.0087 - e, 0.0313 + e, 0.0313 + e, 0.0113 + e};
)";

std::string dieDict(const std::string& grading) {
  return "FoamFile { version 2.0; format ascii; class dictionary; object particleizeMoldDict; }\n"
         "geometry (\"die.geo\");\nspacing 0.002;\nsupportRadius 0.006;\npatches\n{\n"
         "    die { cloud die; type fixedWall; mode volume; " +
         grading + " }\n}\n";
}

ParticleizedMold particleize(const std::string& dict) {
  TemporaryCase die;
  die.write("constant/geometry/die.geo", dieGeo);
  die.write("system/particleizeMoldDict", dict);
  return particleizeMold(CaseFolder(die.root()));
}

// Distance from a point of the die (outside the pocket, at most as high as its top) to the
// pocket's five faces: its distance to the pocket's box, whose nearest point is then never
// inside the open top.
double toPocket(const Vector& p) {
  const auto outside = [](double v, double lo, double hi) {
    return v < lo ? lo - v : (v > hi ? v - hi : 0.0);
  };
  return std::hypot(outside(p.x(), -0.0287, 0.0313), outside(p.y(), -0.0287, 0.0313),
                    outside(p.z(), -0.0087, 0.0113));
}

// The graded die holds the uniform die's volume to round-off in 4 times fewer particles, keeps
// dx within fineLayers dx of the pocket, and writes each particle's spacing. Measured: 66,000
// particles at 2 mm uniform, 14,719 graded up to 8 mm (4.48 times fewer).
TEST(MoldGrading, GradedDieKeepsItsVolumeAndItsPocketFine) {
  const ParticleizedMold uniform = particleize(dieDict(""));
  const ParticleizedMold graded =
      particleize(dieDict("grading { maxSpacing 0.008; fineLayers 3; fineSurfaces (pocket); }"));
  const ParticleCloud& u = uniform.clouds.at(0);
  const ParticleCloud& g = graded.clouds.at(0);
  EXPECT_FALSE(u.hasScalarField(field::localSpacing));
  ASSERT_TRUE(g.hasScalarField(field::localSpacing));
  double uniformVolume = 0, gradedVolume = 0;
  for (const Real v : u.scalarField(field::volume)) uniformVolume += v;
  for (const Real v : g.scalarField(field::volume)) gradedVolume += v;
  EXPECT_NEAR(gradedVolume / uniformVolume, 1.0, 1e-12);
  const double ratio = double(u.size()) / double(g.size());
  std::printf("die: %zu particles at 2 mm, %zu graded up to 8 mm: %.2f times fewer\n", u.size(),
              g.size(), ratio);
  RecordProperty("fewer", std::to_string(ratio));
  EXPECT_GT(ratio, 4.0);
  const auto& spacing = g.scalarField(field::localSpacing);
  const auto& volume = g.scalarField(field::volume);
  const double dx = 0.002, cell = dx * dx * dx * uniformVolume / (double(u.size()) * dx * dx * dx);
  std::size_t levels[4] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < g.size(); ++i) {
    const int level = static_cast<int>(std::lround(std::log2(spacing[i] / dx)));
    ASSERT_GE(level, 0);
    ASSERT_LE(level, 2);
    ++levels[level];
    // a coarser particle stands for at least half its block, at most all of it
    const double points = volume[i] / cell;
    EXPECT_LE(points, std::pow(8.0, level) + 1e-9);
    EXPECT_GE(points, level == 0 ? 1.0 - 1e-9 : 0.5 * std::pow(8.0, level) - 1e-9);
    // every point of its block lies at least fineLayers dx from the pocket
    if (level > 0) {
      EXPECT_GE(toPocket(g.positions()[i]), 3 * dx) << i;
    }
  }
  EXPECT_GT(levels[1], 0u);
  EXPECT_GT(levels[2], 0u);
}

// The message of the Error particleizeMold throws, from "system/..." on.
std::string errorOf(const std::string& dict) {
  try {
    particleize(dict);
  } catch (const Error& error) {
    const std::string message = error.what();
    const auto system = message.find("system/particleizeMoldDict");
    return system == std::string::npos ? message : message.substr(system);
  }
  return "no error";
}

TEST(MoldGrading, MistakesInGradingAreNamed) {
  EXPECT_NE(errorOf(dieDict("grading { maxSpacing 0.003; }"))
                .find("'maxSpacing' must be at least twice the spacing"),
            std::string::npos);
  EXPECT_NE(errorOf(dieDict("grading { maxSpacing 0.008; fineLayers 2; }"))
                .find("'fineLayers' must be at least wallLayers (3)"),
            std::string::npos);
  const std::string absent =
      errorOf(dieDict("grading { maxSpacing 0.008; fineSurfaces (cavity); }"));
  EXPECT_NE(absent.find("fineSurfaces names 'cavity', which is not a Physical Surface"),
            std::string::npos)
      << absent;
  EXPECT_NE(absent.find("the groups present are ( pocket die )"), std::string::npos) << absent;
  const std::string unknown = errorOf(dieDict("grading { maxSpacing 0.008; coarsest 0.01; }"));
  EXPECT_NE(unknown.find("coarsest"), std::string::npos) << unknown;
  EXPECT_EQ(unknown.rfind("system/particleizeMoldDict:", 0), 0u) << unknown;
  std::string shell = dieDict("grading { maxSpacing 0.008; }");
  shell.replace(shell.find("mode volume"), 11, "mode shell");
  shell.replace(shell.find("die { cloud"), 3, "pocket");
  // the guard against too many particles counts the lattice a graded volume is filled with
  std::string tooMany = dieDict("grading { maxSpacing 0.008; }");
  tooMany.replace(tooMany.find("spacing 0.002;"), 14, "spacing 0.002;\nmaxParticles 1000;");
  EXPECT_NE(errorOf(tooMany).find("a graded volume is filled at the spacing before it is graded"),
            std::string::npos)
      << errorOf(tooMany);
  EXPECT_NE(errorOf(shell).find("'grading' is for the volume patches (mode volume"),
            std::string::npos)
      << errorOf(shell);
}

// A 2D die (dimension 2): a section 100 x 60 mm with a pocket 60 x 20 mm in its top, its
// pocket's three sides the Physical Curve "pocket"; the die's corner off the coarser lattices.
const std::string dieGeo2D = R"(x0 = -0.0487; y0 = -0.0487;
Point(1) = {x0, y0, 0}; Point(2) = {x0 + 0.1, y0, 0}; Point(3) = {x0 + 0.1, y0 + 0.06, 0};
Point(4) = {x0 + 0.08, y0 + 0.06, 0}; Point(5) = {x0 + 0.08, y0 + 0.04, 0};
Point(6) = {x0 + 0.02, y0 + 0.04, 0}; Point(7) = {x0 + 0.02, y0 + 0.06, 0};
Point(8) = {x0, y0 + 0.06, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 6};
Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7, 8}; Plane Surface(1) = {1};
Physical Surface("die") = {1};
Physical Curve("pocket") = {4, 5, 6};
)";

ParticleizedMold particleize2D(const std::string& grading) {
  TemporaryCase die;
  die.write("constant/geometry/die.geo", dieGeo2D);
  die.write(
      "system/particleizeMoldDict",
      "FoamFile { version 2.0; format ascii; class dictionary; object particleizeMoldDict; }\n"
      "dimension 2;\ngeometry (\"die.geo\");\nspacing 0.002;\nsupportRadius 0.006;\n"
      "patches\n{\n    die { cloud die; type fixedWall; mode volume; " +
          grading + " }\n}\n");
  return particleizeMold(CaseFolder(die.root()));
}

// Distance from a point of the 2D die to the pocket's three sides (its box's, as in 3D).
double toPocket2D(const Vector& p) {
  const auto outside = [](double v, double lo, double hi) {
    return v < lo ? lo - v : (v > hi ? v - hi : 0.0);
  };
  return std::hypot(outside(p.x(), -0.0287, 0.0313), outside(p.y(), -0.0087, 0.0113));
}

// 2D: the lattice's quadtree, as the 3D octree: the die's area to round-off, dx within fineLayers
// dx of the pocket, each coarser particle for between half and all of its block's 4^l points.
// Measured: 1,200 particles at 2 mm uniform, 386 graded up to 8 mm (3.11 times fewer; in 2D a
// coarser particle stands for 4^l points, not 8^l).
TEST(MoldGrading, A2DDieIsGradedAsAQuadtree) {
  const ParticleizedMold uniform = particleize2D("");
  const ParticleizedMold graded =
      particleize2D("grading { maxSpacing 0.008; fineLayers 3; fineSurfaces (pocket); }");
  const ParticleCloud& u = uniform.clouds.at(0);
  const ParticleCloud& g = graded.clouds.at(0);
  ASSERT_TRUE(g.hasScalarField(field::localSpacing));
  double uniformArea = 0, gradedArea = 0;
  for (const Real v : u.scalarField(field::volume)) uniformArea += v;
  for (const Real v : g.scalarField(field::volume)) gradedArea += v;
  EXPECT_NEAR(gradedArea / uniformArea, 1.0, 1e-12);
  EXPECT_NEAR(uniformArea, 0.1 * 0.06 - 0.06 * 0.02, 1e-12);
  const double ratio = double(u.size()) / double(g.size());
  std::printf("2D die: %zu particles at 2 mm, %zu graded up to 8 mm: %.2f times fewer\n", u.size(),
              g.size(), ratio);
  EXPECT_GT(ratio, 2.5);
  const double dx = 0.002, cell = uniformArea / double(u.size());
  const auto& spacing = g.scalarField(field::localSpacing);
  const auto& volume = g.scalarField(field::volume);
  std::size_t levels[3] = {0, 0, 0};
  for (std::size_t i = 0; i < g.size(); ++i) {
    EXPECT_EQ(g.positions()[i].z(), 0.0);
    const int level = static_cast<int>(std::lround(std::log2(spacing[i] / dx)));
    ASSERT_GE(level, 0);
    ASSERT_LE(level, 2);
    ++levels[level];
    const double points = volume[i] / cell;
    EXPECT_LE(points, std::pow(4.0, level) + 1e-9);
    EXPECT_GE(points, level == 0 ? 1.0 - 1e-9 : 0.5 * std::pow(4.0, level) - 1e-9);
    if (level > 0) {
      EXPECT_GE(toPocket2D(g.positions()[i]), 3 * dx) << i;
      EXPECT_GT(g.scalarField(field::wallDistance)[i], 0.0) << i;
    }
  }
  EXPECT_GT(levels[1], 0u);
  EXPECT_GT(levels[2], 0u);
  // fineSurfaces in 2D are Physical Curves
  try {
    particleize2D("grading { maxSpacing 0.008; fineSurfaces (die); }");
    FAIL() << "a Physical Surface taken for the fine curves";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("'die', which is not a Physical Curve"), std::string::npos) << message;
    EXPECT_NE(message.find("system/particleizeMoldDict"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace sphcast
