// model.cpp: building particles, rods and groups from the settings (see model.h).
#include "setup/model.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "io/mesh_file.h"
#include "io/particle_file.h"
#include "lattice_gen/lattice_disorder.h"
#include "lattice_gen/membrane_lattice.h"
#include "setup/case_keys.h"
#include "swarf/core/errors.h"
#include "swarf/geometry/mass_properties.h"
#include "swarf/geometry/shapes.h"
#include "swarf/laws/hertz.h"
#include "swarf/neighbors/neighbor_pairs.h"
#include "tool_paths/tool_geometry.h"

namespace swarf {

static TriangleMesh rectangle_mesh(const MeshSettings& ms) {
  TriangleMesh m;
  m.name = ms.name;
  const Vec3 o(ms.origin[0], ms.origin[1], ms.origin[2]), e1(ms.edge1[0], ms.edge1[1], ms.edge1[2]),
      e2(ms.edge2[0], ms.edge2[1], ms.edge2[2]);
  const int n1 = ms.divisions[0], n2 = ms.divisions[1];
  for (int b = 0; b <= n2; ++b)
    for (int a = 0; a <= n1; ++a) m.vertices.push_back(o + (double(a) / n1) * e1 + (double(b) / n2) * e2);
  auto id = [&](int a, int b) { return b * (n1 + 1) + a; };
  for (int b = 0; b < n2; ++b)
    for (int a = 0; a < n1; ++a) {
      m.triangles.push_back({id(a, b), id(a + 1, b), id(a + 1, b + 1)});
      m.triangles.push_back({id(a, b), id(a + 1, b + 1), id(a, b + 1)});
    }
  return m;
}

namespace {

// Masses and inertias (lattice particles from the derived mass basis, free ones as solid
// spheres), positions, the free particles' velocities and spins.
void fill_particles(const CaseSettings& cs, const Lattice& lat, const std::vector<Vec3>& free_velocity,
                    const std::vector<Vec3>& free_spin, Model& model) {
  const Derived& d = model.derived;
  auto& p = model.particles;
  const std::size_t n = lat.position.size();
  p.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    p.position[i] = lat.position[i];
    p.initial_position[i] = lat.position[i];
    p.radius[i] = lat.radius[i];
    // Mass scales with R^3 for a lattice of mixed radii read from a file.
    const double s = lat.radius[i] / d.radius;
    p.mass[i] = d.particle_mass * s * s * s;
    p.inv_mass[i] = 1.0 / p.mass[i];
    p.inertia[i] = Vec3::Constant(0.4 * p.mass[i] * p.radius[i] * p.radius[i]);
    p.inv_inertia[i] = 1.0 / p.inertia[i][0];
  }
  for (std::size_t k = 0; k < free_velocity.size(); ++k) {
    const std::size_t i = model.lattice_particles + k;
    // Free particles are solid spheres whatever the lattice's mass basis.
    p.mass[i] = cs.material.density * 4.0 / 3.0 * M_PI * std::pow(p.radius[i], 3);
    p.inv_mass[i] = 1.0 / p.mass[i];
    p.inertia[i] = Vec3::Constant(0.4 * p.mass[i] * p.radius[i] * p.radius[i]);
    p.inv_inertia[i] = 1.0 / p.inertia[i][0];
    p.velocity[i] = free_velocity[k];
    p.omega[i] = free_spin[k];  // world = body frame at the start (identity orientation)
  }
}

// [uniaxial]: the grips as two groups moving along the strain path, the bar's gauge length
// and cross-section, and the rods through its mid-plane (all on the ordered sites).
void build_uniaxial(const CaseSettings& cs, const std::vector<Vec3>& sites, double h, Model& model) {
  const auto& r = model.rods;
  const auto& u = cs.uniaxial;
  auto& info = model.uniaxial;
  info.enabled = true;
  info.axis = u.axis[0] - 'x';
  const int ax = info.axis;
  Vec3 lo = sites[0], hi = sites[0];
  for (const auto& x : sites) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  info.gauge_length = (hi[ax] - lo[ax]) - 2.0 * (u.grip_layers - 1) * h;
  if (!(info.gauge_length > 0.5 * h))
    throw InputError(fmt::format("{}: key 'uniaxial.grip_layers' = {}: the grips leave no free bar between them",
                                 cs.source, u.grip_layers));
  info.cross_section = 1.0;
  for (int c = 0; c < 3; ++c)
    if (c != ax) info.cross_section *= (hi[c] - lo[c]) + h;
  // Grip motion: each grip moves half the separation change, along the strain path.
  Motion mmin, mmax;
  mmin.kind = mmax.kind = Motion::Kind::Table;
  double t = 0.0;
  for (std::size_t k = 0; k < u.strain_path.size(); ++k) {
    if (k > 0) t += std::abs(u.strain_path[k] - u.strain_path[k - 1]) / u.strain_rate;
    const double half = 0.5 * u.strain_path[k] * info.gauge_length;
    Vec3 e = Vec3::Zero();
    e[ax] = half;
    mmin.time.push_back(t);
    mmax.time.push_back(t);
    mmin.displacement.push_back(-e);
    mmax.displacement.push_back(e);
  }
  const std::uint8_t dofs = u.grip_dofs == "xyz" ? 7 : static_cast<std::uint8_t>(1u << ax);
  const std::string smin = std::string(1, u.axis[0]) + "-", smax = std::string(1, u.axis[0]) + "+";
  info.grip_min = static_cast<int>(model.groups.size());
  add_group(model, cs.source, "grip_min", select_side(sites, smin, u.grip_layers, h), dofs, mmin);
  info.grip_max = static_cast<int>(model.groups.size());
  add_group(model, cs.source, "grip_max", select_side(sites, smax, u.grip_layers, h), dofs, mmax);
  if (!(model.settings.integrator.end_time > 0.0)) model.settings.integrator.end_time = t;
  const double mid = 0.5 * (lo[ax] + hi[ax]) + 0.25 * h;  // between two layers
  for (std::size_t b = 0; b < r.size(); ++b) {
    const double xi = sites[r.ends[b][0]][ax], xj = sites[r.ends[b][1]][ax];
    if ((xi < mid) != (xj < mid)) info.midplane_rods.emplace_back(static_cast<std::int32_t>(b), xi < mid ? 1 : -1);
  }
}

static Vec3 to_vec(const std::array<double, 3>& a) { return Vec3(a[0], a[1], a[2]); }

// The mass properties of a [[mesh]] with dynamics = "rigid_body" from its closed mesh, filled
// uniformly at 'density' or so that it has 'mass'.
static RigidBody rigid_body_from_mesh(const CaseSettings& cs, const MeshSettings& ms, std::size_t index,
                                      const TriangleMesh& mesh) {
  const auto where = [&] { return fmt::format("{}: [[mesh]] '{}'", cs.source, ms.name); };
  double density = ms.density;
  if (!(density > 0.0)) {  // from 'mass'
    const double volume = mass_properties(mesh, 1.0).volume;
    if (!(volume > 0.0))
      throw InputError(
          fmt::format("{}: mass = {} kg: the mesh encloses no positive volume ({:.4g} m^3); it must be "
                      "closed with its triangles counterclockwise seen from outside",
                      where(), ms.mass, volume));
    density = ms.mass / volume;
  }
  try {
    return rigid_body_of(index, mesh, density);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", where(), e.what()));
  }
}

// A [[mesh]] with dynamics = "rigid_body": mass properties given or from its closed mesh, then
// the keys' initial state, constraints and loads.
static RigidBody rigid_body(const CaseSettings& cs, const Derived& d, const MeshSettings& ms, std::size_t index,
                            const TriangleMesh& mesh) {
  const auto where = [&] { return fmt::format("{}: [[mesh]] '{}'", cs.source, ms.name); };
  RigidBody rb;
  if (!ms.inertia.empty()) {  // given: the mesh only carries the contacts
    const auto& t = ms.inertia;
    Eigen::Matrix3d I;
    I << t[0], t[3], t[5], t[3], t[1], t[4], t[5], t[4], t[2];
    try {
      rb = rigid_body_given(index, ms.mass, to_vec(ms.centre_of_mass), I);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: key 'inertia': {}", where(), e.what()));
    }
  } else {
    rb = rigid_body_from_mesh(cs, ms, index, mesh);
  }
  // Inertia and mass consistent (issue 37): each principal moment's radius of gyration
  // sqrt(I / m) a physical length, 1 nm to 1 km as any length of a case. A moment of 1e-300
  // kg m^2 with a mass of 1 kg was accepted, and its rotation's step would be 1e-150 s.
  for (int c = 0; c < 3; ++c) {
    const double gyration = std::sqrt(rb.inertia[c] / rb.mass);  // m
    if (!(gyration >= kLength.lo && gyration <= kLength.hi))
      throw InputError(fmt::format(
          "{}: key '{}': principal moments ({:.6g}, {:.6g}, {:.6g}) kg m^2 with mass {:.6g} kg give a radius of "
          "gyration sqrt(I/m) of {:.4g} m, outside {:g} m to {:g} m: the inertia and the mass do not belong to one "
          "body",
          where(), ms.inertia.empty() ? (ms.density > 0.0 ? "density" : "mass") : "inertia", rb.inertia[0],
          rb.inertia[1], rb.inertia[2], rb.mass, gyration, kLength.lo, kLength.hi));
  }
  rb.state.velocity = to_vec(ms.initial_velocity);
  rb.state.omega = to_vec(ms.angular_velocity);
  rb.rotation = ms.rotation == "hinge"        ? BodyRotation::Hinge
                : ms.rotation == "prescribed" ? BodyRotation::Prescribed
                                              : BodyRotation::Free;
  rb.axis = to_vec(ms.hinge_axis).normalized();
  rb.pivoted = ms.hinge_at_point;
  rb.pivot = to_vec(ms.hinge_point);
  for (char c : ms.fixed) rb.fixed |= static_cast<std::uint8_t>(1u << (c - 'x'));
  rb.load.force = to_vec(ms.force);
  rb.load.torque = to_vec(ms.torque);
  rb.load.force_damping = ms.damping;
  rb.load.spring = to_vec(ms.spring_stiffness);
  rb.load.anchor = rb.state.position;  // (the initial centre of mass)
  rb.load.holder_velocity = to_vec(ms.holder_velocity);
  rb.load.torque_damping = ms.torque_damping;
  // The mount is integrated with the particles' step, which knows nothing of it: its period
  // and its damper's time m/c must span enough steps to be stable and resolved (30 steps a
  // period puts Verlet's period error below 0.2 %), or the case is refused, not run wrong.
  const double h = d.implicit ? d.dt_max : d.dt;  // s: the largest step taken
  for (int c = 0; c < 3; ++c) {
    const double omega = std::sqrt(rb.load.spring[c] / rb.mass);  // rad/s
    if (omega * h > 2.0 * M_PI / 30.0)
      throw InputError(fmt::format(
          "{}: key 'spring_stiffness' = {} N/m along {}: the mount's period 2 pi sqrt(m/k) = {:.4g} s (mass {:.4g} kg) "
          "spans fewer than 30 steps of {:.4g} s: lower the stiffness or raise the mass",
          where(), rb.load.spring[c], char('x' + c), 2.0 * M_PI / omega, rb.mass, h));
  }
  if (rb.load.force_damping * h / rb.mass > 0.2)
    throw InputError(
        fmt::format("{}: key 'damping' = {} N s/m: the damper's time m/c = {:.4g} s spans fewer than 5 steps of "
                    "{:.4g} s: lower it or raise the mass",
                    where(), rb.load.force_damping, rb.mass / rb.load.force_damping, h));
  return rb;
}

// The [[mesh]] tables: from a file, a generated tool, a rectangle or a closed shape; with
// their motions, or moved as rigid bodies.
void build_meshes(const CaseSettings& cs, Model& model) {
  for (const auto& ms : cs.meshes) {
    MeshBody mb;
    mb.name = ms.name;
    if (!ms.file.empty()) {
      mb.mesh = read_mesh(ms.file, ms.scale);
      mb.mesh.name = ms.name;
      if (ms.tool_from_file) {  // its measured sharp tip to tool_tip (as a generated tool's to its origin)
        const Vec3 shift = to_vec(ms.tool_tip) - to_vec(ms.file_tip);
        for (auto& v : mb.mesh.vertices) v += shift;
      }
    } else if (ms.tool) {
      ToolSpec ts;
      ts.rake_angle_deg = ms.rake_angle;
      ts.clearance_angle_deg = ms.clearance_angle;
      ts.edge_radius = ms.edge_radius;
      ts.width = ms.width;
      ts.face_length = ms.face_length;
      try {
        mb.mesh = make_tool(ts);
      } catch (const InputError& e) {
        throw InputError(fmt::format("{}: [[mesh]] '{}': {}", cs.source, ms.name, e.what()));
      }
      mb.mesh.name = ms.name;
      const Vec3 o(ms.origin[0], ms.origin[1], ms.origin[2]);
      for (auto& v : mb.mesh.vertices) v += o;
    } else if (ms.box_size[0] > 0.0) {
      mb.mesh = box_mesh(to_vec(ms.origin), to_vec(ms.box_size));
      mb.mesh.name = ms.name;
    } else if (ms.cylinder_radius > 0.0) {
      mb.mesh = cylinder_mesh(to_vec(ms.origin), to_vec(ms.cylinder_axis), ms.cylinder_radius, ms.cylinder_length,
                              ms.cylinder_segments);
      mb.mesh.name = ms.name;
    } else {
      mb.mesh = rectangle_mesh(ms);
      mb.mesh.validate(cs.source + " [[mesh]] " + ms.name);
    }
    if (ms.dynamics == "rigid_body")
      model.bodies.push_back(rigid_body(cs, model.derived, ms, model.meshes.size(), mb.mesh));
    mb.youngs_modulus = ms.youngs_modulus;
    mb.poisson_ratio = ms.poisson_ratio;
    mb.parting.lead = ms.parting_lead;
    mb.parting.behind = std::isfinite(ms.parting_lead) ? ms.parting_lead : 0.0;
    model.meshes.push_back(std::move(mb));
    model.mesh_motion.push_back(motion_from(ms.motion));
  }
}

// The run's end and its output intervals: each a finite positive time, and no more rows or
// frames than a run can write (an interval below the time's rounding would never advance the
// next output time: 'next += interval' leaves it where it is).
void check_output_schedule(const CaseSettings& cs) {
  const double end = cs.integrator.end_time;
  if (!(end > 0.0 && std::isfinite(end)))
    throw InputError(fmt::format("{}: key 'integrator.end_time' = {} s must be a finite positive time", cs.source, end));
  constexpr double kMaxRows = 1e7, kMaxFrames = 1e5;
  const double si = cs.output.series_interval, fi = cs.output.frame_interval;
  if (si > 0.0 && !(end / si <= kMaxRows))
    throw InputError(
        fmt::format("{}: key 'output.series_interval' = {} s gives {:.3g} rows over end_time = {} s; at "
                    "most {:.0e}",
                    cs.source, si, end / si, end, kMaxRows));
  if (fi > 0.0 && !(end / fi <= kMaxFrames))
    throw InputError(
        fmt::format("{}: key 'output.frame_interval' = {} s gives {:.3g} frames over end_time = {} s; at "
                    "most {:.0e}",
                    cs.source, fi, end / fi, end, kMaxFrames));
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
