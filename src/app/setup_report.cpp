// setup_report.cpp: the run's set-up as printed (see setup_report.h).
#include "app/setup_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/build_info.h"
#include "io/console.h"
#include "setup/model.h"
#include "setup/modules/contacts.h"
#include "setup/modules/groups.h"
#include "setup/modules/heat.h"
#include "setup/modules/integrator.h"
#include "setup/modules/material.h"
#include "setup/modules/membrane.h"
#include "setup/modules/meshes.h"
#include "setup/modules/uniaxial.h"
#include "setup/modules/workpiece.h"
#include "swarf/version.h"

namespace swarf {

void print_setup(const Model& m, int threads) {
  const Derived& d = m.derived;
  const BuildInfo& b = build_info();
  say("swarf {} (commit {}{}): case {}\n", b.version, b.git_commit.substr(0, 12),
      b.git_dirty == 1 ? ", uncommitted changes" : "", m.settings.source);
  if (!m.settings.cut_derived.empty()) {
    // What [cut] derived, as the case file that says the same without [cut].
    std::string text;
    for (std::size_t a = 0, b = 0; a < m.settings.cut_derived.size(); a = b + 1) {
      b = m.settings.cut_derived.find('\n', a);
      if (b == std::string::npos) b = m.settings.cut_derived.size();
      text += b > a ? "    " + m.settings.cut_derived.substr(a, b - a) + "\n" : "\n";
    }
    say("{}", text);
  }
  say("  particles {}  rods {}  groups {}  threads {}\n", m.particles.size(), m.rods.size(), m.groups.size(), threads);
  say("{}", groups_echo(m));
  say("{}", meshes_echo(m));
  if (d.membrane)
    say("  radius R = {:.4g} m, site spacing d = {:.4g} m, particle mass m = {:.4g} kg\n", d.radius, d.nn_distance,
        d.particle_mass);
  else
    say("  radius R = {:.4g} m, cell edge a = {:.4g} m, particle mass m = {:.4g} kg\n", d.radius, d.cell_edge,
        d.particle_mass);
  say("{}", workpiece_echo(m));
  if (d.membrane) {
    say("{}", membrane_echo(m));
  } else if (!m.rods.ends.empty()) {
    say("{}", material_echo(m));
    // The law as it describes itself: its name, then each parameter (a table as a list).
    const RodLawDescription law = describe(d.law);
    std::string params;
    for (const LawParameter& p : law.parameters) {
      if (p.table && p.values.empty()) continue;  // (no hardening curve)
      const std::string unit = p.unit == "1" ? "" : " " + p.unit;
      std::string v = p.table ? "[" : "";
      for (std::size_t i = 0; i < p.values.size(); ++i) v += fmt::format("{}{:.4g}", i ? ", " : "", p.values[i]);
      params += fmt::format("{}{} = {}{}{}", params.empty() ? "" : ", ", p.name, v, p.table ? "]" : "", unit);
    }
    say("  rod law \"{}\": {}\n", law.name, params);
    if (std::isfinite(m.settings.rod.failure_elongation))
      say("  rod: failure_strain from rod.failure_elongation = {:.4g} m over L0\n", m.settings.rod.failure_elongation);
    if (m.rods.formation.enabled())
      say("  rod: unbonded lattice particles pressed beyond a relative overlap of {:.4g} form a rod\n",
          m.rods.formation.overlap);
    if (m.rods.isochoric)
      say("  rod: plastic flow keeps the volume (each step's increments of a particle's rods lose their mean{})\n",
          m.rods.formation.enabled() ? "; a formed rod takes the lattice's length, r_i + r_j" : "");
    if (m.rods.compaction_modulus > 0.0)
      say("  rod: a neighbourhood compacted by more than {:.4g} of its volume pushes back with K = {:.4g} Pa\n",
          m.rods.compaction_onset, m.rods.compaction_modulus);
    say("  rod: A = {:.4g} m^2, kb = E A/L0 = {:.4g} N/m, damping c = {:.4g} N s/m\n", d.rod_area, d.rod_stiffness,
        d.rod_damping);
  }
  const double nu = m.settings.material.poisson_ratio;
  if (nu > -1 && std::abs(nu - 1.0 / 3.0) > 1e-3)
    eprint(
        "swarf: warning: material.poisson_ratio = {} cannot be represented: a lattice of central rods "
        "has 1/3 along [100] (1/4 isotropic average); continuing with the lattice's\n",
        nu);
  if (!m.rods.ends.empty() && !d.membrane)
    say("  lattice: E100 = {:.4g} Pa, C11 = {:.4g} Pa, C12 = C44 = {:.4g} Pa, nu100 = 1/3, bulk density {:.5g} "
        "kg/m^3\n",
        d.youngs_modulus_100, d.c11, d.c12, d.bulk_density);
  say("{}", heat_echo(m));
  say("{}", contacts_echo(m));
  say("{}", integrator_echo(m));
  say("{}", uniaxial_echo(m));
  std::fflush(stdout);
}

}  // namespace swarf
