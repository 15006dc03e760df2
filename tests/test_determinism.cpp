// test_determinism.cpp: the same input gives bit-identical results with 1, 2 and 3 threads.
// Forces are gathered per particle in rod order and every reduction sums fixed blocks in
// order, so nothing depends on the thread count.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cstring>

#include "scenes/pulled_bar.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/core/state_archive.h"
#include "swarf/simulation.h"
#include "test_helpers.h"

namespace swarf {
namespace {

// A plastic bar with viscous rods, pulled until rods break: every code path of the step.
const std::string kCase = test::pulled_bar_case({.cells = {12, 3, 3}, .velocity = 20.0, .damping_ratio = 0.2});

struct Snapshot {
  std::vector<Vec3> x, v;
  std::vector<double> shift;
  std::vector<std::uint8_t> intact;
  EnergyLedger ledger;
  double ke;
  std::size_t broken;
  std::uint64_t hash;  ///< Simulation::state_hash: every field of the state
};

Snapshot run(int threads, int steps, const std::string& text = kCase) {
  omp_set_num_threads(threads);
  Model m = build_model(parse_case(text, "det", {}));
  Simulation sim(m, m.step);
  for (int s = 0; s < steps; ++s) sim.step();
  Snapshot out{m.particles.position, m.particles.velocity, m.rods.shift,      m.rods.intact,
               sim.ledger(),         sim.kinetic_energy(), sim.broken_rods(), sim.state_hash()};
  return out;
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(Determinism, OneAndTwoThreadsGiveIdenticalBits) {
  const int saved = omp_get_max_threads();
  const Snapshot a = run(1, 1500), b = run(2, 1500), c = run(2, 1500);
  omp_set_num_threads(saved);
  // The run must exercise plasticity and breakage, or the test proves little.
  EXPECT_GT(a.broken, 0u);
  bool plastic = false;
  for (double s : a.shift) plastic = plastic || s != 0.0;
  EXPECT_TRUE(plastic);
  for (const Snapshot* o : {&b, &c}) {
    EXPECT_TRUE(same_bits(a.x, o->x));
    EXPECT_TRUE(same_bits(a.v, o->v));
    EXPECT_TRUE(same_bits(a.shift, o->shift));
    EXPECT_TRUE(same_bits(a.intact, o->intact));
    EXPECT_EQ(a.broken, o->broken);
    EXPECT_EQ(a.hash, o->hash);
    EXPECT_EQ(a.ke, o->ke);
    EXPECT_EQ(a.ledger.external_work, o->ledger.external_work);
    EXPECT_EQ(a.ledger.plastic_work, o->ledger.plastic_work);
    EXPECT_EQ(a.ledger.viscous_work, o->ledger.viscous_work);
    EXPECT_EQ(a.ledger.fracture_energy, o->ledger.fracture_energy);
  }
}

// Rods whose plastic flow keeps the volume (forces/plastic_volume.h): each particle's mean runs
// over its row in rod order and each rod's correction is its own, so the bits do not depend on
// the thread count either; and the option acts (the shifts are not the plain law's).
TEST(Determinism, IsochoricPlasticityGivesIdenticalBitsOnOneAndTwoThreads) {
  std::string text = kCase;
  const std::size_t at = text.find("[rod]\n");
  ASSERT_NE(at, std::string::npos);
  text.insert(at + 6, "isochoric_plasticity = true\n");
  const int saved = omp_get_max_threads();
  const Snapshot a = run(1, 1500, text), b = run(2, 1500, text), plain = run(2, 1500);
  omp_set_num_threads(saved);
  EXPECT_TRUE(same_bits(a.x, b.x));
  EXPECT_TRUE(same_bits(a.shift, b.shift));
  EXPECT_TRUE(same_bits(a.intact, b.intact));
  EXPECT_EQ(a.hash, b.hash);
  EXPECT_EQ(a.ledger.plastic_work, b.ledger.plastic_work);
  EXPECT_FALSE(same_bits(a.shift, plain.shift));
}

// Contacts: each thread evaluates a range of pairs and sums their results into the
// particles it owns; a particle with pairs in two threads' ranges gets its sum, in the same
// pair order, from the per-pair results (ContactSystem::Sums). With 2 and 3 threads the
// split falls inside the gas, so both ways are taken; the results must not tell them apart.
TEST(Determinism, AGranularGasWithFrictionGivesIdenticalBitsOnOneTwoAndThreeThreads) {
  test::TempDir dir("det_gas");
  const std::string text = test::granular_gas_case(dir);
  struct State {
    std::vector<Vec3> x, v, w;
    std::vector<Quat> q;
    double contact_work;
    std::size_t touching;
    std::uint64_t hash;
  };
  auto run_gas = [&](int threads) {
    omp_set_num_threads(threads);
    Model m = build_model(parse_case(text, "gas", {}));
    Simulation sim(m, m.step);
    std::size_t touching = 0;
    for (int s = 0; s < 1500; ++s) {
      sim.step();
      touching = std::max(touching, sim.contacts().touching_pairs());
    }
    return State{m.particles.position,    m.particles.velocity,      m.particles.omega,
                 m.particles.orientation, sim.ledger().contact_work, touching,
                 sim.state_hash()};
  };
  const int saved = omp_get_max_threads();
  const State a = run_gas(1), b = run_gas(2), c = run_gas(3);
  omp_set_num_threads(saved);
  EXPECT_GT(a.touching, 50u);  // the gas collides
  for (const State* o : {&b, &c}) {
    EXPECT_TRUE(same_bits(a.x, o->x));
    EXPECT_TRUE(same_bits(a.v, o->v));
    EXPECT_TRUE(same_bits(a.w, o->w));
    EXPECT_TRUE(same_bits(a.q, o->q));
    EXPECT_EQ(a.contact_work, o->contact_work);
    EXPECT_EQ(a.hash, o->hash);  // (the contact lists and friction histories too)
  }
}

// The hash sees every field: one bit of one particle's velocity, one rod's committed shift
// or one contact history changes it (a hash that missed a field would let a restart or a
// thread count differ unseen).
TEST(StateHash, ChangesWithOneBitOfAnyField) {
  test::TempDir dir("hash_gas");
  Model m = build_model(parse_case(test::granular_gas_case(dir), "gas", {}));
  Simulation sim(m, m.step);
  for (int s = 0; s < 300; ++s) sim.step();
  const std::uint64_t h0 = sim.state_hash();
  EXPECT_EQ(h0, sim.state_hash());  // a pure function of the state
  auto flip = [](double& x) {
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    b ^= 1;
    std::memcpy(&x, &b, sizeof b);
  };
  flip(m.particles.velocity[7][1]);
  EXPECT_NE(h0, sim.state_hash());
  flip(m.particles.velocity[7][1]);
  EXPECT_EQ(h0, sim.state_hash());
  flip(m.particles.omega[3][2]);
  EXPECT_NE(h0, sim.state_hash());
  flip(m.particles.omega[3][2]);
  ASSERT_EQ(h0, sim.state_hash());

  Model bar = build_model(parse_case(kCase, "det", {}));
  Simulation bsim(bar, bar.step);
  for (int s = 0; s < 50; ++s) bsim.step();
  const std::uint64_t b0 = bsim.state_hash();
  flip(bar.rods.shift[5]);
  EXPECT_NE(b0, bsim.state_hash());
}

// The hash reads the rods' ends where they are (HashArchive::int32_pairs, no copy) and gets what
// hashing them as the flat int32 array a checkpoint holds gives (the base's copy): the same state
// hash as before the copy was dropped, for any pairs.
TEST(StateHash, TheRodsEndsHashAsTheirFlatArray) {
  const std::vector<std::array<std::int32_t, 2>> pairs{{0, 1}, {0, 7}, {3, 2147483647}, {-1, 5}};
  std::vector<std::int32_t> flat;
  for (const auto& e : pairs) flat.insert(flat.end(), e.begin(), e.end());
  HashArchive in_place, copied;
  in_place.int32_pairs("rods/ends", pairs);
  copied.array("rods/ends", flat, flat.size());
  EXPECT_EQ(in_place.value(), copied.value());
  HashArchive one_less;  // (the count is hashed: a pair less is another hash)
  one_less.int32_pairs("rods/ends", std::vector<std::array<std::int32_t, 2>>(pairs.begin(), pairs.end() - 1));
  EXPECT_NE(one_less.value(), copied.value());
}

}  // namespace
}  // namespace swarf
