// newton.cpp: the Newton-Krylov solve of the implicit Newmark step (see
// newton_newmark.h and integration.h).
//
// Choices, and why:
// - Unknowns: the new accelerations a, as the fixed-point sweeps use (the step's
//   prescribe/place/rod_forces stages are shared; only the update of a differs).
// - The residual always uses the real rod law (rod_forces), the tangent the branch of the
//   latest evaluation (its trial state: elastic, plastic or broken), frozen for one linear
//   solve. A converged step is therefore an equilibrium of the real law, and no re-solve is
//   needed when a rod switches branch: the next Newton iteration sees the switch in both its
//   residual and its tangent. A rod that keeps flipping between branches (a piecewise-linear
//   law can make Newton cycle) exhausts max_iterations and rejects the step, which is retried
//   shorter, where the flip is resolved. Plasticity and breakage are committed afterwards,
//   from the converged evaluation, exactly as for the fixed-point solver (integrate::commit).
// - Matrix-free products (forces/rod_tangent.h): one pass over the particles' rows per CG
//   iteration, each rod applied from both ends (twice the flops of a pass over the rods, but
//   no per-rod store, no second pass and no barrier between them), and no sparse matrix to
//   assemble and store (12 neighbours per particle: 117 doubles per particle assembled,
//   against 5 per rod, 30 per particle, here).
// - CG with a 3x3 block-Jacobi preconditioner per particle: J is symmetric and, for tensile
//   or moderately compressed rods, positive definite (M dominates the compressed rods'
//   negative geometric part c (I - n n^T) unless beta h^2 |c| approaches the mass). If CG
//   meets d^T J d <= 0, the step is rejected and retried shorter (reject_factor): J tends to
//   M as h shrinks, so a shorter step restores definiteness, and an indefinite J means the
//   step spans a buckling-like loss of stiffness that a long step would not resolve anyway.
// - A preconditioner handed in (Simulation::set_newton_preconditioner) reads J assembled
//   (tangent_matrix.h) in place of the block-Jacobi. The block-Jacobi stays the solver's own: an
//   algebraic multigrid (study/hypre_amg.h) cut the CG iterations but cost more than it saved
//   (validation/integrators/README.md).
// - Inexact Newton: CG stops at |r| <= krylov_tolerance |R|; the Newton loop then measures the
//   real residual again. A solve stopped at krylov_max_iterations is used as it is (the
//   residual check decides), and the step control does not grow the next step.
// - A rate-hardening law's rate factor (Johnson-Cook's R = 1 + C ln(max(rate/rate_ref, 1))) is
//   read at the rod's rate at the step's start (x_n, v_n), not the iterate's: a lagged rate, as
//   implicit finite-element codes treat viscoplastic rate factors. With the iterate's rate, R is
//   not smooth in the unknowns (flat below rate_ref, a kink there) and its slope C sigma/(R rate)
//   times gamma/(beta h) is a dashpot up to 10^5 times stiffer than the rod near rate_ref; Newton
//   then failed on the cut (steps rejected down to 5e-12 s; so did R linearised about the step
//   start's rate, implicit in the iterate: validation/integrators/README.md). Lagged, the
//   residual is the piecewise-linear law at a fixed scale and the tangent has no rate term
//   (tangent_at_scale). The cost: R is explicit in the rate, an explicit dashpot that a slowly
//   flowing rod (C sigma / rate large against the rod's stiffness over the step) cannot carry:
//   its rate and R then ring in a bounded cycle instead of settling (a few % of the flow stress
//   in tests/test_newton.cpp's chain); and R lags by one step. Measured on the cut in the README
//   ("Newton with Johnson-Cook's rate term"). The viscous stress keeps the iterate's rate (it is
//   linear). The fixed-point sweeps and Verlet read the trial's own rate, as before.
// - Contacts (contacts/contact_tangent.cpp): evaluated in every Newton iteration after the
//   rods, their forces in the residual, their approximate tangent (normal Hertz stiffness and
//   damping, the sticking friction spring) in J beside the rods'. Friction histories are trial
//   values until the commit, as for the sweeps. Rotations (particles without rods) follow
//   the latest torques, a fixed point inside the Newton loop.
// - Every sum is over fixed blocks (deterministic_sum) or in the rows' fixed order, and the
//   maxima are exact, so the result has the same bits for any number of threads.
#include <Eigen/Dense>
#include <array>
#include <cmath>

