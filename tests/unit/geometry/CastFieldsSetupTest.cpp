// setCastFields' fill and setFields on clouds handed in by the application.
#include "geometry/CastFieldsSetup.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "core/dictionary/SourceLocation.h"
#include "particles/FieldNames.h"
#include "support/TemporaryCase.h"

namespace sphcast {
namespace {

using testing::TemporaryCase;

const std::string header = "FoamFile { version 2.0; format ascii; class dictionary; object x; }\n";

TEST(CastFieldsSetup, OverlappingRegionsFillEachLatticePointOnce) {
  // Two spheres of radius 5 dx whose centres are 4 dx apart, in one cloud: the lattice points of
  // their union, each once.
  TemporaryCase folder;
  folder.write("system/setCastFieldsDict",
               header +
                   "spacing 0.001;\nclouds { metal { regions {\n"
                   "  a { type sphere; centre (0 0 0); radius 0.005; }\n"
                   "  b { type sphere; centre (0.004 0 0); radius 0.005; }\n} } }\n");
  const ParticleCloud metal = buildCastClouds(CaseDescription(CaseFolder(folder.root())), {}).at(0);
  std::set<std::tuple<long, long, long>> unionPoints;
  for (long i = -8; i <= 12; ++i) {
    for (long j = -8; j <= 8; ++j) {
      for (long k = -8; k <= 8; ++k) {
        const Eigen::Vector3d p = (Eigen::Vector3d(static_cast<double>(i), static_cast<double>(j),
                                                   static_cast<double>(k)) +
                                   Eigen::Vector3d::Constant(0.5)) *
                                  1e-3;
        if (p.norm() <= 0.005 || (p - Eigen::Vector3d(0.004, 0, 0)).norm() <= 0.005) {
          unionPoints.insert({i, j, k});
        }
      }
    }
  }
  std::set<std::tuple<long, long, long>> filled;
  for (const Vector& x : metal.positions()) {
    filled.insert({std::lround(x.x() / 1e-3 - 0.5), std::lround(x.y() / 1e-3 - 0.5),
                   std::lround(x.z() / 1e-3 - 0.5)});
  }
  EXPECT_EQ(metal.size(), filled.size()) << "a lattice point filled twice";
  EXPECT_EQ(filled, unionPoints);
}

TEST(CastFieldsSetup, SetFieldsWorksOnTheCloudsItIsGivenAndNamesTheMissingOnes) {
  TemporaryCase folder;
  ParticleCloud mold("mold");
  mold.resize(3);
  mold.positions() = {Vector(0, 0, 0), Vector(1, 0, 0), Vector(2, 0, 0)};
  folder.write(
      "system/setCastFieldsDict",
      header +
          "spacing 0.1;\nsetFields\n{\n    mold { fields { T 300; } regions { r { type box; "
          "min (0.5 -1 -1); max (3 1 1); } } }\n}\n");
  const auto clouds = buildCastClouds(CaseDescription(CaseFolder(folder.root())), {mold});
  ASSERT_EQ(clouds.size(), 1u);
  const auto& temperature = clouds[0].scalarField(field::T);
  EXPECT_EQ(temperature[0], 0.0);
  EXPECT_EQ(temperature[1], 300.0);
  EXPECT_EQ(temperature[2], 300.0);
  EXPECT_FALSE(mold.hasScalarField(field::T));  // the cloud handed in is left as it was

  // A density model is for new clouds; an existing one takes a number.
  folder.write(
      "system/setCastFieldsDict",
      header + "spacing 0.1;\nsetFields\n{\n    mold { fields { rho hydrostatic; } }\n}\n");
  try {
    buildCastClouds(CaseDescription(CaseFolder(folder.root())), {mold});
    FAIL() << "rho hydrostatic accepted on an existing cloud";
  } catch (const DictionaryError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("setCastFieldsDict:5:"), std::string::npos) << message;
    EXPECT_NE(message.find("rho hydrostatic is for the new clouds"), std::string::npos) << message;
  }

