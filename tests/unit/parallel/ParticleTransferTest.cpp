// Particles between ranks: a migration sends each particle to its subdomain's rank with all its
// fields and loses none; a halo gives every owned particle exactly the neighbours it has in a
// serial run, so that pair sums over owned particles equal the serial sums to round-off; a
// refresh carries a pass's output to the halo copies, and without it a second pass goes wrong.
// Collective: every rank runs every test (under mpirun -np 1, 2 and 4 in CTest).
#include "parallel/ParticleTransfer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/Error.h"
#include "particles/FieldNames.h"
#include "particles/Neighbourhood.h"
#include "particles/WendlandKernel.h"

namespace sphcast {
namespace {

constexpr Real radius = 2.6;  // the kernel's support, in spacings (the flow's h = 2.6 dx)

// A jittered lattice block of 24 x 16 x 12 spacings (4,608 particles) with a mass that tells
// each particle's id, and a velocity; `first`, `stride`: this rank's share of the ids.
ParticleCloud block(std::size_t first, std::size_t stride) {
  ParticleCloud cloud("metal");
  auto& mass = cloud.addScalarField(field::mass);
  auto& velocity = cloud.addVectorField(field::U);
  auto& id = cloud.addIdField("id");
  cloud.addScalarField(field::rho);
  std::mt19937 random(3);
  std::uniform_real_distribution<Real> shake(-0.2, 0.2);
  std::size_t n = 0;
  for (int i = 0; i < 24; ++i) {
    for (int j = 0; j < 16; ++j) {
      for (int k = 0; k < 12; ++k, ++n) {
        const Vector x(i + shake(random), j + shake(random), k + shake(random));
        if (n % stride != first) continue;
        cloud.resize(cloud.size() + 1);
        cloud.positions().back() = x;
        mass.back() = Real(1) + Real(1e-3) * static_cast<Real>(n);
        velocity.back() = Vector(Real(n), -Real(n), Real(0.5));
        id.back() = static_cast<std::int64_t>(n);
      }
    }
  }
  return cloud;
}

ParticleCloud myShare(const Communicator& comm) {
  return block(static_cast<std::size_t>(comm.rank()), static_cast<std::size_t>(comm.size()));
}

RecursiveBisection decompose(const ParticleCloud& cloud, const Communicator& comm) {
  return RecursiveBisection::build(comm, cloud.positions(),
                                   std::vector<std::int64_t>(cloud.size(), 1), comm.size(), 3);
}

// The sorted ids of particle i's neighbours closer than the radius.
std::vector<std::int64_t> neighbourIds(const ParticleCloud& cloud, const NeighbourList& list,
                                       std::size_t i) {
  std::vector<std::int64_t> ids;
  for (std::uint32_t j : list.of(i)) ids.push_back(cloud.idField("id")[j]);
  std::sort(ids.begin(), ids.end());
  return ids;
}

// rho_i = sum_j m_j W_ij (self included), then phi_i = sum_j m_j / rho_j W_ij (the Shepard
// sum, which reads the neighbours' rho: a second pass), over the first `count` particles.
void densityPass(ParticleCloud& cloud, const NeighbourList& list, std::size_t count,
                 const PeriodicBox& box) {
  const WendlandC2Kernel<3> kernel(radius);
  auto& rho = cloud.scalarField(field::rho);
  const auto& m = cloud.scalarField(field::mass);
  const auto& x = cloud.positions();
  for (std::size_t i = 0; i < count; ++i) {
    Real sum = m[i] * kernel.value(0);
    for (std::uint32_t j : list.of(i)) {
      sum += m[j] * kernel.value(box.separation(x[i], x[j]).norm());
    }
    rho[i] = sum;
  }
}

std::vector<Real> shepardPass(const ParticleCloud& cloud, const NeighbourList& list,
                              std::size_t count, const PeriodicBox& box) {
  const WendlandC2Kernel<3> kernel(radius);
  const auto& rho = cloud.scalarField(field::rho);
  const auto& m = cloud.scalarField(field::mass);
  const auto& x = cloud.positions();
  std::vector<Real> phi(count);
  for (std::size_t i = 0; i < count; ++i) {
    Real sum = m[i] / rho[i] * kernel.value(0);
    for (std::uint32_t j : list.of(i)) {
      sum += m[j] / rho[j] * kernel.value(box.separation(x[i], x[j]).norm());
    }
    phi[i] = sum;
  }
  return phi;
}

TEST(ParticleTransferTest, MigrationSendsEveryParticleToItsOwnerWithItsFields) {
  const Communicator world = Communicator::world();
  ParticleCloud cloud = myShare(world);
  const auto rcb = decompose(cloud, world);
  const std::size_t left = migrateParticles(cloud, rcb, world);
  if (world.size() > 1) {
    EXPECT_GT(world.sum(static_cast<std::int64_t>(left)), 0);
  }
  constexpr std::size_t total = 24 * 16 * 12;
  std::vector<std::int64_t> seen(total, 0);
  bool fieldsFollow = true;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    EXPECT_EQ(rcb.owner(cloud.positions()[i]), world.rank()) << "particle " << i;
    const auto n = cloud.idField("id")[i];
    ++seen[static_cast<std::size_t>(n)];
    fieldsFollow =
        fieldsFollow &&
        cloud.scalarField(field::mass)[i] == Real(1) + Real(1e-3) * static_cast<Real>(n) &&
        cloud.vectorField(field::U)[i] == Vector(Real(n), -Real(n), Real(0.5));
  }
  EXPECT_TRUE(fieldsFollow);
  world.sum(seen);
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](std::int64_t s) { return s == 1; }))
      << "a particle lost or duplicated";
  // a second migration with nothing moved sends nothing
  EXPECT_EQ(migrateParticles(cloud, rcb, world), 0u);
}

