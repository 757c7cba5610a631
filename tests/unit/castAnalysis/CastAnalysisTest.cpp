// castPostProcess's analyses (castAnalysis/): cooling-curve breaks on curves whose kinks are
// known, grad T against a linear field, the solidification maps (G, Niyama, lambda_2, the
// dimensionless Niyama) against values worked by hand, the heat books, and the errors a user
// meets (unknown type, unknown key, a thermocouple outside the casting).
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <fstream>
#include <numeric>

#include "castAnalysis/CastAnalysis.h"
#include "castAnalysis/CoolingCurve.h"
#include "castAnalysis/PlaneInterpolation.h"
#include "castAnalysis/TemperatureGradient.h"
#include "castAnalysis/TimeSeries.h"
#include "castAnalysis/VoxelOccupancy.h"
#include "core/dictionary/SourceLocation.h"
#include "io/VtpCloud.h"
#include "materials/MaterialLibrary.h"
#include "particles/FieldNames.h"
#include "support/TemporaryCase.h"

namespace sphcast {
namespace {

Material ac4ch(const std::string& extra = "") {
  const testing::TemporaryCase folder;
  folder.write("constant/physicalProperties",
               "FoamFile { version 2.0; format ascii; class dictionary; object "
               "physicalProperties; }\nAC4CH { #includeEtc \"materials/AC4CH\" " +
                   extra + " }\n");
  return MaterialLibrary::read(folder.root() / "constant/physicalProperties")
      .get("AC4CH", {}, "metal");
}

// A lumped particle of AC4CH cooling at constant heat extraction (u linear in t: T(t) piecewise
// linear, kinks at the table's nodes) and by Newton's law into 300 K air (curved between kinks):
// the arrest and the end of freezing are found at the liquidus and the solidus, though the
// table's node at 848 K also quickens the cooling (by 3.2 times, against 7.6 at the solidus), and
// a melt first holding its temperature (slopes of round-off) shows no arrest.
TEST(CoolingCurve, BreaksLieAtTheLiquidusAndSolidusOfALumpedCasting) {
  const Material material = ac4ch();
  const InternalEnergyTable& u = *material.internalEnergy;
  for (const bool newton : {false, true}) {
    std::vector<double> time, temperature;
    // a melt holding its 950 K for 1 s first (round-off slopes must not read as an arrest)
    for (int k = 0; k < 100; ++k) {
      time.push_back(k * 0.01 - 1.0);
      temperature.push_back(950 + 1e-9 * ((k * 7919) % 13 - 6));
    }
    double energy = u.energy(950);
    const double dt = 0.01;
    for (int k = 0; k < 12000; ++k) {
      const double T = u.temperature(Real(energy));
      time.push_back(k * dt);
      temperature.push_back(T);
      energy -= dt * (newton ? 40.0 * (T - 300) : 1.5e4);
    }
    const CoolingCurveBreaks breaks = findCoolingCurveBreaks(time, temperature);
    ASSERT_TRUE(breaks.arrest.found && breaks.end.found) << "newton " << newton;
    EXPECT_NEAR(breaks.arrest.temperature, 888.64, newton ? 0.05 : 1e-6) << "newton " << newton;
    EXPECT_NEAR(breaks.end.temperature, 830.44, newton ? 0.05 : 1e-6) << "newton " << newton;
    if (!newton) {  // at u_0 - q t = u(T): exact
      EXPECT_NEAR(breaks.arrest.time, (u.energy(950) - u.energy(888.64)) / 1.5e4, 1e-6);
      EXPECT_NEAR(breaks.end.time, (u.energy(950) - u.energy(830.44)) / 1.5e4, 1e-6);
      // linear between samples: within one sample's time of the kink it lies on
      EXPECT_NEAR(firstTimeAtOrBelow(time, temperature, 888.64),
                  (u.energy(950) - u.energy(888.64)) / 1.5e4, dt);
    }
  }
  // no freezing in the curve: nothing found
  const std::vector<double> time{0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  const std::vector<double> linear{900, 890, 880, 870, 860, 850, 840, 830, 820, 810};
  EXPECT_FALSE(findCoolingCurveBreaks(time, linear).arrest.found);
  EXPECT_TRUE(std::isnan(firstTimeAtOrBelow(time, linear, 700)));
}

ParticleCloud latticeBlock(int n, Real dx, int dimension) {
  ParticleCloud cloud("metal");
  const int nz = dimension == 3 ? n : 1;
  cloud.resize(std::size_t(n) * n * nz);
  auto& mass = cloud.addScalarField(field::mass);
  auto& rho = cloud.addScalarField(field::rho);
  auto& id = cloud.addIdField("id");
  std::size_t k = 0;
  for (int z = 0; z < nz; ++z) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x, ++k) {
        cloud.positions()[k] = Vector((x + Real(0.5)) * dx, (y + Real(0.5)) * dx,
                                      dimension == 3 ? (z + Real(0.5)) * dx : 0);
        rho[k] = 2400;
        mass[k] = 2400 * (dimension == 3 ? dx * dx * dx : dx * dx);
        id[k] = std::int64_t(k);
      }
    }
  }
  cloud.attributes()["spacing"] = dx;
  cloud.addScalarField(field::T);
  return cloud;
}

