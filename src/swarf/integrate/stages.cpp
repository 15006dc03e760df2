// stages.cpp: the stages both schemes are made of (see integration.h), as free functions over an
// Integration: the systems' common stages, the particles' placement, the commit and the account.
#include <algorithm>
#include <cmath>

#include "swarf/core/parallel.h"
#include "swarf/integrate/integration.h"

namespace swarf::integrate {

namespace {

void rebuild_free_list(MotionState& ms) {
  ms.free_list.clear();
  for (std::size_t i = 0; i < ms.free_to_rotate.size(); ++i)
    if (ms.free_to_rotate[i]) ms.free_list.push_back(static_cast<std::int32_t>(i));
}

}  // namespace

double contact_power(const Integration& it, bool from_kick) {
  const World& world = it.world;
  const MotionState& ms = it.ms;
  // Power of the contact forces on the particles (forces and torques) and on the meshes.
  const auto& p = world.particles;
  const bool rot = ms.rotations;
  double power = from_kick ? ms.kick_power : deterministic_sum(p.size(), [&](std::size_t i) {
    return ms.contact_force[i].dot(p.velocity[i]) + (rot ? p.torque[i].dot(p.omega[i]) : 0.0);
  });
  for (std::size_t k = 0; k < world.meshes.size(); ++k) {
    if (const int b = it.sys.bodies.mesh_body(k);
        b >= 0) {  // (a body's: its force and torque, from the same evaluation)
      const RigidBody& rb = world.bodies[b];
      power += rb.contact_force.dot(rb.state.velocity) + rb.contact_torque.dot(rb.state.omega);
    } else {
      power += ms.mesh_force[k].dot(world.meshes[k].velocity);
    }
  }
  return power;
}

void update_free_to_rotate(const World& world, MotionState& ms) {
  // Rods act at the centres and are fixed to the particles (paper section 4.5): a bonded
  // particle turns with its body, not by itself; letting it spin would make it a free roller
  // under friction. Only particles without intact rods rotate.
  const auto& p = world.particles;
  const auto& r = world.rods;
  ms.free_to_rotate.assign(p.size(), 1);
  for (std::size_t k = 0; k < r.size(); ++k)
    if (r.intact[k]) ms.free_to_rotate[r.ends[k][0]] = ms.free_to_rotate[r.ends[k][1]] = 0;
  rebuild_free_list(ms);
}

void update_free_to_rotate(const World& world, MotionState& ms, const std::vector<std::array<std::int32_t, 2>>& pairs) {
  // The same flags as the whole pass gives, from the rows of the particles whose rods changed.
  const auto& r = world.rods;
  bool changed = false;
  for (const auto& e : pairs)
    for (const std::int32_t i : e) {
      std::uint8_t free = 1;
      for (std::int32_t q = r.row_start[i]; q < r.row_start[i + 1] && free; ++q)
        if (r.intact[r.entries[q].rod]) free = 0;
      changed = changed || free != ms.free_to_rotate[i];
      ms.free_to_rotate[i] = free;
    }
  if (changed) rebuild_free_list(ms);
}

void contact_forces(Integration& it, double h, bool final) {
  World& world = it.world;
  MotionState& ms = it.ms;
  if (!it.sys.contacts.enabled()) return;
  it.clock.lap(Stage::Rods);  // (no-op when called outside a timed step)
  it.sys.contacts.update_lists(world.particles, world.rods, ms.rebuild_lists, ms.moved2);
  ms.rebuild_lists = false;
  ms.moved2 = -1.0;
  it.clock.lap(Stage::Lists);
  it.sys.contacts.evaluate(world.particles, h, final);
  it.clock.lap(Stage::Contacts);
}

bool prescribe(Integration& it, double h) {
  const StepContext c = it.context(h);
  bool within = true;
  it.sys.for_each([&](auto& s) {
    if constexpr (requires { s.prescribe(c); }) within = s.prescribe(c) && within;
  });
  return within;
}

bool kick_drift(Integration& it, double h) {
  World& world = it.world;
  MotionState& ms = it.ms;
  auto& p = world.particles;
  const double half = 0.5 * h;
  const double limit2 = std::pow(it.set.max_step_displacement, 2);
  const std::size_t n = p.size();
  // The displacement since the contact lists' build, measured here instead of in a pass of its own.
  const Vec3* xb = it.sys.contacts.enabled() ? it.sys.contacts.build_positions(n) : nullptr;
  int bad = 0;
  double moved2 = 0.0;
  // Raw pointers in locals (Eigen's vector stores may alias the containers' bases).
  Vec3* x = p.position.data();
  Vec3* v = p.velocity.data();
  const Vec3* a = p.acceleration.data();
  const double* radius = p.radius.data();
  const std::uint8_t* prescribed = p.prescribed.data();
#pragma omp parallel for schedule(static) reduction(max : bad, moved2)
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t mask = prescribed[i];
    Vec3 dx = Vec3::Zero();
    if (mask == 0) {
      v[i] += half * a[i];
      dx = h * v[i];
      x[i] += dx;
    } else {
      for (int c = 0; c < 3; ++c) {
        if (mask & (1u << c)) continue;
        v[i][c] += half * a[i][c];
        dx[c] = h * v[i][c];
        x[i][c] += dx[c];
      }
    }
    if (!(dx.squaredNorm() <= limit2 * radius[i] * radius[i])) bad = 1;  // also catches NaN
    if (xb) moved2 = std::max(moved2, (x[i] - xb[i]).squaredNorm());
  }
  ms.moved2 = xb ? moved2 : -1.0;
  return bad == 0;
}

