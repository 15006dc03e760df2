// simulation.cpp: velocity Verlet with rods, stage by stage (see simulation.h).
#include "simulation.h"

#include <cmath>
#include <fmt/format.h>

#include "errors.h"
#include "parallel.h"

namespace swarf {

Simulation::Simulation(Model& model) : m_(model) {
  dt_ = m_.derived.dt;
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
  // Forces of the initial state (nothing committed: the first step re-evaluates them).
  rod_forces();
  gather();
  compute_reactions(reaction_);
  broken_ = m_.rods.broken_count();
}

void Simulation::step() {
  predict();
  rod_forces();
  gather();
  correct();
  commit();
  account();
}

void Simulation::predict() {
  auto& p = m_.particles;
  const double t_new = time_ + dt_;
  for (std::size_t g = 0; g < m_.groups.size(); ++g) {
    group_u_old_[g] = m_.groups[g].motion.displacement_at(time_);
    group_u_new_[g] = m_.groups[g].motion.displacement_at(t_new);
  }
  const double half = 0.5 * dt_, dt = dt_;
  const double limit = m_.settings.integrator.max_step_displacement;
  const std::size_t n = p.size();
  int bad = 0;
#pragma omp parallel for schedule(static) reduction(max : bad)
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 x_old = p.position[i];
    if (p.prescribed[i] == 0) {
      p.velocity[i] += half * p.acceleration[i];
      p.position[i] += dt * p.velocity[i];
    } else {
      const std::int32_t g = p.group[i];
      const std::uint8_t mask = p.prescribed[i];
      for (int c = 0; c < 3; ++c) {
        if (mask & (1u << c)) {
          p.position[i][c] = p.initial_position[i][c] + group_u_new_[g][c];
          p.velocity[i][c] = (group_u_new_[g][c] - group_u_old_[g][c]) / dt;
        } else {
          p.velocity[i][c] += half * p.acceleration[i][c];
          p.position[i][c] += dt * p.velocity[i][c];
        }
      }
    }
    const double q = (p.position[i] - x_old).squaredNorm() / (p.radius[i] * p.radius[i]);
    if (!(q <= limit * limit)) bad = 1;  // also catches NaN
  }
  if (bad) {
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 v = p.velocity[i];
      const double moved = v.norm() * dt / p.radius[i];
      if (!(moved <= limit) || !p.position[i].allFinite()) {
        throw SimulationError(fmt::format(
            "unstable: particle {} (at {:.6g}, {:.6g}, {:.6g} m) moved {:.3g} radii in step {} at t = {:.6g} s "
            "(limit integrator.max_step_displacement = {}); speed {:.4g} m/s. The step dt = {:.4g} s may be "
            "too large for the loads, or the input drives the lattice too hard",
            i, p.position[i][0], p.position[i][1], p.position[i][2], moved, steps_ + 1, t_new, limit, v.norm(), dt));
      }
    }
    throw SimulationError(fmt::format("unstable: non-finite state in step {} at t = {:.6g} s", steps_ + 1, t_new));
  }
}

namespace {

// The rod kernel over one block of rods. Raw pointers keep the compiler from reloading the
// arrays' bases after every store (the uint8_t stores may alias anything). 'Viscous' is a
// compile-time switch so the undamped lattice does not gather velocities.
template <bool Viscous>
void rod_block(const RodLaw& law, double A, std::size_t begin, std::size_t end, const std::array<std::int32_t, 2>* ends,
               const double* rest_length, const double* inv_rest_length, const double* shift, const std::uint8_t* intact, const Vec3* x, const Vec3* v,
               double* trial_shift, std::uint8_t* trial_broken, double* stress, double* coef, double& viscous_power,
               int& changed) {
  double visc = 0.0;
  int any = 0;
  for (std::size_t k = begin; k < end; ++k) {
    if (!intact[k]) continue;
    const std::int32_t i = ends[k][0], j = ends[k][1];
    const Vec3 dx = x[j] - x[i];
    const double len = dx.norm();
    const double inv_len = 1.0 / len;
    const double l0 = rest_length[k];
    const double inv_l0 = inv_rest_length[k];
    const double strain = (len - l0) * inv_l0;
    double rate = 0.0;
    if constexpr (Viscous) rate = dx.dot(v[j] - v[i]) * inv_len * inv_l0;
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
  viscous_power = visc;
  changed = any;
}

}  // namespace

void Simulation::rod_forces() {
  auto& r = m_.rods;
  const auto& p = m_.particles;
  const RodLaw law = r.law;
  const double A = r.area;
  const std::size_t m = r.size(), nb = block_count(m);
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
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < nb; ++b) {
    const std::size_t begin = b * kBlock, end = std::min(m, (b + 1) * kBlock);
    if (viscous)
      rod_block<true>(law, A, begin, end, ends, l0, inv_l0, shift, intact, x, v, trial_shift, trial_broken, stress, coef,
                      block_visc[b], block_changed[b]);
    else
      rod_block<false>(law, A, begin, end, ends, l0, inv_l0, shift, intact, x, v, trial_shift, trial_broken, stress, coef,
                       block_visc[b], block_changed[b]);
  }
}

