// yieldStressStudy: a yield-stress fluid's slump (doc/validation.md §1.3.2). A column of a
// Bingham plastic, H high and as wide (2D, plane strain) or a cylinder as high as its diameter
// (3D), let go on a floor under gravity, comes to rest where the stress nowhere exceeds the yield
// stress. Pashias, Boger, Summers & Glenister (1996, J. Rheol. 40:1179): with tau' = tau0 /
// (rho g H), the material above 2 tau0 / (rho g) stays rigid and each layer below spreads until
// its weight per area is 2 tau0, so that the final height is H 2 tau' (1 - ln(2 tau')); with the
// tensorial law's von Mises criterion a cylinder's uniaxial stress yields at sqrt(3) tau0, and
// plane strain at 2 tau0 (pashiasHeight below). Their argument leaves out the horizontal balance,
// so it is a model, not the law's exact final state: on a slip floor a plane layer at rest can be
// at most 2 tau0 / (rho g) thick (a vertical section's sigma_xx must integrate to zero), 0.52 of
// Pashias' height at tau' = 0.2.
// The study prints the height on the axis against time and against Pashias', the largest speed,
// the viscosity's range and (elastoViscoplastic) how many particles are on the yield surface, and
// exits 1 when the final height is outside 5 % of Pashias'.
//
// Built with `cmake -DSPHCAST_BUILD_STUDIES=ON` (build/tests/studies/yieldStressStudy); run as
//   yieldStressStudy slump --law elastoViscoplastic --plasticViscosity 30 --etaS 50 --seconds 4
// (add --dimension 3 for the cylinder, --floor slip for a frictionless floor, --rows 20) and
// yieldStressStudy --help for the options and their defaults. Measured: doc/validation.md §1.3.2.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "StudyCommandLine.h"
#include "materials/Material.h"
#include "particles/FieldNames.h"
#include "particles/Neighbourhood.h"
#include "rheology/ElastoViscoplastic.h"
#include "rheology/HerschelBulkley.h"
#include "sph/FlowTestCases.h"
#include "sph/WeaklyCompressibleFlow.h"