// The corrected kernel gradient is exact for a linear field at every particle, the corners and
// faces of the block included (where the plain kernel sum is off by about half); one thread and
// two give the same bits.
TEST(TemperatureGradient, ExactForALinearFieldUpToTheSurface) {
  for (const int dimension : {2, 3}) {
    ParticleCloud block = latticeBlock(8, 0.01, dimension);
    const Vector slope = dimension == 3 ? Vector(1000, -500, 200) : Vector(1000, -500, 0);
    for (std::size_t i = 0; i < block.size(); ++i) {
      block.scalarField(field::T)[i] = 900 + slope.dot(block.positions()[i]);
    }
    const auto gradient = temperatureGradient(block, 0.03, dimension);
    double worst = 0;
    for (const Vector& g : gradient) worst = std::max(worst, double((g - slope).norm()));
    EXPECT_LT(worst, 1e-8 * slope.norm()) << dimension << "D";
    // its pass on one and on two threads: the same bits
    const int previous = omp_get_max_threads();
    omp_set_num_threads(2);
    const auto twoThreads = temperatureGradient(block, 0.03, dimension);
    omp_set_num_threads(previous);
    EXPECT_TRUE(twoThreads == gradient) << dimension << "D";
  }
}

// A void planted in a block of particles (those within R of its centre taken out) is found, and
// its volume is the taken-out particles' share, n dx^d, within 5 % (measured in the test's
// output); the same void opened to the outside by a channel is a sink, not a cavity.
TEST(ShrinkageCavities, PlantedVoidMeasuredWithinFivePercent) {
  for (const int dimension : {2, 3}) {
    const int n = dimension == 3 ? 24 : 40;
    const Real dx = 0.001, radius = (dimension == 3 ? 5 : 8) * dx;
    for (const bool open : {false, true}) {
      ParticleCloud block = latticeBlock(n, dx, dimension);
      Vector centre = Vector::Constant(n * dx / 2);
      if (dimension == 2) centre.z() = 0;
      std::vector<std::size_t> keep;
      for (std::size_t i = 0; i < block.size(); ++i) {
        const Vector& x = block.positions()[i];
        const bool inVoid = (x - centre).norm() < radius;
        // the channel: a square tube 3 dx wide from the void to x = 0
        const bool inChannel = open && x.x() < centre.x() &&
                               std::abs(x.y() - centre.y()) < 1.6 * dx &&
                               (dimension == 2 || std::abs(x.z() - centre.z()) < 1.6 * dx);
        if (!inVoid && !inChannel) keep.push_back(i);
      }
      const double planted =
          double(block.size() - keep.size()) * (dimension == 3 ? dx * dx * dx : dx * dx);
      ParticleCloud holed("metal");
      holed.resize(keep.size());
      for (std::size_t k = 0; k < keep.size(); ++k)
        holed.positions()[k] = block.positions()[keep[k]];
      auto& volume = holed.addScalarField(field::volume);
      std::fill(volume.begin(), volume.end(), Real(dimension == 3 ? dx * dx * dx : dx * dx));
      VoxelOccupancy occupancy(Vector::Zero(), Vector::Constant(n * dx), dx / 2, 3 * dx, dimension);
      occupancy.add(holed, 0);
      const auto voids = enclosedVoids(occupancy, 0.5);
      if (open) {
        EXPECT_TRUE(voids.empty()) << dimension << "D: an open void counted as a cavity";
        continue;
      }
      ASSERT_EQ(voids.size(), 1u) << dimension << "D";
      std::printf("%dD planted void %.4g, measured %.4g (%+.2f %%), centroid off by %.3g dx\n",
                  dimension, planted, voids[0].volume, 100 * (voids[0].volume / planted - 1),
                  double((voids[0].centroid - centre).norm() / dx));
      EXPECT_NEAR(voids[0].volume / planted, 1, 0.05) << dimension << "D";
      EXPECT_LT((voids[0].centroid - centre).norm(), 0.25 * dx) << dimension << "D";
    }
  }
}

