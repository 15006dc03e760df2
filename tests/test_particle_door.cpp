// test_particle_door.cpp: reordering, removing and appending particles between steps
// (Simulation::apply_permutation / remove_particles / append_particles, state/reindex.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <numeric>
#include <random>
#include <string>

#include "memory_archive.h"
#include "scenes/pulled_bar.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/core/errors.h"
#include "swarf/simulation.h"
#include "test_helpers.h"

namespace swarf {
namespace {

// A plastic, viscous bar pulled until rods break (Newmark, every path of the bonded step).
const std::string kBar = test::pulled_bar_case({.cells = {10, 3, 3}, .velocity = 20.0, .damping_ratio = 0.2});

std::vector<std::int32_t> shuffled(std::size_t n, unsigned seed) {
  std::vector<std::int32_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::mt19937 rng(seed);
  std::shuffle(order.begin(), order.end(), rng);
  return order;
}

// Index of each id.
std::map<std::int64_t, std::size_t> by_id(const Particles& p) {
  std::map<std::int64_t, std::size_t> m;
  for (std::size_t i = 0; i < p.size(); ++i) m[p.id[i]] = i;
  return m;
}

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(Vec3)) == 0; }

// Each particle's rod forces are summed in rod order, and rods keep their order through a
// permutation (a rod whose ends swap gives the same bits: the kernel uses x_j - x_i for both
// the strain and the force). So a shuffled bar must go on exactly as the unshuffled one,
// particle by particle (by id), through plasticity and breakage.
TEST(ParticleDoor, AShuffledBarContinuesBitIdenticallyParticleByParticle) {
  Model a = build_model(parse_case(kBar, "bar", {})), b = build_model(parse_case(kBar, "bar", {}));
  Simulation sa(a, a.step), sb(b, b.step);
  for (int s = 0; s < 300; ++s) {
    sa.step();
    sb.step();
  }
  sb.apply_permutation(shuffled(b.particles.size(), 7));
  ASSERT_NE(a.particles.id, b.particles.id);  // (the shuffle moved particles)
  for (int s = 0; s < 1200; ++s) {
    sa.step();
    sb.step();
  }
  EXPECT_GT(sa.broken_rods(), 0u);  // breakage happened after the shuffle
  EXPECT_EQ(sa.broken_rods(), sb.broken_rods());
  EXPECT_EQ(sa.time(), sb.time());
  const auto ib = by_id(b.particles);
  for (std::size_t i = 0; i < a.particles.size(); ++i) {
    const std::size_t j = ib.at(a.particles.id[i]);
    ASSERT_TRUE(same_bits(a.particles.position[i], b.particles.position[j])) << "id " << a.particles.id[i];
    ASSERT_TRUE(same_bits(a.particles.velocity[i], b.particles.velocity[j])) << "id " << a.particles.id[i];
  }
  EXPECT_EQ(a.rods.shift, b.rods.shift);  // rods keep their order
  EXPECT_EQ(a.rods.intact, b.rods.intact);
  for (std::size_t g = 0; g < a.groups.size(); ++g) {  // groups follow their particles
    ASSERT_EQ(a.groups[g].members.size(), b.groups[g].members.size());
    for (std::size_t k = 0; k < a.groups[g].members.size(); ++k)
      EXPECT_EQ(a.particles.id[a.groups[g].members[k]], b.particles.id[ib.at(a.particles.id[a.groups[g].members[k]])]);
    EXPECT_TRUE(std::is_sorted(b.groups[g].members.begin(), b.groups[g].members.end()));
  }
}

