// yieldStressStudy: a yield-stress fluid's slump (doc/validation.md §1.3.2). A 2D column of a
// Bingham plastic (rheology/HerschelBulkley.h), H high and as wide, let go on a slip floor under
// gravity, comes to rest where the stress nowhere exceeds the yield stress. Pashias, Boger,
// Summers & Glenister (1996, J. Rheol. 40:1179): with tau' = tau0 / (rho g H), the material
// above 2 tau0 / (rho g) stays rigid and each layer below spreads until its weight per width is
// 2 tau0, so that the final height is H [1 - s'], s' = 1 - 2 tau' (1 - ln(2 tau')); the
// argument uses only the weight above a layer and the layer's volume, so it holds per unit depth
// as for the cylinder. The study prints the column's height at its middle against time and
// against Pashias', the largest speed, and exits 1 when the final height is outside 5 %.
//
// Built with `cmake -DSPHCAST_BUILD_STUDIES=ON` (build/tests/studies/yieldStressStudy); run as
//   yieldStressStudy slump --rows 10 --plasticViscosity 100 --seconds 2
// and yieldStressStudy --help for the options and their defaults. Not reproduced yet (measured,
// doc/validation.md §1.3.2): at k = 1 Pa s the collapse is inertial and overshoots; at k = 100
// Pa s (quasi-static) the column passes Pashias' height at 0.85 s and is at 0.81 of it at 2 s,
// still creeping at 4 mm/s, its largest viscosity 530 Pa s against mu0 = 1e5: no particle is
// unyielded, whichever velocity the shear rate is read from.

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
};

double pashiasHeight(double tauRatio) {
  const double s = 1 - 2 * tauRatio * (1 - std::log(2 * tauRatio));
  return 1 - s;
}

// The column's height over the middle spacing's width, from the floor to its top particle's
// top, m.
double middleHeight(const ParticleCloud& fluid, double middle, double dx) {
  double top = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const Vector& x = fluid.positions()[i];
    if (std::abs(x.x() - middle) <= dx) top = std::max(top, double(x.y()) + dx / 2);
  }
  return top;
}

int runSlump(const SlumpSettings& s) {
  const double rho = 1000, g = 9.81;
  const Real dx = Real(s.height / s.rows);
  const int tankColumns = 12 * s.rows;
  const int first = (tankColumns - s.rows) / 2;
  ParticleCloud fluid = testing::fluidBlock2D(s.rows, s.rows, dx, Vector(first * dx, 0, 0),
                                              Real(rho), Real(s.plasticViscosity));
  ParticleCloud tank = testing::tankWalls2D(tankColumns, s.rows + 4, dx);
  FlowSettings settings;
  settings.dimension = 2;
  settings.supportRadius = 3 * dx;
  settings.soundSpeed = Real(s.soundSpeed);
  settings.gravity = Vector(0, Real(-g), 0);
  settings.walls.all.velocity = WallCondition::Velocity::slip;
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
  HerschelBulkley rheology(
      RheologyContext{fluid, noTables, neighbourhood, shearWalls(flow), 2, settings.supportRadius},
      law);
  const double middle = (first + s.rows / 2.0) * dx;
  const double expected = pashiasHeight(s.tauRatio) * s.height;
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
      std::printf(
          "  t = %.3f s: height %.2f mm (%.3f of Pashias'), largest speed %.4f m/s, "
          "mu %.3g to %.3g Pa s (dt %.2e, %s)\n",
          time, middleHeight(fluid, middle, dx) * 1e3, middleHeight(fluid, middle, dx) / expected,
          speed, muMin, muMax, dt, limiter.c_str());
      std::fflush(stdout);
      nextPrint += s.seconds / 20;
    }
  }
  const double ratio = middleHeight(fluid, middle, dx) / expected;
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
