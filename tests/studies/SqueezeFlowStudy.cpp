// squeezeFlowStudy: the squeeze film of doc/validation.md §1.7 where the unit tests cannot
// afford it (the case of tests/unit/bodies/SqueezeFilmCase.h, which SqueezeFilmTest checks for
// the Newtonian pool at dx = 1 mm).
//   constantLoad     a plate pressed by a constant force per unit depth onto a pool (the
//                    plate's half-width fixed), a filled gap (a floor as wide as the plate,
//                    liquid only between them: the constant-area squeeze of a rheometer) or a
//                    slug (spreading under a wider plate), of a Newtonian liquid or a power law
//                    (rheology/HerschelBulkley.h), closes its gap from 6 mm to 5 and 4 mm in times
//                    lubrication gives; prints the SPH times over those at each refinement
//                    (dx = 1 mm / refinement) and exits 1 when one is outside 10 %.
//   prescribedSpeed  the plate driven at 0.01 m/s: the force, the profiles across the gap and
//                    the pressure along it against lubrication's.
//
// Built with `cmake -DSPHCAST_BUILD_STUDIES=ON` (build/tests/studies/squeezeFlowStudy); run as
//   squeezeFlowStudy constantLoad --liquid gapFilled --law powerLaw --refinements 1,1.5,2
// and squeezeFlowStudy --help for the options and their defaults. Measured (doc/validation.md
// §1.7), the power law (n = 1/2) over lubrication's time from 6 to 5 mm at refinement 1 / 1.5 /
// 2: filled gap 1.168 / 1.101 / 1.069 (2.1, 6.6 and 15.7 minutes on one thread), pool 1.59 /
// 1.54 / 1.50 (its liquid pushing the pool aside, which lubrication leaves out).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "StudyCommandLine.h"
#include "bodies/SqueezeFilmCase.h"
#include "particles/FieldNames.h"

