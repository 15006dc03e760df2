// plastic_strain_system.cpp: the accumulated equivalent plastic strain (see plastic_strain_system.h).
#include "swarf/systems/plastic_strain_system.h"

#include <cmath>

#include "swarf/core/state_archive.h"
#include "swarf/measure/strain_fit.h"

namespace swarf {

namespace {
// The deviatoric fit's components kept: eigenvalues above 1 % of the largest (a lattice sheared
// by gamma 3 keeps all five: strain_fit.h), which bounds each by 10 times the rods' rms increment.
constexpr double kWellDetermined = 0.01;
// A rod shorter than this fraction of its rest length adds nothing: its pair has collapsed (two
// bonded spheres pressed almost onto each other where the lattice compacts at a cut's separation
// line, validation/cutting/compaction/), its increment says nothing about a continuum's strain, and
// the conversion to the current length, L0 / L, grows without bound (with it, single windows gave
// the default cut's particles PEEQ of several hundred). A homogeneous simple shear to gamma 2
// shortens no rod below 0.71 L0.
constexpr double kCollapsed = 0.5;
}  // namespace

void PlasticStrainSystem::setup(World& w, int window) {
  window_ = window > 0 ? window : 0;
  // (its arrays are held only while it runs: 72 B per particle)
  ParticleLayout layout = w.particles.layout;
  layout.plastic_strain = enabled();
  w.particles.set_layout(layout);
}

void PlasticStrainSystem::accumulate(World& w, const RodSystem::WorkList& flowed, double h) {
  if (!enabled()) return;
  auto& p = w.particles;
  const auto& r = w.rods;
  for (const RodSystem::RodWork& f : flowed) {
    const auto [i, j] = f.ends;
    // The work first: every rod the commit booked, a collapsed pair's too (the ledger's sum).
    p.plastic_work[i] += 0.5 * f.work;
    p.plastic_work[j] += 0.5 * f.work;
    if (f.plastic_strain == 0.0) continue;
    Vec3 d = p.position[j] - p.position[i];
    w.periodic.wrap(d);
    const double len2 = d.squaredNorm(), L0 = r.rest_length[f.rod];
    if (!(len2 > kCollapsed * kCollapsed * L0 * L0)) continue;
    // g(n) de with n = d / L and de = de_p L0 / L: g(d) de_p L0 / L^3.
    const double s = f.plastic_strain * L0 / (len2 * std::sqrt(len2));
    const Vec3 normal(d[0] * d[0] * s, d[1] * d[1] * s, d[2] * d[2] * s);
    const Vec3 shear(2 * d[0] * d[1] * s, 2 * d[1] * d[2] * s, 2 * d[0] * d[2] * s);
    p.window_normal[i] += normal;
    p.window_shear[i] += shear;
    p.window_normal[j] += normal;
    p.window_shear[j] += shear;
    pending_ = true;
  }
  ++steps_;
  window_time_ += h;
  if (steps_ >= window_) fit(w);
}

void PlasticStrainSystem::fit(World& w) {
  auto& p = w.particles;
  const auto& r = w.rods;
  const std::size_t n = p.size();
  const double time = window_time_;
  steps_ = 0;
  window_time_ = 0.0;
  if (!pending_) {
    // (a window without flow: every rate is zero, set once)
    if (time > 0.0)
      for (auto& v : p.peeq_rate) v = 0.0;
    return;
  }
  pending_ = false;
  const bool rows = r.row_start.size() == n + 1 && r.entries.size() == 2 * r.size();
  RodRows own;
  if (!rows) build_rod_rows(r.ends, n, own);
  const auto& row_start = rows ? r.row_start : own.row_start;
  const auto& entries = rows ? r.entries : own.entries;
  const double inv_time = time > 0.0 ? 1.0 / time : 0.0;
  // Each particle on its own (its rods' directions, its window): any thread count, the same bits.
  // (Dynamic: the flowing particles, the costly ones, sit together in the index order.)
#pragma omp parallel for schedule(dynamic, 64) if (n > 4096)
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 a = p.window_normal[i], b = p.window_shear[i];
    if (a.isZero(0.0) && b.isZero(0.0)) {
      p.peeq_rate[i] = 0.0;
      continue;
    }
    Mat6 normal = Mat6::Zero();
    Vec6 unused = Vec6::Zero();
    add_rods_to_fit(p.position, r, w.periodic, row_start, entries, i, normal, unused, [](std::int32_t) { return 0.0; });
    Vec6 rhs;
    rhs << a[0], a[1], a[2], b[0], b[1], b[2];
    // (no intact rod left: the window's increment has no tensor to fit and is dropped)
    const double de = normal.isZero(0.0) ? 0.0 : equivalent_strain(fit_deviatoric_strain(normal, rhs, kWellDetermined));
    p.peeq[i] += de;
    p.peeq_rate[i] = de * inv_time;
    p.window_normal[i] = Vec3::Zero();
    p.window_shear[i] = Vec3::Zero();
  }
}

void PlasticStrainSystem::resize(const World& w) {
  // (Without the door, a window is non-zero only when pending_ is set: this changes nothing then.)
  const auto& p = w.particles;
  for (std::size_t i = 0; i < p.window_normal.size() && !pending_; ++i)
    pending_ = !p.window_normal[i].isZero(0.0) || !p.window_shear[i].isZero(0.0);
}

void PlasticStrainSystem::visit_state(StateArchive& ar, World&, EnergyLedger&) {
  // (also when off: a checkpoint loads whether or not the restart writes PEEQ)
  ar.scalar("plastic_strain/window_steps", steps_);
  ar.scalar("plastic_strain/window_time", window_time_);
  ar.scalar("plastic_strain/pending", pending_);
}

}  // namespace swarf
