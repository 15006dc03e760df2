// model.cpp: build_model, the list of the modules' builds in order (setup/modules/), and what lies
// between them and belongs to no one table: the particles' masses (lattice and free ones, from the
// derived mass basis and [material]'s density), the check for coincident particles (the lattice and
// the free particles together), the disorder (its amplitude is derived), the membrane's clamped edge
// (a group added after the rods) and the run's end against the output intervals ([integrator] and
// [output]). See model.h.
#include "setup/model.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "io/output_fields.h"
#include "lattice_gen/lattice_disorder.h"
#include "lattice_gen/membrane_lattice.h"
#include "swarf/core/errors.h"
#include "swarf/neighbors/neighbor_pairs.h"

namespace swarf {
namespace {

// Masses and inertias (lattice particles from the derived mass basis, free ones as solid
// spheres), positions, the free particles' velocities and spins.
void fill_particles(const CaseSettings& cs, const Lattice& lat, const std::vector<Vec3>& free_velocity,
                    const std::vector<Vec3>& free_spin, Model& model) {
  const Derived& d = model.derived;
  auto& p = model.particles;
  const std::size_t n = lat.position.size();
  // The optional arrays only where the run will hold them (Simulation::Simulation decides and
  // takes up or frees a group itself; deciding here too spares the build their memory): the
  // rotation arrays where particles can turn or their spins were given, the plastic strain's
  // where an output field needs it, the temperature with heat.
  bool rigid_body = false;
  for (const auto& m : cs.meshes) rigid_body = rigid_body || m.dynamics == "rigid_body";
  bool spin = false;
  for (const Vec3& w : free_spin) spin = spin || !w.isZero(0.0);
  p.layout.rotation = cs.contact.enabled || rigid_body || spin || !cs.inflows.empty() || !cs.outflows.empty() ||
                      cs.output.orientations;
  p.layout.plastic_strain = needs_plastic_strain_window(cs.output.fields);
  p.layout.temperature = cs.heat.present && cs.heat.enabled;
  p.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    p.position[i] = lat.position[i];
    p.initial_position[i] = lat.position[i];
    p.radius[i] = lat.radius[i];
    // Mass scales with R^3 for a lattice of mixed radii read from a file.
    const double s = lat.radius[i] / d.radius;
    p.mass[i] = d.particle_mass * s * s * s;
    p.inv_mass[i] = 1.0 / p.mass[i];
    if (p.layout.rotation) p.set_sphere_inertia(i);
  }
  for (std::size_t k = 0; k < free_velocity.size(); ++k) {
    const std::size_t i = model.lattice_particles + k;
    // Free particles are solid spheres whatever the lattice's mass basis.
    p.mass[i] = cs.material.density * 4.0 / 3.0 * M_PI * std::pow(p.radius[i], 3);
    p.inv_mass[i] = 1.0 / p.mass[i];
    p.velocity[i] = free_velocity[k];
    if (!p.layout.rotation) continue;
    p.set_sphere_inertia(i);
    p.omega[i] = free_spin[k];  // world = body frame at the start (identity orientation)
  }
}

}  // namespace

Model build_model(const CaseSettings& cs) {
  Model model;
  model.settings = cs;
  Lattice lat = cs.membrane.enabled ? membrane_lattice(cs) : workpiece_lattice(cs, model.periodic);
  model.lattice_particles = lat.position.size();
  std::vector<Vec3> free_velocity, free_spin;
  append_free_particles(cs, lat, free_velocity, free_spin);
  // (two particles at one place have no contact normal: 0/0 in the first contact evaluation)
  const double near = lat.radius.empty() ? 0.0 : 1e-6 * *std::min_element(lat.radius.begin(), lat.radius.end());
  if (const auto c = find_coincident(lat.position, near); c[0] >= 0)
    throw InputError(fmt::format(
        "{}: particles {} and {} lie within {:g} m of each other (a millionth of the smallest radius), at ({}, {}, "
        "{}) m (numbered lattice first, then [[particle]], then the [particles] file)",
        cs.source, c[0], c[1], near, lat.position[c[0]][0], lat.position[c[0]][1], lat.position[c[0]][2]));
  model.derived = compute_derived(cs, lat);  // (of the ordered lattice: the same material for every seed)
  model.sites = lat.position;
  jitter_lattice(lat, static_cast<std::uint64_t>(cs.workpiece.disorder_seed), model.derived.position_jitter,
                 model.lattice_particles, model.periodic);
  fill_particles(cs, lat, free_velocity, free_spin, model);
  // The sheet's edge only: the free particles appended after its sites have no rods either.
  std::vector<std::int32_t> membrane_edges;
  if (cs.membrane.enabled && cs.membrane.clamp_edges) {
    membrane_edges = membrane_edge(lat);
    std::erase_if(membrane_edges, [&](std::int32_t i) { return std::size_t(i) >= model.lattice_particles; });
  }
  // The lattice's sites and radii are in the particles now: freed before the rods are built.
  lat.position = {};
  lat.radius = {};
  build_rods(cs, model.derived, lat, model.particles.size(), model.rods);
  // Spacing of lattice layers along a cube axis; a membrane's sites are d/2 apart in x on
  // alternate rows.
  const double h = cs.membrane.enabled ? 0.5 * model.derived.nn_distance : 0.5 * model.derived.cell_edge;
  if (cs.membrane.enabled && cs.membrane.clamp_edges)
    add_group(model, cs.source, "membrane_edges", std::move(membrane_edges), 7, Motion{});
  build_groups(cs, model.sites, h, model);
  if (cs.uniaxial.enabled) build_uniaxial(cs, model.sites, h, model);
  build_meshes(cs, model);
  build_flows(cs, model);
  build_contacts(cs, model);
  build_heat(cs, model);
  model.gravity = Vec3(cs.gravity[0], cs.gravity[1], cs.gravity[2]);
  model.step = step_settings(model.settings, model.derived);
  check_output_schedule(model.settings);
  return model;
}

}  // namespace swarf
