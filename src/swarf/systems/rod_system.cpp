// rod_system.cpp: the rods' stages (see rod_system.h): the kernel and the parting lines, the
// commit of plasticity and breakage, bond formation and neighbour exchange, the energy.
#include "swarf/systems/rod_system.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "swarf/contacts/contacts.h"
#include "swarf/core/parallel.h"
#include "swarf/core/state_archive.h"
#include "swarf/forces/plastic_volume.h"
#include "swarf/forces/rod_forces.h"

namespace swarf {

void RodSystem::setup(World& m_) {
  floor_.invalidate();
  if (m_.rods.formed.size() != m_.rods.size()) m_.rods.formed.assign(m_.rods.size(), 0);
  broken_ = m_.rods.broken_count();
  // Parting lines: each mesh's lowest reference vertex (the largest x among equals); none
  // without a parting line, so that the rod stage skips them.
  mesh_edge_.clear();
  if (std::any_of(m_.meshes.begin(), m_.meshes.end(), [](const MeshBody& mb) { return mb.parting.enabled(); }))
    mesh_edge_.assign(m_.meshes.size(), Vec3::Zero());
  for (std::size_t k = 0; k < mesh_edge_.size(); ++k) {
    const auto& v = m_.meshes[k].mesh.vertices;
    if (v.empty()) continue;
    Vec3 low = v[0];
    for (const Vec3& p : v)
      if (p[2] < low[2] || (p[2] == low[2] && p[0] > low[0])) low = p;
    mesh_edge_[k] = low;
  }
  block_viscous_.assign(block_count(m_.rods.size()), 0.0);
  block_changed_.assign(block_count(m_.rods.size()), 0);
}

void RodSystem::resize(const World& m_) {
  const std::size_t m = m_.rods.size();
  floor_.invalidate();
  block_viscous_.resize(block_count(m), 0.0);
  block_changed_.resize(block_count(m), 0);
  broken_ = m_.rods.broken_count();
  lattice_.clear();  // (made again from the rods when bond formation next needs it)
}

void RodSystem::forces(World& m_, const Vec3* rate_x, const Vec3* rate_v) {
  auto& r = m_.rods;
  const auto& p = m_.particles;
  if (r.size() == 0) return;  // (no parallel region for nothing: each costs microseconds)
  RodKernelView view;
  view.rods = r.size();
  view.ends = r.ends.data();
  view.rest_length = r.rest_length.data();
  view.shift = r.shift.data();
  view.intact = r.intact.data();
  view.x = p.position.data();
  view.v = p.velocity.data();
  view.temperature = p.temperature.empty() ? nullptr : p.temperature.data();
  view.rate_x = rate_x;
  view.rate_v = rate_v;
  view.trial_shift = r.trial_shift.data();
  view.trial_broken = r.trial_broken.data();
  view.stress = r.stress.data();
  view.coef = r.force_coef.data();
  view.block_viscous = block_viscous_.data();
  view.block_changed = block_changed_.data();
  if (counted_) {
    rod_viscous_.resize(r.size());
    view.rod_viscous = rod_viscous_.data();
  }
  evaluate_rods(r.law, r.area, view, m_.periodic);
  // (the plastic flow kept free of volume change: forces/plastic_volume.h)
  if (r.isochoric)
    keep_plastic_volume(r, p.position.data(), p.size(), m_.periodic, plastic_volume_, block_changed_.data());
  if (!mesh_edge_.empty()) part(m_);
  // (a neighbourhood compacted beyond the onset pushes back: forces/density_floor.h)
  if (r.compaction_modulus > 0.0)
    floor_.evaluate(p.position.data(), p.radius.data(), p.size(), m_.periodic, r.compaction_modulus, r.compaction_onset);
}

void RodSystem::part(World& m_) {
  auto& r = m_.rods;
  const auto& x = m_.particles.position;
  for (std::size_t k = 0; k < m_.meshes.size(); ++k) {
    const PartingRule& rule = m_.meshes[k].parting;
    if (!rule.enabled()) continue;
    const Vec3 edge = mesh_edge_[k] + m_.meshes[k].offset;  // (where the prescribe stage put the mesh)
    for (std::size_t q = 0; q < r.size(); ++q) {
      // (x and z only: a rod across the periodic width along y needs no image)
      if (!r.intact[q] || r.trial_broken[q] || !parts(rule, x[r.ends[q][0]], x[r.ends[q][1]], edge)) continue;
      r.trial_broken[q] = 1;
      r.force_coef[q] = 0.0;
      block_changed_[q / kBlock] = 1;
    }
  }
}

void RodSystem::account(const StepContext& c) {
  double visc = 0.0;
  for (double v : block_viscous_) visc += v;
  c.ledger.viscous_work += visc * c.h;
  if (counted_) {
    if (!runs_ready_) viscous_runs(c.world);
    const double h = c.h;
    exact_.viscous_work.add(exact_sum_of(runs_.size(), [&](std::size_t k, ExactSum& s) { s.add(runs_[k] * h); }));
    runs_ready_ = false;
  }
}

void RodSystem::viscous_runs(const World& w) {
  // (the rods of the last evaluation, index for index: bond formation, which appends and
  // removes rods after it, takes them before it changes them)
  if (rod_viscous_.size() != w.rods.size())
    throw std::logic_error("RodSystem::account: the rods changed since their evaluation under count_exactly");
  // Each run of rods with one first end and consecutive keys summed plainly, in key order,
  // then added exactly: the runs are the same on every partition (all rods of a counted first
  // end are here, in the global order), and one exact add per particle instead of one per rod
  // (the exact add is ten times a plain one: validation/bench/README.md).
  //
  // In blocks, each starting at a rod whose first end differs from the rod's before it: a run
  // starts there in the one loop over all rods too (a run has one first end, and a rod before it
  // that is not counted has a key in between), so the blocks' runs, joined in block order, are
  // that loop's, sum for sum.
  const auto& ends = w.rods.ends;
  const std::size_t m = rod_viscous_.size(), nb = block_count(m);
  const auto block_start = [&](std::size_t k) {
    k = std::min(k, m);
    while (k > 0 && k < m && ends[k][0] == ends[k - 1][0]) ++k;
    return k;
  };
  block_runs_.resize(nb);
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < nb; ++b) {
    std::vector<double>& out = block_runs_[b];
    out.clear();
    double run = 0.0;  // W
    std::int32_t first = -1;
    std::int64_t last = -2;
    for (std::size_t k = block_start(b * kBlock), end = block_start((b + 1) * kBlock); k < end; ++k) {
      if (!counted_[ends[k][0]]) continue;
      const std::int64_t key = keys_ ? keys_[k] : static_cast<std::int64_t>(k);
      if (ends[k][0] != first || key != last + 1) {
        if (first >= 0) out.push_back(run);
        run = 0.0;
        first = ends[k][0];
      }
      run += rod_viscous_[k];
      last = key;
    }
    if (first >= 0) out.push_back(run);
  }
  runs_.clear();
  for (const std::vector<double>& out : block_runs_) runs_.insert(runs_.end(), out.begin(), out.end());
  runs_ready_ = true;
}

