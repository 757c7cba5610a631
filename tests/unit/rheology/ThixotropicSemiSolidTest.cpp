// The thixotropic semi-solid rheology (rheology/ThixotropicSemiSolid.h) on AC4CH's tables: the
// structure after a step change of shear rate against the exact solution of its kinetics, the
// shear rate of a simple shear, the viscosity between the mush at rest and the broken
// suspension, and the registry's errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/Error.h"
#include "core/dictionary/Dictionary.h"
#include "materials/MaterialLibrary.h"
#include "particles/FieldNames.h"
#include "particles/Neighbourhood.h"
#include "rheology/RheologyModel.h"
#include "rheology/ShearedBlock.h"
#include "rheology/ThixotropicSemiSolid.h"
#include "sph/FlowTestCases.h"
#include "support/TemporaryCase.h"

namespace sphcast {
namespace {

Material ac4ch() {
  const testing::TemporaryCase folder;
  folder.write("constant/physicalProperties",
               "FoamFile { version 2.0; format ascii; class dictionary; object "
               "physicalProperties; }\nAC4CH { #includeEtc \"materials/AC4CH\" }\n");
  return MaterialLibrary::read(folder.root() / "constant/physicalProperties")
      .get("AC4CH", {}, "metal");
}

// A block of mush at temperature T and solid fraction fs (ShearedBlock.h).
struct ShearedMush : testing::ShearedBlock {
  ShearedMush(Real temperature, Real fs) : ShearedBlock(2500, 1) {
    fluid.addScalarField(field::T).assign(fluid.size(), temperature);
    fluid.addScalarField(field::solidFraction).assign(fluid.size(), fs);
  }
};

// At rest from a fully built structure, then sheared at 50 1/s, then at rest again: lambda
// against lambda_e + (lambda_0 - lambda_e) exp(-(a + b gammaDot) t) at every step, for the
// interior particles, where the SPH strain rate of a linear field is exact but for the kernel's
// normalisation.
TEST(ThixotropicSemiSolid, StructureFollowsTheExactRelaxationAfterAStepOfShearRate) {
  const Material material = ac4ch();
  ShearedMush mush(Real(868), Real(0.3));
  const RheologyContext context{mush.fluid, material, mush.neighbourhood, {}, 2, 3 * mush.dx};
  ThixotropicSemiSolid model(context, ThixotropicSemiSolidSettings{});
  const ThixotropicSemiSolidSettings& s = model.settings();
  const double dt = 0.01;
  double worstStructure = 0, worstRate = 0;
  double lambda = 1;  // exact, carried from phase to phase
  for (const Real rate : {Real(50), Real(0)}) {
    mush.shear(rate);
    const double k = s.buildUp + s.breakDown * std::pow(double(rate), double(s.exponent));
    const double equilibrium = s.buildUp / k;
    for (int step = 0; step < 300; ++step) {
      model.update(dt);
      lambda = equilibrium + (lambda - equilibrium) * std::exp(-k * dt);
      for (std::size_t i = 0; i < mush.fluid.size(); ++i) {
        if (!mush.interior(i)) continue;
        worstStructure = std::max(
            worstStructure, std::abs(double(mush.fluid.scalarField(field::structure)[i]) - lambda));
        worstRate = std::max(worstRate,
                             std::abs(double(mush.fluid.scalarField(field::shearRate)[i]) - rate));
      }
    }
    std::printf("gammaDot %g 1/s for 3 s: lambda %.4f (exact %.4f)\n", double(rate),
                double(mush.fluid.scalarField(field::structure)[mush.fluid.size() / 2]), lambda);
  }
  std::printf("largest |lambda - exact| %.2e, |gammaDot - 50| %.3f 1/s\n", worstStructure,
              worstRate);
  EXPECT_LT(worstRate, 0.01 * 50);  // the SPH strain rate of the simple shear
  EXPECT_LT(worstStructure, 0.01);  // the bound is 5 %
}

// mu runs from the mush at rest (the table's mu(T), lambda = 1) to the broken suspension
// (Krieger & Dougherty, lambda = 0); shear thins it; the liquid keeps mu(T).
TEST(ThixotropicSemiSolid, ViscosityLiesBetweenTheMushAtRestAndTheBrokenSuspension) {
  const Material material = ac4ch();
  ShearedMush mush(Real(868), Real(0.3));
  const RheologyContext context{mush.fluid, material, mush.neighbourhood, {}, 2, 3 * mush.dx};
  const ThixotropicSemiSolid model(context, ThixotropicSemiSolidSettings{});
  const double atRest = (*material.viscosity)(868);
  const double liquid = (*material.viscosity)(material.freezingRange->liquidus);
  const double broken = liquid * std::pow(1 - 0.3 / 0.6, -2.5 * 0.6);
  EXPECT_NEAR(model.viscosity(Real(0.3), Real(868), 1), atRest, 1e-9 * atRest);
  EXPECT_NEAR(model.viscosity(Real(0.3), Real(868), 0), broken, 1e-9 * broken);
  EXPECT_EQ(model.viscosity(0, Real(900), Real(0.2)), Real((*material.viscosity)(900)));
  double previous = atRest * 2;
  for (const Real rate : {Real(0.1), Real(1), Real(10), Real(100), Real(1000)}) {
    const Real mu = model.viscosity(Real(0.3), Real(868), model.equilibriumStructure(rate));
    std::printf("f_s 0.3 (868 K), steady at %g 1/s: mu %.4g Pa s\n", double(rate), double(mu));
    EXPECT_LT(mu, previous);
    previous = mu;
  }
  std::printf("mu(T) at rest %.4g Pa s, broken %.4g Pa s, liquid %.4g Pa s\n", atRest, broken,
              liquid);
}

TEST(ThixotropicSemiSolid, ItsCoefficientsAndRegisteredNameAreChecked) {
  EXPECT_EQ(rheologyModels().names(),
            (std::vector<std::string>{"newtonian", "thixotropicSemiSolid", "herschelBulkley",
                                      "elastoViscoplastic"}));
  const Material material = ac4ch();
  ShearedMush mush(Real(868), Real(0.3));
  const RheologyContext context{mush.fluid, material, mush.neighbourhood, {}, 2, 3 * mush.dx};
  auto errorOf = [&](const std::string& text) {
    try {
      const Dictionary rheology = Dictionary::parse(text, "physicsModels");
      rheologyModels().build(rheologyModels().choose(rheology, "model"), context, rheology);
    } catch (const std::exception& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  EXPECT_EQ(errorOf("model thixotropicSemiSolid; thixotropicSemiSolidCoeffs { a 0.1; b 0.02; }"),
            "");
  EXPECT_NE(errorOf("model thixotropic;").find("thixotropicSemiSolid"), std::string::npos);
  EXPECT_NE(errorOf("model thixotropicSemiSolid; thixotropicSemiSolidCoeffs { a -1; }")
                .find("'a' must be positive"),
            std::string::npos);
  EXPECT_NE(errorOf("model thixotropicSemiSolid; thixotropicSemiSolidCoeffs { maxPacking 1.2; }")
                .find("maxPacking"),
            std::string::npos);
  EXPECT_NE(errorOf("model thixotropicSemiSolid; thixotropicSemiSolidCoeffs { c 1; }").find("'c'"),
            std::string::npos);
}

}  // namespace
}  // namespace sphcast
