// What the flow reads of a case: the numerics keys of system/sphSchemes and the dimension and
// periodic axes of constant/physicsModels, and the errors a user gets for them.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include "case/CaseDescription.h"
#include "core/CaseFolder.h"
#include "core/Error.h"
#include "core/dictionary/SourceLocation.h"
#include "particles/FieldNames.h"
#include "sph/FlowSetup.h"
#include "support/TemporaryCase.h"

namespace sphcast {
namespace {

const char* header = "FoamFile { version 2.0; format ascii; class dictionary; }\n";

struct FlowCase : testing::TemporaryCase {
  FlowCase(const std::string& models, const std::string& schemes,
           const std::string& density = "1000", const std::string& walls = "(tank);",
           const std::string& model = "weaklyCompressible") {
    write("constant/physicsModels", header + models + "flow { model " + model +
                                        "; fluid water; walls " + walls + " }\n");
    write("system/sphSchemes",
          header + schemes + "viscousForm Morris;\nsupportRadius 0.03;\nsoundSpeed 10;\n");
    write("constant/physicalProperties",
          std::string(header) + "water { density " + density + "; viscosity 1e-3; }\n");
  }
  // constant/g written with `gravity`, then the case read as the tools read it
  FlowSetup read(const Vector& gravity = Vector(0, -9.81, 0)) const {
    std::ostringstream g;
    g.precision(17);
    g << header << "dimensions [0 1 -2 0 0 0 0];\nvalue (" << gravity[0] << ' ' << gravity[1] << ' '
      << gravity[2] << ");\n";
    write("constant/g", g.str());
    return readFlowSetup(CaseDescription(CaseFolder(root())));
  }
};

// The message of the DictionaryError that reading the case throws ("" if none).
std::string errorOf(const FlowCase& flowCase, const Vector& gravity = Vector(0, -9.81, 0)) {
  try {
    flowCase.read(gravity);
  } catch (const DictionaryError& error) {
    return error.what();
  }
  return "";
}

// flow { walls { ... } }: each wall with conditions of its own over system/sphSchemes' (which
// set every wall's), and the errors of a misspelt one.
TEST(FlowSetup, AWallsOwnConditionsOverTheSchemesDefaults) {
  const FlowSetup setup =
      FlowCase("", "densityScheme riemann;\nwallSlip slip;\n", "1000",
               "{ tank {} lid { wallSlip noSlip; wallDissipation normalApproach; } }")
          .read();
  EXPECT_EQ(setup.wallClouds, (std::vector<std::string>{"tank", "lid"}));
  EXPECT_TRUE(setup.settings.walls.all.slip());
  EXPECT_TRUE(setup.settings.walls.of("tank").slip());
  EXPECT_FALSE(setup.settings.walls.of("tank").normalApproach());
  EXPECT_FALSE(setup.settings.walls.of("lid").slip());
  EXPECT_TRUE(setup.settings.walls.of("lid").normalApproach());
  EXPECT_EQ(setup.settings.walls.of("lid").describe(),
            "wallSlip noSlip, wallDissipation normalApproach");

  const std::string misspelt =
      errorOf(FlowCase("", "densityScheme riemann;\n", "1000", "{ tank { wallSlip slp; } }"));
  EXPECT_NE(misspelt.find("physicsModels"), std::string::npos) << misspelt;
  EXPECT_NE(misspelt.find("noSlip"), std::string::npos) << misspelt;
  const std::string unknown =
      errorOf(FlowCase("", "densityScheme riemann;\n", "1000", "{ tank { slip yes; } }"));
  EXPECT_NE(unknown.find("'slip'"), std::string::npos) << unknown;
  const std::string notADictionary =
      errorOf(FlowCase("", "densityScheme riemann;\n", "1000", "{ tank slip; }"));
  EXPECT_NE(notADictionary.find("must be a dictionary"), std::string::npos) << notADictionary;
}

TEST(FlowSetup, ReadsDimensionPeriodicAxesAndTheNumerics) {
  const FlowCase flowCase("dimension 2;\nperiodic { x (-0.1 0.2); }\n",
                          "densityScheme deltaSPH;\nkernelCorrection on;\n"
                          "deltaSPHCoeffs { delta 0.12; alpha 0.03; }\n");
  const FlowSetup setup = flowCase.read();
  EXPECT_EQ(setup.settings.dimension, 2);
  EXPECT_EQ(setup.settings.densityScheme, "deltaSPH");
  EXPECT_TRUE(setup.settings.kernelCorrection);
  EXPECT_DOUBLE_EQ(setup.settings.deltaSPHDiffusion, 0.12);
  EXPECT_DOUBLE_EQ(setup.settings.deltaSPHViscosity, 0.03);
  EXPECT_TRUE(setup.settings.periodic.isPeriodic(0));
  EXPECT_FALSE(setup.settings.periodic.isPeriodic(1));
  EXPECT_DOUBLE_EQ(setup.settings.periodic.lower(0), -0.1);
  EXPECT_NEAR(setup.settings.periodic.period(0), 0.3, 1e-15);
}

TEST(FlowSetup, DefaultsAre3DWithoutCorrectionOrPeriodicAxes) {
  const FlowSetup setup = FlowCase("", "densityScheme riemann;\n").read();
  EXPECT_EQ(setup.settings.dimension, 3);
  EXPECT_FALSE(setup.settings.kernelCorrection);
  EXPECT_FALSE(setup.settings.periodic.anyPeriodic());
}

// rho_s as a table in T (the material tables of doc/physics.md §4): each particle starts with
// restDensity and rho at its own temperature; a cloud without T cannot use a table.
TEST(FlowSetup, RestDensityFromATemperatureTable) {
  const FlowCase flowCase("", "densityScheme riemann;\n",
                          "table ((800 2500) (900 2400) (1000 2350))");
  const FlowSetup setup = flowCase.read();
  ParticleCloud water("water");
  water.resize(3);
  water.attributes()["spacing"] = 0.01;
  auto& temperature = water.addScalarField(field::T);
  temperature = {850, 950, 1100};
  water.addScalarField(field::volume) = {1e-9, 1e-9, 1e-9};
  prepareFluidFields(setup, water);
  const std::vector<Real> expected{2450, 2375, 2350};  // interpolated; clamped above 1000 K
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_DOUBLE_EQ(water.scalarField(field::restDensity)[i], expected[i]);
    EXPECT_DOUBLE_EQ(water.scalarField(field::rho)[i], expected[i]);
    EXPECT_DOUBLE_EQ(water.scalarField(field::mass)[i], expected[i] * 1e-9);
  }