// The same neighbours by id, and the same pair sums to round-off, as the serial run; periodic
// or not.
void expectSerialNeighboursAndSums(const PeriodicBox& box) {
  const Communicator world = Communicator::world();
  ParticleCloud serial = block(0, 1);
  Neighbourhood serialSearch(radius, box);
  serialSearch.addCloud(serial, Neighbourhood::Motion::moving);
  serialSearch.requestPairs(serial, serial);
  serialSearch.update(CloudOrder::keep, true);
  const NeighbourList& serialList = serialSearch.pairs(serial, serial);
  densityPass(serial, serialList, serial.size(), box);
  const std::vector<Real> serialPhi = shepardPass(serial, serialList, serial.size(), box);

  ParticleCloud cloud = myShare(world);
  const auto rcb = decompose(cloud, world);
  migrateParticles(cloud, rcb, world);
  HaloExchange halo;
  halo.build(cloud, rcb, radius, box, world);
  ASSERT_EQ(halo.ownedCount() + halo.haloCount(), cloud.size());
  if (world.size() > 1) {
    EXPECT_GT(halo.haloCount(), 0u);
  }
  Neighbourhood search(radius, box);
  search.addCloud(cloud, Neighbourhood::Motion::moving);
  search.requestPairs(cloud, cloud);
  search.update(CloudOrder::keep, true);  // the halo stays after the owned particles
  const NeighbourList& list = search.pairs(cloud, cloud);

  std::size_t wrongNeighbours = 0;
  for (std::size_t i = 0; i < halo.ownedCount(); ++i) {
    const auto n = static_cast<std::size_t>(cloud.idField("id")[i]);
    if (neighbourIds(cloud, list, i) != neighbourIds(serial, serialList, n)) ++wrongNeighbours;
  }
  EXPECT_EQ(wrongNeighbours, 0u);

  // every halo copy is its owner's particle
  bool copiesTrue = true;
  for (std::size_t i = halo.ownedCount(); i < cloud.size(); ++i) {
    const auto n = static_cast<std::size_t>(cloud.idField("id")[i]);
    copiesTrue = copiesTrue && cloud.positions()[i] == serial.positions()[n] &&
                 cloud.scalarField(field::mass)[i] == serial.scalarField(field::mass)[n];
  }
  EXPECT_TRUE(copiesTrue);

  // the first pass over everything present (the halo's own sums are incomplete at its edge),
  // the second after the refresh: both equal the serial sums up to the order of summation
  densityPass(cloud, list, cloud.size(), box);
  const std::vector<Real> stalePhi = shepardPass(cloud, list, halo.ownedCount(), box);
  halo.refresh(cloud, {"rho"}, world);
  const std::vector<Real> phi = shepardPass(cloud, list, halo.ownedCount(), box);
  double worstRho = 0, worstPhi = 0, worstStale = 0;
  for (std::size_t i = 0; i < halo.ownedCount(); ++i) {
    const auto n = static_cast<std::size_t>(cloud.idField("id")[i]);
    const auto& rho = serial.scalarField(field::rho);
    worstRho =
        std::max(worstRho, std::abs(double(cloud.scalarField(field::rho)[i] - rho[n]) / rho[n]));
    worstPhi = std::max(worstPhi, std::abs(double(phi[i] - serialPhi[n]) / serialPhi[n]));
    worstStale = std::max(worstStale, std::abs(double(stalePhi[i] - serialPhi[n]) / serialPhi[n]));
  }
  // about 60 terms each: reordering them moves the sum by a few ulp
  const double roundOff = 64 * std::numeric_limits<Real>::epsilon();
  EXPECT_LE(worstRho, roundOff);
  EXPECT_LE(worstPhi, roundOff);
  // without the refresh, the halo's rho are its truncated sums: far off at the boundary
  if (world.size() > 1) {
    EXPECT_GT(world.max(worstStale), 1e-3);
  }
}

