// run_limits.cpp: the checks before the first step (see run_limits.h).
#include "app/run_limits.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "lattice_gen/membrane_lattice.h"
#include "setup/model.h"
#include "swarf/core/errors.h"

namespace swarf {
namespace {

// Where [cut] derived the keys a refusal names, the cut's own keys to change.
std::string cut_note(const CaseSettings& cs, bool size) {
  if (!cs.cut.enabled) return {};
  return size ? " ([cut] derived it from cut.uncut_chip_thickness, cut.layers, cut.length_of_cut, "
                "cut.workpiece_length, cut.workpiece_height and cut.width: change those)"
              : " ([cut] derived it from cut.length_of_cut over cut.cutting_speed, and the step from "
                "cut.layers: change those)";
}

// A duration for a message: "42 s", "3.5 h", "12 days", "3e+04 years".
std::string duration_text(double s) {
  if (s < 120) return fmt::format("{:.3g} s", s);
  if (s < 7200) return fmt::format("{:.3g} min", s / 60);
  if (s < 2 * 86400) return fmt::format("{:.3g} h", s / 3600);
  if (s < 365 * 86400) return fmt::format("{:.3g} days", s / 86400);
  return fmt::format("{:.3g} years", s / (365.25 * 86400));
}

}  // namespace

// The memory a generated workpiece needs, estimated before it is built; a case beyond the
// machine's memory is refused with the key named, instead of a bare std::bad_alloc after
// seconds of allocation.
void check_memory(const CaseSettings& cs, bool force) {
  if (force) return;
  const double machine = double(::sysconf(_SC_PHYS_PAGES)) * double(::sysconf(_SC_PAGE_SIZE));
  if (cs.membrane.enabled) {
    // The triangular sheet's sites (lattice_gen/membrane_lattice.h) at the bonded block's bytes
    // per particle (an upper bound: six rods a site, not twelve).
    const MembraneSettings& ms = cs.membrane;
    const double sites = membrane_site_count(ms.length, ms.width, ms.radius);
    const double bytes = 60e6 + 1000.0 * sites;
    if (machine > 0 && bytes > machine)
      throw InputError(
          fmt::format("{}: keys 'membrane.length', 'membrane.width' and 'membrane.radius' make about "
                      "{:.3g} particles, which need about {:.3g} GB; this machine has {:.3g} GB (give "
                      "--force to run anyway)",
                      cs.source, sites, bytes * 1e-9, machine * 1e-9));
    return;
  }
  if (!cs.workpiece.enabled || !cs.workpiece.lattice_file.empty()) return;
  const auto& w = cs.workpiece;
  double cells = 1.0;
  const bool by_cells = w.cells[0] > 0;
  for (int c = 0; c < 3; ++c)
    cells *= by_cells ? double(w.cells[c]) : std::floor(w.size[c] / (2.0 * std::sqrt(2.0) * w.radius)) + 1.0;
  // The peak resident memory of a bonded block, rounded up from the measurements in
  // validation/bench/README.md ("Memory at a million particles"): the process itself, and per
  // particle the explicit or fixed-point step's data, or the Newton solver's, which adds its
  // vectors and tangents.
  const bool newton = cs.integrator.solver == "newton" && cs.integrator.scheme != "verlet";
  const double particles = 4.0 * cells, bytes = 60e6 + (newton ? 1700.0 : 1000.0) * particles;
  if (machine > 0 && bytes > machine)
    throw InputError(
        fmt::format("{}: key 'workpiece.{}' makes about {:.3g} particles, which need about {:.3g} GB{}; "
                    "this machine has {:.3g} GB (give --force to run anyway){}",
                    cs.source, by_cells ? "cells" : "size", particles, bytes * 1e-9,
                    newton ? " with integrator.solver = \"newton\"" : "", machine * 1e-9, cut_note(cs, true)));
}

// What cannot finish is refused before the first step (issue 37 item 2): a run whose step
// count, from the end time and the step, exceeds integrator.max_steps (unless --allow-long);
// an inflow that asks for more particles in one step than its box can hold; inflows whose
// particles over the run need more memory than the machine has (unless --force). Before
// them, such runs started and sat silently (a stable step of 4e-152 s, 1e23 particles a step).
void check_run_length(const Model& m, bool allow_long, bool force, double t_start) {
  const IntegratorSettings& g = m.settings.integrator;
  const std::string& src = m.settings.source;
  const double h = m.step.implicit() ? m.step.dt_max : m.step.dt;  // s: the largest step the run takes
  const double remaining = g.end_time - t_start;                   // s
  // At most this many particles at once: those there are and all the inflows will create.
  double created = 0.0;
  for (const Inflow& f : m.inflows) created += f.rate * remaining;
  const double particles = std::max(1.0, double(m.particles.size()) + created);
  for (std::size_t k = 0; k < m.inflows.size(); ++k) {
    const Inflow& f = m.inflows[k];
    // (centres at least 2 r_min (1 - overlap) apart: a lattice of that spacing in the box)
    const double spacing = 2.0 * f.radius_min * (1.0 - f.overlap);
    double holds = 1.0;
    for (int c = 0; c < 3; ++c) holds *= std::floor((f.box_max[c] - f.box_min[c]) / spacing) + 1.0;
    const double per_step = f.rate * h;
    if (per_step > holds)
      throw InputError(fmt::format(
          "{}: key 'inflow.rate' (inflow {}) = {:.4g} 1/s asks for {:.3g} particles in a step of {:.4g} s, more than "
          "its box can hold ({:.3g} centres {:.3g} m apart: inflow.box_min, box_max, radius_min, overlap); lower the "
          "rate or widen the box",
          src, k, f.rate, per_step, h, holds, spacing));
  }
  if (!force && created > 0.0) {
    // (the bytes per particle of check_memory's bonded block: an upper bound for free spheres)
    const double bytes = 60e6 + 1000.0 * particles;
    const double machine = double(::sysconf(_SC_PHYS_PAGES)) * double(::sysconf(_SC_PAGE_SIZE));
    if (machine > 0 && bytes > machine)
      throw InputError(fmt::format(
          "{}: keys 'inflow.rate' and 'integrator.end_time' = {:.4g} s create up to {:.3g} particles, which need "
          "about {:.3g} GB; this machine has {:.3g} GB (give --force to run anyway)",
          src, g.end_time, created, bytes * 1e-9, machine * 1e-9));
  }
  const double steps = remaining / h;
  if (allow_long || !(steps > g.max_steps)) return;
  std::string step_keys;
  if (m.step.implicit())
    step_keys = fmt::format("integrator.dt_max = {:.4g} s{}", h, g.dt_max > 0 ? "" : " (derived)");
  else if (g.dt > 0)
    step_keys = fmt::format("integrator.dt = {:.4g} s", h);
  else
    step_keys = fmt::format(
        "the stable step {:.4g} s times integrator.dt_safety = {:g}, set by the smallest radius ({:.4g} m: "
        "workpiece.radius, particle or inflow radii), the density and the stiffest modulus of the rods and contacts",
        m.derived.dt_stable, g.dt_safety, m.derived.radius);
  // The measured speed (one thread): about 100 ns per particle-step (the default cut, 94.5 ns)
  // and 10 us a step whatever the particles (an empty flow case, 9.9 us: the loop and its rows).
  constexpr double kNsPerParticleStep = 100.0, kUsPerStep = 10.0;
  throw InputError(fmt::format(
      "{}: key 'integrator.end_time' = {:.4g} s needs about {:.3g} steps of {:.4g} s ({}), more than "
      "integrator.max_steps = {:.3g}; with {:.3g} particles that is about {} at {:g} ns per particle-step and "
      "{:g} us a step. Check the keys that set the step, or give --allow-long to run it anyway{}",
      src, g.end_time, steps, h, step_keys, g.max_steps, particles,
      duration_text(steps * (particles * kNsPerParticleStep * 1e-9 + kUsPerStep * 1e-6)), kNsPerParticleStep,
      kUsPerStep, cut_note(m.settings, false)));
}

}  // namespace swarf
