// simulation.cpp: the step function of both schemes, stage by stage (see simulation.h).
#include "swarf/simulation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "swarf/core/bounds.h"
#include "swarf/core/errors.h"
#include "swarf/core/parallel.h"
#include "swarf/forces/rod_forces.h"

namespace swarf {

Simulation::Simulation(World& world, const StepSettings& settings) : m_(world), set_(settings) {
  implicit_ = set_.implicit();
  dt_ = set_.dt;
  update_mesh_step_limit();
  if (!(dt_ > 0.0 && std::isfinite(dt_)) || (implicit_ && !(set_.dt_min > 0.0 && set_.dt_min <= set_.dt_max)))
    throw SimulationError(
        fmt::format("step settings: dt = {} s, dt_min = {} s, dt_max = {} s: the step must be a "
                    "finite positive time (and dt_min <= dt_max)",
                    dt_, set_.dt_min, set_.dt_max));
  if (set_.solver == Solver::Newton) {
    if (!implicit_) throw InputError("the Newton solver solves the implicit Newmark step: it needs scheme Newmark");
  }
  rods_.setup(m_);
  groups_.setup(m_.groups, m_.particles);
  bodies_.setup(m_, set_.solver == Solver::Newton);
  flows_.setup(m_);
  if (m_.contacts) {
    contact_force_.assign(m_.particles.size(), Vec3::Zero());
    contacts_.setup(m_.contact, m_.particles.size(), &m_.meshes, m_.periodic);
    if (m_.contact.law != FrictionLaw::None && m_.contact.friction > 0.0) rotations_ = true;
  }
  thermal_.setup(m_);
  plastic_.setup(m_, set_.plastic_strain_window);
  // Forces of the initial state (nothing committed: the first step re-evaluates them).
  rod_forces();
  contact_forces(dt_);
  gather();
  bodies_.init_accelerations(m_);
  bodies_.init_power(m_);
  if (rotations_) set_rotations(true);
  groups_.init_reactions(m_.groups, m_.particles);
  if (contacts_.enabled()) {
    contacts_.mesh_forces(mesh_force_);
    contact_power_old_ = contact_power();
  }
}

void Simulation::apply_flows(double h) {
  double out = 0.0, gross = 0.0;  // J
  if (const auto remove = flows_.outflow(m_, out, gross); !remove.empty()) {
    // (their rods' elastic energy leaves with them)
    const double elastic_before = m_.rods.size() > 0 ? elastic_energy() : 0.0;
    ledger_.heat_outflow += thermal_.carried(m_, remove);
    remove_particles(remove);
    const double elastic_after = m_.rods.size() > 0 ? elastic_energy() : 0.0;
    ledger_.flow_energy += out + (elastic_before - elastic_after);
    ledger_.flow_through += gross + std::abs(elastic_before - elastic_after);
  }
  if (const Particles add = flows_.inflow(m_, h, ledger_); !add.position.empty()) append_particles(add);
}

double Simulation::contact_power(bool from_kick) const {
  // Power of the contact forces on the particles (forces and torques) and on the meshes.
  const auto& p = m_.particles;
  const bool rot = rotations_;
  double power = from_kick ? kick_power_ : deterministic_sum(p.size(), [&](std::size_t i) {
    return contact_force_[i].dot(p.velocity[i]) + (rot ? p.torque[i].dot(p.omega[i]) : 0.0);
  });
  for (std::size_t k = 0; k < m_.meshes.size(); ++k) {
    if (const int b = bodies_.mesh_body(k); b >= 0) {  // (a body's: its force and torque, from the same evaluation)
      const RigidBody& rb = m_.bodies[b];
      power += rb.contact_force.dot(rb.state.velocity) + rb.contact_torque.dot(rb.state.omega);
    } else {
      power += mesh_force_[k].dot(m_.meshes[k].velocity);
    }
  }
  return power;
}

void Simulation::update_free_to_rotate() {
  // Rods act at the centres and are fixed to the particles (paper section 4.5): a bonded
  // particle turns with its body, not by itself; letting it spin would make it a free roller
  // under friction. Only particles without intact rods rotate.
  const auto& p = m_.particles;
  const auto& r = m_.rods;
  free_to_rotate_.assign(p.size(), 1);
  for (std::size_t k = 0; k < r.size(); ++k)
    if (r.intact[k]) free_to_rotate_[r.ends[k][0]] = free_to_rotate_[r.ends[k][1]] = 0;
  rebuild_free_list();
}

void Simulation::rebuild_free_list() {
  free_list_.clear();
  for (std::size_t i = 0; i < free_to_rotate_.size(); ++i)
    if (free_to_rotate_[i]) free_list_.push_back(static_cast<std::int32_t>(i));
}

void Simulation::update_free_to_rotate(const std::vector<std::array<std::int32_t, 2>>& pairs) {
  // The same flags as the whole pass gives, from the rows of the particles whose rods changed.
  const auto& r = m_.rods;
  bool changed = false;
  for (const auto& e : pairs)
    for (const std::int32_t i : e) {
      std::uint8_t free = 1;
      for (std::int32_t q = r.row_start[i]; q < r.row_start[i + 1] && free; ++q)
        if (r.intact[r.entries[q].rod]) free = 0;
      changed = changed || free != free_to_rotate_[i];
      free_to_rotate_[i] = free;
    }
  if (changed) rebuild_free_list();
}

void Simulation::set_rotations(bool on) {
  rotations_ = on;
  if (!on) return;
  update_free_to_rotate();
  auto& p = m_.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Quat& q = p.orientation[i];
    p.omega_dot[i] = to_world(q, euler_acceleration(to_body(q, p.torque[i]), to_body(q, p.omega[i]), p.inertia[i]));
  }
}

