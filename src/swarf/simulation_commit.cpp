// simulation_commit.cpp: the commit stage (plastic shifts and breakage of the final
// evaluation written back, broken rods' pairs handed to the contact lists) and the account
// stage (energy ledger, reactions, time and counters); see simulation.h.
#include <algorithm>
#include <cmath>

#include "swarf/core/parallel.h"
#include "swarf/simulation.h"

namespace swarf {

void Simulation::commit() {
  auto& r = m_.rods;
  const double A = r.area;
  const std::size_t m = r.size();
  // Plastic work and fracture energy per rod block, summed in block order.
  const std::size_t nb = block_count(m);
  std::vector<double> plastic(nb, 0.0), fracture(nb, 0.0);
  std::vector<std::size_t> broke(nb, 0), broke_original(nb, 0);
  // The rods that break now, per block: their pairs become contact candidates.
  const bool contacts = contacts_.enabled();
  std::vector<std::vector<std::array<std::int32_t, 2>>> broken_pairs(contacts ? nb : 0);
  // Raw pointers and a local law: through 'r' the compiler reloads every array's base after each
  // uint8_t store (which may alias anything), and this loop visits every rod of a changed block.
  std::uint8_t* intact = r.intact.data();
  const std::uint8_t* trial_broken = r.trial_broken.data();
  const std::uint8_t* formed = r.formed.data();
  const double* trial_shift = r.trial_shift.data();
  const double* rest_length = r.rest_length.data();
  double* shift = r.shift.data();
  double* stress = r.stress.data();
  const auto* ends = r.ends.data();
  const int* changed = block_changed_.data();
  // One visit: the loop over the rods sees the concrete law, copied into a local.
  std::visit(
      [&](const auto& rod_law) {
        const auto law = rod_law;
#pragma omp parallel for schedule(static) if (nb > 0)
        for (std::size_t b = 0; b < nb; ++b) {
          if (!changed[b]) continue;  // no rod of the block yielded or broke
          const std::size_t end = std::min(m, (b + 1) * kBlock);
          double plastic_b = 0.0, fracture_b = 0.0;
          for (std::size_t k = b * kBlock; k < end; ++k) {
            if (!intact[k]) continue;
            const double dshift = trial_shift[k] - shift[k];
            if (dshift != 0.0) {
              plastic_b += plastic_work_density(law, stress[k], dshift) * A * rest_length[k];
              shift[k] = trial_shift[k];
            }
            if (trial_broken[k]) {
              intact[k] = 0;
              fracture_b += elastic_energy_density(law, stress[k]) * A * rest_length[k];
              stress[k] = 0.0;
              ++broke[b];
              broke_original[b] += !formed[k];  // (broken_rods counts the lattice's own rods: Rods::broken_count)
              if (contacts) broken_pairs[b].push_back(ends[k]);
            }
          }
          plastic[b] = plastic_b;
          fracture[b] = fracture_b;
        }
      },
      r.law);
  bool any_broke = false;
  for (std::size_t b = 0; b < nb; ++b) {
    ledger_.plastic_work += plastic[b];
    ledger_.fracture_energy += fracture[b];
    broken_ += broke_original[b];
    any_broke = any_broke || broke[b] > 0;
  }
  if (contacts && implicit_) contacts_.commit();  // explicit: committed by the final evaluation
  if (contacts && any_broke) {
    // Added to the lists as they are: a full rebuild for each break is far dearer
    // (validation/bench/README.md).
    std::vector<std::array<std::int32_t, 2>> fresh;
    for (const auto& v : broken_pairs) fresh.insert(fresh.end(), v.begin(), v.end());
    contacts_.add_pairs(m_.particles, std::move(fresh));
  }
  if (any_broke && rotations_) {
    std::vector<std::array<std::int32_t, 2>> pairs;
    for (const auto& v : broken_pairs) pairs.insert(pairs.end(), v.begin(), v.end());
    update_free_to_rotate(pairs);
  }
  if (contacts && r.formation.enabled()) form_rods();
}

void Simulation::form_rods() {
  auto& r = m_.rods;
  const auto& p = m_.particles;
  if (lattice_.size() != p.size()) {
    lattice_.assign(p.size(), 0);
    for (std::size_t k = 0; k < r.size(); ++k)
      if (!r.formed[k]) lattice_[r.ends[k][0]] = lattice_[r.ends[k][1]] = 1;
  }
  // Candidates are unbonded by construction: bonded pairs are not in the contact lists.
  const auto pressed = contacts_.pressed_pairs(
      p, r.formation.overlap, [&](std::int32_t i, std::int32_t j) { return lattice_[i] && lattice_[j]; });
  if (pressed.empty()) return;
  // Intact rods per particle, so that none gets more than the lattice's coordination.
  auto intact_rods = [&](std::int32_t i) {
    int c = 0;
    for (std::int32_t q = r.row_start[i]; q < r.row_start[i + 1]; ++q) c += r.intact[r.entries[q].rod];
    return c;
  };
  // Counted once per particle and step, in a scratch array that is reset for the particles
  // touched (the same pressed pairs come back at every step of a cut).
  std::vector<int>& count = intact_count_;
  if (count.size() != p.size()) count.assign(p.size(), -1);
  std::vector<std::int32_t> counted;
  std::vector<std::array<std::int32_t, 2>> formed, exchanged;
  const double A = r.area;
  // Neighbour exchange: a particle at the coordination gives up its most stretched rod for
  // the new one (none stretched: no new rod).
  auto most_stretched = [&](std::int32_t i) {
    std::int32_t best = -1;
    double worst = 0.0;
    for (std::int32_t q = r.row_start[i]; q < r.row_start[i + 1]; ++q) {
      const std::int32_t k = r.entries[q].rod;
      if (!r.intact[k]) continue;
      Vec3 d = p.position[r.entries[q].other] - p.position[i];
      m_.periodic.wrap(d);
      const double strain = d.norm() * r.inv_rest_length[k] - 1.0;
      if (strain > worst) {
        worst = strain;
        best = k;
      }
    }
    return best;
  };
  for (const auto& e : pressed) {
    for (auto i : e)
      if (count[i] < 0) {
        count[i] = intact_rods(i);
        counted.push_back(i);
      }
    std::int32_t give[2] = {-1, -1};
    bool ok = true;
    for (int s = 0; s < 2 && ok; ++s) {
      if (may_form(r.formation, count[e[s]])) continue;
      give[s] = r.formation.exchange ? most_stretched(e[s]) : -1;
      ok = give[s] >= 0 && give[s] != give[1 - s];
    }
    if (!ok) continue;
    for (int s = 0; s < 2; ++s) {
      if (give[s] < 0) {
        ++count[e[s]];
        continue;
      }
      const std::int32_t k = give[s];
      r.intact[k] = 0;
      // (A visit for one rod: a few rods per step at the most.)
      ledger_.fracture_energy += elastic_energy_density(r.law, r.stress[k]) * A * r.rest_length[k];
      r.stress[k] = r.force_coef[k] = 0.0;
      broken_ += !r.formed[k];
      const std::int32_t other = r.ends[k][0] == e[s] ? r.ends[k][1] : r.ends[k][0];
      if (count[other] >= 0) --count[other];
      exchanged.push_back(r.ends[k]);
    }
    formed.push_back(e);
  }
  for (auto i : counted) count[i] = -1;
  if (formed.empty()) return;
  std::size_t revived = 0;
  const std::size_t m_before = r.size();
  for (const auto& e : formed) {
    Vec3 d = p.position[e[1]] - p.position[e[0]];
    m_.periodic.wrap(d);
    const double length = d.norm();
    // The pair's broken rod, if it had one, forms again: one rod per pair.
    std::int32_t rod = -1;
    for (std::int32_t q = r.row_start[e[0]]; q < r.row_start[e[0] + 1]; ++q)
      if (r.entries[q].other == e[1]) rod = r.entries[q].rod;
    if (rod < 0) {
      r.append_formed(e[0], e[1], length);
      continue;
    }
    r.rest_length[rod] = length;
    r.inv_rest_length[rod] = 1.0 / length;
    r.shift[rod] = r.trial_shift[rod] = 0.0;
    r.stress[rod] = r.force_coef[rod] = 0.0;
    r.trial_broken[rod] = 0;
    r.intact[rod] = 1;  // (still one of the lattice's rods: 'formed' marks only new pairs)
    revived += !r.formed[rod];
  }
  formed_ += formed.size();
  broken_ -= revived;
  // The rows change only when rods were appended or removed (a revived or exchanged rod keeps
  // its index), and then only from the first rod that moved or was appended on: rebuilding them
  // all, serial and O(rods), at every formation was most of its cost.
  const std::size_t first_changed = std::min(r.remove_broken_formed(), m_before);
  if (first_changed < r.size() || r.size() != m_before) {
    r.update_rows(first_changed, p.size());
    block_viscous_.resize(block_count(r.size()), 0.0);
    block_changed_.resize(block_count(r.size()), 0);
  }
  if (rotations_) {  // (only the pairs' particles gained or lost a rod)
    std::vector<std::array<std::int32_t, 2>> touched = formed;
    touched.insert(touched.end(), exchanged.begin(), exchanged.end());
    update_free_to_rotate(touched);
  }
  contacts_.remove_pairs(p, formed);
  contacts_.add_pairs(p, std::move(exchanged));
}

void Simulation::compute_reactions(std::vector<Vec3>& out) const {
  const auto& p = m_.particles;
  out.assign(m_.groups.size(), Vec3::Zero());
  for (std::size_t g = 0; g < m_.groups.size(); ++g)
    for (auto i : m_.groups[g].members) out[g] -= p.force[i];
}

void Simulation::account(double h) {
  if (!m_.bodies.empty()) {  // the bodies' external loads (gravity: potential_energy())
    const double power = body_load_power();
    ledger_.external_work += 0.5 * (body_power_old_ + power) * h;
    body_power_old_ = power;
  }
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
      if (mesh_body_[k] < 0)  // (a body's mesh is moved by the contacts, not by a prescription)
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

}  // namespace swarf
