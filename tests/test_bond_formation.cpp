// test_bond_formation.cpp: rods formed between unbonded lattice particles pressed together
// (laws/bond_formation.h, Simulation::form_rods), and the turned lattice (fcc_lattice.h).
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "lattice_gen/fcc_lattice.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/simulation.h"

namespace swarf {
namespace {

constexpr double kR = 1e-3;        // particle radius, m
constexpr double kE = 2e11;        // rod Young's modulus, Pa
constexpr double kOverlap = 0.02;  // bond formation threshold, relative overlap

// Two bonded pairs side by side along x, (0, 1) and (2, 3), at rest: particles 1 and 2 are
// not bonded and overlap by 'gap' (relative: 1 - d / 2R). Particle 4, when 'free', is an
// unbonded sphere (not of the lattice) overlapping particle 3 by the same amount. Elastic,
// unbreakable rods; frictionless Hertz contacts; Verlet with a small fixed step.
struct Scene : World {
  StepSettings step;
};

Scene scene(double gap, bool free_sphere) {
  Scene w;
  const std::size_t n = free_sphere ? 5 : 4;
  auto& p = w.particles;
  p.resize(n);
  const double d = 2.0 * kR, pressed = d * (1.0 - gap);
  const double x[5] = {0.0, d, d + pressed, 2.0 * d + pressed, 2.0 * d + 2.0 * pressed};
  for (std::size_t i = 0; i < n; ++i) {
    p.position[i] = p.initial_position[i] = Vec3(x[i], 0.0, 0.0);
    p.radius[i] = kR;
    p.mass[i] = 1e-5;
    p.inv_mass[i] = 1e5;
    p.inertia[i] = Vec3::Constant(0.4 * 1e-5 * kR * kR);
    p.inv_inertia[i] = 1.0 / p.inertia[i][0];
  }
  auto& r = w.rods;
  RodLaw law;
  law.youngs_modulus = kE;
  law.yield_strain = HUGE_VAL;
  law.tensile_strength = HUGE_VAL;
  r.law = law;
  r.area = std::numbers::pi * kR * kR;
  r.formation.overlap = kOverlap;
  r.ends = {{0, 1}, {2, 3}};
  r.rest_length = {d, d};
  r.reset_state();
  r.build_rows(n);
  w.contacts = true;
  w.contact.youngs_modulus = 1e9;
  w.contact.poisson_ratio = 0.3;
  w.contact.skin = 0.1 * kR;
  w.step.scheme = Scheme::Verlet;
  w.step.dt = 1e-8;
  w.step.length_scale = d;
  w.step.stiffness_scale = kE * r.area / d;
  return w;
}

// The pair's rod (or -1).
int rod_between(const Rods& r, int i, int j) {
  for (std::size_t k = 0; k < r.size(); ++k)
    if ((r.ends[k][0] == i && r.ends[k][1] == j) || (r.ends[k][0] == j && r.ends[k][1] == i)) return int(k);
  return -1;
}

TEST(BondFormation, APressedLatticePairFormsAStressFreeRodAtItsDistanceAndLeavesTheContacts) {
  Scene w = scene(1.5 * kOverlap, false);
  Simulation sim(w, w.step);
  ASSERT_EQ(sim.contacts().touching_pairs(), 1u);  // (1, 2) pushes as a contact before the step
  sim.step();
  ASSERT_EQ(sim.formed_rods(), 1u);
  const int k = rod_between(w.rods, 1, 2);
  ASSERT_EQ(k, 2);  // appended after the lattice's rods
  EXPECT_EQ(w.rods.formed[k], 1);
  EXPECT_EQ(w.rods.intact[k], 1);
  // Rest length: the pair's distance at the commit, exactly.
  EXPECT_EQ(w.rods.rest_length[k], (w.particles.position[2] - w.particles.position[1]).norm());
  EXPECT_EQ(w.rods.shift[k], 0.0);
  // The next evaluation: the pair is bonded, so not a contact, and the rod carries the closed
  // form E (d - L0) / L0 of its stretch since the commit (elastic rod, no viscosity).
  const double L0 = w.rods.rest_length[k];
  sim.step();
  EXPECT_EQ(sim.contacts().touching_pairs(), 0u);
  const double strain = ((w.particles.position[2] - w.particles.position[1]).norm() - L0) / L0;
  EXPECT_NEAR(w.rods.stress[k], kE * strain, 1e-9 * kE * std::abs(strain) + 1e-6);
  EXPECT_EQ(sim.formed_rods(), 1u);  // once: a bonded pair is no candidate
}

TEST(BondFormation, APairBelowTheThresholdOrWithAFreeSphereFormsNone) {
  {
    Scene w = scene(0.5 * kOverlap, false);  // touching, but pressed less than the threshold
    Simulation sim(w, w.step);
    sim.step();
    EXPECT_EQ(sim.contacts().touching_pairs(), 1u);
    EXPECT_EQ(sim.formed_rods(), 0u);
    EXPECT_EQ(w.rods.size(), 2u);
  }
  {
    // Particle 4 is a free sphere: its pair with 3 is pressed as much as (1, 2) but never bonds.
    Scene w = scene(1.5 * kOverlap, true);
    Simulation sim(w, w.step);
    sim.step();
    EXPECT_EQ(sim.formed_rods(), 1u);
    EXPECT_EQ(rod_between(w.rods, 3, 4), -1);
    EXPECT_EQ(rod_between(w.rods, 1, 2), 2);
  }
}

TEST(BondFormation, ABrokenRodFormsAgainInsteadOfASecondRodOfThePair) {
  Scene w = scene(1.5 * kOverlap, false);
  // Pair (2, 3) is bonded and pressed: mark its rod broken, as if it had failed earlier.
  w.rods.intact[1] = 0;
  w.particles.position[3] = w.particles.position[2] + Vec3(2.0 * kR * (1.0 - 1.5 * kOverlap), 0.0, 0.0);
  Simulation sim(w, w.step);
  EXPECT_EQ(sim.broken_rods(), 1u);
  sim.step();
  EXPECT_EQ(sim.formed_rods(), 2u);  // (1, 2) new, (2, 3) again
  EXPECT_EQ(w.rods.size(), 3u);      // one new rod only
  EXPECT_EQ(w.rods.intact[1], 1);
  EXPECT_EQ(w.rods.formed[1], 0);  // still one of the lattice's rods
  EXPECT_EQ(sim.broken_rods(), 0u);
  EXPECT_EQ(w.rods.rest_length[1], (w.particles.position[3] - w.particles.position[2]).norm());
}

// A formed rod that broke carries nothing and is dropped at the next formation, so that the
// kernels do not visit it for the rest of the run; broken_rods counts only the lattice's own.
TEST(BondFormation, ABrokenFormedRodIsRemovedAtTheNextFormationAndIsNotCountedBroken) {
  Scene w = scene(1.5 * kOverlap, false);
  w.rods.append_formed(0, 3, 3.0 * kR);  // a rod formed earlier between 0 and 3 ...
  w.rods.intact[2] = 0;                  // ... that broke since
  w.rods.build_rows(w.particles.size());
  Simulation sim(w, w.step);
  EXPECT_EQ(sim.broken_rods(), 0u);
  EXPECT_EQ(w.rods.original_count(), 2u);
  sim.step();  // (1, 2) forms; the dead rod (0, 3) goes
  EXPECT_EQ(sim.formed_rods(), 1u);
  ASSERT_EQ(w.rods.size(), 3u);
  EXPECT_EQ(rod_between(w.rods, 0, 3), -1);
  EXPECT_EQ(rod_between(w.rods, 1, 2), 2);
  EXPECT_EQ(w.rods.formed[2], 1);
  EXPECT_EQ(sim.broken_rods(), 0u);
  // The rows are those of the three rods left: particle 0 has its lattice rod only.
  EXPECT_EQ(w.rods.row_start[1] - w.rods.row_start[0], 1);
  EXPECT_EQ(w.rods.row_start[w.particles.size()], 6);
}

TEST(BondFormation, RowsUpdatedFromTheFirstChangedRodEqualAFullBuild) {
  // The incremental update of the rows (Rods::update_rows) after what form_rods does: formed
  // rods appended at the end, broken formed ones removed from the tail (shifting the rest),
  // over many rounds on random pairs. Exact equality with a full build: the gather sums in row
  // order, so any difference would change results.
  constexpr std::size_t n = 50;
  Rods r;
  std::uint64_t s = 12345;
  auto next = [&](std::uint64_t mod) {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<std::int32_t>((s >> 33) % mod);
  };
  auto pair = [&] {
    std::int32_t i = next(n), j = next(n - 1);
    if (j >= i) ++j;
    return std::array<std::int32_t, 2>{std::min(i, j), std::max(i, j)};
  };
  for (int k = 0; k < 120; ++k) {
    r.ends.push_back(pair());
    r.rest_length.push_back(1.0);
  }
  r.reset_state();
  r.build_rows(n);
  Rods full;
  for (int round = 0; round < 200; ++round) {
    const std::size_t before_appends = r.size();
    for (int a = next(4); a > 0; --a) {
      const auto e = pair();
      r.append_formed(e[0], e[1], 1.0);
    }
    for (std::size_t k = r.original_count(); k < r.size(); ++k)
      if (next(5) == 0) r.intact[k] = 0;
    const std::size_t first = r.remove_broken_formed();
    for (std::size_t k = 0; k < r.size(); ++k) ASSERT_TRUE(r.intact[k] || !r.formed[k]) << k;
    // As form_rods: from the first rod that moved or was appended on (every few rounds from an
    // earlier rod, which must give the same rows).
    std::size_t from = std::min(first, before_appends);
    if (round % 7 == 3) from = std::size_t(next(static_cast<std::uint64_t>(from) + 1));
    r.update_rows(from, n);
    full.ends = r.ends;
    full.build_rows(n);
    ASSERT_EQ(r.row_start, full.row_start) << round;
    ASSERT_EQ(r.entries.size(), full.entries.size()) << round;
    for (std::size_t q = 0; q < r.entries.size(); ++q) {
      ASSERT_EQ(r.entries[q].rod, full.entries[q].rod) << round << " " << q;
      ASSERT_EQ(r.entries[q].other, full.entries[q].other) << round << " " << q;
    }
  }
  EXPECT_GT(r.size(), 120u);  // (formed rods survived some rounds)
}

TEST(BondFormation, NoParticleGetsMoreIntactRodsThanTheCoordination) {
  Scene w = scene(1.5 * kOverlap, false);
  w.rods.formation.coordination = 1;  // particles 1 and 2 have one rod each already
  Simulation sim(w, w.step);
  sim.step();
  EXPECT_EQ(sim.formed_rods(), 0u);
  EXPECT_EQ(w.rods.size(), 2u);
}

// A centre particle bonded to 12 neighbours on an icosahedron of radius 4R (rods 4R long, the
// neighbours clear of each other), the first neighbour pulled out to 4.4R (rod strain 0.1, the
// others 0); a 14th particle, bonded to a partner further out, pressed against the centre along
// a face's direction beyond the threshold. With neighbour exchange the centre keeps 12 rods:
// the new one, and the stretched rod to neighbour 0 broken; without it, no rod forms.
struct Shell {
  Scene w;
  int centre = 0, extra = 13;
};

Shell shell(bool exchange) {
  Shell s{scene(0.0, false)};
  World& w = s.w;
  auto& p = w.particles;
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> dirs;
  for (double a : {-1.0, 1.0})
    for (double b : {-g, g}) {
      dirs.emplace_back(0.0, a, b);
      dirs.emplace_back(a, b, 0.0);
      dirs.emplace_back(b, 0.0, a);
    }
  p.resize(15);
  p.position[0] = Vec3::Zero();
  w.rods.ends.clear();
  w.rods.rest_length.clear();
  for (int k = 0; k < 12; ++k) {
    const Vec3 u = dirs[k].normalized();
    p.position[1 + k] = u * (k == 0 ? 4.4 * kR : 4.0 * kR);
    w.rods.ends.push_back({0, 1 + k});
    w.rods.rest_length.push_back(4.0 * kR);
  }
  // The face (dirs[0], and two of its neighbours on the icosahedron) direction.
  Vec3 face = Vec3::Zero();
  for (int k = 1; k < 12 && face.squaredNorm() == 0.0; ++k)
    for (int l = k + 1; l < 12; ++l) {
      const Vec3 a = dirs[0].normalized(), b = dirs[k].normalized(), c = dirs[l].normalized();
      if (a.dot(b) > 0.4 && a.dot(c) > 0.4 && b.dot(c) > 0.4) {
        face = (a + b + c).normalized();
        break;
      }
    }
  p.position[13] = face * (2.0 * kR * (1.0 - 1.5 * kOverlap));
  p.position[14] = face * (2.0 * kR * (1.0 - 1.5 * kOverlap) + 2.0 * kR);
  w.rods.ends.push_back({13, 14});
  w.rods.rest_length.push_back(2.0 * kR);
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.initial_position[i] = p.position[i];
    p.radius[i] = kR;
    p.mass[i] = 1e-5;
    p.inv_mass[i] = 1e5;
    p.inertia[i] = Vec3::Constant(0.4 * 1e-5 * kR * kR);
    p.inv_inertia[i] = 1.0 / p.inertia[i][0];
  }
  w.rods.formation.exchange = exchange;
  w.rods.reset_state();
  w.rods.build_rows(p.size());
  return s;
}

TEST(BondFormation, NeighbourExchangeKeepsTheCoordinationAndBreaksTheMostStretchedRod) {
  for (bool exchange : {false, true}) {
    Shell s = shell(exchange);
    Simulation sim(s.w, s.w.step);
    ASSERT_EQ(sim.contacts().touching_pairs(), 1u);  // only the pressed pair touches
    sim.step();
    const Rods& r = s.w.rods;
    int intact_centre = 0;
    for (std::size_t k = 0; k < r.size(); ++k)
      if (r.intact[k] && (r.ends[k][0] == 0 || r.ends[k][1] == 0)) ++intact_centre;
    EXPECT_EQ(intact_centre, 12) << exchange;
    if (!exchange) {
      EXPECT_EQ(sim.formed_rods(), 0u);
      EXPECT_EQ(sim.broken_rods(), 0u);
      continue;
    }
    EXPECT_EQ(sim.formed_rods(), 1u);
    EXPECT_EQ(sim.broken_rods(), 1u);
    EXPECT_EQ(r.intact[0], 0);  // the rod to neighbour 0, strain 0.1: the most stretched
    for (int k = 1; k < 12; ++k) EXPECT_EQ(r.intact[k], 1) << k;
    EXPECT_EQ(r.intact[rod_between(r, 0, s.extra)], 1);
  }
}

// A short plane-strain cut whose rods break and form again: bit-identical on 1 and 2 threads,
// and the energy balance closes (a formed rod is stress-free, so it adds no energy).
std::string small_cut() {
  return R"([workpiece]
cells = [10, 2, 5]
radius = 2.0e-5
periodic_width = true
[material]
density = 7870.0
[rod]
youngs_modulus = 276.85e9
flow_plastic_strain = [0.0, 1.0]
flow_stress = [550.0e6, 550.0e6]
failure_strain = 0.2
damping_ratio = 0.1
bond_overlap = 0.005
neighbour_exchange = true
[contact]
youngs_modulus = 205e9
poisson_ratio = 0.3
restitution = 0.5
friction = 0.5
[[group]]
name = "base"
side = "z-"
layers = 2
[[mesh]]
name = "tool"
rake_angle = 10.0
clearance_angle = 7.0
edge_radius = 2.0e-5
width = 0.2e-3
face_length = 0.5e-3
origin = [-0.05e-3, 0.05e-3, 0.17e-3]
motion = "velocity"
velocity = [20.0, 0.0, 0.0]
[integrator]
end_time = 1.5e-5
scheme = "verlet"
dt_safety = 0.9
[output]
vtk = false
plots = false
)";
}

