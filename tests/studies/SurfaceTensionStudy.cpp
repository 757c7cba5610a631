// surfaceTensionStudy: the surface-tension studies of doc/validation.md §2, which measure what the
// unit tests cannot afford (minutes to hours a run) or cannot check (angles the models do not
// reach). Each steps drops as the solver steps them (the cases of tests/unit/surface/
// CapillaryCases.h and SurfaceEnergyCases.h, which the unit tests check at their defaults) and
// prints what it read:
//   static-drop, oscillating-drop, mode-curvature, sessile, gap: the continuum surface force
//     (--model pairwiseForce: the pairwise force, surface/PairwiseForce.h, the sessile drops'
//     surface still read by the continuum surface force's detection): a static drop's pressure
//     against Laplace's and its currents (§2.2), an oscillating drop's period and decay against
//     Lamb's, the curvature it reads on that mode's shape (no dynamics; the continuum surface
//     force's), a sessile drop's contact angle on a flat wall, a cylinder (--cylinder) or a 3D
//     floor (--3d), and a non-wetting pool's entry into a gap;
//   energy-static-drop, energy-oscillating-drop, energy-contact-angle: the surface-energy model
//     (§2.3): a static drop's (or a periodic slab's, --slab) pressure and tension, the n = 2
//     period at each resolution, and the angle a drop settling on a wall reaches (it does not
//     follow Young's law).
// Built with `cmake -DSPHCAST_BUILD_STUDIES=ON` (build/tests/studies/surfaceTensionStudy); run as
//   surfaceTensionStudy <study> [options], e.g. surfaceTensionStudy sessile --angles 90,150 --slip
// and surfaceTensionStudy --help for every study's options and defaults. One OpenMP thread a run
// is how doc/validation.md timed them (OMP_NUM_THREADS=1).

#include <iostream>
#include <string>
#include <vector>

#include "StudyCommandLine.h"
#include "core/Real.h"
#include "surface/CapillaryCases.h"
#include "surface/SurfaceEnergyCases.h"
#include "surface/SurfaceEnergyTension.h"

