#include "particles/ParticleCloud.h"

#include <gtest/gtest.h>

#include "core/Error.h"
#include "particles/FieldNames.h"

namespace sphcast {
namespace {

ParticleCloud threeParticles() {
  ParticleCloud cloud("metal");
  cloud.resize(3);
  auto& temperature = cloud.addScalarField(field::T);
  auto& velocity = cloud.addVectorField(field::U);
  auto& id = cloud.addIdField("id");
  for (std::size_t i = 0; i < 3; ++i) {
    cloud.positions()[i] = Vector(Real(i), 0, 0);
    temperature[i] = Real(900 + i);
    velocity[i] = Vector(0, Real(i), 0);
    id[i] = static_cast<std::int64_t>(10 + i);
  }
  return cloud;
}

TEST(ParticleCloud, ReorderMovesEveryFieldTogether) {
  ParticleCloud cloud = threeParticles();
  cloud.reorder({2, 0, 1});
  EXPECT_EQ(cloud.positions()[0].x(), 2);
  EXPECT_EQ(cloud.scalarField(field::T)[0], 902);
  EXPECT_EQ(cloud.vectorField(field::U)[1].y(), 0);
  EXPECT_EQ(cloud.idField("id")[2], 11);
  EXPECT_THROW(cloud.reorder({0, 1}), Error);
}

TEST(ParticleCloud, RemoveTakesOutTheNamedParticlesAndKeepsTheOthersInOrder) {
  ParticleCloud cloud = threeParticles();
  cloud.resize(5);  // ids 10 11 12 0 0 ...
  cloud.idField("id")[3] = 13;
  cloud.idField("id")[4] = 14;
  const std::uint64_t before = cloud.layoutVersion();
  cloud.remove({3, 0});
  ASSERT_EQ(cloud.size(), 3u);
  EXPECT_EQ(cloud.idField("id")[0], 11);
  EXPECT_EQ(cloud.idField("id")[1], 12);
  EXPECT_EQ(cloud.idField("id")[2], 14);
  EXPECT_EQ(cloud.scalarField(field::T)[1], 902);
  EXPECT_EQ(cloud.positions()[0].x(), 1);
  EXPECT_NE(cloud.layoutVersion(), before);  // a kept pair list would point at others
  EXPECT_THROW(cloud.remove({1, 1}), Error);
  EXPECT_THROW(cloud.remove({3}), Error);
  cloud.setHaloSize(1);
  EXPECT_THROW(cloud.remove({0}), Error);  // a halo is dropped first
}

TEST(ParticleCloud, ResizeGrowsEveryFieldWithZeros) {
  ParticleCloud cloud = threeParticles();
  cloud.resize(5);
  EXPECT_EQ(cloud.size(), 5u);
  EXPECT_EQ(cloud.scalarField(field::T).size(), 5u);
  EXPECT_EQ(cloud.scalarField(field::T)[4], 0);
  EXPECT_EQ(cloud.idField("id")[4], 0);
}

TEST(ParticleCloud, MissingFieldErrorListsTheFieldsPresent) {
  const ParticleCloud cloud = threeParticles();
  try {
    cloud.scalarField(field::rho);
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(),
                 "cloud 'metal' has no scalar field 'rho'; its fields are (position T U id)");
  }
}

TEST(ParticleCloud, ANameServesOneKindOfFieldOnly) {
  ParticleCloud cloud = threeParticles();
  EXPECT_THROW(cloud.addVectorField(field::T), Error);
  EXPECT_THROW(cloud.addScalarField("position"), Error);
  EXPECT_EQ(&cloud.addScalarField(field::T),
            &cloud.scalarField(field::T));  // existing one returned
}

TEST(ParticleCloud, AppendNeedsTheSameFields) {
  ParticleCloud cloud = threeParticles();
  cloud.append(threeParticles());
  EXPECT_EQ(cloud.size(), 6u);
  EXPECT_EQ(cloud.idField("id")[5], 12);
  ParticleCloud other("mold");
  EXPECT_THROW(cloud.append(other), Error);
}

TEST(ParticleCloud, IdenticalToIsBitwise) {
  ParticleCloud a = threeParticles();
  ParticleCloud b = threeParticles();
  EXPECT_TRUE(a.identicalTo(b));
  b.scalarField(field::T)[1] = -0.0;
  a.scalarField(field::T)[1] = 0.0;
  EXPECT_FALSE(a.identicalTo(b));  // -0 == 0 numerically, but not bit for bit
  b = threeParticles();
  b.attributes()["spacing"] = 0.001;
  EXPECT_FALSE(a.identicalTo(b));
}

}  // namespace
}  // namespace sphcast