  ParticleCloud cold("water");
  cold.resize(1);
  cold.attributes()["spacing"] = 0.01;
  cold.addScalarField(field::volume) = {1e-9};
  try {
    prepareFluidFields(setup, cold);
    FAIL() << "a table without T was accepted";
  } catch (const DictionaryError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("physicalProperties:2"), std::string::npos) << message;
    EXPECT_NE(message.find("has no T"), std::string::npos) << message;
  }
}

// mu as a table in T (Table 1 spans eight decades): each particle's viscosity is mu at its T,
// interpolated log-linearly; the AC4CH material of etc/materials reads through #includeEtc.
TEST(FlowSetup, ViscosityFromATemperatureTableIsInterpolatedLogLinearly) {
  const FlowCase flowCase("", "densityScheme riemann;\n");
  flowCase.write("constant/physicalProperties",
                 std::string(header) +
                     "water { density 1000; viscosity table ((800 100) (900 "
                     "1e-2)); }\nalloy { #includeEtc \"materials/AC4CH\" }\n");
  const FlowSetup setup = flowCase.read();
  ParticleCloud water("water");
  water.resize(3);
  water.attributes()["spacing"] = 0.01;
  water.addScalarField(field::T) = {850, 700, 1000};
  water.addScalarField(field::volume) = {1e-9, 1e-9, 1e-9};
  prepareFluidFields(setup, water);
  const auto& mu = water.scalarField(field::viscosity);
  EXPECT_NEAR(mu[0], 1.0, 1e-12);  // sqrt(100 * 1e-2), the geometric mean
  EXPECT_DOUBLE_EQ(mu[1], 100);    // clamped
  EXPECT_DOUBLE_EQ(mu[2], 1e-2);
}