double RodSystem::ghost_reach(const World& m_) const {
  const auto& r = m_.rods;
  const auto& x = m_.particles.position;
  double longest2 = 0.0;
  for (std::size_t k = 0; k < r.size(); ++k) {
    if (!r.intact[k]) continue;
    Vec3 d = x[r.ends[k][1]] - x[r.ends[k][0]];
    m_.periodic.wrap(d);
    longest2 = std::max(longest2, d.squaredNorm());
  }
  return std::sqrt(longest2);
}

double RodSystem::elastic_energy(const World& m_) const { return elastic_energy_exact(m_).value(); }

ExactSum RodSystem::elastic_energy_exact(const World& m_, const std::uint8_t* counted) const {
  const auto& r = m_.rods;
  const double A = r.area;
  ExactSum sum = std::visit(  // (one visit: the sum's loop sees the concrete law)
      [&](const auto& law) {
        return exact_sum(r.size(), [&](std::size_t k) {
          return r.intact[k] && (!counted || counted[k])
                     ? elastic_energy_density(law, r.stress[k]) * A * r.rest_length[k]
                     : 0.0;
        });
      },
      r.law);
  // (the floor's energy as its last evaluation found it; not over domains: refused there)
  if (r.compaction_modulus > 0.0 && !counted) sum.add(floor_.energy());
  return sum;
}

void RodSystem::visit_state(StateArchive& ar, World&, EnergyLedger&) {
  ar.scalar("broken_rods", broken_);
  ar.scalar("formed_rods", formed_);
}

