// main.cpp: swarf's engine as a library, a tutorial in one file (docs/embedding.md).
//
// Builds a World in code (no case file): a bonded FCC block of steel-like spheres clamped at
// its base, and a rigid wedge tool that takes a shallow cut off its top at constant speed.
// It steps the World with the explicit Verlet scheme, prints the tool's force and the clamp's
// reaction as a table, and checks that the two balance the block's momentum:
//
//   d/dt (momentum of the free particles) = clamp reaction - force on the tool.
//
// Units are SI throughout (m, kg, s, N, Pa), as everywhere in the engine. Exit codes: 0 if the
// checks pass, 1 if one fails, 2 for a bad World (InputError), 3 if the run blows up
// (SimulationError).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <utility>
#include <vector>

#include "swarf/core/errors.h"
#include "swarf/laws/hertz.h"
#include "swarf/neighbors/neighbor_pairs.h"
#include "swarf/simulation.h"
#include "swarf/version.h"

namespace {

using swarf::Vec3;

// The block: 8 x 3 x 4 conventional FCC cells of spheres of radius R. The numbers are the
// steel of swarf's default cut, at a coarse resolution so that the example runs in seconds.
constexpr double kRadius = 0.25e-3;    // m
constexpr int kCells[3] = {8, 3, 4};   // conventional cells along x, y, z
constexpr double kDensity = 7850.0;    // kg/m^3
constexpr double kYoungs = 200e9;      // Pa, of the rods (the lattice's own modulus along [100] is 4 kb/(3a))
constexpr double kDampingRatio = 0.1;  // 1, of critical damping of one rod between two particles
constexpr double kToolSpeed = 2.0;     // m/s, along -x
constexpr double kTravel = 0.5e-3;     // m, the tool's path once it touches (one particle diameter)

// Everything the tool and the clamp need to know about the block.
struct Block {
  double layer = 0;                             // m: spacing of lattice layers along a cube axis, a/2
  Vec3 top = Vec3::Zero();                      // m: the largest x, y, z of the particle centres
  double particle_mass = 0, rod_stiffness = 0;  // kg, N/m
};

// FCC sites p * a/2 with an integer triple p of even sum; every nearest-neighbour pair (at 2R)
// becomes a rod. The engine needs each particle's mass and inertia set, and the rods'
// per-particle lists built (build_rows): it never derives them itself.
Block add_fcc_block(swarf::World& w) {
  const double d = 2.0 * kRadius, a = std::sqrt(2.0) * d;
  Block b;
  b.layer = 0.5 * a;
  std::vector<Vec3> sites;
  for (int k = 0; k < 2 * kCells[2]; ++k)
    for (int j = 0; j < 2 * kCells[1]; ++j)
      for (int i = 0; i < 2 * kCells[0]; ++i)
        if ((i + j + k) % 2 == 0) sites.emplace_back(i * b.layer, j * b.layer, k * b.layer);
  for (const Vec3& x : sites) b.top = b.top.cwiseMax(x);

  // Each particle carries the mass of its share of the solid, a^3/4 = d^3/sqrt(2) (denser than
  // the sphere itself): the block weighs what a steel block of its size weighs.
  b.particle_mass = kDensity * d * d * d / std::sqrt(2.0);
  auto& p = w.particles;
  p.resize(sites.size());
  for (std::size_t i = 0; i < sites.size(); ++i) {
    p.position[i] = p.initial_position[i] = sites[i];
    p.radius[i] = kRadius;
    p.mass[i] = b.particle_mass;
    p.inv_mass[i] = 1.0 / b.particle_mass;
    p.inertia[i] = Vec3::Constant(0.4 * b.particle_mass * kRadius * kRadius);  // solid sphere
    p.inv_inertia[i] = 1.0 / p.inertia[i][0];
  }

  auto& r = w.rods;
  r.area = M_PI * kRadius * kRadius;  // m^2, the sphere's cross-section
  r.ends = swarf::find_pairs_in_range(sites, d * (1.0 - 1e-6), d * (1.0 + 1e-6));
  for (const auto& e : r.ends) r.rest_length.push_back((sites[e[1]] - sites[e[0]]).norm());
  b.rod_stiffness = kYoungs * r.area / d;  // kb = E A / L0, N/m
  // The rod law (laws/rod_law.h). Under uniaxial stress along [100] every rod strains by a
  // third of the lattice's strain, so yield at a rod strain of 1e-3 is a yield stress of
  // 3 x 1e-3 x 4 kb/(3a), about 450 MPa; the hardening slope of 0.07 E is about 10 GPa for
  // the lattice, and rods that fail in tension at 340 MPa make it fail at about 750 MPa.
  swarf::RodLaw law;  // the paper's law; Rods hold any of laws/any_rod_law.h
  law.youngs_modulus = kYoungs;
  law.yield_strain = 1e-3;
  law.hardening = 0.07 * kYoungs;  // Pa, slope of the plastic branch
  law.tensile_strength = 340e6;    // Pa
  // Damping as a fraction of critical for two particles and one rod, c = 2 zeta sqrt(kb m/2),
  // written as the rod's viscosity eta = c L0 / A: it calms the ringing the cut starts.
  law.viscosity = kDampingRatio * 2.0 * std::sqrt(b.rod_stiffness * b.particle_mass / 2.0) * d / r.area;
  r.law = law;
  r.reset_state();  // every rod intact, no plastic shift
  r.build_rows(p.size());
  return b;
}

// The two bottom layers follow a fixed motion in x, y and z: the vice. The engine reports the
// force this group exerts on the rest of the block as sim.group_reaction(0).
void clamp_base(swarf::World& w, const Block& b) {
  swarf::Group g;
  g.name = "base";
  g.dofs = 1 | 2 | 4;  // x, y and z prescribed
  g.motion.kind = swarf::Motion::Kind::Fixed;
  auto& p = w.particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.position[i].z() < 1.5 * b.layer) {
      g.members.push_back(static_cast<std::int32_t>(i));
      p.group[i] = static_cast<std::int32_t>(w.groups.size());
      p.prescribed[i] = g.dofs;
    }
  w.groups.push_back(std::move(g));
}