TEST(ParticleTransferTest, HaloGivesEveryOwnedParticleItsSerialNeighboursAndSums) {
  expectSerialNeighboursAndSums(PeriodicBox());
}

TEST(ParticleTransferTest, PeriodicHaloCrossesTheSeam) {
  PeriodicBox box;
  box.setPeriodic(0, -0.5, 24);  // the block's 24 spacings in x, its last layer beside its first
  expectSerialNeighboursAndSums(box);
}

TEST(ParticleTransferTest, RefreshFollowsTheOwnersAfterTheyMove) {
  const Communicator world = Communicator::world();
  ParticleCloud cloud = myShare(world);
  const auto rcb = decompose(cloud, world);
  migrateParticles(cloud, rcb, world);
  HaloExchange halo;
  halo.build(cloud, rcb, radius, PeriodicBox(), world);
  auto displaced = [](std::int64_t n) { return Vector(Real(0.01) * Real(n % 7), 0, Real(-0.02)); };
  const ParticleCloud reference = block(0, 1);
  for (std::size_t i = 0; i < halo.ownedCount(); ++i) {
    cloud.positions()[i] += displaced(cloud.idField("id")[i]);
    cloud.vectorField(field::U)[i] *= 2;
  }
  halo.refresh(cloud, world);
  bool followed = true;
  for (std::size_t i = halo.ownedCount(); i < cloud.size(); ++i) {
    const auto n = cloud.idField("id")[i];
    followed = followed &&
               cloud.positions()[i] ==
                   Vector(reference.positions()[static_cast<std::size_t>(n)] + displaced(n)) &&
               cloud.vectorField(field::U)[i] == Vector(2 * Real(n), -2 * Real(n), Real(1));
  }
  EXPECT_TRUE(followed);
  halo.remove(cloud);
  EXPECT_EQ(cloud.size(), halo.ownedCount());
  // dropped, the halo refreshes nothing until the next build, though particles were added
  // (a pour's new layer) and no rank exchanges anything
  cloud.resize(cloud.size() + 1);
  EXPECT_NO_THROW(halo.refresh(cloud, world));
  EXPECT_NO_THROW(halo.refresh(cloud, {"U"}, world));
  EXPECT_EQ(cloud.size(), halo.ownedCount() + 1);
  cloud.resize(cloud.size() - 1);
  // a refresh of a cloud whose particle count changed since the build is refused
  HaloExchange rebuilt;
  rebuilt.build(cloud, rcb, radius, PeriodicBox(), world);
  cloud.resize(cloud.size() + 1);
  EXPECT_THROW(rebuilt.refresh(cloud, world), Error);
}