void Simulation::step(double max_dt) {
  for (StepListener* l : listeners_) l->before_step(*this);
  step_scheme(max_dt);
  if (!m_.inflows.empty() || !m_.outflows.empty()) apply_flows(last_dt_);
  for (StepListener* l : listeners_) l->after_step(*this);
}

void Simulation::step_scheme(double max_dt) {
  if (!implicit_) {
    step_explicit();
    return;
  }
  const StepSettings& g = set_;
  clock_.start();  // the state save and restores after rejected tries count as 'prescribe'
  save_state();
  while (true) {
    const double h = std::min(dt_, max_dt);
    const bool newton = g.solver == Solver::Newton;
    if (newton ? try_newton(h) : try_newmark(h)) {
      commit(h);
      clock_.lap(Stage::Commit);
      account(h);
      clock_.lap(Stage::Account);
      // Step size control from the number of sweeps (paper section 3.4), or of Newton
      // iterations; a Newton step whose linear solve hit krylov_max_iterations does not grow
      // (its CG iterations grow with h / dt_stable) and shrinks the next one.
      const int it = stats_.last_iterations;
      const bool capped = newton && newton_stats_.last_capped;
      if (it <= g.iterations_grow && !capped)
        dt_ = std::min(dt_ * g.grow_factor, g.dt_max);
      else if (it >= g.iterations_shrink || capped)
        dt_ = std::max(dt_ * g.shrink_factor, g.dt_min);
      return;
    }
    restore_state();
    ++stats_.rejected;
    dt_ = h * g.reject_factor;
    if (!(dt_ >= g.dt_min) && mesh_rejected_)
      bodies_.throw_mesh_too_far(m_, time_, h, stats_.accepted + 1, set_.max_step_displacement);
    if (!(dt_ >= g.dt_min))  // (a NaN step too: it is never below dt_min)
      throw SimulationError(fmt::format(
          "the Newmark step did not converge at t = {:.6g} s with dt = {:.4g} s, and the next try ({:.4g} s) "
          "would be below dt_min = {:.4g} s (integrator.dt_min); {} sweeps allowed (integrator.max_iterations), "
          "tolerance {}",
          time_, h, dt_, g.dt_min, g.max_iterations, g.tolerance));
  }
}

void Simulation::step_explicit() {
  const double h = dt_;
  clock_.start();
  if (!prescribe(h)) bodies_.throw_mesh_too_far(m_, time_, h, stats_.accepted + 1, set_.max_step_displacement);
  if (!m_.bodies.empty() && !bodies_.drift(m_, time_, h))
    throw SimulationError(fmt::format(
        "a rigid body moves more than integrator.max_step_displacement = {} radii of the smallest particle in "
        "step {} at t = {:.6g} s (dt = {:.4g} s): lower the step",
        set_.max_step_displacement, stats_.accepted + 1, time_, h));
  clock_.lap(Stage::Prescribe);
  if (!kick_drift(h)) throw_too_far(h);
  clock_.lap(Stage::Integrate);
  rod_forces();
  clock_.lap(Stage::Rods);
  contact_forces(h, true);
  gather_kick(h);  // (rotations included: the explicit update needs only this step's torque)
  clock_.lap(Stage::Gather);
  commit(h);
  clock_.lap(Stage::Commit);
  account(h);
  clock_.lap(Stage::Account);
  stats_.last_iterations = 1;
  stats_.iterations += 1;
  stats_.max_iterations = 1;
}