// A rigid wedge of four triangles: a rake face tilted back by the rake angle and a flank face
// rising by the clearance angle from the cutting edge. The edge lies one radius above the
// centres of the third layer from the top, so the tool cuts the top two layers and its flank
// clears the rest. It starts just clear of the block's +x face and moves along -x.
double add_tool(swarf::World& w, const Block& b) {
  const double rake = 10.0 * M_PI / 180.0, clearance = 7.0 * M_PI / 180.0;  // rad
  const double face = 1.5e-3;                                               // m, length of each face
  const double x0 = b.top.x() + 1.05 * kRadius;                             // m, a twentieth of R clear
  const double z0 = b.top.z() - 2.0 * b.layer + kRadius;                    // m, the edge's height
  const double y0 = -b.layer, y1 = b.top.y() + b.layer;                     // m, wider than the block
  swarf::MeshBody tool;
  tool.name = "tool";
  auto& m = tool.mesh;
  m.name = "tool";
  const Vec3 rake_up(face * std::sin(rake), 0.0, face * std::cos(rake));
  const Vec3 flank_back(face * std::cos(clearance), 0.0, face * std::sin(clearance));
  m.vertices = {{x0, y0, z0},
                {x0, y1, z0},
                Vec3(x0, y0, z0) + rake_up,
                Vec3(x0, y1, z0) + rake_up,
                Vec3(x0, y0, z0) + flank_back,
                Vec3(x0, y1, z0) + flank_back};
  // Counterclockwise seen from outside (the side the block is on), as mesh.h asks.
  m.triangles = {{0, 3, 1}, {0, 2, 3}, {0, 1, 5}, {0, 5, 4}};
  m.validate("examples/embed tool");
  tool.youngs_modulus = std::numeric_limits<double>::infinity();  // rigid
  w.meshes.push_back(std::move(tool));
  swarf::Motion motion;
  motion.kind = swarf::Motion::Kind::Velocity;
  motion.velocity = Vec3(-kToolSpeed, 0.0, 0.0);
  w.mesh_motion.push_back(motion);
  return x0 - b.top.x() - kRadius;  // m, the gap the tool closes before it touches
}