namespace sphcast::studies {
namespace {

struct SlumpSettings {
  double height = 0.02;  // m
  int rows = 10;
  double tauRatio = 0.2;  // tau0 / (rho g H)
  double plasticViscosity = 1;
  double mu0 = 1e5;
  double soundSpeed = 10;
  double seconds = 1;
  bool shearRateFromSolved = false;
  bool elastic = false;         // elastoViscoplastic instead of the regularised herschelBulkley
  double shearModulus = 0;      // G over tau0 (elastoViscoplastic)
  double solventViscosity = 0;  // etaS, Pa s (elastoViscoplastic)
  bool slipFloor = false;       // no-slip: the slump test's plate holds the base
  bool printStress = false;     // the stress and pressure up the axis at the end
  int dimension = 2;  // 2: a square column (plane strain); 3: a cylinder, its height its diameter
};

// The final height over H. Pashias et al. take a layer to yield where its vertical stress
// reaches 2 tau0 (the largest shear stress of a uniaxial stress, Tresca); a tensorial law yields
// where |tau| = sqrt(tau:tau / 2) reaches tau0 (von Mises), which in plane strain (tau_zz = 0) is
// the same, but in a cylinder (uniaxial, tau = sigma diag(2, -1, -1) / 3) at sqrt(3) tau0: their
// argument with sqrt(3) in place of 2.
double pashiasHeight(double tauRatio, int dimension) {
  const double yieldRatio = (dimension == 2 ? 2 : std::sqrt(3.0)) * tauRatio;
  return yieldRatio * (1 - std::log(yieldRatio));
}

// The column's height over its axis (within a spacing of it), from the floor to its top
// particle's top, m.
double middleHeight(const ParticleCloud& fluid, const Vector& axis, double dx) {
  double top = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const Vector& x = fluid.positions()[i];
    const double off = std::hypot(double(x.x() - axis.x()), double(x.z() - axis.z()));
    if (off <= dx) top = std::max(top, double(x.y()) + dx / 2);
  }
  return top;
}

// A cylinder of fluid, its diameter and height the column's, on a lattice of dx (the cells whose
// centres lie within the radius), standing on the origin.
ParticleCloud cylinder(int rows, Real dx, Real density, Real viscosity) {
  ParticleCloud fluid = testing::fluidBlock2D(0, 0, dx, Vector::Zero(), density, viscosity);
  const Real radius = Real(0.5) * Real(rows) * dx;
  for (int layer = 0; layer < rows; ++layer) {
    for (int i = -rows; i < rows; ++i) {
      for (int k = -rows; k < rows; ++k) {
        const Vector x((i + Real(0.5)) * dx, (layer + Real(0.5)) * dx, (k + Real(0.5)) * dx);
        if (std::hypot(x.x(), x.z()) > radius) continue;
        const std::size_t n = fluid.size();
        fluid.resize(n + 1);
        fluid.positions()[n] = x;
        fluid.vectorField(field::U)[n] = Vector::Zero();
        fluid.scalarField(field::rho)[n] = fluid.scalarField(field::restDensity)[n] = density;
        fluid.scalarField(field::mass)[n] = density * dx * dx * dx;
        fluid.scalarField(field::viscosity)[n] = viscosity;
      }
    }
  }
  return fluid;
}

// Three layers of floor under the square |x|, |z| < halfWidth.
ParticleCloud floor3D(Real halfWidth, Real dx) {
  ParticleCloud floor = testing::emptyWall("floor");
  const int cells = static_cast<int>(std::ceil(halfWidth / dx));
  for (int layer = 1; layer <= 3; ++layer) {
    for (int i = -cells; i < cells; ++i) {
      for (int k = -cells; k < cells; ++k) {
        const std::size_t n = floor.size();
        floor.resize(n + 1);
        floor.positions()[n] =
            Vector((i + Real(0.5)) * dx, (Real(0.5) - layer) * dx, (k + Real(0.5)) * dx);
        floor.scalarField(field::volume)[n] = dx * dx * dx;
        floor.vectorField(field::normal)[n] = Vector(0, 1, 0);
        floor.scalarField(field::wallDistance)[n] = (layer - Real(0.5)) * dx;
      }
    }
  }
  return floor;
}

int runSlump(const SlumpSettings& s) {
  const double rho = 1000, g = 9.81;
  const Real dx = Real(s.height / s.rows);
  const int tankColumns = 12 * s.rows;
  const int first = (tankColumns - s.rows) / 2;
  const bool cylindrical = s.dimension == 3;
  ParticleCloud fluid = cylindrical
                            ? cylinder(s.rows, dx, Real(rho), Real(s.plasticViscosity))
                            : testing::fluidBlock2D(s.rows, s.rows, dx, Vector(first * dx, 0, 0),
                                                    Real(rho), Real(s.plasticViscosity));
  ParticleCloud tank = cylindrical ? floor3D(Real(2.5) * s.rows * dx, dx)
                                   : testing::tankWalls2D(tankColumns, s.rows + 4, dx);
  FlowSettings settings;
  settings.dimension = s.dimension;
  settings.supportRadius = 3 * dx;
  settings.soundSpeed = Real(s.soundSpeed);
  settings.gravity = Vector(0, Real(-g), 0);
  settings.walls.all.velocity =
      s.slipFloor ? WallCondition::Velocity::slip : WallCondition::Velocity::noSlip;
  Neighbourhood neighbourhood(settings.supportRadius, settings.periodic);
  WeaklyCompressibleFlow flow(settings, fluid, std::vector<const ParticleCloud*>{&tank},
                              neighbourhood);
  neighbourhood.update();
  flow.start();
  HerschelBulkleySettings law;
  law.yieldStress = Real(s.tauRatio * rho * g * s.height);
  law.consistency = Real(s.plasticViscosity);
  law.exponent = 1;
  law.restViscosity = Real(s.mu0);
  const Material noTables;
  const RheologyContext context{
      fluid, noTables, neighbourhood, shearWalls(flow), s.dimension, settings.supportRadius};
  std::unique_ptr<RheologyModel> model;
  if (s.elastic) {
    ElastoViscoplasticSettings evp;
    evp.yieldStress = law.yieldStress;
    evp.consistency = law.consistency;
    evp.exponent = 1;
    evp.shearModulus = Real(s.shearModulus) * law.yieldStress;
    evp.solventViscosity = Real(s.solventViscosity);
    model = std::make_unique<ElastoViscoplastic>(context, evp);
    flow.addForceModel(*model->force());
  } else {
    model = std::make_unique<HerschelBulkley>(context, law);
  }
  RheologyModel& rheology = *model;
  std::printf("%s\n", rheology.description().c_str());
  const Vector axis = cylindrical ? Vector::Zero() : Vector((first + s.rows / 2.0) * dx, 0, 0);
  const double expected = pashiasHeight(s.tauRatio, s.dimension) * s.height;
  std::printf(
      "slump, %d rows (dx = %.2f mm, %zu particles), tau' = %.3f (tau0 = %.1f Pa), "
      "shear rate from the %s velocity: Pashias' height %.2f mm (%.3f H)\n",
      s.rows, dx * 1e3, fluid.size(), s.tauRatio, double(law.yieldStress),
      s.shearRateFromSolved ? "solved" : "step's starting", expected * 1e3, expected / s.height);
  const auto start = std::chrono::steady_clock::now();
  if (s.shearRateFromSolved) rheology.update(0);
  double time = 0, nextPrint = 0;
  const auto& U = fluid.vectorField(field::U);
  while (time < s.seconds - 1e-12) {
    std::string limiter;
    const double dt = std::min(flow.stepLimits(0.25).smallest(limiter), s.seconds - time);
    flow.kickAndDrift(dt);
    neighbourhood.update();
    flow.keepClearOfWalls();
    if (!s.shearRateFromSolved) rheology.update(dt);
    flow.computeRatesAndKick(dt);
    if (s.shearRateFromSolved) rheology.update(dt);
    time += dt;
    if (time >= nextPrint - 1e-12) {
      double speed = 0;
      for (const Vector& u : U) speed = std::max(speed, double(u.norm()));
      double muMin = 1e300, muMax = 0;
      for (const Real mu : fluid.scalarField(field::viscosity)) {
        muMin = std::min(muMin, double(mu));
        muMax = std::max(muMax, double(mu));
      }
      // elastoViscoplastic: the share of particles on the yield surface (|tau| >= tau0)
      int yielded = 0;
      if (s.elastic) {
        const auto& diagonal = fluid.vectorField("stressDiagonal");
        const auto& shear = fluid.vectorField("stressShear");
        for (std::size_t i = 0; i < fluid.size(); ++i) {
          const double magnitude =
              std::sqrt(0.5 * diagonal[i].squaredNorm() + shear[i].squaredNorm());
          if (magnitude >= 0.999 * law.yieldStress) ++yielded;
        }
      }
      std::printf(
          "  t = %.3f s: height %.2f mm (%.3f of Pashias'), largest speed %.4f m/s, "
          "mu %.3g to %.3g Pa s, %d yielded (dt %.2e, %s)\n",
          time, middleHeight(fluid, axis, dx) * 1e3, middleHeight(fluid, axis, dx) / expected,
          speed, muMin, muMax, yielded, dt, limiter.c_str());
      std::fflush(stdout);
      nextPrint += s.seconds / 20;
    }
  }
  if (s.elastic && s.printStress) {
    const auto& diagonal = fluid.vectorField("stressDiagonal");
    const auto& shear = fluid.vectorField("stressShear");
    const auto& p = fluid.scalarField(field::p);
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      const Vector& x = fluid.positions()[i];
      if (std::abs(x.x() - axis.x()) > dx || std::abs(x.z()) > dx) continue;
      std::printf("  y %.2f mm x-mid %.2f: tau xx %.2f yy %.2f zz %.2f xy %.2f |tau| %.2f p %.2f\n",
                  x.y() * 1e3, (x.x() - axis.x()) * 1e3, diagonal[i].x(), diagonal[i].y(),
                  diagonal[i].z(), shear[i].x(),
                  std::sqrt(0.5 * diagonal[i].squaredNorm() + shear[i].squaredNorm()), p[i]);
    }
  }
  const double ratio = middleHeight(fluid, axis, dx) / expected;
  std::printf("final height over Pashias' %.4f, %.1f s\n", ratio,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return std::abs(ratio - 1) <= 0.05 ? 0 : 1;
}

Study slumpStudy() {
  return {"slump", "a Bingham column's slump against Pashias et al.'s height",
          [](po::options_description_easy_init add) {
            add("rows", po::value<std::string>()->default_value("10"),
                "particles across the column (and up it), one run each");
            add("tauRatio", po::value<double>()->default_value(0.2), "tau0 / (rho g H)");
            add("height", po::value<double>()->default_value(20), "H, mm");
            add("plasticViscosity", po::value<double>()->default_value(1), "k, Pa s");
            add("mu0", po::value<double>()->default_value(1e5), "the cap, Pa s");
            add("soundSpeed", po::value<double>()->default_value(10), "c, m/s");
            add("seconds", po::value<double>()->default_value(1), "simulated time, s");
            add("dimension", po::value<int>()->default_value(2),
                "2: a square column (plane strain), 3: a cylinder as high as it is wide");
            add("floor", po::value<std::string>()->default_value("noSlip"),
                "noSlip (a plate that holds the base) or slip");
            add("printStress", po::value<bool>()->default_value(false),
                "print tau and p up the axis at the end (elastoViscoplastic)");
            add("law", po::value<std::string>()->default_value("herschelBulkley"),
                "herschelBulkley (the regularised viscosity) or elastoViscoplastic (an elastic "
                "solid below tau0)");
            add("shearModulus", po::value<double>()->default_value(100),
                "G over tau0 (elastoViscoplastic)");
            add("etaS", po::value<double>()->default_value(0),
                "the Newtonian part, Pa s (elastoViscoplastic)");
            add("shearRateFrom", po::value<std::string>()->default_value("start"),
                "start (the step's starting velocity, before the rates) or solved (the "
                "velocity the viscous solve left, for the next step)");
          },
          [](const po::variables_map& values) {
            SlumpSettings s;
            s.tauRatio = values["tauRatio"].as<double>();
            s.height = values["height"].as<double>() * 1e-3;
            s.plasticViscosity = values["plasticViscosity"].as<double>();
            s.mu0 = values["mu0"].as<double>();
            s.soundSpeed = values["soundSpeed"].as<double>();
            s.seconds = values["seconds"].as<double>();
            const std::string from = values["shearRateFrom"].as<std::string>();
            if (from != "start" && from != "solved") {
              throw std::invalid_argument("--shearRateFrom must be start or solved, not '" + from +
                                          "'");
            }
            s.shearRateFromSolved = from == "solved";
            const std::string law = values["law"].as<std::string>();
            if (law != "herschelBulkley" && law != "elastoViscoplastic") {
              throw std::invalid_argument(
                  "--law must be herschelBulkley or elastoViscoplastic, not '" + law + "'");
            }
            s.elastic = law == "elastoViscoplastic";
            s.shearModulus = values["shearModulus"].as<double>();
            s.solventViscosity = values["etaS"].as<double>();
            s.dimension = values["dimension"].as<int>();
            const std::string floor = values["floor"].as<std::string>();
            if (floor != "noSlip" && floor != "slip") {
              throw std::invalid_argument("--floor must be noSlip or slip, not '" + floor + "'");
            }
            s.slipFloor = floor == "slip";
            s.printStress = values["printStress"].as<bool>();
            if (s.dimension != 2 && s.dimension != 3) {
              throw std::invalid_argument("--dimension must be 2 or 3");
            }
            int status = 0;
            for (const double rows : numberList(values["rows"].as<std::string>(), "rows")) {
              s.rows = static_cast<int>(rows);
              status = std::max(status, runSlump(s));
            }
            return status;
          }};
}

}  // namespace
}  // namespace sphcast::studies

int main(int argc, char* argv[]) {
  using namespace sphcast::studies;
  return runStudy(argc, argv, "A yield-stress fluid's slump (doc/validation.md §1.3.2)",
                  {slumpStudy()});
}