namespace {

// The arrays the commit reads and writes, as raw pointers.
struct CommitArrays {
  std::uint8_t* intact;
  const std::uint8_t* trial_broken;
  const std::uint8_t* formed;
  const double* trial_shift;
  const double* rest_length;
  double* shift;
  double* stress;
  const std::array<std::int32_t, 2>* ends;
};

// One block of rods [begin, end): their trial shifts and breaks written back. The law and the
// pointers are this function's own copies: through a closure's references (or through the Rods)
// the compiler reloads every array's base after each uint8_t store, which may alias anything.
// (Measured with callgrind: validation/bench/README.md, the systems restructuring.)
template <class Law>
void commit_block(const Law law, double A, std::size_t begin, std::size_t end, const CommitArrays arrays,
                  double& plastic, double& fracture, std::size_t& broke_original, RodSystem::PairList& pairs,
                  RodSystem::WorkList* works, const std::uint8_t* counted, RodSystem::ExactLedger* exact) {
  std::uint8_t* intact = arrays.intact;
  const std::uint8_t* trial_broken = arrays.trial_broken;
  const std::uint8_t* formed = arrays.formed;
  const double* trial_shift = arrays.trial_shift;
  const double* rest_length = arrays.rest_length;
  double* shift = arrays.shift;
  double* stress = arrays.stress;
  const auto* ends = arrays.ends;
  double plastic_b = 0.0, fracture_b = 0.0;
  std::size_t original = 0;
  for (std::size_t k = begin; k < end; ++k) {
    if (!intact[k]) continue;
    const double dshift = trial_shift[k] - shift[k];
    if (dshift != 0.0) {
      const double wA = plastic_work_density(law, stress[k], dshift) * A;
      const double w = wA * rest_length[k];
      // The sum is the fused multiply-add the compiler made of 'plastic_b += wA * L' before the
      // work list also read the product (a second use stops the contraction); kept so that the
      // ledger's plastic work, and the golden series, keep their bits.
#if defined(__FMA__)
      plastic_b = std::fma(wA, rest_length[k], plastic_b);
#else
      plastic_b += w;
#endif
      if (works)
        works->push_back({ends[k], w, static_cast<std::int32_t>(k),
                          plastic_strain(law, trial_shift[k]) - plastic_strain(law, shift[k])});
      if (exact && counted[ends[k][0]]) exact->plastic_work.add(w);
      shift[k] = trial_shift[k];
    }
    if (trial_broken[k]) {
      intact[k] = 0;
      const double eA = elastic_energy_density(law, stress[k]) * A;
      // (the fused sum the compiler made of 'fracture_b += eA * L' before the exact ledger also
      // read the product, as for the plastic work above: the golden series keep their bits)
#if defined(__FMA__)
      fracture_b = std::fma(eA, rest_length[k], fracture_b);
#else
      fracture_b += eA * rest_length[k];
#endif
      if (exact && counted[ends[k][0]]) exact->fracture_energy.add(eA * rest_length[k]);
      stress[k] = 0.0;
      original += !formed[k];  // (broken_rods counts the lattice's own rods: Rods::broken_count)
      pairs.push_back(ends[k]);
    }
  }
  plastic = plastic_b;
  fracture = fracture_b;
  broke_original = original;
}

}  // namespace

RodSystem::PairList RodSystem::commit(World& m_, EnergyLedger& ledger, WorkList* work) {
  auto& r = m_.rods;
  const double A = r.area;
  const std::size_t m = r.size();
  // Plastic work and fracture energy per rod block, summed in block order.
  const std::size_t nb = block_count(m);
  std::vector<double> plastic(nb, 0.0), fracture(nb, 0.0);
  std::vector<std::size_t> broke_original(nb, 0);
  // The rods that break now, per block: their pairs become contact candidates (and their
  // particles may become free to rotate).
  std::vector<PairList> broken_pairs(nb);
  // (per block, zeroed and merged only where a rod yielded or broke: a domain of millions of rods
  // would otherwise clear a kilobyte per block and step)
  if (counted_ && block_exact_.size() != nb) block_exact_.resize(nb);
  if (work) {
    work->clear();
    if (block_work_.size() != nb) block_work_.resize(nb);
  }
  // One visit: the loop over the blocks sees the concrete law (commit_block).
  std::visit(
      [&](const auto& law) {
        const CommitArrays a{r.intact.data(),      r.trial_broken.data(), r.formed.data(), r.trial_shift.data(),
                             r.rest_length.data(), r.shift.data(),        r.stress.data(), r.ends.data()};
        const int* changed = block_changed_.data();
// (Dynamic: the blocks that yield or break, the costly ones, sit together in the rod order.)
#pragma omp parallel for schedule(dynamic, 1) if (nb > 0)
        for (std::size_t b = 0; b < nb; ++b) {
          WorkList* wb = work ? &block_work_[b] : nullptr;
          if (wb) wb->clear();
          if (!changed[b]) continue;  // no rod of the block yielded or broke
          commit_block(law, A, b * kBlock, std::min(m, (b + 1) * kBlock), a, plastic[b], fracture[b], broke_original[b],
                       broken_pairs[b], wb, counted_, counted_ ? &(block_exact_[b] = ExactLedger{}) : nullptr);
        }
      },
      r.law);
  PairList pairs;
  if (counted_)
    for (std::size_t b = 0; b < nb; ++b)
      if (block_changed_[b]) {
        exact_.plastic_work.add(block_exact_[b].plastic_work);
        exact_.fracture_energy.add(block_exact_[b].fracture_energy);
      }
  for (std::size_t b = 0; b < nb; ++b) {
    ledger.plastic_work += plastic[b];
    ledger.fracture_energy += fracture[b];
    broken_ += broke_original[b];
    pairs.insert(pairs.end(), broken_pairs[b].begin(), broken_pairs[b].end());
    if (work) work->insert(work->end(), block_work_[b].begin(), block_work_[b].end());
  }
  return pairs;
}

