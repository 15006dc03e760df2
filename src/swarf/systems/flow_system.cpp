// flow_system.cpp: inflow and outflow regions after each accepted step (see flow_system.h).
#include "swarf/systems/flow_system.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "swarf/core/bounds.h"
#include "swarf/core/errors.h"
#include "swarf/core/nan_safe.h"
#include "swarf/core/state_archive.h"
#include "swarf/state/particle_flows.h"

namespace swarf {

namespace {

bool good_box(const Vec3& lo, const Vec3& hi) {
  return all_finite(lo) && all_finite(hi) && lo[0] <= hi[0] && lo[1] <= hi[1] && lo[2] <= hi[2];
}

}  // namespace

void FlowSystem::setup(const World& m_) {
  for (std::size_t k = 0; k < m_.inflows.size(); ++k) {
    const Inflow& f = m_.inflows[k];
    const auto bad = [&](const std::string& why) { throw InputError(fmt::format("inflow {}: {}", k, why)); };
    if (!good_box(f.box_min, f.box_max)) bad("its box must be finite with box_min <= box_max (m)");
    if (!(finite_bits(f.rate) && f.rate >= 0.0)) bad("its rate must be finite and >= 0 (particles per second)");
    if (!(finite_bits(f.radius_min) && finite_bits(f.radius_max) && f.radius_min >= kMinRadius &&
          f.radius_max >= f.radius_min && f.radius_max <= kMaxRadius))
      bad(fmt::format("its radii must satisfy {:g} m <= radius_min <= radius_max <= {:g} m", kMinRadius, kMaxRadius));
    if (!(finite_bits(f.density) && f.density > 0.0)) bad("its density must be finite and > 0 (kg/m^3)");
    if (!all_finite(f.velocity)) bad("its velocity must be finite (m/s)");
    if (!(finite_bits(f.overlap) && f.overlap >= 0.0 && f.overlap < 1.0)) bad("its overlap must lie in [0, 1)");
    if (f.attempts < 1) bad("it needs at least 1 attempt per particle");
  }
  for (std::size_t k = 0; k < m_.outflows.size(); ++k) {
    const Outflow& o = m_.outflows[k];
    if (o.is_plane() && !(all_finite(o.plane_point) && all_finite(o.plane_normal)))
      throw InputError(fmt::format("outflow {}: its plane's point (m) and normal must be finite", k));
    if (!o.is_plane() && !good_box(o.box_min, o.box_max))
      throw InputError(fmt::format("outflow {}: its box must be finite with box_min <= box_max (m)", k));
  }
}

std::vector<std::uint8_t> FlowSystem::outflow(World& m_, double& out, double& gross) {
  const auto& p = m_.particles;
  const Vec3 g = m_.gravity;
  std::vector<std::uint8_t> remove;
  out = gross = 0.0;
  if (m_.outflows.empty()) return remove;
  // What leaves takes its kinetic and potential energy with it (and its rods' elastic energy:
  // booked by the caller, which removes them); a contact's stored energy is not tracked: it
  // shows in the balance's error, so outflow regions belong where particles fly free.
  remove.assign(p.size(), 0);
  std::size_t count = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (Outflow& o : m_.outflows)
      if (o.contains(p.position[i])) {
        remove[i] = 1;
        ++o.removed;
        ++count;
        const double kinetic = 0.5 * p.mass[i] * p.velocity[i].squaredNorm() +
                               0.5 * p.inertia[i].dot(p.omega[i].cwiseAbs2());
        const double potential = -p.mass[i] * g.dot(p.position[i] - p.initial_position[i]);
        out += kinetic + potential;
        gross += kinetic + std::abs(potential);
        break;
      }
  if (count == 0) remove.clear();
  return remove;
}

Particles FlowSystem::inflow(World& m_, double h, EnergyLedger& ledger) {
  const auto& p = m_.particles;
  const Vec3 g = m_.gravity;
  // Inflow: each region owes rate x h particles more; each due particle draws up to
  // 'attempts' places (centre and radius) and takes the first that overlaps nothing beyond
  // the tolerance, the ones created this step included.
  Particles add;
  double largest = 0.0;  // the largest radius of the particles there are, m
  for (double r : p.radius) largest = std::max(largest, r);
  std::vector<std::int32_t> near;
  for (Inflow& f : m_.inflows) {
    f.owed += f.rate * h;
    if (f.owed >= 1.0) {
      // Only particles within radius_max + the largest radius of the box can overlap a new one:
      // found once per step instead of at every draw (the same answer, far fewer distances).
      const Vec3 reach = Vec3::Constant(f.radius_max + largest);
      near.clear();
      for (std::size_t j = 0; j < p.size(); ++j)
        if (in_box(p.position[j], f.box_min - reach, f.box_max + reach)) near.push_back(static_cast<std::int32_t>(j));
    }
    while (f.owed >= 1.0) {
      f.owed -= 1.0;
      bool placed = false;
      for (int a = 0; a < f.attempts && !placed; ++a) {
        Vec3 x;
        for (int c = 0; c < 3; ++c)
          x[c] = f.box_min[c] + (f.box_max[c] - f.box_min[c]) * flow_uniform(f.seed, f.draws++);
        const double r = f.radius_min + (f.radius_max - f.radius_min) * flow_uniform(f.seed, f.draws++);
        const auto overlaps = [&](const Particles& q, std::size_t j) {
          const double s = r + q.radius[j];
          return (q.position[j] - x).squaredNorm() < (1.0 - f.overlap) * (1.0 - f.overlap) * s * s;
        };
        const auto clear = [&] {
          for (const std::int32_t j : near)
            if (overlaps(p, j)) return false;
          for (std::size_t j = 0; j < add.position.size(); ++j)
            if (overlaps(add, j)) return false;
          return true;
        };
        if (!clear()) continue;
        const std::size_t k = add.position.size();
        add.resize(k + 1);
        const double m = f.density * 4.0 / 3.0 * M_PI * r * r * r;
        add.position[k] = add.initial_position[k] = x;
        add.velocity[k] = f.velocity;
        add.acceleration[k] = g;  // (force-free: the first half kick sees gravity)
        add.force[k] = m * g;
        add.radius[k] = r;
        add.mass[k] = m;
        add.inv_mass[k] = 1.0 / m;
        add.set_sphere_inertia(k);
        ledger.flow_energy -= 0.5 * m * f.velocity.squaredNorm();
        ledger.flow_through += 0.5 * m * f.velocity.squaredNorm();
        ++f.created;
        placed = true;
      }
      if (!placed) ++f.missed;
    }
  }
  return add;
}

double FlowSystem::ghost_reach(const World& m_) const {
  if (m_.inflows.empty()) return 0.0;
  double largest = 0.0, new_largest = 0.0;
  for (double r : m_.particles.radius) largest = std::max(largest, r);
  for (const Inflow& f : m_.inflows) new_largest = std::max(new_largest, f.radius_max);
  return largest + new_largest;
}

void FlowSystem::visit_state(StateArchive& ar, World& m_, EnergyLedger& ledger) {
  if (m_.inflows.empty() && m_.outflows.empty()) return;  // (only then: older checkpoints and hashes stay as they were)
  const bool load = ar.loading();
  ar.scalar("ledger/flow_energy", ledger.flow_energy);
  ar.scalar("ledger/flow_through", ledger.flow_through);
  for (std::size_t k = 0; k < m_.inflows.size(); ++k) {
    Inflow& f = m_.inflows[k];
    const std::string at = fmt::format("flows/inflow_{}/", k);
    ar.scalar(at + "owed", f.owed);
    ar.scalar(at + "draws", f.draws);
    ar.scalar(at + "created", f.created);
    ar.scalar(at + "missed", f.missed);
    if (load && !(finite_bits(f.owed) && f.owed >= 0.0 && f.owed < 1.0))
      throw InputError(fmt::format("state field '{}owed' = {}: it must lie in [0, 1)", at, nan_safe(f.owed)));
  }
  for (std::size_t k = 0; k < m_.outflows.size(); ++k)
    ar.scalar(fmt::format("flows/outflow_{}/removed", k), m_.outflows[k].removed);
}

}  // namespace swarf