#include "swarf/core/parallel.h"
#include "swarf/forces/rod_tangent.h"
#include "swarf/integrate/integration.h"

namespace swarf::integrate {

namespace {

// The force level never counts below that of a rod strained by this (as in the gather: a
// body at rest has forces that are rounding noise).
constexpr double kForceFloorStrain = 1e-8;

// Sums of two quantities over i in [0, n), bit-identical for any thread count (as
// deterministic_sum, one pass for both).
template <class F>
std::array<double, 2> deterministic_sums2(std::size_t n, F&& f) {
  const std::size_t nb = block_count(n);
  std::vector<std::array<double, 2>> part(nb, {0.0, 0.0});
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < nb; ++b) {
    std::array<double, 2> s{0.0, 0.0};
    const std::size_t end = std::min(n, (b + 1) * kBlock);
    for (std::size_t i = b * kBlock; i < end; ++i) {
      const std::array<double, 2> v = f(i);
      s[0] += v[0];
      s[1] += v[1];
    }
    part[b] = s;
  }
  std::array<double, 2> total{0.0, 0.0};
  for (const auto& s : part) {
    total[0] += s[0];
    total[1] += s[1];
  }
  return total;
}

// Zeroes the prescribed components (bit c of mask) of v.
inline void mask_prescribed(Vec3& v, std::uint8_t mask) {
  if (mask)
    for (int c = 0; c < 3; ++c)
      if (mask & (1u << c)) v[c] = 0.0;
}

template <bool Wrap, bool Contacts>
double newton_residual_impl(Integration& it) {
  World& world = it.world;
  MotionState& ms = it.ms;
  auto& p = world.particles;
  const auto& r = world.rods;
  const std::size_t n = p.size();
  ms.newton.residual.resize(n);
  const double d = it.set.length_scale;
  const Vec3 gravity = world.gravity;
  const Periodic periodic = world.periodic;
  const Vec3* x = p.position.data();
  Vec3* force = p.force.data();
  Vec3* acc = p.acceleration.data();
  Vec3* res = ms.newton.residual.data();
  const double* mass = p.mass.data();
  const double* inv_mass = p.inv_mass.data();
  const std::uint8_t* prescribed = p.prescribed.data();
  const std::int32_t* row_start = r.row_start.data();
  const Rods::Entry* entries = r.entries.data();
  const double* force_coef = r.force_coef.data();
  const double* radius = p.radius.data();
  Vec3* torque = p.torque.data();
  Vec3* contact_force = ms.contact_force.data();
  const ContactSystem::Sums sums = Contacts ? it.sys.contacts.sums() : ContactSystem::Sums{};
  // The residual's largest component against the force level: the largest of the net
  // forces, the inertial forces m a and the sums of rod force magnitudes on a particle.
  double rmax = 0.0, fmax = 0.0;
#pragma omp parallel for schedule(static) reduction(max : rmax, fmax)
  for (std::size_t i = 0; i < n; ++i) {
    Vec3 f = Vec3::Zero();
    double level = 0.0;
    const Vec3 xi = x[i];
    for (std::int32_t e = row_start[i]; e < row_start[i + 1]; ++e) {
      const Rods::Entry en = entries[e];
      const double c = force_coef[en.rod];
      Vec3 dx = x[en.other] - xi;
      if constexpr (Wrap) periodic.wrap(dx);
      f += c * dx;
      level += std::abs(c);
    }
    if constexpr (Contacts) {
      // (the gather's sums, in the same order: the torques drive the rotations' placement,
      // the contact forces the step's contact power)
      Vec3 fc = Vec3::Zero(), tau = Vec3::Zero();
      sums.add(i, radius[i], fc, tau);
      f += fc;
      contact_force[i] = fc;
      torque[i] = tau;
    }
    f += mass[i] * gravity;
    force[i] = f;
    const std::uint8_t mask = prescribed[i];
    Vec3 ma = mass[i] * acc[i];
    Vec3 ff = f;
    if (mask)
      for (int c = 0; c < 3; ++c)
        if (mask & (1u << c)) {
          acc[i][c] = inv_mass[i] * f[c];  // (as the gather: the prescribed components are not placed from it)
          ma[c] = ff[c] = 0.0;
        }
    const Vec3 ri = ma - ff;
    res[i] = ri;
    const double r2 = ri.squaredNorm();
    rmax = std::max(rmax, std::isnan(r2) ? HUGE_VAL : r2);
    fmax = std::max({fmax, ff.squaredNorm(), ma.squaredNorm(), level * level * d * d});
  }
  const double floor = kForceFloorStrain * it.set.stiffness_scale * d;
  fmax = std::max(fmax, floor * floor);
  ms.newton.level2 = fmax;
  return std::sqrt(rmax / fmax);
}

double newton_residual(Integration& it, double h) {
  World& world = it.world;
  MotionState& ms = it.ms;
  ms.sweep_dt = h;
  const bool wrap = world.periodic.on();
  if (it.sys.contacts.enabled())
    return wrap ? newton_residual_impl<true, true>(it) : newton_residual_impl<false, true>(it);
  return wrap ? newton_residual_impl<true, false>(it) : newton_residual_impl<false, false>(it);
}

void newton_tangent(Integration& it, double h) {
  World& world = it.world;
  MotionState& ms = it.ms;
  const auto& p = world.particles;
  const auto& r = world.rods;
  const std::size_t n = p.size(), m = r.size();
  ms.newton.axis.resize(m);
  ms.newton.axial.resize(m);
  ms.newton.lateral.resize(m);
  RodTangentView v;
  v.rods = m;
  v.ends = r.ends.data();
  v.rest_length = r.rest_length.data();
  v.shift = r.shift.data();
  v.trial_shift = r.trial_shift.data();
  v.intact = r.intact.data();
  v.trial_broken = r.trial_broken.data();
  v.coef = r.force_coef.data();
  v.x = p.position.data();
  v.v = p.velocity.data();
  v.temperature = p.temperature.empty() ? nullptr : p.temperature.data();  // (as RodSystem::forces)
  v.rate_x = ms.x_n.data();  // (the lagged rate factor, as rod_forces(it, true))
  v.rate_v = ms.v_n.data();
  v.axis = ms.newton.axis.data();
  v.axial = ms.newton.axial.data();
  v.lateral = ms.newton.lateral.data();
  if (m > 0) rod_tangent_setup(r.law, r.area, it.set.beta * h * h, it.set.gamma * h, v, world.periodic);
  const bool contacts = it.sys.contacts.enabled();
  if (contacts) it.sys.contacts.tangent(p, h, it.set.beta * h * h, it.set.gamma * h);
  if (ms.newton.preconditioner) {
    // A preconditioner of the assembled J in place of the block-Jacobi (tangent_matrix.h).
    if (!ms.newton.preconditioner->wants_tangent(3 * n)) return;
    assemble_tangent(it, ms.newton.matrix);
    ms.newton.preconditioner->setup(ms.newton.matrix);
    return;
  }
  ms.newton.block_inverse.resize(n);
  const ContactSystem::TangentRows ct = contacts ? it.sys.contacts.tangent_rows() : ContactSystem::TangentRows{};
  // Block-Jacobi: particle i's 3x3 diagonal block m_i I + sum of its rods' S_k, with the
  // prescribed components' rows and columns replaced by the identity (their d stays 0).
  const double* mass = p.mass.data();
  const std::uint8_t* prescribed = p.prescribed.data();
  const std::int32_t* row_start = r.row_start.data();
  const Rods::Entry* entries = r.entries.data();
  const Vec3* axis = ms.newton.axis.data();
  const double* axial = ms.newton.axial.data();
  const double* lateral = ms.newton.lateral.data();
  Eigen::Matrix3d* inv = ms.newton.block_inverse.data();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    Eigen::Matrix3d b = mass[i] * Eigen::Matrix3d::Identity();
    for (std::int32_t e = row_start[i]; e < row_start[i + 1]; ++e) {
      const std::int32_t k = entries[e].rod;
      b.diagonal().array() += lateral[k];
      b.noalias() += axial[k] * (axis[k] * axis[k].transpose());
    }
    if (contacts) ct.add_diagonal(i, b);
    const std::uint8_t mask = prescribed[i];
    if (mask)
      for (int c = 0; c < 3; ++c)
        if (mask & (1u << c)) {
          b.row(c).setZero();
          b.col(c).setZero();
          b(c, c) = 1.0;
        }
    inv[i] = b.inverse();
  }
}

