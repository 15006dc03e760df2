// simulation.cpp: the step control around the integrators (see simulation.h and
// integrate/integration.h), the flows after a step, and the energies a run reads.
#include "swarf/simulation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "swarf/core/errors.h"
#include "swarf/core/parallel.h"

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
  sys_.rods.setup(m_);
  sys_.groups.setup(m_.groups, m_.particles);
  sys_.bodies.setup(m_, set_.solver == Solver::Newton);
  sys_.flows.setup(m_);
  if (m_.contacts) {
    ms_.contact_force.assign(m_.particles.size(), Vec3::Zero());
    sys_.contacts.setup(m_.contact, m_.particles.size(), &m_.meshes, m_.periodic);
    if (m_.contact.law != FrictionLaw::None && (m_.contact.friction > 0.0 || m_.contact.tool_friction.points > 0))
      ms_.rotations = true;
  }
  sys_.thermal.setup(m_);
  // The rotation arrays only where something can turn a particle or read its turn: contacts
  // (torques), bodies and flows (their particles' and new particles' spins), orientation output.
  const bool turns = ms_.rotations || m_.contacts || !m_.bodies.empty() || !m_.inflows.empty() ||
                     !m_.outflows.empty() || set_.sphere_orientations;
  ParticleLayout layout = m_.particles.layout;
  layout.rotation = turns;
  m_.particles.set_layout(layout);
  sys_.plastic.setup(m_, set_.plastic_strain_window);
  // Forces of the initial state (nothing committed: the first step re-evaluates them).
  Integration it = integration();
  integrate::rod_forces(it);
  integrate::contact_forces(it, dt_);
  integrate::gather(it);
  sys_.bodies.init_accelerations(m_);
  sys_.bodies.init_power(m_);
  if (ms_.rotations) set_rotations(true);
  sys_.groups.init_reactions(m_.groups, m_.particles);
  if (sys_.contacts.enabled()) {
    sys_.contacts.mesh_forces(ms_.mesh_force);
    ms_.contact_power_old = integrate::contact_power(it);
  }
}

void Simulation::apply_flows(double h) {
  double out = 0.0, gross = 0.0;  // J
  if (const auto remove = sys_.flows.outflow(m_, out, gross); !remove.empty()) {
    // (their rods' elastic energy leaves with them)
    const double elastic_before = m_.rods.size() > 0 ? elastic_energy() : 0.0;
    ledger_.heat_outflow += sys_.thermal.carried(m_, remove);
    remove_particles(remove);
    const double elastic_after = m_.rods.size() > 0 ? elastic_energy() : 0.0;
    ledger_.flow_energy += out + (elastic_before - elastic_after);
    ledger_.flow_through += gross + std::abs(elastic_before - elastic_after);
  }
  if (const Particles add = sys_.flows.inflow(m_, h, ledger_); !add.position.empty()) append_particles(add);
}

