// setCastFields' fill and setFields on clouds handed in by the application.
#include "geometry/CastFieldsSetup.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <tuple>

#include "core/dictionary/SourceLocation.h"
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
  const ParticleCloud metal = buildCastClouds(CaseFolder(folder.root()), {}).at(0);
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
  const auto clouds = buildCastClouds(CaseFolder(folder.root()), {mold});
  ASSERT_EQ(clouds.size(), 1u);
  const auto& temperature = clouds[0].scalarField("T");
  EXPECT_EQ(temperature[0], 0.0);
  EXPECT_EQ(temperature[1], 300.0);
  EXPECT_EQ(temperature[2], 300.0);
  EXPECT_FALSE(mold.hasScalarField("T"));  // the cloud handed in is left as it was

  // A density model is for new clouds; an existing one takes a number.
  folder.write(
      "system/setCastFieldsDict",
      header + "spacing 0.1;\nsetFields\n{\n    mold { fields { rho hydrostatic; } }\n}\n");
  try {
    buildCastClouds(CaseFolder(folder.root()), {mold});
    FAIL() << "rho hydrostatic accepted on an existing cloud";
  } catch (const DictionaryError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("setCastFieldsDict:5:"), std::string::npos) << message;
    EXPECT_NE(message.find("rho hydrostatic is for the new clouds"), std::string::npos) << message;
  }

  folder.write("system/setCastFieldsDict",
               header + "spacing 0.1;\nsetFields\n{\n    lid { fields { T 300; } }\n}\n");
  try {
    buildCastClouds(CaseFolder(folder.root()), {mold});
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
    buildCastClouds(CaseFolder(folder.root()), {});
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
               header + "dimension 2;\nspacing 0.01;\nclouds\n{\n    water\n    {\n        regions "
                        "{ r { type box; min (0 0 0); max (0.1 0.2 0); } }\n    }\n}\n");
  const auto clouds = buildCastClouds(CaseFolder(folder.root()), {});
  ASSERT_EQ(clouds.size(), 1u);
  EXPECT_EQ(clouds[0].size(), 200u);
  for (std::size_t i = 0; i < clouds[0].size(); ++i) {
    EXPECT_DOUBLE_EQ(double(clouds[0].scalarField("volume")[i]), 1e-4);  // dx^2
    EXPECT_EQ(clouds[0].positions()[i].z(), 0);
  }
}

TEST(CastFieldsSetup, TwoDimensionalCloudOffThePlaneIsAnErrorAtTheDimensionKey) {
  TemporaryCase folder;
  folder.write("system/setCastFieldsDict",
               header + "dimension 2;\nspacing 0.01;\nclouds\n{\n    water\n    {\n        regions "
                        "{ r { type box; min (0 0 0); max (0.1 0.2 0.05); } }\n    }\n}\n");
  try {
    buildCastClouds(CaseFolder(folder.root()), {});
    FAIL() << "a 2D cloud off z = 0 accepted";
  } catch (const DictionaryError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("setCastFieldsDict:2:1: cloud 'water' has a particle at z = 0.005"),
              std::string::npos)
        << message;
  }
}

}  // namespace
}  // namespace sphcast