void newton_product(Integration& it, const std::vector<Vec3>& x, std::vector<Vec3>& out, double& dot) {
  World& world = it.world;
  MotionState& ms = it.ms;
  const auto& p = world.particles;
  const auto& r = world.rods;
  const std::size_t n = p.size();
  const double* mass = p.mass.data();
  const std::uint8_t* prescribed = p.prescribed.data();
  const std::int32_t* row_start = r.row_start.data();
  const Rods::Entry* entries = r.entries.data();
  const Vec3* axis = ms.newton.axis.data();
  const double* axial = ms.newton.axial.data();
  const double* lateral = ms.newton.lateral.data();
  const Vec3* xs = x.data();
  Vec3* o = out.data();
  ++ms.newton_stats.tangent_products;
  const bool contacts = it.sys.contacts.enabled();
  const ContactSystem::TangentRows ct = contacts ? it.sys.contacts.tangent_rows() : ContactSystem::TangentRows{};
  // (J x)_i = m_i x_i - sum over i's rods of S_k (x_other - x_i), in the rows' order.
  dot = deterministic_sum(n, [&](std::size_t i) {
    Vec3 s = mass[i] * xs[i];
    const Vec3 xi = xs[i];
    for (std::int32_t e = row_start[i]; e < row_start[i + 1]; ++e) {
      const Rods::Entry en = entries[e];
      const std::int32_t k = en.rod;
      s -= rod_block_times(axis[k], axial[k], lateral[k], xs[en.other] - xi);
    }
    if (contacts) s += ct.times(i, xs);
    mask_prescribed(s, prescribed[i]);
    o[i] = s;
    return xs[i].dot(s);
  });
}

