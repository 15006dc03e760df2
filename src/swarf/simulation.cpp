// simulation.cpp: the step function of both schemes, stage by stage (see simulation.h).
#include "swarf/simulation.h"

#include <cmath>
#include <fmt/format.h>

#include "swarf/core/errors.h"
#include "swarf/core/parallel.h"

namespace swarf {

namespace {
constexpr double kForceFloorStrain = 1e-8;  // see gather_impl
}  // namespace

Simulation::Simulation(World& world, const StepSettings& settings) : m_(world), set_(settings) {
  implicit_ = set_.implicit();
  dt_ = set_.dt;
  block_viscous_.assign(block_count(m_.rods.size()), 0.0);
  block_changed_.assign(block_count(m_.rods.size()), 0);
  const std::size_t ng = m_.groups.size();
  group_u_old_.assign(ng, Vec3::Zero());
  group_u_new_.assign(ng, Vec3::Zero());
  reaction_.assign(ng, Vec3::Zero());
  group_v_.assign(ng, Vec3::Zero());
  group_mass_.assign(ng, 0.0);
  for (std::size_t g = 0; g < ng; ++g)
    for (auto i : m_.groups[g].members) group_mass_[g] += m_.particles.mass[i];
  if (m_.contacts) {
    contact_force_.assign(m_.particles.size(), Vec3::Zero());
    contacts_.setup(m_.contact, m_.particles.size(), &m_.meshes, m_.periodic);
    if (m_.contact.law != FrictionLaw::None && m_.contact.friction > 0.0) rotations_ = true;
  }
  // Forces of the initial state (nothing committed: the first step re-evaluates them).
  rod_forces();
  contact_forces(dt_);
  gather();
  if (rotations_) set_rotations(true);
  compute_reactions(reaction_);
  broken_ = m_.rods.broken_count();
  if (contacts_.enabled()) {
    contacts_.mesh_forces(mesh_force_);
    contact_power_old_ = contact_power();
  }
}

double Simulation::contact_power(bool from_kick) const {
  // Power of the contact forces on the particles (forces and torques) and on the meshes.
  const auto& p = m_.particles;
  const bool rot = rotations_;
  double power = from_kick ? kick_power_ : deterministic_sum(p.size(), [&](std::size_t i) {
    return contact_force_[i].dot(p.velocity[i]) + (rot ? p.torque[i].dot(p.omega[i]) : 0.0);
  });
  for (std::size_t k = 0; k < m_.meshes.size(); ++k) power += mesh_force_[k].dot(m_.meshes[k].velocity);
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
  free_list_.clear();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (free_to_rotate_[i]) free_list_.push_back(static_cast<std::int32_t>(i));
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
    if (try_newmark(h)) {
      commit();
      clock_.lap(Stage::Commit);
      account(h);
      clock_.lap(Stage::Account);
      // Step size control from the number of sweeps (paper section 3.4).
      const int it = stats_.last_iterations;
      if (it <= g.iterations_grow) dt_ = std::min(dt_ * g.grow_factor, g.dt_max);
      else if (it >= g.iterations_shrink) dt_ = std::max(dt_ * g.shrink_factor, g.dt_min);
      return;
    }
    restore_state();
    ++stats_.rejected;
    dt_ = h * g.reject_factor;
    if (dt_ < g.dt_min)
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
  prescribe(h);
  clock_.lap(Stage::Prescribe);
  if (!kick_drift(h)) throw_too_far(h);
  clock_.lap(Stage::Integrate);
  rod_forces();
  clock_.lap(Stage::Rods);
  contact_forces(h, true);
  gather_kick(h);  // (rotations included: the explicit update needs only this step's torque)
  clock_.lap(Stage::Gather);
  commit();
  clock_.lap(Stage::Commit);
  account(h);
  clock_.lap(Stage::Account);
  stats_.last_iterations = 1;
  stats_.iterations += 1;
  stats_.max_iterations = 1;
}

bool Simulation::try_newmark(double h) {
  const StepSettings& g = set_;
  prescribe(h);
  clock_.lap(Stage::Prescribe);
  int it = 0, growing = 0;
  bool converged = false;
  double previous = HUGE_VAL;
  // Relaxation w < 1: the next sweep places with (1 - w) a_guess + w a_swept. The sweep maps
  // a guess to new accelerations with eigenvalues in [-(dt/dt_stable)^2, 0] (physics notes
  // section 6); relaxed, they become 1 - w + w lambda: at dt_max (0.8 dt_stable, L = 0.64 the
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

void Simulation::prescribe(double h) {
  auto& p = m_.particles;
  const double t_new = time_ + h;
  for (std::size_t k = 0; k < m_.meshes.size(); ++k) {
    const Vec3 u_old = m_.mesh_motion[k].displacement_at(time_), u_new = m_.mesh_motion[k].displacement_at(t_new);
    m_.meshes[k].offset = u_new;
    m_.meshes[k].velocity = (u_new - u_old) / h;
  }
  for (std::size_t g = 0; g < m_.groups.size(); ++g) {
    group_u_old_[g] = m_.groups[g].motion.displacement_at(time_);
    group_u_new_[g] = m_.groups[g].motion.displacement_at(t_new);
  }
  for (std::size_t g = 0; g < m_.groups.size(); ++g) {
    const Vec3 v = (group_u_new_[g] - group_u_old_[g]) / h;
    const std::uint8_t mask = m_.groups[g].dofs;
    for (auto i : m_.groups[g].members)
      for (int c = 0; c < 3; ++c)
        if (mask & (1u << c)) {
          p.position[i][c] = p.initial_position[i][c] + group_u_new_[g][c];
          p.velocity[i][c] = v[c];
        }
  }
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
  return bad == 0;
}

namespace {

// The rod kernel over one block of rods. Raw pointers keep the compiler from reloading the
// arrays' bases after every store (the uint8_t stores may alias anything). 'Viscous' is a
// compile-time switch so the undamped lattice does not gather velocities.
template <bool Viscous, bool Wrap>
void rod_block(const RodLaw& law, double A, std::size_t begin, std::size_t end, const std::array<std::int32_t, 2>* ends,
               const double* rest_length, const double* inv_rest_length, const double* shift, const std::uint8_t* intact, const Vec3* x, const Vec3* v,
               double* trial_shift, std::uint8_t* trial_broken, double* stress, double* coef, double& viscous_power,
               int& changed, Periodic periodic) {
  double visc = 0.0;
  int any = 0;
  // In chunks, three passes: the rods' vectors (scalar gathers), their lengths and inverse
  // lengths (a loop of square roots and divisions the compiler vectorises: in one loop with
  // the law, their latency bound the kernel), then the law. The same values, bit for bit.
  constexpr std::size_t kChunk = 256;
  alignas(64) double dxs[3][kChunk], len_c[kChunk], inv_c[kChunk];
  for (std::size_t c0 = begin; c0 < end; c0 += kChunk) {
    const std::size_t nc = std::min(kChunk, end - c0);
    for (std::size_t c = 0; c < nc; ++c) {
      const std::size_t k = c0 + c;
      Vec3 dx = x[ends[k][1]] - x[ends[k][0]];
      if constexpr (Wrap) periodic.wrap(dx);
      dxs[0][c] = dx[0];
      dxs[1][c] = dx[1];
      dxs[2][c] = dx[2];
      len_c[c] = intact[k] ? dx.squaredNorm() : 1.0;  // (broken rods are skipped below)
    }
#pragma omp simd
    for (std::size_t c = 0; c < nc; ++c) {
      len_c[c] = std::sqrt(len_c[c]);
      inv_c[c] = 1.0 / len_c[c];
    }
    for (std::size_t c = 0; c < nc; ++c) {
      const std::size_t k = c0 + c;
      if (!intact[k]) continue;
      const double len = len_c[c];
      const double inv_len = inv_c[c];
      const double l0 = rest_length[k];
      const double inv_l0 = inv_rest_length[k];
      const double strain = (len - l0) * inv_l0;
      double rate = 0.0;
      if constexpr (Viscous) {
        const std::int32_t i = ends[k][0], j = ends[k][1];
        const Vec3 dx(dxs[0][c], dxs[1][c], dxs[2][c]);
        rate = dx.dot(v[j] - v[i]) * inv_len * inv_l0;
      }
      const RodResponse res = evaluate(law, strain, rate, shift[k]);
      trial_shift[k] = res.shift;
      trial_broken[k] = res.broken;
      stress[k] = res.stress;
      any |= (res.shift != shift[k]) | res.broken;
      if (res.broken) {
        coef[k] = 0.0;
      } else {
        coef[k] = (res.stress + res.viscous_stress) * A * inv_len;
        if constexpr (Viscous) visc += res.viscous_stress * rate * A * l0;
      }
    }
  }
  viscous_power = visc;
  changed = any;
}

}  // namespace

void Simulation::rod_forces() {
  ++stats_.force_evaluations;
  auto& r = m_.rods;
  const auto& p = m_.particles;
  const RodLaw law = r.law;
  const double A = r.area;
  const std::size_t m = r.size(), nb = block_count(m);
  if (m == 0) return;  // (no parallel region for nothing: each costs microseconds)
  const auto* ends = r.ends.data();
  const double* l0 = r.rest_length.data();
  const double* inv_l0 = r.inv_rest_length.data();
  const double* shift = r.shift.data();
  const std::uint8_t* intact = r.intact.data();
  const Vec3* x = p.position.data();
  const Vec3* v = p.velocity.data();
  double* trial_shift = r.trial_shift.data();
  std::uint8_t* trial_broken = r.trial_broken.data();
  double* stress = r.stress.data();
  double* coef = r.force_coef.data();
  double* block_visc = block_viscous_.data();
  int* block_changed = block_changed_.data();
  const bool viscous = law.viscosity != 0.0;
  const Periodic periodic = m_.periodic;
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < nb; ++b) {
    const std::size_t begin = b * kBlock, end = std::min(m, (b + 1) * kBlock);
    // Compile-time switches: the common undamped or non-periodic cases pay for neither.
    if (viscous && periodic.on())
      rod_block<true, true>(law, A, begin, end, ends, l0, inv_l0, shift, intact, x, v, trial_shift, trial_broken, stress,
                            coef, block_visc[b], block_changed[b], periodic);
    else if (viscous)
      rod_block<true, false>(law, A, begin, end, ends, l0, inv_l0, shift, intact, x, v, trial_shift, trial_broken, stress,
                             coef, block_visc[b], block_changed[b], periodic);
    else if (periodic.on())
      rod_block<false, true>(law, A, begin, end, ends, l0, inv_l0, shift, intact, x, v, trial_shift, trial_broken, stress,
                             coef, block_visc[b], block_changed[b], periodic);
    else
      rod_block<false, false>(law, A, begin, end, ends, l0, inv_l0, shift, intact, x, v, trial_shift, trial_broken, stress,
                              coef, block_visc[b], block_changed[b], periodic);
  }
}

template <Simulation::GatherMode Mode, bool Wrap>
double Simulation::gather_impl(double h) {
  constexpr bool Measure = Mode == GatherMode::Measure, Kick = Mode == GatherMode::Kick;
  auto& p = m_.particles;
  const auto& r = m_.rods;
  const std::size_t n = p.size();
  const double d = set_.length_scale;
  const bool contacts = contacts_.enabled();
  const bool rot = rotations_;
  const Vec3 gravity = m_.gravity;
  const Periodic periodic = m_.periodic;
  // Convergence measure of the fixed-point iteration: the largest change of a particle's
  // force between sweeps, relative to the largest force level in the body, which is the
  // larger of the net forces and the sums of rod force magnitudes |sigma A| on a particle.
  // Near equilibrium the net forces are small differences of large rod forces; measuring
  // against them alone would ask for accuracy below the rounding of the sums.
  double dmax = 0.0, fmax = 0.0, damax = 0.0;
  // Kick: the contact power after the kick, summed per fixed block of particles and then
  // over the blocks in order (the same rounding for any thread count).
  constexpr std::size_t kPowerBlock = 256;
  const std::size_t nb = (n + kPowerBlock - 1) / kPowerBlock;
  if constexpr (Kick) block_power_.assign(nb, 0.0);
  // Raw pointers in locals: Eigen's vector stores may alias anything, and through the
  // containers every array's base was loaded again after each store.
  const Vec3* x = p.position.data();
  Vec3* force = p.force.data();
  Vec3* acc = p.acceleration.data();
  Vec3* torque = p.torque.data();
  Vec3* vel = p.velocity.data();
  Vec3* omega = p.omega.data();
  Vec3* omega_dot = p.omega_dot.data();
  Quat* orient = p.orientation.data();
  const double* mass = p.mass.data();
  const double* inv_mass = p.inv_mass.data();
  const double* radius = p.radius.data();
  const double* inv_inertia = p.inv_inertia.data();
  const std::uint8_t* prescribed = p.prescribed.data();
  const std::uint8_t* free_to_rotate = free_to_rotate_.data();
  const std::int32_t* row_start = r.row_start.data();
  const Rods::Entry* entries = r.entries.data();
  const double* force_coef = r.force_coef.data();
  Vec3* contact_force = contact_force_.data();
  const ContactSystem::Sums sums = contacts ? contacts_.sums() : ContactSystem::Sums{};
  [[maybe_unused]] const double half = 0.5 * h;
  const bool turn_spheres = set_.sphere_orientations;
  // One block of particles; dmax_, fmax_, damax_ are the calling thread's reduction copies.
  // (Contacts: a compile-time switch, so that the rods-only loop keeps its registers.)
  auto block = [&]<bool Contacts>(std::size_t b, double& dmax_, double& fmax_, double& damax_) {
    [[maybe_unused]] double power = 0.0;
    const std::size_t end = std::min(n, (b + 1) * kPowerBlock);
    for (std::size_t i = b * kPowerBlock; i < end; ++i) {
      Vec3 f = Vec3::Zero();
      [[maybe_unused]] double level = 0.0;
      const Vec3 xi = x[i];
      for (std::int32_t e = row_start[i]; e < row_start[i + 1]; ++e) {
        const Rods::Entry en = entries[e];
        const double c = force_coef[en.rod];
        Vec3 dx = x[en.other] - xi;
        if constexpr (Wrap) periodic.wrap(dx);
        f += c * dx;
        if constexpr (Measure) level += std::abs(c);
      }
      Vec3 fc = Vec3::Zero();
      if constexpr (Contacts) {
        Vec3 tau = Vec3::Zero();
        sums.add(i, radius[i], fc, tau);
        f += fc;
        if constexpr (!Kick) contact_force[i] = fc;  // (the explicit scheme's power is summed below)
        torque[i] = tau;
      }
      f += mass[i] * gravity;
      const std::uint8_t mask = prescribed[i];
      if constexpr (Measure) {
        Vec3 df = f - force[i];
        Vec3 ff = f;
        if (mask)
          for (int c = 0; c < 3; ++c)
            if (mask & (1u << c)) df[c] = ff[c] = 0.0;
        const double d2 = df.squaredNorm();
        dmax_ = std::max(dmax_, std::isnan(d2) ? HUGE_VAL : d2);
        fmax_ = std::max({fmax_, ff.squaredNorm(), level * level * d * d});
        damax_ = std::max(damax_, std::isnan(d2) ? HUGE_VAL : d2 * inv_mass[i] * inv_mass[i]);
      }
      force[i] = f;
      const Vec3 a = inv_mass[i] * f;
      acc[i] = a;
      if constexpr (Kick) {
        // The corrector v += h/2 a (free components) and the rotation, which needs only this
        // step's torque (beta 0, gamma 1/2).
        if (mask == 0) {
          vel[i] += half * a;
        } else {
          for (int c = 0; c < 3; ++c)
            if (!(mask & (1u << c))) vel[i][c] += half * a[c];
        }
        if (rot && free_to_rotate[i]) {
          if (inv_inertia[i] > 0.0)
            sphere_rotation_step(orient[i], omega[i], omega_dot[i], torque[i], inv_inertia[i], h, 0.5, turn_spheres);
          else
            rotate_one(i, h, 0.0, 0.5);
        }
        if constexpr (Contacts) power += fc.dot(vel[i]) + (rot ? torque[i].dot(omega[i]) : 0.0);
      }
    }
    if constexpr (Kick) block_power_[b] = power;
  };
  // Static, as the passes that move the particles and the pair loop: each thread finds its
  // particles' data in its own core's cache (dynamic blocks were 3 to 10 % slower on W2).
#pragma omp parallel for schedule(static) reduction(max : dmax, fmax, damax)
  for (std::size_t b = 0; b < nb; ++b) {
    if (contacts) block.template operator()<true>(b, dmax, fmax, damax);
    else block.template operator()<false>(b, dmax, fmax, damax);
  }
  if constexpr (Kick) {
    kick_power_ = 0.0;
    for (double w : block_power_) kick_power_ += w;
  }
  if (!Measure || dmax == 0.0) return 0.0;
  // A body at rest and unstressed (before the tool touches it) has forces that are rounding
  // noise: measured against them, the sweeps never "converge" and the step shrinks to dt_min
  // (seen as a 2-cycle of a 1e-13 N change at the first contact of a sharp tool). The force
  // level therefore never counts below that of a rod strained by 1e-8.
  const double floor = kForceFloorStrain * set_.stiffness_scale * d;
  fmax = std::max(fmax, floor * floor);
  // Two scale-aware measures; the iteration has converged when either is small:
  //  - the force change relative to the force level (quasi-static, stressed states);
  //  - the position correction beta h^2 |da| relative to the largest displacement of the
  //    step (fast motion through unstressed states, where the force level vanishes).
  const double by_force = fmax > 0.0 ? std::sqrt(dmax / fmax) : HUGE_VAL;
  const double by_motion = step_disp2_ > 0.0 ? set_.beta * h * h * std::sqrt(damax / step_disp2_)
                                             : HUGE_VAL;
  return std::min(by_force, by_motion);
}

double Simulation::gather() {
  const double h = sweep_dt_;
  if (!implicit_) return m_.periodic.on() ? gather_impl<GatherMode::Plain, true>(h) : gather_impl<GatherMode::Plain, false>(h);
  return m_.periodic.on() ? gather_impl<GatherMode::Measure, true>(h) : gather_impl<GatherMode::Measure, false>(h);
}

void Simulation::gather_kick(double h) {
  if (m_.periodic.on()) gather_impl<GatherMode::Kick, true>(h);
  else gather_impl<GatherMode::Kick, false>(h);
}

void Simulation::commit() {
  auto& r = m_.rods;
  const double E = r.law.youngs_modulus, k_h = r.law.hardening, A = r.area;
  const double plastic_factor = (E - k_h) / E;  // eps_p = (E - k)/E * shift
  const std::size_t m = r.size();
  // Plastic work and fracture energy per rod block, summed in block order.
  const std::size_t nb = block_count(m);
  std::vector<double> plastic(nb, 0.0), fracture(nb, 0.0);
  std::vector<std::size_t> broke(nb, 0);
  // The rods that break now, per block: their pairs become contact candidates.
  const bool contacts = contacts_.enabled();
  std::vector<std::vector<std::array<std::int32_t, 2>>> broken_pairs(contacts ? nb : 0);
#pragma omp parallel for schedule(static) if (nb > 0)
  for (std::size_t b = 0; b < nb; ++b) {
    if (!block_changed_[b]) continue;  // no rod of the block yielded or broke
    const std::size_t end = std::min(m, (b + 1) * kBlock);
    for (std::size_t k = b * kBlock; k < end; ++k) {
      if (!r.intact[k]) continue;
      const double dshift = r.trial_shift[k] - r.shift[k];
      if (dshift != 0.0) {
        plastic[b] += r.stress[k] * plastic_factor * dshift * A * r.rest_length[k];
        r.shift[k] = r.trial_shift[k];
      }
      if (r.trial_broken[k]) {
        r.intact[k] = 0;
        fracture[b] += elastic_energy_density(r.law, r.stress[k]) * A * r.rest_length[k];
        r.stress[k] = 0.0;
        ++broke[b];
        if (contacts) broken_pairs[b].push_back(r.ends[k]);
      }
    }
  }
  bool any_broke = false;
  for (std::size_t b = 0; b < nb; ++b) {
    ledger_.plastic_work += plastic[b];
    ledger_.fracture_energy += fracture[b];
    broken_ += broke[b];
    any_broke = any_broke || broke[b] > 0;
  }
  if (contacts && implicit_) contacts_.commit();  // explicit: committed by the final evaluation
  if (contacts && any_broke) {
    // Added to the lists as they are (a full rebuild for each break cost a tenth of a cut).
    std::vector<std::array<std::int32_t, 2>> fresh;
    for (const auto& v : broken_pairs) fresh.insert(fresh.end(), v.begin(), v.end());
    contacts_.add_pairs(m_.particles, std::move(fresh));
  }
  if (any_broke && rotations_) update_free_to_rotate();
}

void Simulation::compute_reactions(std::vector<Vec3>& out) const {
  const auto& p = m_.particles;
  out.assign(m_.groups.size(), Vec3::Zero());
  for (std::size_t g = 0; g < m_.groups.size(); ++g)
    for (auto i : m_.groups[g].members) out[g] -= p.force[i];
}

void Simulation::account(double h) {
  double visc = 0.0;
  for (double v : block_viscous_) visc += v;
  ledger_.viscous_work += visc * h;
  reaction_old_.swap(reaction_);
  compute_reactions(reaction_);
  for (std::size_t g = 0; g < m_.groups.size(); ++g) {
    const Vec3 du = group_u_new_[g] - group_u_old_[g];
    const Vec3 v = du / h;
    for (int c = 0; c < 3; ++c) {
      if (!(m_.groups[g].dofs & (1u << c))) continue;
      // Work on the body through the reaction, plus the work that changes the prescribed
      // particles' own kinetic energy (a grip that starts or reverses accelerates them).
      ledger_.external_work += 0.5 * (reaction_old_[g][c] + reaction_[g][c]) * du[c];
      ledger_.external_work += 0.5 * group_mass_[g] * (v[c] * v[c] - group_v_[g][c] * group_v_[g][c]);
    }
    group_v_[g] = v;
  }
  // Moving meshes (tools) work on the particles: minus the force the particles exert on the
  // mesh times its displacement (trapezoid over the step).
  if (contacts_.enabled()) {
    std::vector<Vec3> previous;
    previous.swap(mesh_force_);
    contacts_.mesh_forces(mesh_force_);
    for (std::size_t k = 0; k < m_.meshes.size(); ++k)
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
}

void Simulation::restore_state() {
  auto& p = m_.particles;
  p.position = x_n_;
  p.velocity = v_n_;
  p.acceleration = a_n_;
  p.force = f_n_;
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
    if (!(moved <= limit) || !p.position[i].allFinite())
      throw SimulationError(fmt::format(
          "unstable: particle {} (at {:.6g}, {:.6g}, {:.6g} m) moved {:.3g} radii in step {} at t = {:.6g} s "
          "(limit integrator.max_step_displacement = {}); speed {:.4g} m/s. The step dt = {:.4g} s may be "
          "too large for the loads, or the input drives the lattice too hard",
          i, p.position[i][0], p.position[i][1], p.position[i][2], moved, stats_.accepted + 1, time_ + h, limit,
          v.norm(), h));
  }
  throw SimulationError(fmt::format("unstable: non-finite state in step {} at t = {:.6g} s", stats_.accepted + 1,
                                    time_ + h));
}

double Simulation::kinetic_energy() const {
  const auto& p = m_.particles;
  const bool rot = rotations_;
  return deterministic_sum(p.size(), [&](std::size_t i) {
    return 0.5 * p.mass[i] * p.velocity[i].squaredNorm();
  }) + (rot ? rotational_energy() : 0.0);
}

double Simulation::rotational_energy() const {
  if (!rotations_) return 0.0;
  const auto& p = m_.particles;
  return deterministic_sum(p.size(), [&](std::size_t i) {
    const Vec3 wb = to_body(p.orientation[i], p.omega[i]);
    return 0.5 * wb.dot(p.inertia[i].cwiseProduct(wb));
  });
}

double Simulation::elastic_energy() const {
  const auto& r = m_.rods;
  const double A = r.area;
  return deterministic_sum(r.size(), [&](std::size_t k) {
    return r.intact[k] ? elastic_energy_density(r.law, r.stress[k]) * A * r.rest_length[k] : 0.0;
  });
}

double Simulation::potential_energy() const {
  const auto& p = m_.particles;
  const Vec3 g = m_.gravity;
  if (g.squaredNorm() == 0.0) return 0.0;
  return deterministic_sum(p.size(),
                           [&](std::size_t i) { return -p.mass[i] * g.dot(p.position[i] - p.initial_position[i]); });
}

}  // namespace swarf