void RodSystem::formation_applied(World& w, std::size_t formed, std::int64_t broken_change, std::size_t first_changed) {
  formed_ += formed;
  broken_ = static_cast<std::size_t>(static_cast<std::int64_t>(broken_) + broken_change);
  w.rods.update_rows(first_changed, w.particles.size());
  block_viscous_.resize(block_count(w.rods.size()), 0.0);
  block_changed_.resize(block_count(w.rods.size()), 0);
}

RodSystem::PairList RodSystem::form(World& m_, ContactSystem& contacts, EnergyLedger& ledger) {
  if (x_) {  // (over domains: decided for the whole run; the step's viscous runs taken first)
    if (counted_) viscous_runs(m_);
    return x_->form_rods(*this, m_, contacts);
  }
  auto& r = m_.rods;
  const auto& p = m_.particles;
  if (lattice_.size() != p.size()) {
    lattice_.assign(p.size(), 0);
    for (std::size_t k = 0; k < r.size(); ++k)
      if (!r.formed[k]) lattice_[r.ends[k][0]] = lattice_[r.ends[k][1]] = 1;
  }
  // Candidates are unbonded by construction: bonded pairs are not in the contact lists.
  const auto pressed = contacts.pressed_pairs(
      p, r.formation.overlap, [&](std::int32_t i, std::int32_t j) { return lattice_[i] && lattice_[j]; });
  if (pressed.empty()) return {};
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
      const double strain = d.norm() * (1.0 / r.rest_length[k]) - 1.0;
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
      ledger.fracture_energy += elastic_energy_density(r.law, r.stress[k]) * A * r.rest_length[k];
      r.stress[k] = r.force_coef[k] = 0.0;
      broken_ += !r.formed[k];
      const std::int32_t other = r.ends[k][0] == e[s] ? r.ends[k][1] : r.ends[k][0];
      if (count[other] >= 0) --count[other];
      exchanged.push_back(r.ends[k]);
    }
    formed.push_back(e);
  }
  for (auto i : counted) count[i] = -1;
  if (formed.empty()) return {};
  std::size_t revived = 0;
  const std::size_t m_before = r.size();
  // A rod born at the lattice's length (BondFormation::lattice_length) is born pressed: its
  // elastic energy is booked against the fracture energy (the ledger's line for rods that part
  // and form).
  double formation_energy = 0.0;
  for (const auto& e : formed) {
    Vec3 d = p.position[e[1]] - p.position[e[0]];
    m_.periodic.wrap(d);
    const double distance = d.norm();
    const double length = formed_rest_length(r.formation, distance, p.radius[e[0]], p.radius[e[1]]);
    if (length != distance) {
      const double strain = (distance - length) / length;
      formation_energy += elastic_energy_density(r.law, elastic_modulus(r.law) * strain) * A * length;
    }
    // The pair's broken rod, if it had one, forms again: one rod per pair.
    std::int32_t rod = -1;
    for (std::int32_t q = r.row_start[e[0]]; q < r.row_start[e[0] + 1]; ++q)
      if (r.entries[q].other == e[1]) rod = r.entries[q].rod;
    if (rod < 0) {
      r.append_formed(e[0], e[1], length);
      continue;
    }
    r.rest_length[rod] = length;
    r.shift[rod] = r.trial_shift[rod] = 0.0;
    r.stress[rod] = r.force_coef[rod] = 0.0;
    r.trial_broken[rod] = 0;
    r.intact[rod] = 1;  // (still one of the lattice's rods: 'formed' marks only new pairs)
    revived += !r.formed[rod];
  }
  formed_ += formed.size();
  broken_ -= revived;
  ledger.fracture_energy -= formation_energy;
  // The rows change only when rods were appended or removed (a revived or exchanged rod keeps
  // its index), and then only from the first rod that moved or was appended on: rebuilding them
  // all, serial and O(rods), at every formation was most of its cost.
  const std::size_t first_changed = std::min(r.remove_broken_formed(), m_before);
  if (first_changed < r.size() || r.size() != m_before) {
    r.update_rows(first_changed, p.size());
    block_viscous_.resize(block_count(r.size()), 0.0);
    block_changed_.resize(block_count(r.size()), 0);
  }
  // (only the pairs' particles gained or lost a rod)
  PairList touched = formed;
  touched.insert(touched.end(), exchanged.begin(), exchanged.end());
  contacts.remove_pairs(p, formed);
  contacts.add_pairs(p, std::move(exchanged));
  return touched;
}

}  // namespace swarf