// Each error names the file and line (the header is line 1, the first entry line 2) and says
// what is wrong.
TEST(FlowSetup, BadKeysAreErrorsAtTheirLine) {
  const std::string riemann = "densityScheme riemann;\n";
  auto expectError = [](const std::string& message, const std::string& place,
                        const std::string& what) {
    EXPECT_NE(message.find(place), std::string::npos) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
  };
  expectError(errorOf(FlowCase("dimension 4;\n", riemann)), "physicsModels:2",
              "'dimension' must be 2 or 3");
  EXPECT_EQ(errorOf(FlowCase("dimension 3;\n", riemann), Vector(0, 0, -9.81)), "");
  expectError(errorOf(FlowCase("dimension 2;\n", riemann), Vector(0, 0, -9.81)), "physicsModels:2",
              "constant/g has a z component");
  // the minimum image needs a period longer than 2 h = 0.06 m
  expectError(errorOf(FlowCase("periodic { y (0 0.05); }\n", riemann)), "physicsModels:2",
              "longer than twice the supportRadius");
  expectError(errorOf(FlowCase("dimension 2;\nperiodic { z (0 1); }\n", riemann)),
              "physicsModels:3", "a 2D case has no periodic z axis");
  expectError(errorOf(FlowCase("periodic { w (0 1); }\n", riemann)), "physicsModels:2", "'w'");
  expectError(errorOf(FlowCase("", "densityScheme delta;\n")), "sphSchemes:2",
              "riemann standard deltaSPH");
  expectError(errorOf(FlowCase("", riemann + "kernelCorrection maybe;\n")), "sphSchemes:3",
              "kernelCorrection");
  expectError(errorOf(FlowCase("", "densityScheme deltaSPH;\ndeltaSPHCoeffs { delta -1; }\n")),
              "sphSchemes:3", "'delta' must not be negative");
  expectError(errorOf(FlowCase("", riemann + "densityReinitialisation summed;\n")), "sphSchemes:3",
              "none packed");
  expectError(
      errorOf(FlowCase("", riemann + "densityReinitialisation packed;\n"
                                     "densityReinitialisationCoeffs { relaxation 1.5; }\n")),
      "sphSchemes:4", "'relaxation'");
  expectError(errorOf(FlowCase("", riemann + "densityReinitialisationCoeffs { relax 0.2; }\n")),
              "sphSchemes:3", "relax");
}

// densityReinitialisation: none by default; packed with its relaxation (DensityReinitialisation.h).
TEST(FlowSetup, DensityReinitialisationIsOffByDefaultAndTakesItsRelaxation) {
  EXPECT_FALSE(FlowCase("", "densityScheme riemann;\n").read().settings.reinitialiseDensity);
  const FlowSetup setup = FlowCase("",
                                   "densityScheme riemann;\ndensityReinitialisation packed;\n"
                                   "densityReinitialisationCoeffs { relaxation 0.2; }\n")
                              .read();
  EXPECT_TRUE(setup.settings.reinitialiseDensity);
  EXPECT_DOUBLE_EQ(setup.settings.densityRelaxation, 0.2);
}