  folder.write("system/setCastFieldsDict",
               header + "spacing 0.1;\nsetFields\n{\n    lid { fields { T 300; } }\n}\n");
  try {
    buildCastClouds(CaseDescription(CaseFolder(folder.root())), {mold});
    FAIL() << "a cloud that is not in constant/particles was accepted";
  } catch (const DictionaryError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("setCastFieldsDict:5:"), std::string::npos) << message;
    EXPECT_NE(message.find("cloud 'lid'"), std::string::npos) << message;
    EXPECT_NE(message.find("( mold )"), std::string::npos) << message;
  }
}

TEST(CastFieldsSetup, RelaxationOfAFlatCloudIsAnErrorAtTheRelaxationKey) {
  // A box of zero height is one layer (a 2D case); the relaxation's kernel is 3D.
  TemporaryCase folder;
  folder.write("system/setCastFieldsDict",
               header +
                   "spacing 0.01;\nclouds\n{\n    metal\n    {\n        regions { r { type box; "
                   "min (0 0 0); max (0.1 0.1 0); } }\n        relaxation { iterations 10; }\n"
                   "    }\n}\n");
  try {
    buildCastClouds(CaseDescription(CaseFolder(folder.root())), {});
    FAIL() << "relaxation of a flat cloud accepted";
  } catch (const DictionaryError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("setCastFieldsDict:8:"), std::string::npos) << message;
    EXPECT_NE(message.find("one particle thick"), std::string::npos) << message;
  }
}

TEST(CastFieldsSetup, TwoDimensionalCloudsHaveTheAreaOfTheirCellAsVolume) {
  TemporaryCase folder;
  folder.write("system/setCastFieldsDict",
               header +
                   "dimension 2;\nspacing 0.01;\nclouds\n{\n    water\n    {\n        regions "
                   "{ r { type box; min (0 0 0); max (0.1 0.2 0); } }\n    }\n}\n");
  const auto clouds = buildCastClouds(CaseDescription(CaseFolder(folder.root())), {});
  ASSERT_EQ(clouds.size(), 1u);
  EXPECT_EQ(clouds[0].size(), 200u);
  for (std::size_t i = 0; i < clouds[0].size(); ++i) {
    EXPECT_DOUBLE_EQ(double(clouds[0].scalarField(field::volume)[i]), 1e-4);  // dx^2
    EXPECT_EQ(clouds[0].positions()[i].z(), 0);
  }
}

TEST(CastFieldsSetup, TwoDimensionalCaseFillsTheSectionOfABoxAndRefusesOneOffThePlane) {
  // A box with depth in z fills its rectangle in the plane z = 0 (the 200 points of 0.1 x 0.2).
  TemporaryCase folder;
  folder.write("system/setCastFieldsDict",
               header +
                   "dimension 2;\nspacing 0.01;\nclouds\n{\n    water\n    {\n        regions "
                   "{ r { type box; min (0 0 -0.05); max (0.1 0.2 0.05); } }\n    }\n}\n");
  const auto clouds = buildCastClouds(CaseDescription(CaseFolder(folder.root())), {});
  ASSERT_EQ(clouds.size(), 1u);
  EXPECT_EQ(clouds[0].size(), 200u);
  for (const Vector& x : clouds[0].positions()) EXPECT_EQ(x.z(), 0);

  // A box wholly above the plane holds nothing of it: an error at the region, saying why.
  folder.write("system/setCastFieldsDict",
               header +
                   "dimension 2;\nspacing 0.01;\nclouds\n{\n    water\n    {\n        regions "
                   "{ r { type box; min (0 0 0.01); max (0.1 0.2 0.05); } }\n    }\n}\n");
  try {
    buildCastClouds(CaseDescription(CaseFolder(folder.root())), {});
    FAIL() << "a 2D region off z = 0 accepted";
  } catch (const DictionaryError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("setCastFieldsDict:8:"), std::string::npos) << message;
    EXPECT_NE(message.find("region 'r' of cloud 'water' holds no lattice point"), std::string::npos)
        << message;
    EXPECT_NE(message.find("does not reach the plane z = 0"), std::string::npos) << message;
  }
}