void rotate_one(Integration& it, std::size_t i, double h, double beta, double gamma) {
  World& world = it.world;
  MotionState& ms = it.ms;
  auto& p = world.particles;
  // Start-of-step state (world frame): saved for Newmark, current for the explicit scheme.
  const RotState s = it.implicit ? ms.rot_n[i] : RotState{p.orientation[i], p.omega[i], p.omega_dot[i]};
  if (p.inv_inertia[i] > 0.0) {  // isotropic inertia: a sphere
    Quat q = s.q;
    Vec3 w = s.w, dw = s.dw;
    sphere_rotation_step(q, w, dw, p.torque[i], p.inv_inertia[i], h, gamma, it.set.sphere_orientations);
    p.orientation[i] = q;
    p.omega[i] = w;
    p.omega_dot[i] = dw;
  } else {
    // Euler's equations live in the body frame.
    RotationSettings rs;
    rs.beta = beta;
    rs.gamma = gamma;
    const RotState body{s.q, to_body(s.q, s.w), to_body(s.q, s.dw)};
    const RotStepResult r = rotation_step(body, p.torque[i], p.inertia[i], h, rs);
    p.orientation[i] = r.state.q;
    p.omega[i] = to_world(r.state.q, r.state.w);
    p.omega_dot[i] = to_world(r.state.q, r.state.dw);
  }
}

bool place(Integration& it, double h) {
  World& world = it.world;
  MotionState& ms = it.ms;
  auto& p = world.particles;
  const StepSettings& g = it.set;
  const double cx_n = h * h * (0.5 - g.beta), cx = h * h * g.beta;
  const double cv_n = h * (1.0 - g.gamma), cv = h * g.gamma;
  const double limit2 = std::pow(g.max_step_displacement, 2);
  const std::size_t n = p.size();
  int bad = 0;
  double disp2 = 0.0, moved2 = 0.0;
  ms.sweep_dt = h;
  const Vec3* xb = it.sys.contacts.enabled() ? it.sys.contacts.build_positions(n) : nullptr;
  const std::size_t nfree = ms.rotations ? ms.free_list.size() : 0;
  const double beta = g.beta, gamma = g.gamma;
  // Raw pointers in locals (Eigen's vector stores may alias the containers' bases).
  Vec3* pos = p.position.data();
  Vec3* vel = p.velocity.data();
  const Vec3* acc = p.acceleration.data();
  const Vec3 *x_n = ms.x_n.data(), *v_n = ms.v_n.data(), *a_n = ms.a_n.data();
  const double* radius = p.radius.data();
  const std::uint8_t* prescribed = p.prescribed.data();
  // The rotations have a loop of their own over the free particles: they cluster (the chip's
  // loose particles), and in the positions' partition one thread would get them all.
#pragma omp parallel reduction(max : bad, disp2, moved2)
  {
#pragma omp for schedule(static) nowait
    for (std::size_t f = 0; f < nfree; ++f) rotate_one(it, ms.free_list[f], h, beta, gamma);
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint8_t mask = prescribed[i];
      const Vec3 x = x_n[i] + h * v_n[i] + cx_n * a_n[i] + cx * acc[i];
      const Vec3 v = v_n[i] + cv_n * a_n[i] + cv * acc[i];
      if (mask == 0) {
        pos[i] = x;
        vel[i] = v;
      } else {
        for (int c = 0; c < 3; ++c)
          if (!(mask & (1u << c))) {
            pos[i][c] = x[c];
            vel[i][c] = v[c];
          }
      }
      const double dx2 = (pos[i] - x_n[i]).squaredNorm();
      disp2 = std::max(disp2, dx2);
      if (!(dx2 <= limit2 * radius[i] * radius[i])) bad = 1;
      if (xb) moved2 = std::max(moved2, (pos[i] - xb[i]).squaredNorm());
    }
  }
  ms.step_disp2 = disp2;
  ms.moved2 = xb ? moved2 : -1.0;
  const bool bodies_within = world.bodies.empty() || it.sys.bodies.place(world, it.t, h, g.beta, g.gamma);
  return bad == 0 && bodies_within;
}

void rod_forces(Integration& it, bool lagged_rate) {
  World& world = it.world;
  ++it.stats.force_evaluations;
  if (lagged_rate)
    it.sys.rods.forces(world, it.ms.x_n.data(), it.ms.v_n.data());
  else
    it.sys.rods.forces(world);
}

