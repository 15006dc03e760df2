// body_system.cpp: the rigid bodies' part of the step (state/rigid_body.h): their
// wrench from the contacts, loads and gravity; their translation and rotation by the step's
// scheme; their meshes placed from their poses; the prescribed meshes' motions (see
// body_system.h and integrate/integration.h for the stages).
//
// Newmark: the bodies take part in the fixed point like particles. place() puts each body at
// x+ = x + h v + h^2 ((1/2 - beta) a + beta a+), with a+ from the latest wrench, and turns
// it by the quaternion Newmark update (rotation_step, with its inner loop) under the latest
// torque; gather() sums the new wrench and adds the change of force and torque to the
// sweep's convergence measure. A rejected step restores them with the particles.
// Verlet: the drift (v += h/2 a, x += h v; q+ from the beta = 0 update, which needs only the
// start of the step) before the contacts, the kick (v += h/2 a+, the angular velocity from the
// same update under the new torque) after them. Loads linear in the velocities see the
// drift's predicted velocities v + h a (for the hinge's damper: Heun's explicit trapezoid).
// A hinge integrates the angle about its fixed axis as a scalar with the same scheme, with
// I_axis and the torque's axial part, and builds q from the angle, so the axis holds exactly;
// a pivoted hinge places the centre of mass on its circle about the axis from the same angle.
#include "swarf/systems/body_system.h"

#include <fmt/format.h>

#include <cmath>

#include "swarf/contacts/contacts.h"
#include "swarf/core/bounds.h"
#include "swarf/core/errors.h"
#include "swarf/core/state_archive.h"
#include "swarf/laws/rotation.h"