bool Simulation::try_newmark(double h) {
  const StepSettings& g = set_;
  mesh_rejected_ = !prescribe(h);
  if (mesh_rejected_) return false;  // (a mesh would move too far: a shorter step)
  clock_.lap(Stage::Prescribe);
  int it = 0, growing = 0;
  bool converged = false;
  double previous = HUGE_VAL;
  // Relaxation w < 1: the next sweep places with (1 - w) a_guess + w a_swept. The sweep maps
  // a guess to new accelerations with eigenvalues in [-(dt/dt_stable)^2, 0] (docs/physics.md
  // section 7); relaxed, they become 1 - w + w lambda: at dt_max (0.8 dt_stable, L = 0.64 the
  // spectrum's extent) the contraction per sweep drops from 0.64 to 0.25 with w = 0.75 (optimal:
  // w = 2 / (2 + L)), and the iteration converges up to dt/dt_stable = sqrt(2/w - 1).
  const double w = g.relaxation;
  auto& acc = m_.particles.acceleration;
  for (it = 1; it <= g.max_iterations; ++it) {
    if (w != 1.0 && it == 1) a_guess_ = acc;  // (later sweeps: the blend below)
    if (!place(h)) return false;
    clock_.lap(Stage::Integrate);
    rod_forces();
    clock_.lap(Stage::Rods);
    contact_forces(h);
    const double change = gather();
    clock_.lap(Stage::Gather);
    if (!std::isfinite(change)) return false;
    if (change <= g.tolerance) {
      converged = true;
      break;
    }
    // A contraction shrinks the change every sweep; two growing sweeps in a row mean the
    // step is beyond the fixed-point limit: give up early instead of sweeping on.
    // (Changes within a decade of the tolerance may fluctuate at the rounding level.)
    growing = change > previous && change > 10.0 * g.tolerance ? growing + 1 : 0;
    if (growing >= 2) return false;
    previous = change;
    if (w != 1.0) {
      const std::size_t n = acc.size();
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < n; ++i) acc[i] = a_guess_[i] = (1.0 - w) * a_guess_[i] + w * acc[i];
    }
  }
  if (!converged) return false;
  if (!place(h)) return false;  // x+, v+ (and rotations) from the converged accelerations
  clock_.lap(Stage::Integrate);
  stats_.last_iterations = it;
  stats_.iterations += it;
  stats_.max_iterations = std::max(stats_.max_iterations, it);
  return true;
}

void Simulation::contact_forces(double h, bool final) {
  if (!contacts_.enabled()) return;
  clock_.lap(Stage::Rods);  // (no-op when called outside a timed step)
  contacts_.update_lists(m_.particles, m_.rods, rebuild_lists_, moved2_);
  rebuild_lists_ = false;
  moved2_ = -1.0;
  clock_.lap(Stage::Lists);
  contacts_.evaluate(m_.particles, h, final);
  clock_.lap(Stage::Contacts);
}

void Simulation::update_mesh_step_limit() {
  double rmin = HUGE_VAL;
  for (double r : m_.particles.radius) rmin = std::min(rmin, r);
  bodies_.set_step_limit(set_.max_step_displacement * rmin);
}

bool Simulation::prescribe(double h) {
  const StepContext c = context(h);
  bool within = true;
  for_each_system([&](auto& s) {
    if constexpr (requires { s.prescribe(c); }) within = s.prescribe(c) && within;
  });
  return within;
}

double Simulation::ghost_reach() const {
  double reach = contacts_.enabled() ? contacts_.ghost_reach(m_.particles) : 0.0;
  auto& self = const_cast<Simulation&>(*this);  // (systems() ties the members; nothing is changed)
  self.for_each_system([&](const auto& s) { reach = std::max(reach, s.ghost_reach(m_)); });
  return reach;
}

bool Simulation::kick_drift(double h) {
  auto& p = m_.particles;
  const double half = 0.5 * h;
  const double limit2 = std::pow(set_.max_step_displacement, 2);
  const std::size_t n = p.size();
  // The displacement since the contact lists' build, measured here instead of in a pass of its own.
  const Vec3* xb = contacts_.enabled() ? contacts_.build_positions(n) : nullptr;
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
  moved2_ = xb ? moved2 : -1.0;
  return bad == 0;
}