void commit(Integration& it, double h) {
  World& world = it.world;
  MotionState& ms = it.ms;
  const bool heat = it.sys.thermal.enabled(), peeq = it.sys.plastic.enabled();
  const RodSystem::PairList broke = it.sys.rods.commit(world, it.ledger, heat || peeq ? &ms.rod_work : nullptr);
  if (heat) it.sys.thermal.heat(it.context(h), it.sys.contacts, ms.rod_work);
  if (peeq) it.sys.plastic.accumulate(world, ms.rod_work, h);  // (before bond formation: the rods' ends as they flowed)
  const bool contacts = it.sys.contacts.enabled();
  if (contacts && it.implicit) it.sys.contacts.commit();  // explicit: committed by the final evaluation
  // The broken rods' pairs join the contact lists as they are: a full rebuild for each break
  // is far dearer (validation/bench/README.md).
  if (contacts && !broke.empty()) it.sys.contacts.add_pairs(world.particles, broke);
  if (ms.rotations && !broke.empty()) update_free_to_rotate(world, ms, broke);
  if (contacts && world.rods.formation.enabled()) {
    const RodSystem::PairList touched = it.sys.rods.form(world, it.sys.contacts, it.ledger);
    if (ms.rotations && !touched.empty()) update_free_to_rotate(world, ms, touched);
  }
}

void account(Integration& it, double h) {
  World& world = it.world;
  MotionState& ms = it.ms;
  const StepContext c = it.context(h);
  it.sys.for_each([&](auto& s) {
    if constexpr (requires { s.account(c); }) s.account(c);
  });
  // Moving meshes (tools) work on the particles: minus the force the particles exert on the
  // mesh times its displacement (trapezoid over the step).
  if (it.sys.contacts.enabled()) {
    std::vector<Vec3> previous;
    previous.swap(ms.mesh_force);
    it.sys.contacts.mesh_forces(ms.mesh_force);
    for (std::size_t k = 0; k < world.meshes.size(); ++k)
      if (it.sys.bodies.mesh_body(k) < 0)  // (a body's mesh is moved by the contacts, not by a prescription)
        it.ledger.external_work -= 0.5 * (previous[k] + ms.mesh_force[k]).dot(world.meshes[k].velocity * h);
    // What the contacts take up (stored + dissipated): minus the power of their forces,
    // trapezoid over the step.
    const double power = contact_power(it, !it.implicit);
    it.ledger.contact_work -= 0.5 * (ms.contact_power_old + power) * h;
    ms.contact_power_old = power;
  }
}

void save_state(Integration& it) {
  World& world = it.world;
  MotionState& ms = it.ms;
  // In parallel with the placement's partition: each thread copies the particles it will
  // place, so the saved state is in its own core's cache for every sweep of the step.
  const auto& p = world.particles;
  const std::size_t n = p.size();
  ms.x_n.resize(n);
  ms.v_n.resize(n);
  ms.a_n.resize(n);
  ms.f_n.resize(n);
  const bool rot = ms.rotations;
  if (rot) ms.rot_n.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    ms.x_n[i] = p.position[i];
    ms.v_n[i] = p.velocity[i];
    ms.a_n[i] = p.acceleration[i];
    ms.f_n[i] = p.force[i];
    if (rot) ms.rot_n[i] = RotState{p.orientation[i], p.omega[i], p.omega_dot[i]};
  }
  if (!world.bodies.empty()) it.sys.bodies.save(world);
  if (it.set.solver == Solver::Newton) {
    // The rods' trial fields too: a rejected Newton try then leaves the state hash as it was
    // (the fixed-point solver leaves the failed try's trial values, which no step reads).
    const auto& r = world.rods;
    ms.newton.trial_shift = r.trial_shift;
    ms.newton.trial_broken = r.trial_broken;
    ms.newton.stress = r.stress;
    ms.newton.coef = r.force_coef;
  }
}

void restore_state(Integration& it) {
  World& world = it.world;
  MotionState& ms = it.ms;
  auto& p = world.particles;
  p.position = ms.x_n;
  p.velocity = ms.v_n;
  p.acceleration = ms.a_n;
  p.force = ms.f_n;
  if (!world.bodies.empty()) it.sys.bodies.restore(world, it.t);
  if (it.set.solver == Solver::Newton) {
    auto& r = world.rods;
    r.trial_shift = ms.newton.trial_shift;
    r.trial_broken = ms.newton.trial_broken;
    r.stress = ms.newton.stress;
    r.force_coef = ms.newton.coef;
  }
  if (ms.rotations)
    for (std::size_t i = 0; i < p.size(); ++i) {
      p.orientation[i] = ms.rot_n[i].q;
      p.omega[i] = ms.rot_n[i].w;
      p.omega_dot[i] = ms.rot_n[i].dw;
    }
}

}  // namespace swarf::integrate