// A slice's picture (PlaneInterpolation): a metal block with T = 900 + 10^4 x (10 K a spacing)
// and a mold block without T beside it in y, on a plane through them. Inside the metal, further
// than h from its faces, T is read within 0.2 K (Shepard's error for a linear field is its
// first moment, a small fraction of a spacing on a full lattice; a wrong weight or volume would
// be off by kelvins). The metal's free surface, where its kernel sum falls through 1/2, lies
// within a quarter spacing of the lattice's outer cell faces, x = n dx; the mold shows as no
// field and meets the metal at their common face, y = n dx, within a quarter spacing. The mold
// moved half a spacing away shows no air between (the seam a lattice's staircase leaves against
// a sloping wall), moved two spacings away a gap of two spacings within a quarter spacing.
TEST(PlaneInterpolation, ABlocksFieldAndSurfaceOnAPlaneThroughIt) {
  for (const int dimension : {2, 3}) {
    const int n = 16;
    const Real dx = 0.001, h = 3 * dx, pixel = dx / 8;
    ParticleCloud metal = latticeBlock(n, dx, dimension);
    auto& T = metal.addScalarField(field::T);
    for (std::size_t i = 0; i < metal.size(); ++i) T[i] = 900 + 1e4 * metal.positions()[i].x();
    const ParticleCloud block = latticeBlock(n, dx, dimension);
    ParticleCloud mold("mold");
    mold.resize(block.size());
    auto& volume = mold.addScalarField(field::volume);
    for (std::size_t i = 0; i < block.size(); ++i) {
      mold.positions()[i] = block.positions()[i] + Vector(0, n * dx, 0);
      volume[i] = dimension == 3 ? dx * dx * dx : dx * dx;
    }
    PlaneGrid grid;
    grid.right = Vector::UnitX();
    grid.up = Vector::UnitY();
    grid.normal = Vector::UnitZ();
    grid.pixel = pixel;
    grid.origin = Vector(-2 * dx + pixel / 2, -2 * dx + pixel / 2,
                         dimension == 3 ? Real(n / 2) * dx : Real(0));
    grid.width = int(std::lround((n + 4) * dx / pixel));
    grid.height = int(std::lround((2 * n + 4) * dx / pixel));
    PlaneInterpolation plane(grid, dimension);
    plane.add(metal, 0, "T", h);
    plane.add(mold, 1, "T", h);
    double worst = 0;
    for (int y = 0; y < grid.height; ++y) {
      for (int x = 0; x < grid.width; ++x) {
        const Vector at = grid.centre(x, y);
        if (at.x() > h && at.x() < n * dx - h && at.y() > h && at.y() < n * dx - h) {
          ASSERT_EQ(plane.owner(x, y), 0) << dimension << "D at " << at.transpose();
          worst = std::max(worst, std::abs(plane.value(x, y) - (900 + 1e4 * double(at.x()))));
        }
      }
    }
    EXPECT_LT(worst, 0.2) << dimension << "D: T inside the metal";
    // along the row through the metal's middle: its surface at x = n dx
    const int row = int((n * dx / 2 - grid.origin.y()) / pixel);
    int last = -1;
    for (int x = 0; x < grid.width; ++x) {
      if (plane.owner(x, row) == 0) last = x;
    }
    ASSERT_GE(last, 0);
    EXPECT_NEAR(double(grid.centre(last, row).x()), n * dx, 0.25 * dx) << dimension << "D";
    EXPECT_EQ(plane.owner(grid.width - 1, row), -1) << dimension << "D: air beyond the metal";
    // up the column through the middle: metal, then mold (no T) from y = n dx to 2 n dx
    const int column = int((n * dx / 2 - grid.origin.x()) / pixel);
    int firstMold = -1, lastMold = -1;
    for (int y = 0; y < grid.height; ++y) {
      if (plane.owner(column, y) != 1) continue;
      if (firstMold < 0) firstMold = y;
      lastMold = y;
      EXPECT_TRUE(std::isnan(plane.value(column, y))) << dimension << "D: a mold without T";
    }
    ASSERT_GE(firstMold, 0);
    EXPECT_EQ(plane.owner(column, firstMold - 1), 0) << dimension << "D: the mold on the metal";
    EXPECT_NEAR(double(grid.centre(column, firstMold).y()), n * dx, 0.25 * dx) << dimension << "D";
    EXPECT_NEAR(double(grid.centre(column, lastMold).y()), 2 * n * dx, 0.25 * dx)
        << dimension << "D";
    std::printf("%dD: T inside within %.3g K, surface at %+.3f dx, interface at %+.3f dx\n",
                dimension, worst, double((grid.centre(last, row).x() - n * dx) / dx),
                double((grid.centre(column, firstMold).y() - n * dx) / dx));
    // the mold moved away by half a spacing (a lattice's staircase against a sloping wall): no
    // air shows between them; by two spacings (a real gap): air over one to two spacings
    for (const Real gap : {Real(0.5) * dx, 2 * dx}) {
      ParticleCloud apart = mold;
      for (Vector& x : apart.positions()) x.y() += gap;
      PlaneInterpolation seam(grid, dimension);
      seam.add(metal, 0, "T", h);
      seam.add(apart, 1, "T", h);
      int air = 0;
      for (int y = 0; y < grid.height; ++y) {
        const double at = double(grid.centre(column, y).y());
        if (at > n * dx / 2 && at < n * dx * 1.5 && seam.owner(column, y) < 0) ++air;
      }
      std::printf("%dD: a gap of %.1f dx shows %.2f dx of air\n", dimension, double(gap / dx),
                  double(air * pixel / dx));
      if (gap < dx) {
        EXPECT_EQ(air, 0) << dimension << "D: a seam of half a spacing shows";
      } else {
        EXPECT_NEAR(double(air * pixel), double(gap), 0.25 * dx) << dimension << "D: the gap";
      }
    }
  }
}