// The lattice points ((i + 1/2) dx, (j + 1/2) dx, 0) for which inside(x, y) holds.
template <class Inside>
std::set<std::pair<long, long>> planeLatticeInside(double dx, long range, const Inside& inside) {
  std::set<std::pair<long, long>> points;
  for (long i = -range; i < range; ++i) {
    for (long j = -range; j < range; ++j) {
      if (inside((static_cast<double>(i) + 0.5) * dx, (static_cast<double>(j) + 0.5) * dx)) {
        points.insert({i, j});
      }
    }
  }
  return points;
}

std::set<std::pair<long, long>> planeLatticeOf(const ParticleCloud& cloud, double dx) {
  std::set<std::pair<long, long>> points;
  for (const Vector& x : cloud.positions()) {
    EXPECT_EQ(x.z(), 0) << "a 2D particle off the plane";
    points.insert({std::lround(x.x() / dx - 0.5), std::lround(x.y() / dx - 0.5)});
  }
  EXPECT_EQ(points.size(), cloud.size()) << "a lattice point filled twice";
  return points;
}

TEST(CastFieldsSetup, TwoDimensionalCaseFillsTheSectionOfEveryRegionType) {
  // Each region cut by z = 0 fills exactly the plane lattice points of its section (a point on
  // the boundary may go either way: the shapes are chosen so that none lies on one).
  const double dx = 0.001;
  struct Case {
    const char* region;
    std::function<bool(double, double)> inside;
  };
  const double r = 0.0103, zc = 0.004, rSection = std::sqrt(r * r - zc * zc);
  const std::vector<Case> cases = {
      {"{ type sphere; centre (0.0002 0.0001 0.004); radius 0.0103; }",
       [&](double x, double y) { return std::hypot(x - 0.0002, y - 0.0001) <= rSection; }},
      {"{ type cylinder; point1 (0 0 -0.01); point2 (0 0 0.02); radius 0.0081; }",
       [](double x, double y) { return std::hypot(x, y) <= 0.0081; }},
      {"{ type cone; point1 (-0.0101 0 0); point2 (0.0101 0 0); radius1 0.002; radius2 0.009; }",
       [](double x, double y) {
         return std::abs(x) <= 0.0101 && std::abs(y) <= 0.002 + 0.007 * (x + 0.0101) / 0.0202;
       }},
      {"{ type intersection; regions { s { type sphere; centre (0 0 0); radius 0.0123; }\n"
       "  slab { type box; min (-1 -0.0052 -0.0001); max (1 1 0.0001); } } }",
       [](double x, double y) { return std::hypot(x, y) <= 0.0123 && y >= -0.0052; }},
      {"{ type gmshSurface; file \"disk.geo\"; group melt; }",
       [](double x, double y) { return std::hypot(x - 0.0004, y) <= 0.0092; }},
  };
  TemporaryCase folder;
  folder.write("constant/geometry/disk.geo",
               "SetFactory(\"OpenCASCADE\");\nDisk(1) = {0.0004, 0, 0, 0.0092};\n"
               "Physical Surface(\"melt\") = {1};\n");
  for (const Case& c : cases) {
    folder.write("system/setCastFieldsDict",
                 header + "dimension 2;\nspacing 0.001;\nclouds { metal { regions {\n  r " +
                     c.region + "\n} } }\n");
    const ParticleCloud metal =
        buildCastClouds(CaseDescription(CaseFolder(folder.root())), {}).at(0);
    const auto expected = planeLatticeInside(dx, 30, c.inside);
    ASSERT_GT(expected.size(), 100u) << c.region;
    EXPECT_EQ(planeLatticeOf(metal, dx), expected) << c.region;
  }
  // gmsh volumes are 3D; a 2D case names a surface (and the reverse).
  folder.write("system/setCastFieldsDict",
               header +
                   "dimension 2;\nspacing 0.001;\nclouds { metal { regions {\n  r { type "
                   "gmshVolume; file \"disk.geo\"; group melt; }\n} } }\n");
  EXPECT_THROW(buildCastClouds(CaseDescription(CaseFolder(folder.root())), {}), DictionaryError);
}