// Removal: the particles go with their rods; the others keep their order, ids and rods.
TEST(ParticleDoor, RemovingParticlesTakesTheirRodsAndGroupMembershipAlong) {
  Model m = build_model(parse_case(kBar, "bar", {}));
  Simulation sim(m, m.step);
  for (int s = 0; s < 100; ++s) sim.step();
  const std::size_t n = m.particles.size();
  std::vector<std::uint8_t> remove(n, 0);
  double xmax = -HUGE_VAL;
  for (const auto& x : m.particles.initial_position) xmax = std::max(xmax, x[0]);
  for (std::size_t i = 0; i < n; ++i) remove[i] = m.particles.initial_position[i][0] > xmax - 1.5e-3;  // the pulled end
  std::size_t gone_rods = 0, kept = 0;
  for (const auto& e : m.rods.ends) gone_rods += remove[e[0]] || remove[e[1]];
  std::vector<std::int64_t> kept_ids;
  for (std::size_t i = 0; i < n; ++i)
    if (!remove[i]) kept_ids.push_back(m.particles.id[i]), ++kept;
  const std::size_t rods_before = m.rods.size();
  EXPECT_EQ(sim.remove_particles(remove), gone_rods);
  EXPECT_GT(gone_rods, 0u);
  EXPECT_EQ(m.particles.size(), kept);
  EXPECT_EQ(m.particles.id, kept_ids);
  EXPECT_EQ(m.rods.size(), rods_before - gone_rods);
  for (const auto& e : m.rods.ends) {
    EXPECT_LT(e[0], e[1]);
    EXPECT_LT(std::size_t(e[1]), kept);
  }
  EXPECT_TRUE(m.groups[1].members.empty());  // 'right' was all in the removed end
  EXPECT_FALSE(m.groups[0].members.empty());
  for (int s = 0; s < 100; ++s) sim.step();  // the rest steps on (the left grip holds it)
  for (const auto& x : m.particles.position) EXPECT_TRUE(x.allFinite());
}

// An appended particle under gravity, with nothing to touch, falls as the closed form says:
// Newmark (beta 1/4) and Verlet are exact for a constant acceleration up to rounding
// (relative 1e-12 over 200 steps), and the bar beside it steps on exactly as without it.
TEST(ParticleDoor, AnAppendedParticleFallsFreelyAndLeavesTheOthersUntouched) {
  const std::string text = std::string(kBar) + "[environment]\ngravity = [0.0, 0.0, -9.81]\n";
  Model a = build_model(parse_case(text, "bar", {})), b = build_model(parse_case(text, "bar", {}));
  Simulation sa(a, a.step), sb(b, b.step);
  for (int s = 0; s < 50; ++s) {
    sa.step();
    sb.step();
  }
  const Vec3 g(0, 0, -9.81), x0(0.0, 0.0, 0.05), v0(1.0, -2.0, 3.0);
  Particles extra;
  extra.resize(1);
  extra.position[0] = extra.initial_position[0] = x0;
  extra.velocity[0] = v0;
  extra.acceleration[0] = g;  // (the start of the step: the scheme needs a_n)
  extra.radius[0] = 0.5e-3;
  extra.mass[0] = 1e-6;
  extra.inv_mass[0] = 1e6;
  extra.force[0] = extra.mass[0] * g;
  const std::int64_t next = b.particles.next_id;
  const std::size_t n = b.particles.size();
  sb.append_particles(extra);
  ASSERT_EQ(b.particles.size(), n + 1);
  EXPECT_EQ(b.particles.id[n], next);
  const double t0 = sb.time();
  for (int s = 0; s < 200; ++s) {
    sa.step();
    sb.step();
  }
  const double t = sb.time() - t0;
  const Vec3 want = x0 + v0 * t + 0.5 * g * t * t;
  EXPECT_LT((b.particles.position[n] - want).norm(), 1e-12 * want.norm()) << b.particles.position[n].transpose();
  for (std::size_t i = 0; i < n; ++i) ASSERT_TRUE(same_bits(a.particles.position[i], b.particles.position[i])) << i;
}

// The state visit carries the World's variable part: a checkpoint taken after a removal loads
// into a Simulation built from the case (the full, original particle set) and continues as the
// one it was taken from, bit for bit (same state hash after more steps).
using test::MemoryArchive;