struct MapsCase {
  testing::TemporaryCase folder;
  AnalysisContext context;
  MapsCase(const std::string& materialExtra) {
    context.caseRoot = folder.root();
    context.clouds = {"metal"};
    context.supportRadius = 0.03;
    context.dimension = 3;
    context.materials.emplace("metal", ac4ch(materialExtra));
    context.times = {{1, "1"}, {2, "2"}};
  }
  std::vector<std::unique_ptr<CastAnalysis>> read(const std::string& text) {
    return readCastAnalyses(Dictionary::parse(text, "system/castPostProcessDict"), context);
  }
};

// Two writes of a 6^3 block: T = 900 + 1000 x at t = 1, 850 + 3000 x at t = 2 (G = 1000 then
// 3000 K/m); the solver's history at t = 2 says T_c was crossed at 1.25 s with -dT/dt = 4 K/s,
// the liquidus at 0.5 s and the solidus at 2 s, and the particles come in reverse order.
// By hand: G(T_c) = 0.75 * 1000 + 0.25 * 3000 = 1500 K/m, Niyama = 1.5 K/mm / sqrt(4 K/s) = 0.75,
// t_f = 1.5 s, lambda_2 = 1e-5 * 1.5^(1/3) m, and with mu_l = 1.57e-3 Pa s, beta = 2565.5 /
// 2426.6 - 1, dT_f = 58.2 K (Table 1) Ny* = lambda_2 G sqrt(1.01e5 / (mu_l beta dT_f 4)).
TEST(SolidificationMaps, NiyamaAndArmSpacingFromTheRunsHistoryAndTheWrittenGradients) {
  MapsCase maps("dendriteArmSpacing (1e-5 0.3333333333333333);");
  auto analyses = maps.read("maps { type solidificationMaps; cloud metal; }");
  ASSERT_EQ(analyses.size(), 1u);
  ParticleCloud first = latticeBlock(6, 0.01, 3);
  for (const char* field : {"liquidusTime", "criticalTime", "coolingRate", "solidusTime"}) {
    auto& values = first.addScalarField(field);
    std::fill(values.begin(), values.end(), Real(-1));
  }
  first.addScalarField(field::solidFraction);
  ParticleCloud second = first;
  for (std::size_t i = 0; i < first.size(); ++i) {
    first.scalarField(field::T)[i] = 900 + 1000 * first.positions()[i].x();
    second.scalarField(field::T)[i] = 850 + 3000 * second.positions()[i].x();
    second.scalarField(field::liquidusTime)[i] = Real(0.5);
    second.scalarField(field::criticalTime)[i] = Real(1.25);
    second.scalarField(field::coolingRate)[i] = 4;
    second.scalarField(field::solidusTime)[i] = 2;
  }
  second.scalarField(field::criticalTime)[0] = -1;  // one particle not yet at T_c
  std::vector<std::size_t> reverse(second.size());
  std::iota(reverse.rbegin(), reverse.rend(), std::size_t(0));
  second.reorder(reverse);
  WrittenTime time1, time2;
  time1.folder = {1, "1"};
  time1.clouds = {first};
  time2.folder = {2, "2"};
  time2.clouds = {second};
  analyses[0]->add(time1);
  analyses[0]->add(time2);
  const ReportSection section = analyses[0]->finish();
  EXPECT_NE(section.markdown.find("Niyama minimum: 0.75"), std::string::npos) << section.markdown;
  // the freezing range over G dx: 58.2 K / (1500 K/m * 0.01 m) = 3.88 spacings, none below one
  EXPECT_NE(section.markdown.find("- 0 of 215 particles passed T_c where the freezing range"),
            std::string::npos)
      << section.markdown;

  const ParticleCloud result =
      readCloudVtp(maps.folder.root() / "postProcessing/maps/2/metal.vtp", "metal");
  const double lambda2 = 1e-5 * std::cbrt(1.5);
  const double ny =
      lambda2 * 1500 * std::sqrt(1.01e5 / (1.57e-3 * (2565.5 / 2426.6 - 1) * 58.2 * 4));
  std::size_t checked = 0;
  for (std::size_t i = 0; i < result.size(); ++i) {
    if (result.idField("id")[i] == 0) {
      EXPECT_EQ(result.scalarField(field::niyama)[i], -1);
      EXPECT_EQ(result.scalarField(field::temperatureGradient)[i], -1);
      continue;
    }
    EXPECT_NEAR(result.scalarField(field::temperatureGradient)[i], 1500, 1e-6);
    EXPECT_NEAR(result.scalarField(field::niyama)[i], 0.75, 1e-9);
    EXPECT_NEAR(result.scalarField(field::mushyZoneSpacings)[i], 58.2 / (1500 * 0.01), 1e-9);
    EXPECT_NEAR(result.scalarField(field::localFreezingTime)[i], 1.5, 1e-12);
    EXPECT_NEAR(result.scalarField(field::solidificationTime)[i], 2, 1e-12);
    EXPECT_NEAR(result.scalarField(field::secondaryArmSpacing)[i], lambda2, 1e-12);
    EXPECT_NEAR(result.scalarField(field::dimensionlessNiyama)[i], ny, 1e-9 * ny);
    // the first time's T, by id (the order was reversed since)
    EXPECT_NEAR(result.scalarField(field::temperatureAtFillEnd)[i],
                900 + 1000 * result.positions()[i].x(), 1e-9);
    ++checked;
  }
  EXPECT_EQ(checked, result.size() - 1);
  EXPECT_TRUE(std::filesystem::exists(maps.folder.root() / "postProcessing/maps/maps.pvd"));
}