TEST(CastFieldsSetup, EmptyFillIsAnErrorNamingTheCloudTheRegionAndWhy) {
  TemporaryCase folder;
  auto expectError = [&](const std::string& clouds, const std::vector<std::string>& parts,
                         const std::vector<ParticleCloud>& mold) {
    folder.write("system/setCastFieldsDict",
                 header + "spacing 0.01;\nclouds\n{\n" + clouds + "}\n");
    try {
      buildCastClouds(CaseDescription(CaseFolder(folder.root())), mold);
      ADD_FAILURE() << "an empty fill accepted: " << clouds;
    } catch (const DictionaryError& error) {
      const std::string message = error.what();
      for (const std::string& part : parts) {
        EXPECT_NE(message.find(part), std::string::npos) << message;
      }
    }
  };
  // thinner than a spacing, between the lattice planes
  expectError(
      "  disk { regions { thin { type cylinder; point1 (0 0 0.001); point2 (0 0 0.004); "
      "radius 0.05; } } }\n",
      {"setCastFieldsDict:5:", "region 'thin' of cloud 'disk' holds no lattice point",
       "thinner than a spacing"},
      {});
  // inside a mold: a block of mold particles on the lattice covers the region
  std::vector<Vector> block;
  for (int i = -5; i < 5; ++i) {
    for (int j = -5; j < 5; ++j) {
      for (int k = -5; k < 5; ++k) {
        block.push_back(Vector(Real(i + 0.5), Real(j + 0.5), Real(k + 0.5)) * Real(0.01));
      }
    }
  }
  ParticleCloud mold("mold");
  mold.resize(block.size());
  std::copy(block.begin(), block.end(), mold.positions().begin());
  expectError("  metal { regions { a { type sphere; centre (0 0 0); radius 0.02; } } }\n",
              {"setCastFieldsDict:5:", "region 'a' of cloud 'metal' is filled by no particle",
               "inside the mold"},
              {mold});
  // in other units than the mold (a centre in mm, the mold in m): wholly outside its domain
  expectError("  metal { regions { a { type sphere; centre (0 0 20); radius 0.03; } } }\n",
              {"setCastFieldsDict:5:", "cloud 'metal' lies wholly outside the domain", "units"},
              {mold});
}

TEST(CastFieldsSetup, TheCloudsMaterialComesFromPhysicsModelsWhenTheDictNamesNone) {
  TemporaryCase folder;
  folder.write("constant/physicalProperties",
               header +
                   "alloy { density 2500; viscosity 1e-3; }\nwater { density 1000; "
                   "viscosity 1e-3; }\n");
  folder.write("constant/physicsModels", header + "materials { metal alloy; }\n");
  folder.write("system/setCastFieldsDict",
               header +
                   "spacing 0.01;\nclouds { metal { regions { a { type box; min (0 0 0); "
                   "max (0.02 0.02 0.02); } } fields { rho standard; } } }\n");
  const ParticleCloud metal = buildCastClouds(CaseDescription(CaseFolder(folder.root())), {}).at(0);
  ASSERT_EQ(metal.size(), 8u);
  for (const Real rho : metal.scalarField(field::rho)) EXPECT_EQ(rho, Real(2500));

  // the two files naming different materials is an error naming both places
  folder.write("system/setCastFieldsDict",
               header +
                   "spacing 0.01;\nclouds { metal { material water; regions { a { type box; "
                   "min (0 0 0); max (0.02 0.02 0.02); } } fields { rho standard; } } }\n");
  try {
    buildCastClouds(CaseDescription(CaseFolder(folder.root())), {});
    FAIL() << "two materials for one cloud accepted";
  } catch (const DictionaryError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("setCastFieldsDict:3:"), std::string::npos) << message;
    EXPECT_NE(message.find("physicsModels:2:"), std::string::npos) << message;
  }
}