TEST(ParticleDoor, AStateSavedAfterARemovalLoadsIntoAFreshWorldAndContinuesBitIdentically) {
  test::TempDir dir("door_gas");
  const std::string text = test::granular_gas_case(dir);
  Model a = build_model(parse_case(text, "gas", {}));
  Simulation sa(a, a.step);
  for (int s = 0; s < 400; ++s) sa.step();
  std::vector<std::uint8_t> remove(a.particles.size(), 0);
  for (std::size_t i = 0; i < remove.size(); i += 5) remove[i] = 1;
  sa.remove_particles(remove);
  sa.apply_permutation(shuffled(a.particles.size(), 3));
  for (int s = 0; s < 100; ++s) sa.step();
  MemoryArchive ar;
  sa.visit_state(ar);
  Model b = build_model(parse_case(text, "gas", {}));
  Simulation sb(b, b.step);
  ar.set_loading(true);
  sb.visit_state(ar);
  EXPECT_EQ(b.particles.size(), a.particles.size());
  EXPECT_EQ(sa.state_hash(), sb.state_hash());
  for (int s = 0; s < 500; ++s) {
    sa.step();
    sb.step();
  }
  EXPECT_GT(sa.contacts().touching(), 0u);
  EXPECT_EQ(sa.state_hash(), sb.state_hash());
}

// Contacts follow a shuffle with their friction histories: the gas goes on as before to the
// rounding of the per-particle contact sums, whose order changes (relative 1e-9 after 20
// steps, where dropping the histories changes forces at the percent level).
TEST(ParticleDoor, ContactsAndTheirHistoriesFollowAShuffle) {
  test::TempDir dir("door_shuffle");
  const std::string text = test::granular_gas_case(dir);
  Model a = build_model(parse_case(text, "gas", {})), b = build_model(parse_case(text, "gas", {}));
  Simulation sa(a, a.step), sb(b, b.step);
  for (int s = 0; s < 1500; ++s) {
    sa.step();
    sb.step();
  }
  ASSERT_GT(sa.contacts().touching(), 20u);
  sb.apply_permutation(shuffled(b.particles.size(), 11));
  for (int s = 0; s < 20; ++s) {
    sa.step();
    sb.step();
  }
  EXPECT_EQ(sa.contacts().touching(), sb.contacts().touching());
  const auto ib = by_id(b.particles);
  double worst = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < a.particles.size(); ++i) {
    const std::size_t j = ib.at(a.particles.id[i]);
    worst = std::max(worst, (a.particles.force[i] - b.particles.force[j]).norm());
    scale = std::max(scale, a.particles.force[i].norm());
  }
  EXPECT_LT(worst, 1e-9 * scale) << "largest force difference " << worst << " N of " << scale << " N";
}

// Simulation::replace_particles (the domains' migration, swarf/domains/domain_run.h) with a copy
// of the World's own particles and rods: the step's own state (time, counters, the plastic strain
// window) stays, and the run goes on bit for bit, state hash included.
TEST(ParticleDoor, ReplacingTheParticlesWithTheirOwnCopyChangesNothing) {
  const std::string bar = test::pulled_bar_case(
      {.cells = {10, 3, 3}, .integrator = "scheme = \"verlet\"\nend_time = 1"});
  Model a = build_model(parse_case(bar, "bar", {})), b = build_model(parse_case(bar, "bar", {}));
  for (Model* m : {&a, &b}) {  // (a free bar, stretched: replace_particles refuses groups)
    m->groups.clear();
    for (std::size_t i = 0; i < m->particles.size(); ++i) {
      m->particles.prescribed[i] = 0;
      m->particles.group[i] = -1;
      m->particles.velocity[i] = Vec3(4000.0 * m->particles.position[i][0], 0.0, 0.0);
    }
  }
  Simulation sa(a, a.step), sb(b, b.step);
  for (int s = 0; s < 317; ++s) sa.step(), sb.step();  // (317: mid-way through a plastic strain window)
  sb.replace_particles(Particles(b.particles), Rods(b.rods));
  for (int s = 0; s < 700; ++s) sa.step(), sb.step();
  EXPECT_GT(sa.broken_rods(), 0u);
  EXPECT_EQ(sa.state_hash(), sb.state_hash());
  EXPECT_EQ(sa.time(), sb.time());
  EXPECT_EQ(sa.steps(), sb.steps());
}