// flow { model incompressible; } with pressureSolverCoeffs, and the weakly compressible flow's
// own schemes refused at their line.
TEST(FlowSetup, IncompressibleFlowReadsItsSolverAndRefusesTheAcousticSchemes) {
  auto incompressible = [](const std::string& schemes) {
    return FlowCase("", schemes, "1000", "(tank);", "incompressible");
  };
  const FlowSetup plain = incompressible("densityScheme riemann;\n").read();
  EXPECT_TRUE(plain.settings.incompressible);
  EXPECT_DOUBLE_EQ(plain.settings.pressureSolver.densityTolerance, 1e-3);
  EXPECT_FALSE(FlowCase("", "densityScheme riemann;\n").read().settings.incompressible);
  const FlowSetup tuned =
      incompressible(
          "densityScheme riemann;\npressureSolverCoeffs { densityTolerance 5e-4; maxIterations "
          "400; relaxation 0.4; advectionCo 0.3; largestCompression 0.02; }\n")
          .read();
  EXPECT_DOUBLE_EQ(tuned.settings.pressureSolver.largestCompression, 0.02);
  EXPECT_DOUBLE_EQ(tuned.settings.pressureSolver.densityTolerance, 5e-4);
  EXPECT_EQ(tuned.settings.pressureSolver.maxIterations, 400);
  EXPECT_DOUBLE_EQ(tuned.settings.pressureSolver.relaxation, 0.4);
  EXPECT_DOUBLE_EQ(tuned.settings.pressureSolver.advectionCo, 0.3);
  const std::string dual = errorOf(
      incompressible("densityScheme riemann;\ntimeStepping dualCriteria;\n"));
  EXPECT_NE(dual.find("sphSchemes:3:"), std::string::npos) << dual;
  EXPECT_NE(dual.find("weakly compressible"), std::string::npos) << dual;
  const std::string delta = errorOf(incompressible("densityScheme deltaSPH;\n"));
  EXPECT_NE(delta.find("sphSchemes:2:"), std::string::npos) << delta;
  const std::string relaxation = errorOf(
      incompressible("densityScheme riemann;\npressureSolverCoeffs { relaxation 1.5; }\n"));
  EXPECT_NE(relaxation.find("'relaxation'"), std::string::npos) << relaxation;
  EXPECT_NE(relaxation.find("sphSchemes:3:"), std::string::npos) << relaxation;
  const std::string unknown = errorOf(
      incompressible("densityScheme riemann;\npressureSolverCoeffs { tolerance 1e-3; }\n"));
  EXPECT_NE(unknown.find("tolerance"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("densityTolerance"), std::string::npos) << unknown;
  const std::string model = errorOf(FlowCase("", "densityScheme riemann;\n", "1000", "(tank);",
                                             "incompressibel"));
  EXPECT_NE(model.find("incompressible"), std::string::npos) << model;
}

// c is the case's (case/CaseDescription.h), read and checked in one place for the flow and the
// fill's hydrostatic start alike.
TEST(FlowSetup, ANonPositiveSoundSpeedIsAnErrorAtItsLine) {
  testing::TemporaryCase folder;
  folder.write("system/sphSchemes", std::string(header) + "supportRadius 0.03;\nsoundSpeed -5;\n");
  try {
    CaseDescription(CaseFolder(folder.root())).soundSpeed();
    FAIL() << "a negative soundSpeed accepted";
  } catch (const DictionaryError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("sphSchemes:3:"), std::string::npos) << message;
    EXPECT_NE(message.find("'soundSpeed' is -5"), std::string::npos) << message;
  }
}

// A switch reads alike in every file: on/off, yes/no, true/false.
TEST(FlowSetup, ASwitchTakesOnYesOrTrue) {
  for (const char* on : {"on", "yes", "true"}) {
    const FlowCase flowCase("",
                            std::string("densityScheme riemann;\nkernelCorrection ") + on + ";\n");
    EXPECT_TRUE(flowCase.read().settings.kernelCorrection) << on;
  }
  for (const char* off : {"off", "no", "false"}) {
    const FlowCase flowCase("",
                            std::string("densityScheme riemann;\nkernelCorrection ") + off + ";\n");
    EXPECT_FALSE(flowCase.read().settings.kernelCorrection) << off;
  }
}