// The heat books sum every heat cloud: the metal's loss is the held mold's intake.
TEST(TimeSeries, HeatBooksBalanceAcrossTheClouds) {
  ParticleCloud metal = latticeBlock(2, 0.01, 3), mold = latticeBlock(2, 0.01, 3);
  mold = ParticleCloud("mold");
  mold.resize(1);
  mold.addScalarField(field::mass)[0] = 1;
  mold.addScalarField(field::u)[0] = 5e5;
  mold.attributes()["internalEnergyAtStart"] = 5e5;
  mold.attributes()["heatLost.fixedTemperature"] = 300;  // taken from the metal, held at 300 K
  auto& u = metal.addScalarField(field::u);
  std::fill(u.begin(), u.end(), Real(1e6));
  const double metalEnergy = 8 * 2400 * 1e-6 * 1e6;
  metal.attributes()["internalEnergyAtStart"] = metalEnergy + 300;
  WrittenTime time;
  time.folder = {3, "3"};
  time.clouds = {metal, mold};
  const std::string row = TimeSeries::energyBalanceRow(time);
  double at, change, lost, imbalance;
  ASSERT_EQ(std::sscanf(row.c_str(), "%lf,%lf,%lf,%lf", &at, &change, &lost, &imbalance), 4);
  EXPECT_NEAR(change, -300, 1e-6);
  EXPECT_NEAR(lost, 300, 1e-12);
  EXPECT_NEAR(imbalance, 0, 1e-6);
  // T by mass, f_s by mass, counts
  auto& T = metal.scalarField(field::T);
  auto& fs = metal.addScalarField(field::solidFraction);
  for (std::size_t i = 0; i < 8; ++i) {
    T[i] = Real(800 + 10 * i);
    fs[i] = i < 2 ? 1 : 0;
  }
  const std::string cloudRow = TimeSeries::csvRow(3, metal);
  EXPECT_EQ(cloudRow.rfind("3,8,800,835,870,0.25,6,", 0), 0u) << cloudRow;
}