namespace swarf {

namespace {

// Rotation by 'angle' (rad) about the unit 'axis'.
Quat axis_turn(const Vec3& axis, double angle) {
  const double s = std::sin(0.5 * angle);
  return Quat(std::cos(0.5 * angle), s * axis[0], s * axis[1], s * axis[2]);
}

// Free components only: the held ones keep their velocity and get no acceleration.
Vec3 masked(Vec3 a, std::uint8_t fixed) {
  for (int c = 0; c < 3; ++c)
    if (fixed & (1u << c)) a[c] = 0.0;
  return a;
}

}  // namespace

void BodySystem::setup(World& m_, bool newton) {
  mesh_body_.assign(m_.meshes.size(), -1);
  body_x0_.clear();
  for (std::size_t b = 0; b < m_.bodies.size(); ++b) {
    RigidBody& rb = m_.bodies[b];
    if (rb.mesh >= m_.meshes.size())
      throw InputError(fmt::format("rigid body {} names mesh {} of {}", b, rb.mesh, m_.meshes.size()));
    const std::string& name = m_.meshes[rb.mesh].name;
    if (mesh_body_[rb.mesh] >= 0) throw InputError(fmt::format("mesh '{}' is moved by two rigid bodies", name));
    mesh_body_[rb.mesh] = static_cast<int>(b);
    if (!(rb.mass > 0.0 && std::isfinite(rb.mass)) || !(rb.inertia.minCoeff() > 0.0) || !all_finite(rb.inertia))
      throw InputError(
          fmt::format("rigid body '{}': mass {} kg and principal inertia ({}, {}, {}) kg m^2 must be "
                      "positive and finite",
                      name, rb.mass, rb.inertia[0], rb.inertia[1], rb.inertia[2]));
    if (newton)
      throw InputError(
          fmt::format("rigid body '{}': the Newton solver's tangent treats meshes as prescribed; "
                      "use the fixed-point solver with rigid bodies",
                      name));
    BodyState& s = rb.state;
    s.orientation /= s.orientation.norm();
    if (rb.pivoted && (rb.rotation != BodyRotation::Hinge || rb.fixed != 0))
      throw InputError(
          fmt::format("rigid body '{}': a pivot needs a hinge and no held components (the centre "
                      "of mass turns about the axis)",
                      name));
    if (rb.rotation == BodyRotation::Hinge) {
      rb.axis.normalize();
      if (!((s.omega - s.omega.dot(rb.axis) * rb.axis).norm() <= 1e-12 * s.omega.norm()))
        throw InputError(fmt::format("rigid body '{}': its angular velocity must lie along the hinge axis", name));
    } else if (rb.rotation == BodyRotation::Prescribed) {
      // Turns at its initial angular velocity: a hinge without angular acceleration.
      rb.axis = s.omega.norm() > 0.0 ? Vec3(s.omega.normalized()) : Vec3::UnitZ();
    }
    rb.hinge_start = qmul(axis_turn(rb.axis, -s.angle), s.orientation);
    if (rb.pivoted) {  // (the velocity follows from the turn: what was given for it is replaced)
      const Vec3 r = s.position - rb.pivot;
      rb.pivot_arm = to_world(axis_turn(rb.axis, -s.angle), r);
      s.velocity = s.omega.cross(r);
    }
    body_x0_.push_back(s.position);
    place_mesh(m_, b);
  }
}

void BodySystem::place_mesh(World& m_, std::size_t b) {
  const RigidBody& rb = m_.bodies[b];
  MeshBody& mb = m_.meshes[rb.mesh];
  mb.turns = true;
  mb.pivot = rb.centre_ref;
  mb.offset = rb.state.position - rb.centre_ref;
  mb.turn = qmul(rb.state.orientation, qconj(rb.principal));  // reference frame -> world
  mb.velocity = rb.state.velocity;
  mb.omega = rb.state.omega;
  mb.place();
}

bool BodySystem::advance(World& m_, double t, double h, double beta, double gamma) {
  bool within = true;
  body_time_ = t + h;  // (the placement's time: the loads' anchors move with it)
  for (std::size_t b = 0; b < m_.bodies.size(); ++b) {
    RigidBody& rb = m_.bodies[b];
    const BodyState& n = body_n_[b].state;
    BodyState& s = rb.state;
    // (before the state moves: a pivoted hinge's torque has its arm at the latest placement,
    // where the wrench was evaluated)
    const double alpha = rb.rotation == BodyRotation::Hinge ? rb.hinge_acceleration() : 0.0;
    const double cx_n = h * h * (0.5 - beta), cx = h * h * beta, cv_n = h * (1.0 - gamma), cv = h * gamma;
    const Vec3 a = masked(rb.force / rb.mass, rb.fixed);
    s.acceleration = a;
    s.position = n.position + h * n.velocity + cx_n * n.acceleration + cx * a;
    s.velocity = n.velocity + cv_n * n.acceleration + cv * a;
    if (rb.rotation == BodyRotation::Free) {
      RotationSettings rs;
      rs.beta = beta;
      rs.gamma = gamma;
      const RotState body{n.orientation, to_body(n.orientation, n.omega), to_body(n.orientation, n.omega_dot)};
      const RotStepResult r = rotation_step(body, rb.torque, rb.inertia, h, rs);
      s.orientation = r.state.q;
      s.omega = to_world(r.state.q, r.state.w);
      s.omega_dot = to_world(r.state.q, r.state.dw);
    } else {
      const double w_n = n.omega.dot(rb.axis), alpha_n = n.omega_dot.dot(rb.axis);
      s.angle = n.angle + h * w_n + cx_n * alpha_n + cx * alpha;
      s.omega = (w_n + cv_n * alpha_n + cv * alpha) * rb.axis;
      s.omega_dot = alpha * rb.axis;
      s.orientation = qmul(axis_turn(rb.axis, s.angle), rb.hinge_start);
      if (rb.pivoted) {
        const Vec3 r = to_world(axis_turn(rb.axis, s.angle), rb.pivot_arm);
        s.position = rb.pivot + r;
        s.velocity = s.omega.cross(r);
        s.acceleration = s.omega_dot.cross(r) + s.omega.cross(s.omega.cross(r));
      }
    }
    // How far a vertex moved in the step: the centre's move plus the chord of the turn.
    const double moved = (s.position - n.position).norm() +
                         2.0 * m_.meshes[rb.mesh].reach * vec(qmul(qconj(n.orientation), s.orientation)).norm();
    if (!(moved <= step_limit_)) within = false;
    place_mesh(m_, b);
  }
  return within;
}

bool BodySystem::drift(World& m_, double t, double h) {
  body_n_ = m_.bodies;
  // beta = 0: the positions and the orientation need only the start of the step; the
  // velocities are the drift's (the kick redoes them with the new wrench).
  return advance(m_, t, h, 0.0, 0.5);
}

void BodySystem::kick(World& m_, double t, double h) {
  // The same beta = 0 update from the start of the step, now with the new wrench: the
  // positions and the orientation come out the same bits, the velocities get the kick.
  advance(m_, t, h, 0.0, 0.5);
}

double BodySystem::wrenches(World& m_, const ContactSystem& contacts, const SweepMeasure& sweep) {
  if (m_.bodies.empty()) return 0.0;
  std::vector<Vec3> f, t;
  if (contacts.enabled()) contacts.mesh_wrenches(f, t);
  double dmax = 0.0, level = sweep.force_level2, damax = 0.0, disp2 = 0.0;
  for (std::size_t b = 0; b < m_.bodies.size(); ++b) {
    RigidBody& rb = m_.bodies[b];
    const BodyState& s = rb.state;
    const MeshBody& mb = m_.meshes[rb.mesh];
    rb.contact_force = f.empty() ? Vec3::Zero() : f[rb.mesh];
    rb.contact_torque = t.empty() ? Vec3::Zero() : t[rb.mesh];
    const Vec3 force = rb.contact_force + rb.load.force_at(s.position, s.velocity, body_time_) + rb.mass * m_.gravity;
    const Vec3 torque = rb.contact_torque + rb.load.torque - rb.load.torque_damping * s.omega;
    // Convergence: the change of force, and of torque over the mesh's reach (a force at its
    // rim), against the particles' force level and the body's own; or, as for the particles,
    // the position correction it makes against the step's displacement.
    const double r = std::max(mb.reach, 1e-300);
    const Vec3 df = masked(force - rb.force, rb.fixed);
    const double dt = (torque - rb.torque).norm() / r;
    dmax = std::max({dmax, df.squaredNorm(), dt * dt});
    level = std::max({level, force.squaredNorm(), torque.squaredNorm() / (r * r)});
    const double da = std::max(df.norm() / rb.mass, dt * r * r / rb.inertia.minCoeff());
    damax = std::max(damax, da * da);
    if (!body_n_.empty()) disp2 = std::max(disp2, (s.position - body_n_[b].state.position).squaredNorm());
    rb.force = force;
    rb.torque = torque;
  }
  if (!sweep.implicit || dmax == 0.0) return 0.0;
  const double h = sweep.h;
  const double by_force = level > 0.0 ? std::sqrt(dmax / level) : HUGE_VAL;
  const double moved2 = std::max(disp2, sweep.step_disp2);
  const double by_motion = moved2 > 0.0 ? sweep.beta * h * h * std::sqrt(damax / moved2) : HUGE_VAL;
  return std::min(by_force, by_motion);
}

void BodySystem::init_accelerations(World& m_) {
  for (RigidBody& rb : m_.bodies) {
    BodyState& s = rb.state;
    s.acceleration = masked(rb.force / rb.mass, rb.fixed);
    if (rb.rotation == BodyRotation::Free) {
      const Quat& q = s.orientation;
      s.omega_dot = to_world(q, euler_acceleration(to_body(q, rb.torque), to_body(q, s.omega), rb.inertia));
    } else {
      s.omega_dot = (rb.rotation == BodyRotation::Hinge ? rb.hinge_acceleration() : 0.0) * rb.axis;
      if (rb.pivoted) {
        const Vec3 r = s.position - rb.pivot;
        s.acceleration = s.omega_dot.cross(r) + s.omega.cross(s.omega.cross(r));
      }
    }
  }
}

void BodySystem::restore(World& m_, double t) {
  m_.bodies = body_n_;
  body_time_ = t;
  for (std::size_t b = 0; b < m_.bodies.size(); ++b) place_mesh(m_, b);
}

double BodySystem::load_power(const World& m_) const {
  double p = 0.0;
  for (const RigidBody& rb : m_.bodies) {
    const BodyState& s = rb.state;
    p += rb.load.force_at(s.position, s.velocity, body_time_).dot(s.velocity) +
         (rb.load.torque - rb.load.torque_damping * s.omega).dot(s.omega);
  }
  return p;
}

bool BodySystem::prescribe(const StepContext& c) {
  World& m_ = c.world;
  const double t = c.t, h = c.h;
  const double t_new = t + h;
  // A mesh may move in a step no further than a particle may (step_limit_): a tool that
  // jumps past the block would cut nothing.
  const double limit = step_limit_;
  bool within = true;
  for (std::size_t k = 0; k < m_.meshes.size(); ++k) {
    if (mesh_body_[k] >= 0) continue;  // (placed from its body's pose)
    const Vec3 u_old = m_.mesh_motion[k].displacement_at(t), u_new = m_.mesh_motion[k].displacement_at(t_new);
    m_.meshes[k].offset = u_new;
    m_.meshes[k].velocity = (u_new - u_old) / h;
    if (!((u_new - u_old).norm() <= limit)) within = false;  // (no particles: the limit is inf)
  }
  return within;
}

void BodySystem::throw_mesh_too_far(const World& m_, double t, double h, std::int64_t step,
                                    double max_step_displacement) const {
  for (std::size_t k = 0; k < m_.meshes.size(); ++k) {
    if (mesh_body_[k] >= 0) continue;
    const Vec3 du = m_.mesh_motion[k].displacement_at(t + h) - m_.mesh_motion[k].displacement_at(t);
    if (du.norm() <= step_limit_) continue;
    throw SimulationError(fmt::format(
        "mesh '{}' moves {:.4g} m in step {} at t = {:.6g} s (dt = {:.4g} s, speed {:.4g} m/s), more than "
        "integrator.max_step_displacement = {} radii of the smallest particle: lower the step or the mesh's speed",
        m_.meshes[k].name, du.norm(), step, t, h, du.norm() / h, max_step_displacement));
  }
  throw SimulationError("a mesh moves too far in one step");
}

void BodySystem::account(const StepContext& c) {
  if (c.world.bodies.empty()) return;  // the bodies' external loads (gravity: potential_energy())
  const double power = load_power(c.world);
  c.ledger.external_work += 0.5 * (power_old_ + power) * c.h;
  power_old_ = power;
}

double BodySystem::kinetic_energy(const World& m_) const {
  double e = 0.0;
  for (const RigidBody& rb : m_.bodies) e += rb.kinetic_energy();
  return e;
}

double BodySystem::potential_energy(const World& m_) const {
  double bodies = 0.0;
  for (std::size_t b = 0; b < m_.bodies.size(); ++b)
    bodies -= m_.bodies[b].mass * m_.gravity.dot(m_.bodies[b].state.position - body_x0_[b]);
  return bodies;
}

void BodySystem::visit_state(StateArchive& ar, World& m_, EnergyLedger&) {
  const bool load = ar.loading();
  const std::size_t nm = m_.meshes.size();
  std::vector<Vec3> offset, velocity;
  for (const auto& mb : m_.meshes) {
    offset.push_back(mb.offset);
    velocity.push_back(mb.velocity);
  }
  ar.array("meshes/offset", offset, nm);
  ar.array("meshes/velocity", velocity, nm);
  if (load)
    for (std::size_t k = 0; k < nm; ++k) {
      m_.meshes[k].offset = offset[k];
      m_.meshes[k].velocity = velocity[k];
    }
  const std::size_t nb = m_.bodies.size();
  if (nb == 0) return;
  // The rigid bodies' state and last wrench (the next step's predictor reads it); their
  // meshes are placed again from it after a load.
  std::vector<Vec3> x(nb), v(nb), a(nb), w(nb), dw(nb), f(nb), t(nb), cf(nb), ct(nb);
  std::vector<Quat> q(nb);
  std::vector<double> angle(nb);
  for (std::size_t b = 0; b < nb; ++b) {
    const RigidBody& rb = m_.bodies[b];
    x[b] = rb.state.position, v[b] = rb.state.velocity, a[b] = rb.state.acceleration;
    q[b] = rb.state.orientation, w[b] = rb.state.omega, dw[b] = rb.state.omega_dot, angle[b] = rb.state.angle;
    f[b] = rb.force, t[b] = rb.torque, cf[b] = rb.contact_force, ct[b] = rb.contact_torque;
  }
  ar.array("bodies/position", x, nb);
  ar.array("bodies/velocity", v, nb);
  ar.array("bodies/acceleration", a, nb);
  ar.array("bodies/orientation", q, nb);
  ar.array("bodies/omega", w, nb);
  ar.array("bodies/omega_dot", dw, nb);
  ar.array("bodies/angle", angle, nb);
  ar.array("bodies/force", f, nb);
  ar.array("bodies/torque", t, nb);
  ar.array("bodies/contact_force", cf, nb);
  ar.array("bodies/contact_torque", ct, nb);
  ar.scalar("bodies/load_power_old", power_old_);
  if (!load) return;
  for (std::size_t b = 0; b < nb; ++b) {
    RigidBody& rb = m_.bodies[b];
    // (finite first: an ordered comparison with a NaN raises FE_INVALID, a trap in the test build)
    const bool finite_q = finite_bits(q[b][0]) && finite_bits(q[b][1]) && finite_bits(q[b][2]) && finite_bits(q[b][3]);
    if (!all_finite(x[b]) || !all_finite(v[b]) || !all_finite(w[b]) || !finite_q ||
        !(std::abs(q[b].norm() - 1.0) < 1e-9))
      throw InputError(fmt::format("state fields 'bodies/*': body {} has a non-finite pose or velocity", b));
    rb.state = BodyState{x[b], v[b], a[b], q[b], w[b], dw[b], angle[b]};
    rb.force = f[b], rb.torque = t[b], rb.contact_force = cf[b], rb.contact_torque = ct[b];
    place_mesh(m_, b);
  }
}

}  // namespace swarf