int newton_krylov(Integration& it) {
  World& world = it.world;
  MotionState& ms = it.ms;
  const std::size_t n = world.particles.size();
  NewtonWork& w = ms.newton;
  w.d.assign(n, Vec3::Zero());
  w.r.resize(n);
  w.z.resize(n);
  w.p.resize(n);
  w.q.resize(n);
  Vec3 *d = w.d.data(), *r = w.r.data(), *z = w.z.data(), *pp = w.p.data();
  const Vec3* q = w.q.data();
  const Vec3* res = w.residual.data();
  const Eigen::Matrix3d* inv = w.block_inverse.data();
  LinearPreconditioner* pc = w.preconditioner.get();
  const std::uint8_t* prescribed = world.particles.prescribed.data();
  // z = P r for a preconditioner handed in (its prescribed components kept at 0, as the
  // block-Jacobi's unit rows keep them), then the two sums over the rows.
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "the preconditioner reads the Vec3 arrays as 3 n doubles");
  auto external = [&]() {
    pc->apply(r->data(), z->data());
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) mask_prescribed(z[i], prescribed[i]);
    return deterministic_sums2(n, [&](std::size_t i) {
      return std::array<double, 2>{r[i].dot(z[i]), r[i].squaredNorm()};
    });
  };
  if (pc) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) r[i] = -res[i];
  }
  auto [rz, rr] = pc ? external() : deterministic_sums2(n, [&](std::size_t i) {
    r[i] = -res[i];
    z[i] = inv[i] * r[i];
    pp[i] = z[i];
    return std::array<double, 2>{r[i].dot(z[i]), r[i].squaredNorm()};
  });
  if (pc) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) pp[i] = z[i];
  }
  if (rr == 0.0) return 0;
  // Stop at krylov_tolerance of the Newton residual, or as soon as the linear residual is
  // below half the Newton tolerance of the force level (2-norm, so every particle's too):
  // solving further would buy nothing the Newton test can see, and a step that starts near
  // its solution (slow loading, a good predictor) then needs one short solve.
  const double eta = it.set.krylov_tolerance, half_tol = 0.5 * it.set.tolerance;
  const double target = std::max(eta * eta * rr, half_tol * half_tol * ms.newton.level2);
  const int kmax = it.set.krylov_max_iterations;
  int k = 0;
  while (k < kmax) {
    ++k;
    ++ms.newton_stats.krylov_iterations;
    double pq = 0.0;
    newton_product(it, w.p, w.q, pq);
    if (!(pq > 0.0)) return -1;  // J is not positive definite on this direction (or NaN)
    const double alpha = rz / pq;
    if (pc) {
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < n; ++i) {
        d[i] += alpha * pp[i];
        r[i] -= alpha * q[i];
      }
    }
    const auto [rz_new, rr_new] = pc ? external() : deterministic_sums2(n, [&](std::size_t i) {
      d[i] += alpha * pp[i];
      r[i] -= alpha * q[i];
      z[i] = inv[i] * r[i];
      return std::array<double, 2>{r[i].dot(z[i]), r[i].squaredNorm()};
    });
    if (rr_new <= target) break;
    const double b = rz_new / rz;
    rz = rz_new;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) pp[i] = z[i] + b * pp[i];
  }
  return k;
}

}  // namespace