// Hertz contacts between unbonded spheres and between spheres and the tool, with Coulomb
// friction (which turns the particles' rotations on).
void enable_contacts(swarf::World& w) {
  w.contacts = true;
  auto& c = w.contact;
  c.youngs_modulus = kYoungs;
  c.poisson_ratio = 0.3;
  c.alpha = swarf::restitution_to_alpha(0.5);  // restitution 0.5 at every impact speed
  c.friction = 0.3;
  c.law = swarf::FrictionLaw::Spring;
  c.skin = 0.2 * kRadius;  // m: the Verlet lists are rebuilt after a particle moves skin/2
}

// Sums, step by step, the impulses of the tool's force and of the clamp's reaction. The
// trapezoid rule over each step is exactly how velocity Verlet updates the velocities
// (v += h/2 (a_old + a_new)), so the impulses are those the particles actually received.
struct Impulses final : swarf::StepListener {
  Vec3 tool = Vec3::Zero(), clamp = Vec3::Zero();  // N s
  Vec3 last_tool, last_clamp;                      // N, at the end of the last step
  explicit Impulses(const swarf::Simulation& sim) : last_tool(sim.mesh_force(0)), last_clamp(sim.group_reaction(0)) {}
  void after_step(swarf::Simulation& sim) override {
    const double h = sim.last_dt();
    tool += 0.5 * h * (last_tool + sim.mesh_force(0));
    clamp += 0.5 * h * (last_clamp + sim.group_reaction(0));
    last_tool = sim.mesh_force(0);
    last_clamp = sim.group_reaction(0);
  }
};

// Momentum and mass of the particles no group holds, N s and kg.
std::pair<Vec3, double> free_momentum(const swarf::Particles& p) {
  Vec3 momentum = Vec3::Zero();
  double mass = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.group[i] < 0) {
      momentum += p.mass[i] * p.velocity[i];
      mass += p.mass[i];
    }
  return {momentum, mass};
}

