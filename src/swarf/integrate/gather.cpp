// gather.cpp: the gather stage: each particle's rod and contact forces summed in a
// fixed order, the accelerations, the convergence measure of the Newmark sweeps, and the
// explicit scheme's corrector fused with it (see integration.h).
#include <omp.h>

#include <algorithm>
#include <cmath>

#include "swarf/core/parallel.h"
#include "swarf/integrate/integration.h"

namespace swarf::integrate {

namespace {
constexpr double kForceFloorStrain = 1e-8;  // see gather_impl
constexpr int kGatherTimed = 64;            // gathers timed before the threads' ranges move
enum class GatherMode { Plain, Measure, Kick };

// Moves the gather's block boundaries so that each thread's predicted time is the same: a
// thread's blocks are taken to cost its measured time over their number each, and the
// boundaries go halfway to where that cost profile splits evenly (halfway: the cost is not
// uniform within a thread's range, and a full move could swing back and forth). Only which
// thread sums which block changes, never a result.
void rebalance_gather(std::vector<std::size_t>& split, const std::vector<double>& seconds) {
  const std::size_t nt = seconds.size(), nb = split.back();
  double total = 0.0;
  for (std::size_t t = 0; t < nt; ++t) {
    if (!(seconds[t] >= 0.0) || !std::isfinite(seconds[t])) return;
    total += seconds[t];
  }
  if (!(total > 0.0)) return;
  std::vector<std::size_t> next(split);
  std::size_t t = 0;
  double before = 0.0;  // the predicted time of the blocks before split[t]
  for (std::size_t k = 1; k < nt; ++k) {
    const double target = total * static_cast<double>(k) / static_cast<double>(nt);
    while (t < nt && before + seconds[t] < target) before += seconds[t++];
    if (t >= nt) break;
    const std::size_t blocks = split[t + 1] - split[t];
    const double per_block = blocks > 0 ? seconds[t] / static_cast<double>(blocks) : 0.0;
    const double x = per_block > 0.0 ? static_cast<double>(split[t]) + (target - before) / per_block
                                     : static_cast<double>(split[t]);
    const double moved = 0.5 * (static_cast<double>(split[k]) + std::min(x, static_cast<double>(nb)));
    next[k] = std::clamp(static_cast<std::size_t>(std::lround(moved)), next[k - 1], nb);
  }
  split = next;
}

// The particles' part of the sweep's convergence measure, for the bodies' part.
SweepMeasure sweep_measure(const Integration& it) {
  return {it.implicit, it.ms.sweep_dt, it.set.beta, it.ms.sweep_force_level2, it.ms.step_disp2};
}

template <GatherMode Mode, bool Wrap>
double gather_impl(Integration& it, double h) {
  World& world = it.world;
  MotionState& ms = it.ms;
  constexpr bool Measure = Mode == GatherMode::Measure, Kick = Mode == GatherMode::Kick;
  auto& p = world.particles;
  const auto& r = world.rods;
  const std::size_t n = p.size();
  const double d = it.set.length_scale;
  const bool contacts = it.sys.contacts.enabled();
  const bool rot = ms.rotations;
  const Vec3 gravity = world.gravity;
  const Periodic periodic = world.periodic;
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
  if constexpr (Kick) ms.block_power.assign(nb, 0.0);
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
  const std::uint8_t* free_to_rotate = ms.free_to_rotate.data();
  const std::int32_t* row_start = r.row_start.data();
  const Rods::Entry* entries = r.entries.data();
  const double* force_coef = r.force_coef.data();
  const Vec3* floor_force = it.sys.rods.floor_force(world);  // (null: no compaction floor)
  Vec3* contact_force = ms.contact_force.data();
  const bool keep_contact_force = ms.keep_contact_force;
  const ContactSystem::Sums sums = contacts ? it.sys.contacts.sums() : ContactSystem::Sums{};
  [[maybe_unused]] const double half = 0.5 * h;
  const bool turn_spheres = it.set.sphere_orientations;
  // One block of particles; dmax_, fmax_, damax_ are the calling thread's reduction copies.
  // (Contacts: a compile-time switch, so that the rods-only loop keeps its registers.)
  auto block = [&]<bool Contacts>(std::size_t b, double& dmax_, double& fmax_, double& damax_) {
    [[maybe_unused]] double power = 0.0;
    const std::size_t end = std::min(n, (b + 1) * kPowerBlock);
    for (std::size_t i = b * kPowerBlock; i < end; ++i) {
      [[maybe_unused]] double level = 0.0;
      const Vec3 xi = x[i];
      // (in scalars: through a Vec3 whose y the wrap may change, the compiler kept the difference
      // in memory and each rod waited on a store and a reload; the same operations, the same bits)
      double f0 = 0.0, f1 = 0.0, f2 = 0.0;
      for (std::int32_t e = row_start[i]; e < row_start[i + 1]; ++e) {
        const Rods::Entry en = entries[e];
        const double c = force_coef[en.rod];
        const Vec3& xo = x[en.other];
        const double d0 = xo[0] - xi[0], d2 = xo[2] - xi[2];
        double d1 = xo[1] - xi[1];
        if constexpr (Wrap) d1 = periodic.wrapped(d1);
        f0 += c * d0;
        f1 += c * d1;
        f2 += c * d2;
        if constexpr (Measure) level += std::abs(c);
      }
      Vec3 f(f0, f1, f2);
      Vec3 fc = Vec3::Zero();
      if constexpr (Contacts) {
        Vec3 tau = Vec3::Zero();
        sums.add(i, radius[i], fc, tau);
        f += fc;
        // (the explicit scheme's power is summed below; a domain counts it per particle)
        if (!Kick || keep_contact_force) contact_force[i] = fc;
        torque[i] = tau;
      }
      f += mass[i] * gravity;
      if (floor_force) f += floor_force[i];
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
            rotate_one(it, i, h, 0.0, 0.5);
        }
        if constexpr (Contacts) power += fc.dot(vel[i]) + (rot ? torque[i].dot(omega[i]) : 0.0);
      }
    }
    if constexpr (Kick) ms.block_power[b] = power;
  };
  // Contiguous ranges of blocks per thread, as the passes that move the particles: each thread
  // finds its particles' data in its own core's cache (dynamic blocks were slower:
  // validation/bench/README.md). Equal ranges are not equal work in a cut (the chip's particles,
  // their rods' other ends scattered by the exchange and their contacts, sit in one thread's
  // range), so the ranges follow the threads' measured times.
  const std::size_t nt = static_cast<std::size_t>(std::max(1, omp_get_max_threads()));
  std::vector<std::size_t>& split = ms.gather_split;
  if (split.size() != nt + 1 || split.back() != nb) {
    split.resize(nt + 1);
    for (std::size_t t = 0; t <= nt; ++t) split[t] = nb * t / nt;
    ms.gather_seconds.assign(nt, 0.0);
    ms.gather_timed = 0;
  }
  bool whole_team = true;
#pragma omp parallel num_threads(static_cast <int>(nt)) reduction(max : dmax, fmax, damax)
  {
    const std::size_t t = static_cast<std::size_t>(omp_get_thread_num());
    const auto sum_block = [&](std::size_t b) {
      if (contacts)
        block.template operator()<true>(b, dmax, fmax, damax);
      else
        block.template operator()<false>(b, dmax, fmax, damax);
    };
    if (static_cast<std::size_t>(omp_get_num_threads()) != nt) {
#pragma omp single
      whole_team = false;  // (fewer threads than asked: the ranges below would miss blocks)
    }
    if (whole_team) {
      const double t0 = omp_get_wtime();
      for (std::size_t b = split[t]; b < split[t + 1]; ++b) sum_block(b);
      ms.gather_seconds[t] += omp_get_wtime() - t0;
    } else {
#pragma omp for schedule(static)
      for (std::size_t b = 0; b < nb; ++b) sum_block(b);
    }
  }
  // Over kGatherTimed gathers at a time: one gather's times carry the machine's noise (a thread
  // descheduled for a moment would move the ranges by what it lost).
  if (whole_team && nt > 1 && ++ms.gather_timed >= kGatherTimed) {
    rebalance_gather(split, ms.gather_seconds);
    std::fill(ms.gather_seconds.begin(), ms.gather_seconds.end(), 0.0);
    ms.gather_timed = 0;
  }
  if constexpr (Measure) ms.sweep_force_level2 = fmax;  // (the bodies' measure compares with it)
  if constexpr (Kick) {
    ms.kick_power = 0.0;
    for (double w : ms.block_power) ms.kick_power += w;
  }
  if (!Measure || dmax == 0.0) return 0.0;
  // A body at rest and unstressed (before the tool touches it) has forces that are rounding
  // noise: measured against them, the sweeps never "converge" and the step shrinks to dt_min
  // (seen as a 2-cycle of a 1e-13 N change at the first contact of a sharp tool). The force
  // level therefore never counts below that of a rod strained by 1e-8.
  const double floor = kForceFloorStrain * it.set.stiffness_scale * d;
  fmax = std::max(fmax, floor * floor);
  // Two scale-aware measures; the iteration has converged when either is small:
  //  - the force change relative to the force level (quasi-static, stressed states);
  //  - the position correction beta h^2 |da| relative to the largest displacement of the
  //    step (fast motion through unstressed states, where the force level vanishes).
  const double by_force = fmax > 0.0 ? std::sqrt(dmax / fmax) : HUGE_VAL;
  const double by_motion = ms.step_disp2 > 0.0 ? it.set.beta * h * h * std::sqrt(damax / ms.step_disp2) : HUGE_VAL;
  return std::min(by_force, by_motion);
}

}  // namespace

double gather(Integration& it) {
  World& world = it.world;
  MotionState& ms = it.ms;
  const double h = ms.sweep_dt;
  double change;
  if (!it.implicit)
    change = world.periodic.on() ? gather_impl<GatherMode::Plain, true>(it, h)
                                 : gather_impl<GatherMode::Plain, false>(it, h);
  else
    change = world.periodic.on() ? gather_impl<GatherMode::Measure, true>(it, h)
                                 : gather_impl<GatherMode::Measure, false>(it, h);
  if (world.bodies.empty()) return change;
  const double bodies = it.sys.bodies.wrenches(
      world, it.sys.contacts, sweep_measure(it));  // (NaN-safe: a NaN change fails the isfinite test of the caller)
  return std::isnan(bodies) ? bodies : std::max(change, bodies);
}

void gather_kick(Integration& it, double h) {
  World& world = it.world;
  if (world.periodic.on())
    gather_impl<GatherMode::Kick, true>(it, h);
  else
    gather_impl<GatherMode::Kick, false>(it, h);
  if (world.bodies.empty()) return;
  it.sys.bodies.wrenches(world, it.sys.contacts, sweep_measure(it));
  it.sys.bodies.kick(world, it.t, h);
}

}  // namespace swarf::integrate