struct CutEnd {
  std::uint64_t hash;
  std::size_t formed, broken;
  double external, error;
};

CutEnd run_cut(int threads) {
  omp_set_num_threads(threads);
  Model m = build_model(parse_case(small_cut(), "cut", {}));
  Simulation sim(m, m.step);
  while (sim.time() < m.settings.integrator.end_time) sim.step();
  const EnergyLedger& l = sim.ledger();
  const double stored = sim.kinetic_energy() + sim.elastic_energy();  // (kinetic: rotation included)
  const double error = l.external_work - stored - l.plastic_work - l.viscous_work - l.fracture_energy - l.contact_work;
  return {sim.state_hash(), sim.formed_rods(), sim.broken_rods(), l.external_work, error};
}

TEST(BondFormation, ACutThatFormsRodsIsBitIdenticalOnOneAndTwoThreadsAndBalancesEnergy) {
  const int saved = omp_get_max_threads();
  const CutEnd a = run_cut(1), b = run_cut(2);
  omp_set_num_threads(saved);
  ASSERT_GT(a.formed, 0u);  // the test means nothing unless rods formed
  ASSERT_GT(a.broken, 0u);
  EXPECT_EQ(a.hash, b.hash);
  EXPECT_EQ(a.formed, b.formed);
  // The explicit scheme's own error (trapezoidal work sums) stays near 0.1 % of the work in
  // the cuts of validation/cutting; 1 % bounds it with room and fails for any real source.
  EXPECT_LT(std::abs(a.error), 0.01 * a.external) << a.error << " J of " << a.external << " J";
}