bool newton_try(Integration& it, double h) {
  World& world = it.world;
  MotionState& ms = it.ms;
  const StepSettings& g = it.set;
  if (!prescribe(it, h)) return false;  // (a mesh would move too far in the step: a shorter one)
  it.clock.lap(Stage::Prescribe);
  auto& acc = world.particles.acceleration;
  const std::size_t n = acc.size();
  const double kx = g.beta * h * h;
  int solves = 0, growing = 0, cg_total = 0;
  bool capped = false;
  double previous = HUGE_VAL, before_previous = HUGE_VAL, correction = HUGE_VAL;
  while (true) {
    if (!place(it, h)) return false;  // also rejects a particle moving further than max_step_displacement
    it.clock.lap(Stage::Integrate);
    rod_forces(it, /*lagged_rate=*/true);
    it.clock.lap(Stage::Rods);
    contact_forces(it, h);  // (the trial evaluation from the committed histories, as the sweeps')
    const double res = newton_residual(it, h);
    it.clock.lap(Stage::Gather);
    if (!std::isfinite(res)) return false;
    // Converged: the residual is small against the force level, or the last correction
    // moved the particles by little against the step's displacement (fast motion through
    // unstressed states, where the force level vanishes; the same two measures as the gather).
    if (res <= g.tolerance || correction <= g.tolerance) break;
    if (solves >= g.max_iterations) return false;
    // Newton near the solution shrinks the residual every iteration; two growing in a row
    // mean it is not converging (a step too long for the nonlinearity): give up early.
    growing = res > previous && res > 10.0 * g.tolerance ? growing + 1 : 0;
    if (growing >= 2) return false;
    // Nor does it stall: a rod or a contact that flips its branch at every iteration (a
    // piecewise-linear law, a contact at the edge of touching) makes a 2-cycle whose
    // residuals alternate, so they never grow twice in a row. Seen on the cut: 25 iterations
    // between the same two residuals before the step was rejected anyway. From the fourth
    // iteration on, the residual must have halved over the last two.
    if (solves >= 3 && res > 0.5 * before_previous && res > 10.0 * g.tolerance) return false;
    before_previous = previous;
    previous = res;
    newton_tangent(it, h);
    const int cg = newton_krylov(it);
    it.clock.lap(Stage::Krylov);
    ++solves;
    ++ms.newton_stats.solves;
    if (cg < 0) {
      ++ms.newton_stats.indefinite;
      return false;
    }
    cg_total += cg;
    if (cg >= g.krylov_max_iterations) {
      capped = true;
      ++ms.newton_stats.krylov_capped;
    }
    double dmax2 = 0.0;
    const Vec3* d = ms.newton.d.data();
    Vec3* a = acc.data();
#pragma omp parallel for schedule(static) reduction(max : dmax2)
    for (std::size_t i = 0; i < n; ++i) {
      a[i] += d[i];  // (d is zero in the prescribed components)
      dmax2 = std::max(dmax2, d[i].squaredNorm());
    }
    correction = ms.step_disp2 > 0.0 ? kx * std::sqrt(dmax2 / ms.step_disp2) : HUGE_VAL;
  }
  // The rotations of particles without rods were placed with the torques of the evaluation
  // before the last; place them (and nothing else: a is unchanged) with the converged ones,
  // as the sweeps do after their last gather.
  if (ms.rotations && !ms.free_list.empty() && !place(it, h)) return false;
  it.stats.last_iterations = solves;
  it.stats.iterations += solves;
  it.stats.max_iterations = std::max(it.stats.max_iterations, solves);
  ms.newton_stats.last_krylov = cg_total;
  ms.newton_stats.last_capped = capped;
  return true;
}

}  // namespace swarf::integrate