void Simulation::set_rotations(bool on) {
  ms_.rotations = on;
  if (!on) return;
  if (!m_.particles.layout.rotation) {
    ParticleLayout layout = m_.particles.layout;
    layout.rotation = true;
    m_.particles.set_layout(layout);
    resize_scratch();
  }
  integrate::update_free_to_rotate(m_, ms_);
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
  Integration it = integration();
  // Both schemes end with the step's time and counters.
  const auto advance = [&](double h) {
    time_ += h;
    last_dt_ = h;
    ++stats_.accepted;
  };
  if (!implicit_) {
    integrate::verlet_step(it, dt_);
    advance(dt_);
    return;
  }
  const StepSettings& g = set_;
  clock_.start();  // the state save and restores after rejected tries count as 'prescribe'
  integrate::save_state(it);
  while (true) {
    const double h = std::min(dt_, max_dt);
    const bool newton = g.solver == Solver::Newton;
    if (newton ? integrate::newton_try(it, h) : integrate::newmark_try(it, h)) {
      integrate::commit(it, h);
      clock_.lap(Stage::Commit);
      integrate::account(it, h);
      advance(h);
      clock_.lap(Stage::Account);
      // Step size control from the number of sweeps (paper section 3.4), or of Newton
      // iterations; a Newton step whose linear solve hit krylov_max_iterations does not grow
      // (its CG iterations grow with h / dt_stable) and shrinks the next one.
      const int iterations = stats_.last_iterations;
      const bool capped = newton && ms_.newton_stats.last_capped;
      if (iterations <= g.iterations_grow && !capped)
        dt_ = std::min(dt_ * g.grow_factor, g.dt_max);
      else if (iterations >= g.iterations_shrink || capped)
        dt_ = std::max(dt_ * g.shrink_factor, g.dt_min);
      return;
    }
    integrate::restore_state(it);
    ++stats_.rejected;
    dt_ = h * g.reject_factor;
    if (!(dt_ >= g.dt_min) && ms_.mesh_rejected)
      sys_.bodies.throw_mesh_too_far(m_, time_, h, stats_.accepted + 1, set_.max_step_displacement);
    if (!(dt_ >= g.dt_min))  // (a NaN step too: it is never below dt_min)
      throw SimulationError(fmt::format(
          "the Newmark step did not converge at t = {:.6g} s with dt = {:.4g} s, and the next try ({:.4g} s) "
          "would be below dt_min = {:.4g} s (integrator.dt_min); {} sweeps allowed (integrator.max_iterations), "
          "tolerance {}",
          time_, h, dt_, g.dt_min, g.max_iterations, g.tolerance));
  }
}

void Simulation::update_mesh_step_limit() {
  double rmin = HUGE_VAL;
  for (double r : m_.particles.radius) rmin = std::min(rmin, r);
  sys_.bodies.set_step_limit(set_.max_step_displacement * rmin);
}

double Simulation::ghost_reach() const {
  double reach = sys_.contacts.enabled() ? sys_.contacts.ghost_reach(m_.particles) : 0.0;
  sys_.for_each([&](const auto& s) { reach = std::max(reach, s.ghost_reach(m_)); });
  return reach;
}

double Simulation::kinetic_energy() const { return particle_kinetic_energy().value() + body_kinetic_energy(); }

namespace {
// Particle i's rotational kinetic energy, J.
double rotational_term(const Particles& p, std::size_t i) {
  const Vec3 wb = to_body(p.orientation[i], p.omega[i]);
  return 0.5 * wb.dot(p.inertia[i].cwiseProduct(wb));
}
}  // namespace

ExactSum Simulation::particle_kinetic_energy(const std::uint8_t* counted) const {
  const auto& p = m_.particles;
  ExactSum e = exact_sum(p.size(), [&](std::size_t i) {
    return counted && !counted[i] ? 0.0 : 0.5 * p.mass[i] * p.velocity[i].squaredNorm();
  });
  if (ms_.rotations)
    e.add(exact_sum(p.size(), [&](std::size_t i) { return counted && !counted[i] ? 0.0 : rotational_term(p, i); }));
  return e;
}

ExactSum Simulation::contact_power_exact(const std::uint8_t* counted) const {
  const auto& p = m_.particles;
  if (!sys_.contacts.enabled()) return ExactSum{};
  const bool rot = ms_.rotations;
  // (the terms of integrate::contact_power, here counted by owner and added exactly)
  return exact_sum(p.size(), [&](std::size_t i) {
    return !counted[i] ? 0.0 : ms_.contact_force[i].dot(p.velocity[i]) + (rot ? p.torque[i].dot(p.omega[i]) : 0.0);
  });
}

double Simulation::rotational_energy() const {
  if (!ms_.rotations) return 0.0;
  const auto& p = m_.particles;
  return exact_sum(p.size(), [&](std::size_t i) { return rotational_term(p, i); }).value();
}

double Simulation::elastic_energy() const { return sys_.rods.elastic_energy(m_); }

double Simulation::potential_energy() const {
  const auto& p = m_.particles;
  const Vec3 g = m_.gravity;
  if (g.squaredNorm() == 0.0) return 0.0;
  const double bodies = sys_.bodies.potential_energy(m_);
  return deterministic_sum(p.size(),
                           [&](std::size_t i) { return -p.mass[i] * g.dot(p.position[i] - p.initial_position[i]); }) +
         bodies;
}

}  // namespace swarf