namespace sphcast::studies {
namespace {

using testing::CapillaryOptions;
using testing::SurfaceForceModel;

void declareModel(po::options_description_easy_init add) {
  add("model", po::value<std::string>()->default_value("continuumSurfaceForce"),
      "the force: continuumSurfaceForce or pairwiseForce");
}

SurfaceForceModel forceModel(const po::variables_map& values) {
  const std::string name = values["model"].as<std::string>();
  if (name == "continuumSurfaceForce") return SurfaceForceModel::continuumSurfaceForce;
  if (name == "pairwiseForce") return SurfaceForceModel::pairwiseForce;
  throw po::error("--model: continuumSurfaceForce or pairwiseForce, not \"" + name + "\"");
}

template <class T>
T get(const po::variables_map& values, const char* name) {
  return values[name].as<T>();
}

// The continuum surface force's (or the pairwise force's) drops.

Study staticDropStudy() {
  return {
      "static-drop", "a drop at rest: pressure inside against Laplace's, the currents left",
      [](po::options_description_easy_init add) {
        add("dimension", po::value<int>()->default_value(2), "2 or 3");
        add("across", po::value<int>()->default_value(30), "particles across the diameter");
        add("capillary-times", po::value<double>()->default_value(5, "5"),
            "how long, in capillary times sqrt(rho R^3 / sigma)");
        add("nu", po::value<double>()->default_value(1e-5, "1e-5"), "kinematic viscosity, m^2/s");
        add("lattice", po::bool_switch(), "start from lattice particles instead of rings");
        add("sound-speed-scale", po::value<double>()->default_value(1, "1"),
            "a factor on the speed of sound");
        declareModel(add);
        add("trace", po::bool_switch(), "print the largest speed every half capillary time");
      },
      [](const po::variables_map& values) {
        CapillaryOptions options;
        options.model = forceModel(values);
        options.latticeStart = get<bool>(values, "lattice");
        options.soundSpeedScale = get<double>(values, "sound-speed-scale");
        options.trace = get<bool>(values, "trace");
        const int dimension = get<int>(values, "dimension"), across = get<int>(values, "across");
        const double times = get<double>(values, "capillary-times");
        const double nu = get<double>(values, "nu");
        const testing::StaticDropResult result =
            testing::staticDrop(dimension, across, times, nu, options);
        std::cout << dimension << "D static drop, " << across << " across (" << result.particles
                  << " particles), " << times << " capillary times, nu " << nu
                  << ": pressure / Laplace's " << result.pressureRatio
                  << ", largest speed / sqrt(sigma/(rho R)) " << result.largestSpeed << ", mean "
                  << result.meanSpeed << ", nearest pair " << result.closest << " dx, "
                  << result.seconds << " s" << std::endl;
        return 0;
      }};
}

Study oscillatingDropStudy() {
  return {
      "oscillating-drop", "the n = 2 oscillation of a free drop: period and decay vs Lamb's",
      [](po::options_description_easy_init add) {
        add("dimension", po::value<int>()->default_value(2), "2 or 3");
        add("across", po::value<int>()->default_value(30), "particles across the diameter");
        add("periods", po::value<double>()->default_value(3, "3"), "how long, in Lamb's periods");
        add("sound-speed-scale", po::value<double>()->default_value(1, "1"),
            "a factor on the speed of sound");
        add("amplitude", po::value<double>()->default_value(0.05, "0.05"),
            "a0: the surface moves a0 R in 2D, 2 a0 R in 3D");
        declareModel(add);
        add("trace", po::bool_switch(), "print the moment's extremes and zero crossings");
      },
      [](const po::variables_map& values) {
        CapillaryOptions options;
        options.model = forceModel(values);
        options.soundSpeedScale = get<double>(values, "sound-speed-scale");
        options.amplitude = get<double>(values, "amplitude");
        options.trace = get<bool>(values, "trace");
        const int dimension = get<int>(values, "dimension"), across = get<int>(values, "across");
        std::cout << dimension << "D drop, " << across << " across: "
                  << testing::oscillatingDrop(dimension, across, get<double>(values, "periods"),
                                              options)
                  << std::endl;
        return 0;
      }};
}

Study modeCurvatureStudy() {
  return {
      "mode-curvature",
      "the curvature read on a drop displaced into the n = 2 mode, against the exact",
      [](po::options_description_easy_init add) {
        add("dimension", po::value<int>()->default_value(3), "2 or 3");
        add("across", po::value<std::string>()->default_value("20,30,60"),
            "particles across the diameter, a drop each");
        add("epsilon", po::value<std::string>()->default_value("0.005,0.02,0.1"),
            "the mode's amplitude over R, a drop each");
      },
      [](const po::variables_map& values) {
        const int dimension = get<int>(values, "dimension");
        for (const double across : numberList(get<std::string>(values, "across"), "across")) {
          for (const double epsilon : numberList(get<std::string>(values, "epsilon"), "epsilon")) {
            std::cout << dimension << "D drop, " << across << " across, epsilon " << epsilon << ": "
                      << testing::modeCurvature(dimension, static_cast<int>(across), epsilon)
                      << std::endl;
          }
        }
        return 0;
      }};
}

Study sessileStudy() {
  return {"sessile", "drops settling on a wall: the contact angle each reaches",
          [](po::options_description_easy_init add) {
            add("angles", po::value<std::string>()->required(),
                "required: the contact angles set, degrees, a drop each (60,90,120,150)");
            add("layers", po::value<int>()->default_value(15),
                "the drop's starting radius (half disk, half ball), in spacings");
            add("capillary-times", po::value<double>()->default_value(10, "10"),
                "how long, in sqrt(rho A^(3/2) / sigma) (3D: sqrt(rho V / sigma))");
            add("bond", po::value<double>()->default_value(0.2, "0.2"),
                "rho g A / sigma (3D: rho g V^(2/3) / sigma): gravity onto the wall");
            add("cylinder", po::value<double>()->default_value(0, "0"),
                "2D: on a cylinder of this many times the cap's radius (0: a flat wall)");
            add("3d", po::bool_switch(), "half balls on a 3D floor instead of 2D drops");
            add("start", po::value<double>()->default_value(0, "0"),
                "2D flat wall: start as a cap of this angle, degrees (0: the half disk)");
            add("slip", po::bool_switch(), "slip walls (wallSlip slip) instead of no-slip");
            declareModel(add);
            add("trace", po::bool_switch(),
                "print the fastest and lowest particles every 200 steps (3D: 100)");
            add("trace-fastest", po::bool_switch(),
                "with --trace, the fastest particle's state (continuumSurfaceForce)");
          },
          [](const po::variables_map& values) {
            CapillaryOptions options;
            options.model = forceModel(values);
            options.startDegrees = get<double>(values, "start");
            options.slipWalls = get<bool>(values, "slip");
            options.trace = get<bool>(values, "trace");
            options.traceFastest = get<bool>(values, "trace-fastest");
            const int layers = get<int>(values, "layers");
            const double times = get<double>(values, "capillary-times");
            const double bond = get<double>(values, "bond");
            const double cylinder = get<double>(values, "cylinder");
            const bool threeD = get<bool>(values, "3d");
            for (const double degrees : numberList(get<std::string>(values, "angles"), "angles")) {
              const testing::SessileResult r =
                  threeD ? testing::sessileDrop3D(degrees, layers, times, bond, options)
                         : testing::sessileDrop(degrees, layers, times, bond, cylinder, options);
              std::cout << "theta " << degrees << ": " << r.angle << " degrees (from height "
                        << r.heightAngle << "), " << r.particles << " particles, lowest "
                        << r.lowest << " dx above the wall, nearest pair " << r.closest << " dx, "
                        << r.seconds << " s" << std::endl;
            }
            return 0;
          }};
}

Study gapStudy() {
  return {"gap", "a non-wetting pool over a slot: does it enter below/above its entry pressure",
          [](po::options_description_easy_init add) {
            add("ratios", po::value<std::string>()->required(),
                "required: pressures at the slot's mouth over the entry pressure, a run each");
            add("gap", po::value<int>()->default_value(8), "the slot's width, in spacings");
            add("capillary-times", po::value<double>()->default_value(20, "20"),
                "how long, in capillary times sqrt(rho w^3 / sigma)");
            add("degrees", po::value<double>()->default_value(150, "150"),
                "the contact angle of every wall");
            add("slip", po::bool_switch(), "slip walls (wallSlip slip) instead of no-slip");
            add("gap-meniscus", po::bool_switch(),
                "Young-Laplace's curvature in a slot narrower than the kernel (gapMeniscus on)");
          },
          [](const po::variables_map& values) {
            CapillaryOptions options;
            options.slipWalls = get<bool>(values, "slip");
            options.gapMeniscus = get<bool>(values, "gap-meniscus");
            const int gap = get<int>(values, "gap");
            const double times = get<double>(values, "capillary-times");
            const double degrees = get<double>(values, "degrees");
            for (const double ratio : numberList(get<std::string>(values, "ratios"), "ratios")) {
              const testing::GapResult r = testing::gapEntry(gap, ratio, times, degrees, options);
              std::cout << "gap " << gap << " dx, theta " << degrees << ", pressure / entry "
                        << ratio << ": slot filled " << r.filled << ", deepest " << r.deepest
                        << " dx, " << r.particles << " particles, " << r.seconds << " s"
                        << std::endl;
            }
            return 0;
          }};
}

// The surface-energy model's drops.

void declareEnergyModel(po::options_description_easy_init add) {
  add("core", po::value<double>()->default_value(1, "1"), "the kernel's core radius r0 / dx");
  add("compression", po::value<double>()->default_value(0.01, "0.01"),
      "R_d Gamma / (rho c^2 dx): sets the speed of sound c");
  add("h-over-dx", po::value<double>()->default_value(3, "3"), "the support radius h / dx");
  add("no-coupling", po::bool_switch(), "without the model's density coupling");
}

Study energyStaticDropStudy() {
  return {"energy-static-drop",
          "a drop (or a periodic slab) at rest: pressure vs Laplace's, currents, energy",
          [](po::options_description_easy_init add) {
            add("dimension", po::value<int>()->default_value(2), "2 or 3");
            add("across", po::value<int>()->default_value(20),
                "particles across the diameter (the slab's thickness)");
            add("relaxation", po::value<double>()->default_value(4, "4"),
                "how long, in capillary times sqrt(rho R^3 / sigma)");
            declareEnergyModel(add);
            add("slab", po::bool_switch(),
                "a periodic flat slab instead: prints its mechanical tension");
            add("slab-period", po::value<double>()->default_value(0, "0"),
                "the slab's period in x (and z), spacings (0: across + 2); implies --slab");
          },
          [](const po::variables_map& values) {
            testing::StaticDropletSetup setup;
            setup.dimension = get<int>(values, "dimension");
            setup.across = get<int>(values, "across");
            setup.relaxation = get<double>(values, "relaxation");
            setup.core = static_cast<Real>(get<double>(values, "core"));
            setup.compression = get<double>(values, "compression");
            setup.hOverDx = get<double>(values, "h-over-dx");
            setup.densityCoupling = !get<bool>(values, "no-coupling");
            setup.slabPeriod = get<double>(values, "slab-period");
            setup.slab = get<bool>(values, "slab") || setup.slabPeriod > 0;
            const testing::StaticDropletResult r = testing::staticDroplet(setup);
            std::cout << setup.dimension << "D static, " << setup.across << " across, "
                      << r.particles << " particles: jump " << r.jump << " Pa against Laplace "
                      << r.laplace << " (" << 100 * (r.jump / r.laplace - 1)
                      << " %), spurious velocity " << r.spuriousVelocity / r.capillaryVelocity
                      << " sigma/mu, E_s / (sigma surface) " << r.energyRatio << ", " << r.steps
                      << " steps in " << r.seconds << " s" << std::endl;
            return 0;
          }};
}

Study energyOscillatingDropStudy() {
  return {"energy-oscillating-drop",
          "the n = 2 oscillation after a damped relaxation: period and decay vs Lamb's",
          [](po::options_description_easy_init add) {
            add("dimension", po::value<int>()->default_value(2), "2 or 3");
            add("across", po::value<int>()->default_value(20), "particles across the diameter");
            add("amplitude", po::value<double>()->default_value(0.05, "0.05"),
                "the mode's amplitude a0 / R");
            add("periods", po::value<double>()->default_value(2, "2"),
                "how long, in Lamb's periods");
            add("relaxation", po::value<double>()->default_value(2, "2"),
                "damped relaxation first, in capillary times sqrt(rho R^3 / sigma)");
            declareEnergyModel(add);
            add("energy-factor", po::value<double>()->default_value(0, "0"),
                "R_d (0: the calibrated one)");
            add("density-scheme", po::value<std::string>()->default_value(""),
                "the flow's densityScheme (empty: its default)");
            add("trace-every", po::value<long>()->default_value(0),
                "print the amplitude and energies every N steps (0: never)");
          },
          [](const po::variables_map& values) {
            testing::DropletSetup setup;
            setup.dimension = get<int>(values, "dimension");
            setup.across = get<int>(values, "across");
            setup.energyFactor = static_cast<Real>(get<double>(values, "energy-factor"));
            setup.surfaceCompression = get<double>(values, "compression");
            setup.periods = get<double>(values, "periods");
            setup.core = get<double>(values, "core");
            setup.amplitude = get<double>(values, "amplitude");
            setup.relaxation = get<double>(values, "relaxation");
            setup.hOverDx = get<double>(values, "h-over-dx");
            setup.densityScheme = get<std::string>(values, "density-scheme");
            setup.densityCoupling = !get<bool>(values, "no-coupling");
            setup.traceEvery = get<long>(values, "trace-every");
            const Real hOverDx = static_cast<Real>(setup.hOverDx);
            std::cout << "R_d "
                      << SurfaceEnergyTension::calibratedEnergyFactor(setup.dimension, hOverDx, 1,
                                                                      static_cast<Real>(setup.core))
                      << " " << setup.dimension << "D, " << setup.across
                      << " across: " << testing::oscillatingDroplet(setup) << std::endl;
            return 0;
          }};
}

// A study, not a check: the model does not reach the angles (doc/validation.md §2.3).
Study energyContactAngleStudy() {
  return {"energy-contact-angle",
          "a 2D block (or cap) settling on a wall: the angle vs Young's law",
          [](po::options_description_easy_init add) {
            add("width", po::value<int>()->required(),
                "required: particles across the block (its height half that), e.g. 24");
            add("angles", po::value<std::string>()->default_value("90,120,150,180"),
                "the contact angles set, degrees (one drop each)");
            add("capillary-times", po::value<double>()->default_value(12, "12"),
                "how long, in capillary times sqrt(rho A^(3/2) / sigma)");
            add("damping", po::value<double>()->default_value(0.99995, "0.99995"),
                "velocity factor a step (0.9995 held the drops where they started)");
            add("start", po::value<double>()->default_value(0, "0"),
                "start as a cap of this angle and the block's area (0: the block)");
            add("bond", po::value<double>()->default_value(0, "0"),
                "rho g A / sigma: gravity towards the wall keeps the drop on it");
          },
          [](const po::variables_map& values) {
            testing::WallDropSetup setup;
            setup.width = get<int>(values, "width");
            setup.height = setup.width / 2;
            setup.capillaryTimes = get<double>(values, "capillary-times");
            setup.damping = static_cast<Real>(get<double>(values, "damping"));
            setup.startAngle = get<double>(values, "start");
            setup.bond = get<double>(values, "bond");
            for (const double degrees : numberList(get<std::string>(values, "angles"), "angles")) {
              setup.degrees = degrees;
              const testing::SettledDrop drop = testing::settleOnWall(setup);
              std::cout << "theta " << degrees << ": measured " << drop.angle
                        << " degrees (fitted circle" << (drop.detached ? ", left the wall" : "")
                        << "; from the height " << drop.heightAngle << "), nearest pair "
                        << drop.closest << " dx, " << drop.steps << " steps in " << drop.seconds
                        << " s" << std::endl;
            }
            return 0;
          }};
}

}  // namespace
}  // namespace sphcast::studies

int main(int argc, char* argv[]) {
  using namespace sphcast::studies;
  return runStudy(
      argc, argv, "the surface-tension studies of doc/validation.md §2",
      {staticDropStudy(), oscillatingDropStudy(), modeCurvatureStudy(), sessileStudy(), gapStudy(),
       energyStaticDropStudy(), energyOscillatingDropStudy(), energyContactAngleStudy()});
}