// The gripped bar (Newmark): the groups' members are found again from the particles' group
// indices, and the run goes on bit for bit; a group index out of range is refused.
TEST(ParticleDoor, ReplacingTheParticlesOfAGrippedBarKeepsItsGroups) {
  Model a = build_model(parse_case(kBar, "bar", {})), b = build_model(parse_case(kBar, "bar", {}));
  Simulation sa(a, a.step), sb(b, b.step);
  for (int s = 0; s < 100; ++s) sa.step(), sb.step();
  Particles bad = b.particles;
  bad.group[0] = static_cast<std::int32_t>(b.groups.size());
  EXPECT_THROW(sb.replace_particles(bad, Rods(b.rods)), InputError);
  sb.replace_particles(Particles(b.particles), Rods(b.rods));
  for (int s = 0; s < 300; ++s) sa.step(), sb.step();
  EXPECT_EQ(sa.state_hash(), sb.state_hash());
  EXPECT_EQ(a.groups[1].members, b.groups[1].members);
}

TEST(ParticleDoor, RejectsAnOrderThatIsNotAPermutation) {
  Model m = build_model(parse_case(kBar, "bar", {}));
  Simulation sim(m, m.step);
  std::vector<std::int32_t> order(m.particles.size(), 0);
  EXPECT_THROW(sim.apply_permutation(order), InputError);
  order.pop_back();
  EXPECT_THROW(sim.apply_permutation(order), InputError);
  EXPECT_THROW(sim.remove_particles(std::vector<std::uint8_t>(3, 0)), InputError);
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// A bonded bar without contacts cannot turn its particles: its World holds no rotation arrays
// (136 B per particle), none of the plastic strain's (72 B) unless an output needs them and no
// temperature without heat (8 B), and
// steps to the same bits as with them held. Turning rotations on afterwards takes the arrays up
// with a solid sphere's inertia, as the build gives it.
TEST(ParticleLayout, ABarThatCannotTurnHoldsNoRotationArraysAndStepsToTheSameBits) {
  Model lean = build_model(parse_case(kBar, "bar", {"output.fields=[]"}));
  Model full = build_model(parse_case(kBar, "bar", {"output.orientations=true", "output.fields=[\"peeq\"]"}));
  Simulation sl(lean, lean.step), sf(full, full.step);
  const Particles& pl = lean.particles;
  const Particles& pf = full.particles;
  EXPECT_FALSE(pl.layout.rotation);
  EXPECT_FALSE(pl.layout.plastic_strain);
  EXPECT_TRUE(pl.omega.empty() && pl.inertia.empty() && pl.orientation.empty() && pl.torque.empty());
  EXPECT_TRUE(pl.peeq.empty() && pl.window_normal.empty());
  EXPECT_FALSE(pl.layout.temperature);  // (no [heat] in either)
  EXPECT_TRUE(pl.temperature.empty());
  ASSERT_TRUE(pf.layout.rotation && pf.layout.plastic_strain);
  ASSERT_EQ(pf.omega.size(), pf.size());
  for (int s = 0; s < 400; ++s) {
    sl.step();
    sf.step();
  }
  ASSERT_EQ(pl.size(), pf.size());
  for (std::size_t i = 0; i < pl.size(); ++i) {
    ASSERT_TRUE(same_bits(pl.position[i], pf.position[i])) << i;
    ASSERT_TRUE(same_bits(pl.velocity[i], pf.velocity[i])) << i;
  }
  sl.set_rotations(true);
  ASSERT_EQ(pl.inertia.size(), pl.size());
  for (std::size_t i = 0; i < pl.size(); ++i) {
    EXPECT_EQ(pl.inertia[i], pf.inertia[i]) << i;
    EXPECT_EQ(pl.inv_inertia[i], pf.inv_inertia[i]) << i;
    EXPECT_EQ(pl.orientation[i], Quat(1.0, 0.0, 0.0, 0.0)) << i;
  }
}

}  // namespace
}  // namespace swarf