// A column of three particles along z, bonded 0-1 and 1-2; a small triangle (far from the
// particles: no contact) whose lowest vertex lies between particles 0 and 1 moves along +x at
// v towards them from x = -X. Rod 0-1 crosses the plane through that vertex and parts on the
// first step that ends with the vertex within 'lead' of its midpoint; rod 1-2 never.
TEST(PartingLine, ARodCrossingTheEdgesPlanePartsWhenTheEdgeIsWithinTheLeadAndNoOtherDoes) {
  Scene w = scene(0.0, false);
  auto& p = w.particles;
  p.resize(3);
  const double d = 2.0 * kR;
  for (int i = 0; i < 3; ++i) p.position[i] = p.initial_position[i] = Vec3(0.0, 0.0, d * i);
  w.rods.ends = {{0, 1}, {1, 2}};
  w.rods.rest_length = {d, d};
  w.rods.formation = BondFormation{};  // (off)
  w.rods.reset_state();
  w.rods.build_rows(3);
  const double X = 10.0 * kR, v = 10.0, lead = 0.5 * kR;
  MeshBody tool;
  tool.name = "edge";
  const Vec3 low(-X, 0.0, 0.5 * d);  // between particles 0 and 1
  tool.mesh.vertices = {low, low + Vec3(-3 * kR, 0.0, 3 * kR), low + Vec3(-3 * kR, 3 * kR, 3 * kR)};
  tool.mesh.triangles = {{0, 1, 2}};
  tool.youngs_modulus = HUGE_VAL;
  tool.poisson_ratio = 0.3;
  tool.parting.lead = lead;
  tool.parting.behind = lead;
  w.meshes = {tool};
  Motion m;
  m.kind = Motion::Kind::Velocity;
  m.velocity = Vec3(v, 0.0, 0.0);
  w.mesh_motion = {m};
  Simulation sim(w, w.step);
  // The step at which the edge, at -X + v t, first comes within 'lead' of x = 0.
  const double t_part = (X - lead) / v;
  while (w.rods.intact[0] && sim.time() < 2.0 * t_part) {
    const double before = sim.time();
    sim.step();
    if (!w.rods.intact[0]) {
      EXPECT_GE(sim.time(), t_part * (1.0 - 1e-12));
      EXPECT_LT(before, t_part);
    }
  }
  EXPECT_EQ(w.rods.intact[0], 0);  // parted
  EXPECT_EQ(w.rods.intact[1], 1);  // does not cross the plane
  EXPECT_EQ(sim.broken_rods(), 1u);
}