void Simulation::gather() {
  auto& p = m_.particles;
  const auto& r = m_.rods;
  const std::size_t n = p.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    Vec3 f = Vec3::Zero();
    const Vec3 xi = p.position[i];
    for (std::int32_t e = r.row_start[i]; e < r.row_start[i + 1]; ++e) {
      const Rods::Entry en = r.entries[e];
      f += r.force_coef[en.rod] * (p.position[en.other] - xi);
    }
    p.force[i] = f;
    p.acceleration[i] = p.inv_mass[i] * f;
  }
}

void Simulation::correct() {
  auto& p = m_.particles;
  const double half = 0.5 * dt_;
  const std::size_t n = p.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t mask = p.prescribed[i];
    if (mask == 0) {
      p.velocity[i] += half * p.acceleration[i];
    } else {
      for (int c = 0; c < 3; ++c)
        if (!(mask & (1u << c))) p.velocity[i][c] += half * p.acceleration[i][c];
    }
  }
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
#pragma omp parallel for schedule(static)
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
      }
    }
  }
  for (std::size_t b = 0; b < nb; ++b) {
    ledger_.plastic_work += plastic[b];
    ledger_.fracture_energy += fracture[b];
    broken_ += broke[b];
  }
}

void Simulation::compute_reactions(std::vector<Vec3>& out) const {
  const auto& p = m_.particles;
  out.assign(m_.groups.size(), Vec3::Zero());
  for (std::size_t g = 0; g < m_.groups.size(); ++g)
    for (auto i : m_.groups[g].members) out[g] -= p.force[i];
}

void Simulation::account() {
  double visc = 0.0;
  for (double v : block_viscous_) visc += v;
  ledger_.viscous_work += visc * dt_;
  reaction_old_.swap(reaction_);
  compute_reactions(reaction_);
  for (std::size_t g = 0; g < m_.groups.size(); ++g) {
    const Vec3 du = group_u_new_[g] - group_u_old_[g];
    const Vec3 v = du / dt_;
    for (int c = 0; c < 3; ++c) {
      if (!(m_.groups[g].dofs & (1u << c))) continue;
      // Work on the body through the reaction, plus the work that changes the prescribed
      // particles' own kinetic energy (a grip that starts or reverses accelerates them).
      ledger_.external_work += 0.5 * (reaction_old_[g][c] + reaction_[g][c]) * du[c];
      ledger_.external_work += 0.5 * group_mass_[g] * (v[c] * v[c] - group_v_[g][c] * group_v_[g][c]);
    }
    group_v_[g] = v;
  }
  time_ += dt_;
  ++steps_;
}

double Simulation::kinetic_energy() const {
  const auto& p = m_.particles;
  return deterministic_sum(p.size(), [&](std::size_t i) { return 0.5 * p.mass[i] * p.velocity[i].squaredNorm(); });
}

double Simulation::elastic_energy() const {
  const auto& r = m_.rods;
  const double A = r.area;
  return deterministic_sum(r.size(), [&](std::size_t k) {
    return r.intact[k] ? elastic_energy_density(r.law, r.stress[k]) * A * r.rest_length[k] : 0.0;
  });
}

}  // namespace swarf