namespace sphcast::studies {
namespace {

testing::Liquid liquidOf(const std::string& name) {
  for (const testing::Liquid liquid :
       {testing::Liquid::pool, testing::Liquid::gapFilled, testing::Liquid::slug}) {
    if (name == testing::nameOf(liquid)) return liquid;
  }
  throw std::invalid_argument("--liquid must be pool, gapFilled or slug, not '" + name + "'");
}

// The plate driven down at V = 0.01 m/s from 8 mm (a prescribed body) over the pool (or the
// filled gap) of a power law; at the gap `at`, the force over lubrication's and, on the columns x =
// a/4, a/2 and 3a/4 from the plate's middle, the profiles of u_x, the shear rate and the viscosity
// across the gap against lubrication's (SqueezeFilmCase.h; u = (G/k)^(1/n) n/(n+1) (H^((n+1)/n) -
// |y|^((n+1)/n)), gammaDot = (G |y| / k)^(1/n) about the gap's middle line, G from q = V x).
Study prescribedSpeedStudy() {
  return {"prescribedSpeed",
          "the plate driven at 0.01 m/s: force and profiles across the gap against lubrication",
          [](po::options_description_easy_init add) {
            add("consistency", po::value<double>()->default_value(7.2), "k, Pa s^n");
            add("exponent", po::value<double>()->default_value(0.5), "n");
            add("mu0", po::value<double>()->default_value(100), "the cap, Pa s");
            add("at", po::value<double>()->default_value(6), "the gap of the profiles, mm");
            add("refinement", po::value<double>()->default_value(1), "1 mm over the spacing");
            add("liquid", po::value<std::string>()->default_value("pool"), "pool or gapFilled");
          },
          [](const po::variables_map& values) {
            const double speed = 0.01, refinement = values["refinement"].as<double>();
            const double k = values["consistency"].as<double>();
            const double n = values["exponent"].as<double>();
            const double at = values["at"].as<double>() * 1e-3;
            const double travel = 8e-3 - at;
            RigidBodySettings settings = testing::plateSettings();
            settings.displacement = {{0.0, Vector::Zero()},
                                     {travel / speed, Vector(0, -static_cast<Real>(travel), 0)}};
            const testing::Liquid liquid = liquidOf(values["liquid"].as<std::string>());
            if (liquid == testing::Liquid::slug) {
              throw std::invalid_argument("--liquid slug: the slug's half-width is not fixed");
            }
            testing::SqueezeFilmCase squeeze(settings, refinement, liquid);
            HerschelBulkleySettings law = testing::halfPowerLaw(k);
            law.exponent = Real(n);
            law.restViscosity = Real(values["mu0"].as<double>());
            const Material noTables;
            squeeze.rheology = std::make_unique<HerschelBulkley>(
                RheologyContext{squeeze.fluid, noTables, *squeeze.neighbourhood,
                                shearWalls(*squeeze.flow), 2, squeeze.flowSettings.supportRadius},
                law);
            const double a = squeeze.halfWidth();
            double time = 0, force = 0, weight = 0;
            while (time < travel / speed - 1e-9) {
              const double dt = squeeze.step(time);
              time += dt;
              if (std::abs(squeeze.gap() - at) < 0.25e-3) {
                force +=
                    dt * (squeeze.flow->wallLoad(squeeze.plate).force.y() + squeeze.clearanceForce);
                weight += dt;
              }
            }
            const double h = squeeze.gap(), half = h / 2;
            const double shape = std::pow((2 * n + 1) / (2 * n), n);
            const double lubrication = 2 * k * shape * std::pow(speed, n) * std::pow(a, n + 2) /
                                       ((n + 2) * std::pow(half, 2 * n + 1));
            std::printf("gap %.3f mm: F = %.2f N/m, lubrication %.2f N/m, ratio %.4f\n", h * 1e3,
                        force / weight, lubrication, force / weight / lubrication);
            const auto& x = squeeze.fluid.positions();
            const auto& u = squeeze.fluid.vectorField(field::U);
            const auto& rate = squeeze.fluid.scalarField(field::shearRate);
            const auto& mu = squeeze.fluid.scalarField(field::viscosity);
            const double middle = 0.08, floor = 0;  // the tank's middle and its floor
            for (const double fraction : {0.25, 0.5, 0.75}) {
              const double column = middle + fraction * a;
              const double q = speed * fraction * a;
              const double G =
                  k * std::pow(q * (2 * n + 1) / (2 * n * std::pow(half, (2 * n + 1) / n)), n);
              std::printf(
                  "x = %.2f a: G = %.1f Pa/m\n  y/h    u_x    u_lub   rate  rate_lub  "
                  "mu  mu_lub\n",
                  fraction, G);
              double flux = 0;
              for (std::size_t i = 0; i < squeeze.fluid.ownedSize(); ++i) {
                if (std::abs(x[i].x() - column) > 0.5 * squeeze.dx) continue;
                if (x[i].y() > floor + h) continue;
                const double y = x[i].y() - floor - half;
                const double ulub =
                    std::pow(G / k, 1 / n) * n / (n + 1) *
                    (std::pow(half, (n + 1) / n) - std::pow(std::abs(y), (n + 1) / n));
                const double rlub = std::pow(G * std::abs(y) / k, 1 / n);
                const double mulub = std::min(law.restViscosity, Real(k * std::pow(rlub, n - 1)));
                flux += u[i].x() * squeeze.dx;
                std::printf("  %.3f  %.4f  %.4f  %6.1f  %6.1f  %.3f  %.3f\n", (y + half) / h,
                            u[i].x(), ulub, rate[i], rlub, mu[i], mulub);
              }
              std::printf("  flux %.3e m^2/s, lubrication's V x = %.3e\n", flux, q);
            }
            // the pressure along the gap, averaged over its height in bins of 5 mm from the
            // plate's middle, against lubrication's (zero at the edge, and beyond it)
            const auto& p = squeeze.fluid.scalarField(field::p);
            std::printf("  x/a    p      p_lub\n");
            for (int bin = 0; bin < 16; ++bin) {
              const double from = bin * 5e-3, to = from + 5e-3, centre = (from + to) / 2;
              double sum = 0;
              int count = 0;
              for (std::size_t i = 0; i < squeeze.fluid.ownedSize(); ++i) {
                const double distance = std::abs(x[i].x() - middle);
                if (distance < from || distance >= to || x[i].y() > floor + h) continue;
                sum += p[i];
                ++count;
              }
              const double lub = centre >= a ? 0
                                             : k * shape * std::pow(speed, n) *
                                                   (std::pow(a, n + 1) - std::pow(centre, n + 1)) /
                                                   ((n + 1) * std::pow(half, 2 * n + 1));
              std::printf("  %.3f  %7.1f  %7.1f\n", centre / a, count ? sum / count : 0.0, lub);
            }
            return 0;
          }};
}

Study constantLoadStudy() {
  return {
      "constantLoad", "a plate pressed by a constant load: gap closing times over lubrication's",
      [](po::options_description_easy_init add) {
        add("liquid", po::value<std::string>()->default_value("pool"),
            "pool (the plate's half-width fixed, 60 mm), gapFilled (the same plate over a floor "
            "as wide, liquid only in the gap) or slug (60 x 8 mm, spreading)");
        add("law", po::value<std::string>()->default_value("powerLaw"),
            "newtonian (1 Pa s) or powerLaw (herschelBulkley, tau0 = 0)");
        add("load", po::value<double>(),
            "N per metre of depth (default: V = 0.01 m/s at 6 mm by lubrication: 80 on the "
            "pool and the filled gap, 24 on the slug)");
        add("consistency", po::value<double>(),
            "k of the power law, Pa s^(1/2) (default: 7.2 on the pool and the filled gap, 6 on "
            "the slug: about 0.7 Pa s at the wall)");
        add("exponent", po::value<double>()->default_value(0.5),
            "n of the power law (with --consistency and --load to suit)");
        add("mu0", po::value<double>()->default_value(100),
            "the power law's viscosity at rest, its cap, Pa s");
        add("refinements", po::value<std::string>()->default_value("1,1.5,2"),
            "1 mm over the spacing, one run each");
      },
      [](const po::variables_map& values) {
        const std::string liquidName = values["liquid"].as<std::string>();
        const std::string lawName = values["law"].as<std::string>();
        const testing::Liquid liquid = liquidOf(liquidName);
        if (lawName != "newtonian" && lawName != "powerLaw") {
          throw std::invalid_argument("--law must be newtonian or powerLaw, not '" + lawName + "'");
        }
        const bool fixedHalfWidth = liquid != testing::Liquid::slug;
        const double load =
            values.count("load") ? values["load"].as<double>() : (fixedHalfWidth ? 80.0 : 24.0);
        std::optional<HerschelBulkleySettings> law;
        if (lawName == "powerLaw") {
          law =
              testing::halfPowerLaw(values.count("consistency") ? values["consistency"].as<double>()
                                                                : (fixedHalfWidth ? 7.2 : 6.0));
          law->restViscosity = Real(values["mu0"].as<double>());
          law->exponent = Real(values["exponent"].as<double>());
        }
        int status = 0;
        for (const double refinement :
             numberList(values["refinements"].as<std::string>(), "refinements")) {
          const testing::ClosingTimes times = testing::closingTimes(liquid, load, refinement, law);
          const bool within = std::abs(times.to5 - 1) <= 0.1 && std::abs(times.to4 - 1) <= 0.1;
          std::printf("refinement %g: %s\n", refinement,
                      within ? "within 10 %" : "OUTSIDE 10 % of lubrication's times");
          if (!within) status = 1;
        }
        return status;
      }};
}

}  // namespace
}  // namespace sphcast::studies

int main(int argc, char* argv[]) {
  using namespace sphcast::studies;
  return runStudy(argc, argv, "The squeeze film under a constant load (doc/validation.md §1.7)",
                  {constantLoadStudy(), prescribedSpeedStudy()});
}
