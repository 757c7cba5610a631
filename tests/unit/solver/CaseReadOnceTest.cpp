// Each tool reads each of the case's shared files once (case/CaseDescription.h): sphCastFoam's
// set-up of a case with every model family (flow, walls, a body, an inlet, surface tension,
// heat with every path, solidification), setCastFields' fill and start pressure, and
// castPostProcess's reading of h, the dimension and the heat clouds' materials.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>

#include "case/CaseDescription.h"
#include "core/CaseFolder.h"
#include "core/Log.h"
#include "core/dictionary/Dictionary.h"
#include "geometry/CastFieldsSetup.h"
#include "io/VtpCloud.h"
#include "particles/FieldNames.h"
#include "solver/CastingSolver.h"
#include "sph/FlowSetup.h"
#include "sph/FlowTestCases.h"
#include "support/TemporaryCase.h"

namespace sphcast {
namespace {

constexpr Real dx = 0.004;

// The files a case shares among its model families.
const char* const sharedFiles[] = {"constant/physicsModels", "system/sphSchemes",
                                   "constant/physicalProperties", "constant/g"};

// How often each shared file of `root` has been read, less `before`.
struct ReadCounts {
  explicit ReadCounts(const std::filesystem::path& root) : root_(root) {
    for (int k = 0; k < 4; ++k) before_[k] = Dictionary::readCount(root_ / sharedFiles[k]);
  }
  int since(int k) const { return Dictionary::readCount(root_ / sharedFiles[k]) - before_[k]; }
  std::filesystem::path root_;
  int before_[4] = {};
};

// A 2D pour into an iron tank with a lid that falls, every model family on: the case of
// ParallelSolverTest's pour, at rest after one step.
void writeCastingCase(const testing::TemporaryCase& folder) {
  folder.write("system/controlDict",
               "application sphCastFoam; startFrom latestTime; stopAt endTime; endTime 1e-5;\n"
               "deltaT 1e-5; adjustTimeStep no; maxCo 0.25; writeControl timeStep;\n"
               "writeInterval 1; logInterval 100000;\n");
  folder.write("system/sphSchemes",
               "densityScheme riemann; viscousForm Morris; supportRadius 0.012;\n"
               "soundSpeed 20; wallDissipation normalApproach;\n");
  folder.write("constant/physicsModels",
               "dimension 2; materials { metal alloy; mold iron; lid iron; }\n"
               "flow { model weaklyCompressible; fluid metal; walls (mold lid); }\n"
               "surfaceTension { model continuumSurfaceForce; contactAngle 120; }\n"
               "heatTransfer { clouds (metal mold lid); conduction on;\n"
               "  moldContact { coefficients ((alloy iron 150)); }\n"
               "  atmosphere { T 300; coefficients ((iron 80) (alloy 20)); }\n"
               "  radiation { T 300; materials (iron alloy); } }\n"
               "solidification { model frozenSolid; }\n");
  folder.write("constant/physicalProperties",
               "alloy { liquidus 888.64; solidus 830.44; emissivity 0.1; surfaceTension 0.9;\n"
               "  temperatures (803.0 830.44 848 873 888.64 973);\n"
               "  internalEnergy (7.89e5 8.44e5 1.11e6 1.23e6 1.33e6 1.431e6);\n"
               "  viscosity (4.88e4 4.73e4 2.154e3 1.86e2 1.57e-3 1.28e-3);\n"
               "  density (2571.9 2565.5 2517 2474.3 2426.6 2398.8);\n"
               "  conductivity (174.35 175.34 114.78 98.33 83.3 86.05); }\n"
               "iron { density 7874; conductivity 26; specificHeat 700; emissivity 0.3; }\n");
  folder.write("constant/g", "dimensions [0 1 -2 0 0 0 0]; value (0 -9.81 0);\n");
  folder.write("constant/inlets",
               "ladle { centre (0.03 0.07 0); direction (0 -1 0); radius 0.016; speed 0.5;\n"
               "        endTime 0.08; T 950; }\n");
  folder.write("constant/dynamicBodies",
               "lid { density 7874; translation (0 1 0); rotation locked; releaseTime 0.02; }\n");
  ParticleCloud metal = testing::fluidBlock2D(40, 5, dx, Vector::Zero(), 2400, Real(1.3e-3));
  ParticleCloud mold = testing::tankWalls2D(40, 25, dx);
  ParticleCloud lid = testing::emptyWall();
  testing::addWallCells(
      lid, 22, 35, 10, 13, dx, Vector::Zero(), [](int, int) { return Vector(0, -1, 0); },
      [](int, int row) { return (Real(row - 10) + Real(0.5)) * dx; });
  for (ParticleCloud* cloud : {&metal, &mold, &lid}) {
    auto& T = cloud->addScalarField(field::T);
    for (Real& t : T) t = cloud == &metal ? Real(950) : Real(500);
    cloud->attributes()["spacing"] = dx;
  }
  std::filesystem::create_directories(folder.root() / "0");
  writeCloudVtp(metal, folder.root() / "0/metal.vtp");
  writeCloudVtp(mold, folder.root() / "0/mold.vtp");
  writeCloudVtp(lid, folder.root() / "0/lid.vtp");
}

TEST(CaseReadOnce, TheSolverReadsEachSharedCaseFileOnceWithEveryModelFamilyOn) {
  const testing::TemporaryCase folder;
  writeCastingCase(folder);
  const ReadCounts counts(folder.root());
  silenceInfo(true);
  const CaseFolder caseFolder(folder.root());  // the solver keeps a reference to it
  CastingSolver(caseFolder).run();
  silenceInfo(false);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(counts.since(k), 1) << sharedFiles[k];
}

// The names of particles/FieldNames.h, read from its text: the one list of field names.
std::set<std::string> listedFieldNames() {
  std::ifstream file(std::filesystem::path(SPHCAST_SOURCE_DIR) / "src/particles/FieldNames.h");
  std::set<std::string> names;
  const std::regex entry("inline constexpr const char\\* (\\w+) = \"(\\w+)\";");
  for (std::string line; std::getline(file, line);) {
    std::smatch match;
    if (std::regex_search(line, match, entry)) {
      EXPECT_EQ(match[1], match[2]) << line;  // a constant is named as its field
      names.insert(match[2]);
    }
  }
  return names;
}

// Every field the solver writes, with every model family on, is one of the listed names.
TEST(CaseReadOnce, EveryFieldTheSolverWritesIsInTheOneListOfFieldNames) {
  const testing::TemporaryCase folder;
  writeCastingCase(folder);
  silenceInfo(true);
  const CaseFolder caseFolder(folder.root());
  CastingSolver solver(caseFolder);
  solver.run();
  silenceInfo(false);
  const std::set<std::string> listed = listedFieldNames();
  ASSERT_GT(listed.size(), 40u);
  std::size_t checked = 0;
  for (const ParticleCloud& cloud : solver.clouds()) {
    std::vector<std::string> names;
    for (const auto& entry : cloud.scalarFields()) names.push_back(entry.first);
    for (const auto& entry : cloud.vectorFields()) names.push_back(entry.first);
    for (const auto& entry : cloud.idFields()) names.push_back(entry.first);
    for (const std::string& name : names) {
      EXPECT_TRUE(listed.contains(name))
          << cloud.name() << "." << name << " is not in FieldNames.h";
      ++checked;
    }
  }
  EXPECT_GT(checked, 30u);
}

TEST(CaseReadOnce, SetCastFieldsAndCastPostProcessReadEachSharedCaseFileOnce) {
  const testing::TemporaryCase folder;
  writeCastingCase(folder);
  folder.write("system/setCastFieldsDict",
               "dimension 2; spacing 0.004;\n"
               "clouds { metal { regions { pool { type box; min (0.004 0.004 0);\n"
               "  max (0.06 0.02 0); } } fields { T 950; rho standard; U (0 0 0); } } }\n");
  {  // setCastFields: the fill (rho from the material's rho_s(T)) and the flow's start pressure
    const ReadCounts counts(folder.root());
    silenceInfo(true);
    const CaseDescription description{CaseFolder(folder.root())};
    std::vector<ParticleCloud> clouds = buildCastClouds(description, {});
    const FlowSetup flow = readFlowSetup(description);
    ASSERT_EQ(clouds.at(0).name(), flow.fluidCloud);
    EXPECT_EQ(startPressure(flow, clouds.at(0)).size(), clouds.at(0).size());
    silenceInfo(false);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(counts.since(k), 1) << sharedFiles[k];
  }
  {  // castPostProcess: h, the dimension and each heat cloud's material
    const ReadCounts counts(folder.root());
    const CaseDescription description{CaseFolder(folder.root())};
    EXPECT_EQ(description.dimension(), 2);
    EXPECT_DOUBLE_EQ(description.supportRadius(), 0.012);
    for (const std::string& cloud : description.heatClouds()) {
      EXPECT_EQ(description.heatCloudMaterial(cloud).name, cloud == "metal" ? "alloy" : "iron");
    }
    EXPECT_EQ(counts.since(0), 1);  // physicsModels
    EXPECT_EQ(counts.since(1), 1);  // sphSchemes
    EXPECT_EQ(counts.since(2), 1);  // physicalProperties
  }
}

// A file no family asks for is not read: a case of ballistic clouds needs neither
// physicalProperties nor sphSchemes, and a missing one is no error.
TEST(CaseReadOnce, AFileNoModelAsksForIsNotRead) {
  const testing::TemporaryCase folder;
  folder.write("constant/physicsModels", "dimension 2;\n");
  folder.write("system/sphSchemes", "this is not read;\n");
  const CaseDescription description{CaseFolder(folder.root())};
  EXPECT_FALSE(description.hasFlow());
  EXPECT_FALSE(description.hasHeat());
  EXPECT_EQ(Dictionary::readCount(folder.root() / "system/sphSchemes"), 0);
  EXPECT_EQ(Dictionary::readCount(folder.root() / "constant/physicalProperties"), 0);
}

}  // namespace
}  // namespace sphcast