int run() {
  swarf::World world;
  const Block block = add_fcc_block(world);
  clamp_base(world, block);
  const double gap = add_tool(world, block);
  enable_contacts(world);

  // The explicit step is stable below 2/omega_max, omega_max^2 = 8 kb/m (the lattice's
  // highest mode), shortened by the rods' damping (ratio 2 zeta at that mode), and below a
  // fifth of the Rayleigh time of a contact (a solid sphere of the particle's mass); take
  // half of the smaller, as setup/derived.cpp does for a case file.
  const double m = block.particle_mass, kb = block.rod_stiffness, zeta_max = 2.0 * kDampingRatio;
  const double dt_rods = std::sqrt(m / (2.0 * kb)) * (std::sqrt(1.0 + zeta_max * zeta_max) - zeta_max);
  const double nu = world.contact.poisson_ratio, shear = kYoungs / (2.0 * (1.0 + nu));
  const double sphere_density = m / (4.0 / 3.0 * M_PI * std::pow(kRadius, 3));
  const double rayleigh = M_PI * kRadius * std::sqrt(sphere_density / shear) / (0.1631 * nu + 0.8766);
  swarf::StepSettings settings;  // defaults for everything else (step_settings.h)
  settings.scheme = swarf::Scheme::Verlet;
  settings.dt = 0.5 * std::min(dt_rods, 0.2 * rayleigh);

  swarf::Simulation sim(world, settings);
  Impulses impulses(sim);
  sim.add_listener(&impulses);
  const auto [momentum0, free_mass] = free_momentum(world.particles);

  const double end_time = (gap + kTravel) / kToolSpeed;  // s
  const long rows = 20, steps_per_row = static_cast<long>(std::ceil(end_time / settings.dt / rows));
  const long steps = rows * steps_per_row;
  std::printf("swarf %s: %zu particles, %zu rods, %zu clamped; dt = %.4g s (stable %.4g s), %ld steps\n", SWARF_VERSION,
              world.particles.size(), world.rods.size(), world.groups[0].members.size(), settings.dt,
              std::min(dt_rods, 0.2 * rayleigh), steps);
  // Each row: the mean forces over the interval since the previous row (impulse / time),
  // which the step-to-step noise of a cut does not blur.
  std::printf("time_s,tool_travel_m,tool_force_x_N,tool_force_z_N,clamp_reaction_x_N,clamp_reaction_z_N,broken_rods\n");
  Vec3 tool_before = Vec3::Zero(), clamp_before = Vec3::Zero();
  double t_before = 0.0;
  for (long s = 1; s <= steps; ++s) {
    sim.step();
    if (s % steps_per_row != 0) continue;
    const double span = sim.time() - t_before;
    const Vec3 f = (impulses.tool - tool_before) / span, r = (impulses.clamp - clamp_before) / span;
    std::printf("%.4e,%.4e,%.2f,%.2f,%.2f,%.2f,%zu\n", sim.time(), -world.meshes[0].offset.x(), f.x(), f.z(), r.x(),
                r.z(), sim.broken_rods());
    tool_before = impulses.tool;
    clamp_before = impulses.clamp;
    t_before = sim.time();
  }

  // Check 1, Newton's second law for the free particles, step by step: their momentum changed
  // by exactly the impulse of the external forces on them, the clamp's reaction minus the
  // force they put on the tool (rods and contacts between particles cancel in pairs). Both
  // sides add up the same floating-point forces in other orders, so they differ by rounding
  // only: 1e-16 of each running sum per addition, some 1e4 additions for the impulses and far
  // smaller terms for the momenta, about 1e-12 of the tool's impulse at the worst. A force
  // missing or counted twice, even one particle's contact in one step (some 1e-5 of the
  // tool's impulse), stands far above the tolerance of 1e-9.
  const Vec3 dp = free_momentum(world.particles).first - momentum0;
  const Vec3 external = impulses.clamp - impulses.tool;
  const double newton_error = (dp - external).norm() / impulses.tool.norm();
  const double newton_tolerance = 1e-9;
  // Check 2, quasi-static balance: over the cut the clamp took up the tool's push. Their
  // impulses differ by the free particles' momentum, which stays below the whole free mass
  // moving at the tool's speed while no part of the block outruns the tool; a block that was
  // thrown about or blew up would break that bound. The tool must have pushed harder than
  // the bound, or the balance would say nothing.
  const double bound = free_mass * kToolSpeed;  // N s
  const double imbalance = (impulses.clamp - impulses.tool).norm();
  const double T = sim.time();
  std::printf("\nover %.4g s: mean tool force (%.2f, %.2f, %.2f) N, mean clamp reaction (%.2f, %.2f, %.2f) N\n", T,
              impulses.tool.x() / T, impulses.tool.y() / T, impulses.tool.z() / T, impulses.clamp.x() / T,
              impulses.clamp.y() / T, impulses.clamp.z() / T);
  std::printf(
      "momentum change of the free particles %.4g N s; clamp - tool impulse %.4g N s; "
      "|difference| / |tool impulse| = %.3g (tolerance %.0e)\n",
      dp.norm(), external.norm(), newton_error, newton_tolerance);
  std::printf(
      "|mean reaction - mean tool force| = %.4g N = %.3g %% of the tool force; "
      "bound (free mass %.4g kg x tool speed) / time = %.4g N\n",
      imbalance / T, 100.0 * imbalance / impulses.tool.norm(), free_mass, bound / T);
  bool ok = true;
  if (!(impulses.tool.norm() > bound)) {
    std::fprintf(stderr,
                 "embed: FAILED: the tool's impulse %.4g N s is not above the momentum bound %.4g N s: "
                 "did it touch the block?\n",
                 impulses.tool.norm(), bound);
    ok = false;
  }
  if (!(newton_error <= newton_tolerance)) {
    std::fprintf(stderr, "embed: FAILED: momentum balance off by %.3g of the tool's impulse (tolerance %.0e)\n",
                 newton_error, newton_tolerance);
    ok = false;
  }
  if (!(imbalance <= bound)) {
    std::fprintf(stderr,
                 "embed: FAILED: clamp and tool impulses differ by %.4g N s, above the quasi-static bound "
                 "%.4g N s\n",
                 imbalance, bound);
    ok = false;
  }
  std::printf("%s\n", ok ? "embed: checks passed" : "embed: checks FAILED");
  return ok ? 0 : 1;
}

}  // namespace

int main() {
  try {
    return run();
  } catch (const swarf::InputError& e) {
    std::fprintf(stderr, "embed: bad input: %s\n", e.what());
    return 2;
  } catch (const swarf::SimulationError& e) {
    std::fprintf(stderr, "embed: the simulation failed: %s\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "embed: %s\n", e.what());
    return 1;
  }
}