// A zero viscosity would make the harmonic mean of two particles' viscosities 0/0.
TEST(FlowSetup, NonPositiveViscosityIsAnErrorWithItsValueAndRange) {
  const FlowCase flowCase("", "densityScheme riemann;\n");
  flowCase.write("constant/physicalProperties",
                 std::string(header) + "water { density 1000; viscosity 0; }\n");
  EXPECT_EQ(errorOf(flowCase),
            (flowCase.root() / "constant/physicalProperties").string() +
                ":2:23: 'viscosity' is 0 in physicalProperties/water; it must be positive (valid "
                "range: > 0)");
}

// The flow needs the fluid's spacing dx (the step limits, h/dx): a cloud not written by
// setCastFields may lack it, which used to end the run with a bare "map::at".
TEST(FlowSetup, FluidWithoutSpacingOrWithASupportRadiusOutOfRangeIsAnError) {
  const FlowSetup setup = FlowCase("", "densityScheme riemann;\n").read();  // h = 0.03 m
  ParticleCloud water("water");
  water.resize(2);
  water.addScalarField(field::volume) = {1e-6, 1e-6};
  try {
    prepareFluidFields(setup, water);
    ADD_FAILURE() << "a cloud without spacing was accepted";
  } catch (const Error& error) {
    EXPECT_EQ(std::string(error.what()),
              "cloud 'water' (water.vtp of the start time) has no positive 'spacing' attribute, "
              "the particle spacing dx that the flow needs; write the cloud with setCastFields, "
              "which records it");
  }

  for (const double spacing : {0.001, 0.05}) {  // h/dx = 30 and 0.6
    water.attributes()["spacing"] = spacing;
    try {
      prepareFluidFields(setup, water);
      ADD_FAILURE() << "h/dx = " << 0.03 / spacing << " was accepted";
    } catch (const DictionaryError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find("sphSchemes:4:1: 'supportRadius' 0.03 m is "), std::string::npos)
          << message;
      EXPECT_NE(message.find("supportRadius/spacing must lie in [1.2, 6]"), std::string::npos)
          << message;
    }
  }
  water.attributes()["spacing"] = 0.01;  // h/dx = 3
  EXPECT_NO_THROW(prepareFluidFields(setup, water));
}

// setCastFields writes p to 0/ (the first frame of the series) as the flow starts it: eq. (3)
// on the start's rho, or on rho = rho_s where the cloud has none.
TEST(FlowSetup, StartPressureIsTheEquationOfStateOfTheStartDensity) {
  const FlowSetup setup = FlowCase("", "densityScheme riemann;\n").read();  // c = 10 m/s
  ParticleCloud water("water");
  water.resize(3);
  water.attributes()["spacing"] = 0.01;
  water.addScalarField(field::volume) = {1e-6, 1e-6, 1e-6};
  EXPECT_EQ(startPressure(setup, water), (std::vector<Real>{0, 0, 0}));
  EXPECT_FALSE(water.hasScalarField(field::rho));  // the cloud itself is left as it was
  water.addScalarField(field::rho) = {1000, 1001, 999.5};
  EXPECT_EQ(startPressure(setup, water), (std::vector<Real>{0, 100, -50}));
}