// The report's history table: a quantity a cloud does not have (a held mold's solid fraction,
// its frozen count and its kinetic energy) is a dash, not nan; the metal's are numbers.
TEST(TimeSeries, TheReportShowsWhatACloudLacksAsADash) {
  MapsCase maps("");
  maps.context.clouds = {"metal", "mold"};
  auto analyses = maps.read("history { type timeSeries; }");
  ParticleCloud metal = latticeBlock(2, 0.01, 3);
  metal.addScalarField(field::T);
  metal.addScalarField(field::solidFraction);
  metal.addScalarField(field::u);
  metal.addVectorField(field::U);
  ParticleCloud mold = latticeBlock(2, 0.01, 3);
  mold = ParticleCloud("mold");
  mold.resize(2);
  for (Real& m : mold.addScalarField(field::mass)) m = 1;
  for (Real& T : mold.addScalarField(field::T)) T = 300;
  for (int t = 1; t <= 2; ++t) {
    WrittenTime time;
    time.folder = {double(t), std::to_string(t)};
    time.clouds = {metal, mold};
    analyses[0]->add(time);
  }
  const std::string markdown = analyses[0]->finish().markdown;
  EXPECT_EQ(markdown.find("nan"), std::string::npos) << markdown;
  EXPECT_NE(markdown.find("| mold | 2 | 300 / 300 / 300 | – | – / 0 | – |"), std::string::npos)
      << markdown;
  EXPECT_NE(markdown.find("| metal | 2 | 0 / 0 / 0 | 0 | "), std::string::npos) << markdown;
}