void Simulation::rotate_one(std::size_t i, double h, double beta, double gamma) {
  auto& p = m_.particles;
  // Start-of-step state (world frame): saved for Newmark, current for the explicit scheme.
  const RotState s = implicit_ ? rot_n_[i] : RotState{p.orientation[i], p.omega[i], p.omega_dot[i]};
  if (p.inv_inertia[i] > 0.0) {  // isotropic inertia: a sphere
    Quat q = s.q;
    Vec3 w = s.w, dw = s.dw;
    sphere_rotation_step(q, w, dw, p.torque[i], p.inv_inertia[i], h, gamma, set_.sphere_orientations);
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

bool Simulation::place(double h) {
  auto& p = m_.particles;
  const StepSettings& g = set_;
  const double cx_n = h * h * (0.5 - g.beta), cx = h * h * g.beta;
  const double cv_n = h * (1.0 - g.gamma), cv = h * g.gamma;
  const double limit2 = std::pow(g.max_step_displacement, 2);
  const std::size_t n = p.size();
  int bad = 0;
  double disp2 = 0.0, moved2 = 0.0;
  sweep_dt_ = h;
  const Vec3* xb = contacts_.enabled() ? contacts_.build_positions(n) : nullptr;
  const std::size_t nfree = rotations_ ? free_list_.size() : 0;
  const double beta = g.beta, gamma = g.gamma;
  // Raw pointers in locals (Eigen's vector stores may alias the containers' bases).
  Vec3* pos = p.position.data();
  Vec3* vel = p.velocity.data();
  const Vec3* acc = p.acceleration.data();
  const Vec3 *x_n = x_n_.data(), *v_n = v_n_.data(), *a_n = a_n_.data();
  const double* radius = p.radius.data();
  const std::uint8_t* prescribed = p.prescribed.data();
  // The rotations have a loop of their own over the free particles: they cluster (the chip's
  // loose particles), and in the positions' partition one thread would get them all.
#pragma omp parallel reduction(max : bad, disp2, moved2)
  {
#pragma omp for schedule(static) nowait
    for (std::size_t f = 0; f < nfree; ++f) rotate_one(free_list_[f], h, beta, gamma);
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
  step_disp2_ = disp2;
  moved2_ = xb ? moved2 : -1.0;
  const bool bodies_within = m_.bodies.empty() || bodies_.place(m_, time_, h, g.beta, g.gamma);
  return bad == 0 && bodies_within;
}

void Simulation::rod_forces() {
  ++stats_.force_evaluations;
  rods_.forces(m_);
}

void Simulation::commit(double h) {
  const bool heat = thermal_.enabled(), peeq = plastic_.enabled();
  const RodSystem::PairList broke = rods_.commit(m_, ledger_, heat || peeq ? &rod_work_ : nullptr);
  if (heat) thermal_.heat(context(h), contacts_, rod_work_);
  if (peeq) plastic_.accumulate(m_, rod_work_, h);  // (before bond formation: the rods' ends as they flowed)
  const bool contacts = contacts_.enabled();
  if (contacts && implicit_) contacts_.commit();  // explicit: committed by the final evaluation
  // The broken rods' pairs join the contact lists as they are: a full rebuild for each break
  // is far dearer (validation/bench/README.md).
  if (contacts && !broke.empty()) contacts_.add_pairs(m_.particles, broke);
  if (rotations_ && !broke.empty()) update_free_to_rotate(broke);
  if (contacts && m_.rods.formation.enabled()) {
    const RodSystem::PairList touched = rods_.form(m_, contacts_, ledger_);
    if (rotations_ && !touched.empty()) update_free_to_rotate(touched);
  }
}

void Simulation::account(double h) {
  const StepContext c = context(h);
  for_each_system([&](auto& s) {
    if constexpr (requires { s.account(c); }) s.account(c);
  });
  // Moving meshes (tools) work on the particles: minus the force the particles exert on the
  // mesh times its displacement (trapezoid over the step).
  if (contacts_.enabled()) {
    std::vector<Vec3> previous;
    previous.swap(mesh_force_);
    contacts_.mesh_forces(mesh_force_);
    for (std::size_t k = 0; k < m_.meshes.size(); ++k)
      if (bodies_.mesh_body(k) < 0)  // (a body's mesh is moved by the contacts, not by a prescription)
        ledger_.external_work -= 0.5 * (previous[k] + mesh_force_[k]).dot(m_.meshes[k].velocity * h);
    // What the contacts take up (stored + dissipated): minus the power of their forces,
    // trapezoid over the step.
    const double power = contact_power(!implicit_);
    ledger_.contact_work -= 0.5 * (contact_power_old_ + power) * h;
    contact_power_old_ = power;
  }
  time_ += h;
  last_dt_ = h;
  ++stats_.accepted;
}

void Simulation::save_state() {
  // In parallel with the placement's partition: each thread copies the particles it will
  // place, so the saved state is in its own core's cache for every sweep of the step.
  const auto& p = m_.particles;
  const std::size_t n = p.size();
  x_n_.resize(n);
  v_n_.resize(n);
  a_n_.resize(n);
  f_n_.resize(n);
  const bool rot = rotations_;
  if (rot) rot_n_.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    x_n_[i] = p.position[i];
    v_n_[i] = p.velocity[i];
    a_n_[i] = p.acceleration[i];
    f_n_[i] = p.force[i];
    if (rot) rot_n_[i] = RotState{p.orientation[i], p.omega[i], p.omega_dot[i]};
  }
  if (!m_.bodies.empty()) bodies_.save(m_);
  if (set_.solver == Solver::Newton) {
    // The rods' trial fields too: a rejected Newton try then leaves the state hash as it was
    // (the fixed-point solver leaves the failed try's trial values, which no step reads).
    const auto& r = m_.rods;
    nk_.trial_shift = r.trial_shift;
    nk_.trial_broken = r.trial_broken;
    nk_.stress = r.stress;
    nk_.coef = r.force_coef;
  }
}

void Simulation::restore_state() {
  auto& p = m_.particles;
  p.position = x_n_;
  p.velocity = v_n_;
  p.acceleration = a_n_;
  p.force = f_n_;
  if (!m_.bodies.empty()) bodies_.restore(m_, time_);
  if (set_.solver == Solver::Newton) {
    auto& r = m_.rods;
    r.trial_shift = nk_.trial_shift;
    r.trial_broken = nk_.trial_broken;
    r.stress = nk_.stress;
    r.force_coef = nk_.coef;
  }
  if (rotations_)
    for (std::size_t i = 0; i < p.size(); ++i) {
      p.orientation[i] = rot_n_[i].q;
      p.omega[i] = rot_n_[i].w;
      p.omega_dot[i] = rot_n_[i].dw;
    }
}

void Simulation::throw_too_far(double h) const {
  const auto& p = m_.particles;
  const double limit = set_.max_step_displacement;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 v = p.velocity[i];
    const double moved = v.norm() * h / p.radius[i];
    if (!(moved <= limit) || !all_finite(p.position[i]))
      throw SimulationError(fmt::format(
          "unstable: particle {} (at {:.6g}, {:.6g}, {:.6g} m) moved {:.3g} radii in step {} at t = {:.6g} s "
          "(limit integrator.max_step_displacement = {}); speed {:.4g} m/s. The step dt = {:.4g} s may be "
          "too large for the loads, or the input drives the lattice too hard",
          i, p.position[i][0], p.position[i][1], p.position[i][2], moved, stats_.accepted + 1, time_ + h, limit,
          v.norm(), h));
  }
  throw SimulationError(
      fmt::format("unstable: non-finite state in step {} at t = {:.6g} s", stats_.accepted + 1, time_ + h));
}

double Simulation::kinetic_energy() const {
  const auto& p = m_.particles;
  const bool rot = rotations_;
  return deterministic_sum(p.size(), [&](std::size_t i) { return 0.5 * p.mass[i] * p.velocity[i].squaredNorm(); }) +
         (rot ? rotational_energy() : 0.0) + body_kinetic_energy();
}

double Simulation::rotational_energy() const {
  if (!rotations_) return 0.0;
  const auto& p = m_.particles;
  return deterministic_sum(p.size(), [&](std::size_t i) {
    const Vec3 wb = to_body(p.orientation[i], p.omega[i]);
    return 0.5 * wb.dot(p.inertia[i].cwiseProduct(wb));
  });
}

double Simulation::elastic_energy() const { return rods_.elastic_energy(m_); }

double Simulation::potential_energy() const {
  const auto& p = m_.particles;
  const Vec3 g = m_.gravity;
  if (g.squaredNorm() == 0.0) return 0.0;
  const double bodies = bodies_.potential_energy(m_);
  return deterministic_sum(p.size(),
                           [&](std::size_t i) { return -p.mass[i] * g.dot(p.position[i] - p.initial_position[i]); }) +
         bodies;
}

}  // namespace swarf