// `fluid water;` in constant/physicsModels without a material water in
// constant/physicalProperties: the error is at the 'fluid' entry, names the file that lacks the
// material and lists the materials it has.
TEST(FlowSetup, FluidMaterialMissingFromPhysicalPropertiesIsReportedWhereItIsNamed) {
  const FlowCase flowCase("", "densityScheme riemann;\n");
  flowCase.write("constant/physicalProperties",
                 std::string(header) + "steel { density 7000; viscosity 5e-3; }\n");
  const std::string message = errorOf(flowCase);
  EXPECT_EQ(message, (flowCase.root() / "constant/physicsModels").string() +
                         ":2:34: 'fluid' names the material 'water', which is not in " +
                         (flowCase.root() / "constant/physicalProperties").string() +
                         "; materials there: (steel)");

  flowCase.write("constant/physicalProperties", std::string(header) +
                                                    "steel { density 7000; viscosity 5e-3; }\n" +
                                                    "watr { density 1000; viscosity 1e-3; }\n");
  EXPECT_NE(errorOf(flowCase).find("; did you mean 'watr'? materials there: (steel watr)"),
            std::string::npos)
      << errorOf(flowCase);
}

TEST(FlowSetup, PhysicalPropertiesMayHoldOtherMaterialsThanTheFluid) {
  const FlowCase flowCase("", "densityScheme riemann;\n");
  flowCase.write("constant/physicalProperties", std::string(header) +
                                                    "steel { density 7000; viscosity 5e-3; }\n" +
                                                    "water { density 1000; viscosity 1e-3; }\n");
  EXPECT_EQ(errorOf(flowCase), "");
}

TEST(FlowSetup, AFlowWithoutConstantGIsAnErrorAtTheFlowEntry) {
  const FlowCase flowCase("", "densityScheme riemann;\n");
  try {
    readFlowSetup(CaseDescription(CaseFolder(flowCase.root())));
    FAIL() << "a flow without gravity accepted";
  } catch (const DictionaryError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("physicsModels:2:"), std::string::npos) << message;
    EXPECT_NE(message.find("a flow needs gravity"), std::string::npos) << message;
    EXPECT_NE(message.find("constant/g does not exist"), std::string::npos) << message;
  }
}

// The foreseen Mach number: a column of water 0.5 m high over a floor 0.3 m below it falls
// at most sqrt(2 g 0.8) = 3.96 m/s; with U0 = 3 m/s, sqrt(9 + 2 g 0.8) = 4.97 m/s.
TEST(FlowSetup, SoundSpeedCheckForeseesTheFallAndTheInitialSpeed) {
  FlowSettings settings;
  settings.gravity = Vector(0, -9.81, 0);
  settings.soundSpeed = 20;
  ParticleCloud water("water"), tank("tank");
  water.resize(2);
  water.positions() = {Vector(0, 0.3, 0), Vector(0.1, 0.8, 0)};
  tank.resize(1);
  tank.positions() = {Vector(0, 0, 0)};
  const double fall = std::sqrt(2 * 9.81 * 0.8);
  SoundSpeedCheck check = checkSoundSpeed(settings, water, {&tank});
  EXPECT_NEAR(check.fallHeight, 0.8, 1e-6);
  EXPECT_NEAR(check.largestSpeed, fall, 1e-6);
  EXPECT_NEAR(check.mach, fall / 20, 1e-6);
  EXPECT_TRUE(check.tooLow) << check.message;  // Mach 0.198
  EXPECT_NE(check.message.find("at least 39.6 m/s"), std::string::npos) << check.message;

  settings.soundSpeed = 50;  // Mach 0.079
  EXPECT_FALSE(checkSoundSpeed(settings, water, {&tank}).tooLow);
  water.addVectorField(field::U)[1] = Vector(3, 0, 0);  // Mach 0.0995
  check = checkSoundSpeed(settings, water, {&tank});
  EXPECT_NEAR(check.largestSpeed, std::sqrt(9 + fall * fall), 1e-6);
  EXPECT_FALSE(check.tooLow) << check.message;
  water.vectorField(field::U)[0] = Vector(0, -3.2, 0);  // Mach 0.1018
  EXPECT_TRUE(checkSoundSpeed(settings, water, {&tank}).tooLow);
  // without walls the fall is the fluid's own height
  EXPECT_NEAR(checkSoundSpeed(settings, water, {}).fallHeight, 0.5, 1e-6);
}

}  // namespace
}  // namespace sphcast