TEST(TurnedLattice, EverySiteKeepsItsTwelveNeighboursInsideAndTheBoxIsTheUnturnedOne) {
  FccSpec spec;
  spec.radius = 1e-3;
  spec.cells = {6, 3, 6};
  const Lattice plain = generate_fcc(spec);
  spec.rotation_y = 30.0 * std::numbers::pi / 180.0;
  const Lattice turned = generate_fcc(spec);
  // The FCC density, one site per 2 h^3 (h = a/2), over the box [0, 11 h]^2 x 6 y layers:
  // 11 x 11 x 3 = 363 sites, within the boundary's share (a site's cell cut by a face: 5 %).
  const double a = plain.cell_edge, lx = (2 * 6 - 1) * 0.5 * a, lz = lx;
  EXPECT_NEAR(double(turned.position.size()), 363.0, 0.05 * 363.0);
  std::vector<int> degree(turned.position.size(), 0);
  for (const auto& b : turned.rods) {
    ++degree[b[0]];
    ++degree[b[1]];
  }
  for (std::size_t i = 0; i < turned.position.size(); ++i) {
    const Vec3& x = turned.position[i];
    ASSERT_GE(x[0], -1e-9 * a);
    ASSERT_LE(x[0], lx + 1e-9 * a);
    ASSERT_GE(x[2], -1e-9 * a);
    ASSERT_LE(x[2], lz + 1e-9 * a);
    // A site one neighbour distance (and a y layer) inside every face has all 12.
    const double d = 2.0 * spec.radius;
    if (x[0] > d && x[0] < lx - d && x[2] > d && x[2] < lz - d && x[1] > d && x[1] < (2 * 3 - 1) * 0.5 * a - d) {
      EXPECT_EQ(degree[i], 12) << i;
    }
  }
  // The cube axes are turned: rods come in the turned directions, e.g. (cos 30 - sin 30)/sqrt 2
  // along x for the former [1 0 -1]/sqrt 2, and no bond lies along x itself.
  int along_x = 0;
  for (std::size_t k = 0; k < turned.rods.size(); ++k) {
    const Vec3 u = (turned.position[turned.rods[k][1]] - turned.position[turned.rods[k][0]]).normalized();
    if (std::abs(std::abs(u[0]) - 1.0) < 1e-9) ++along_x;
  }
  EXPECT_EQ(along_x, 0);
  for (const double L : turned.rest_length) ASSERT_NEAR(L, 2.0 * spec.radius, 1e-12);
}

}  // namespace
}  // namespace swarf