// A liquid pool that splits: at t = 1 one region, at t = 2 a pocket of 2 x 2 x 2 particles cut
// off from it (a solid wall of particles between), at t = 3 the pocket frozen. One hot spot,
// closed between 1 and 2 s, of 8 dx^3 at the pocket's centre, last seen at 2 s.
TEST(HotSpots, APocketCutOffFromTheFeedingPathIsFollowedUntilItFreezes) {
  MapsCase maps("");
  auto analyses = maps.read("spots { type hotSpots; cloud metal; }");
  const Real dx = 0.01;
  ParticleCloud block = latticeBlock(8, dx, 3);
  block.attributes()["spacing"] = dx;
  auto& fs = block.addScalarField(field::solidFraction);
  const auto at = [&](int t) {
    for (std::size_t i = 0; i < block.size(); ++i) {
      const Vector x = block.positions()[i] / dx;                        // (k + 0.5)
      const bool pocket = x.x() > 6 && x.y() > 6 && x.z() > 6;           // the corner 2 x 2 x 2
      const bool wall = !pocket && x.x() > 5 && x.y() > 5 && x.z() > 5;  // one layer round it
      fs[i] = t == 1 ? 0 : (wall || (pocket && t == 3)) ? 1 : 0;
    }
    WrittenTime time;
    time.folder = {double(t), std::to_string(t)};
    time.clouds = {block};
    return time;
  };
  for (int t = 1; t <= 3; ++t) analyses[0]->add(at(t));
  const ReportSection section = analyses[0]->finish();
  EXPECT_NE(section.markdown.find("1 isolated liquid region "), std::string::npos)
      << section.markdown;
  std::ifstream list(maps.folder.root() / "postProcessing/spots/hotSpotList.csv");
  std::string header, row;
  std::getline(list, header);
  std::getline(list, row);
  // closed after 1, by 2; 8 particles of 2400 dx^3 / 2400; centroid (7 7 7) dx; last seen 2
  EXPECT_EQ(row, "1,1,2,8,8e-06,0.07,0.07,0.07,2") << row;
}

void expectError(MapsCase& maps, const std::string& text, const std::string& where,
                 const std::string& message) {
  try {
    maps.read(text);
    ADD_FAILURE() << "no error for " << text;
  } catch (const DictionaryError& error) {
    EXPECT_NE(std::string(error.what()).find(where), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find(message), std::string::npos) << error.what();
  }
}

TEST(CastAnalysis, BadEntriesNameFileLineAndKey) {
  MapsCase maps("");
  expectError(maps, "a { type solidificationMap; cloud metal; }",
              "system/castPostProcessDict:1:", "did you mean 'solidificationMaps'?");
  expectError(maps, "a { type timeSeries;\n cluods (metal); }",
              "system/castPostProcessDict:2:", "did you mean 'clouds'?");
  expectError(maps, "a { type thermocouples; cloud steel; locations { c (0 0 0); } }",
              "system/castPostProcessDict:1:", "no cloud 'steel'");
  expectError(maps, "a 1;", "system/castPostProcessDict:1:", "is not an analysis");
  expectError(maps, "a { type thermocouples; cloud metal; }",
              "system/castPostProcessDict:1:", "either 'locations'");
  // a view: its clip, its size, and a 2D case, whose picture is a slice
  expectError(maps, "a { type view; cloud metal; field T;\n clip ((0 0 0) (0 0 0)); }",
              "system/castPostProcessDict:2:", "non-zero normal");
  expectError(maps, "a { type view; cloud metal; field T; size (10 10); }",
              "system/castPostProcessDict:1:", "64 to 8192");
  expectError(maps, "a { type view; cloud metal; field T; show (1); }",
              "system/castPostProcessDict:1:", "'show' needs 'times all'");
  maps.context.dimension = 2;
  expectError(maps, "a { type view; cloud metal; field T; }",
              "system/castPostProcessDict:1:", "a 2D case's picture is a slice");
  maps.context.dimension = 3;
  // a thermocouple outside the casting, at its line
  auto analyses = maps.read(
      "a { type thermocouples; cloud metal;\n locations { in (0.03 0.03 0.03);\n out (1 0 0); "
      "} }");
  ParticleCloud block = latticeBlock(6, 0.01, 3);
  WrittenTime time;
  time.folder = {1, "1"};
  time.clouds = {block};
  try {
    analyses[0]->add(time);
    ADD_FAILURE() << "no error for a thermocouple outside the casting";
  } catch (const DictionaryError& error) {
    EXPECT_NE(std::string(error.what()).find("castPostProcessDict:3:2: thermocouple 'out'"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace sphcast