TEST(ParticleTransferTest, ALayoutGivesTheCloudsNameAttributesAndFieldsWithoutParticles) {
  ParticleCloud cloud = block(0, 1);
  cloud.attributes()["spacing"] = 0.1 / 3;  // not a round number in decimal
  cloud.attributes()["internalEnergyAtStart"] = -1.5e7;
  const ParticleCloud empty = unpackLayout(packLayout(cloud));
  EXPECT_EQ(empty.name(), "metal");
  EXPECT_EQ(empty.size(), 0u);
  EXPECT_EQ(empty.attributes(), cloud.attributes());  // bit for bit
  EXPECT_TRUE(empty.hasScalarField(field::mass) && empty.hasScalarField(field::rho));
  EXPECT_TRUE(empty.hasVectorField(field::U) && empty.hasIdField("id"));
  EXPECT_EQ(empty.scalarFields().size(), 2u);
  // it takes the packed cloud's particles (the same fields)
  ParticleCloud receiver = unpackLayout(packLayout(cloud));
  std::vector<char> buffer;
  packParticles(cloud, {0, 7}, buffer);
  unpackParticles(buffer, receiver);
  EXPECT_EQ(receiver.idField("id")[1], 7);
  std::string truncated = packLayout(cloud);
  truncated.pop_back();
  EXPECT_THROW(unpackLayout(truncated), Error);
}

// A serial start: rank 0 alone reads the cloud, the others get its fields, and the migration
// leaves every particle on its subdomain's rank, none lost; rank 0's read error is everyone's.
TEST(ParticleTransferTest, ACloudReadOnRankZeroReachesEveryRankWhole) {
  const Communicator world = Communicator::world();
  int reads = 0;
  ParticleCloud cloud = readOnMaster(
      [&] {
        ++reads;
        return block(0, 1);
      },
      world);
  EXPECT_EQ(reads, world.master() ? 1 : 0);
  EXPECT_EQ(cloud.size(), world.master() ? 4608u : 0u);
  EXPECT_TRUE(cloud.hasVectorField(field::U) && cloud.hasIdField("id"));
  const auto rcb = decompose(cloud, world);
  migrateParticles(cloud, rcb, world);
  EXPECT_EQ(world.sum(static_cast<std::int64_t>(cloud.size())), 4608);
  double idSum = 0;
  bool home = true;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    idSum += static_cast<double>(cloud.idField("id")[i]);
    home = home && rcb.owner(cloud.positions()[i]) == world.rank();
  }
  EXPECT_EQ(world.sum(idSum), 4607.0 * 4608.0 / 2);
  EXPECT_TRUE(home);
  try {
    readOnMaster([]() -> ParticleCloud { throw Error("metal.vtp: no such file"); }, world);
    FAIL() << "no error";
  } catch (const Error& error) {  // on 1 rank the read's own; on more a CollectiveError
    EXPECT_EQ(std::string(error.what()), "metal.vtp: no such file");
  }
}

TEST(ParticleTransferTest, AMessageForOtherFieldsIsAnError) {
  ParticleCloud sender("metal"), receiver("metal");
  sender.resize(3);
  receiver.resize(2);
  sender.addScalarField(field::T);
  receiver.addScalarField(field::rho);
  std::vector<char> buffer;
  packParticles(sender, {0, 2}, buffer);
  EXPECT_THROW(unpackParticles(buffer, receiver), Error);
  receiver.addScalarField(field::T);
  EXPECT_THROW(unpackParticles(buffer, receiver), Error);  // still one field more
  ParticleCloud same("metal");
  same.addScalarField(field::T);
  unpackParticles(buffer, same);
  EXPECT_EQ(same.size(), 2u);
  buffer.pop_back();
  EXPECT_THROW(unpackParticles(buffer, same), Error);  // a truncated message
}

}  // namespace
}  // namespace sphcast