TEST(CastFieldsSetup, AMissingFileSaysWhatNeedsIt) {
  // rho hydrostatic reads the material, constant/g and system/sphSchemes: a missing one is
  // reported at the rho entry, naming the file.
  TemporaryCase folder;
  folder.write("constant/physicalProperties", header + "metal { density 2500; viscosity 1e-3; }\n");
  folder.write("system/setCastFieldsDict",
               header +
                   "spacing 0.01;\nclouds { metal { regions { a { type box; min (0 0 0); "
                   "max (0.02 0.02 0.02); } }\n  fields { rho hydrostatic; } } }\n");
  try {
    buildCastClouds(CaseDescription(CaseFolder(folder.root())), {});
    FAIL() << "rho hydrostatic without constant/g accepted";
  } catch (const DictionaryError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("setCastFieldsDict:4:"), std::string::npos) << message;
    EXPECT_NE(message.find("rho hydrostatic (of cloud 'metal') needs it: "), std::string::npos)
        << message;
    EXPECT_NE(message.find("constant/g"), std::string::npos) << message;
  }
}

// setCastFieldsDict's moldClearance (metres to a mold particle's centre) was wallClearance, a
// name system/sphSchemes gives another length; the old name is still read, both is an error.
TEST(CastFieldsSetup, MoldClearanceTakesItsFormerNameAndNotBoth) {
  ParticleCloud mold("mold");  // 3.5 mm beyond the box's right-hand side, and far to its left
  mold.resize(2);
  mold.positions() = {Vector(Real(0.0135), Real(0.0005), 0), Vector(Real(-0.02), Real(0.0005), 0)};
  auto metalWith = [&](const std::string& clearance) {
    TemporaryCase folder;
    folder.write("system/setCastFieldsDict",
                 header + "dimension 2; spacing 0.001;\n" + clearance +
                     "clouds { metal { regions { r { type box; min (0 0 0); max (0.01 0.001 0); "
                     "} } } }\n");
    return buildCastClouds(CaseDescription(CaseFolder(folder.root())), {mold}).at(0).size();
  };
  // the 10 particles at x = 0.5 ... 9.5 mm, the mold at 13.5 mm: a clearance of 4.5 mm takes
  // the last one (4 mm from it; the next is 5 mm off), 0.75 dx none
  EXPECT_EQ(metalWith(""), 10u);
  EXPECT_EQ(metalWith("moldClearance 0.0045;\n"), 9u);
  EXPECT_EQ(metalWith("wallClearance 0.0045;\n"), 9u);
  EXPECT_THROW(metalWith("moldClearance 0.0045;\nwallClearance 0.0045;\n"), DictionaryError);
}

// The dimension is the case's (constant/physicsModels): setCastFieldsDict need not repeat it,
// and may not contradict it.
TEST(CastFieldsSetup, TheDimensionIsTheCasesUnlessGivenAlike) {
  TemporaryCase folder;
  folder.write("constant/physicsModels", header + "dimension 2;\n");
  folder.write("system/setCastFieldsDict",
               header +
                   "spacing 0.001;\n"
                   "clouds { metal { regions { r { type box; min (0 0 -1); max (0.004 0.003 1); "
                   "} } } }\n");
  EXPECT_EQ(buildCastClouds(CaseDescription(CaseFolder(folder.root())), {}).at(0).size(), 12u);
  folder.write("system/setCastFieldsDict",
               header +
                   "dimension 3; spacing 0.001;\n"
                   "clouds { metal { regions { r { type box; min (0 0 0); max (0.004 0.003 "
                   "0.001); } } } }\n");
  try {
    buildCastClouds(CaseDescription(CaseFolder(folder.root())), {});
    FAIL() << "a 3D fill of a 2D case accepted";
  } catch (const DictionaryError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("setCastFieldsDict:2:"), std::string::npos) << message;
    EXPECT_NE(message.find("in constant/physicsModels"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace sphcast
