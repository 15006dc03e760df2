// particle_fields.cpp: per-particle stress and plastic strain (see particle_fields.h). Run at
// output times only, so it favours plainness over speed: one pass over the rods, one over the
// contacts, a 6 x 6 least-squares solve per particle.
#include "swarf/measure/particle_fields.h"

#include <Eigen/Core>
#include <cmath>

#include "swarf/contacts/contacts.h"
#include "swarf/measure/strain_fit.h"

namespace swarf {

double von_mises(const SymTensor& t) {
  const double m = (t[0] + t[1] + t[2]) / 3.0;
  const double sx = t[0] - m, sy = t[1] - m, sz = t[2] - m;
  const double ss = sx * sx + sy * sy + sz * sz + 2.0 * (t[3] * t[3] + t[4] * t[4] + t[5] * t[5]);
  return std::sqrt(1.5 * ss);
}

ParticleFields particle_fields(const Particles& p, const Rods& r, const Periodic& periodic,
                               const ContactSystem* contacts) {
  const std::size_t n = p.size();
  // The moments are summed into the output's stress and scaled there; the plastic fit's
  // normal equations are built one particle at a time from its rod list (ascending rods, as
  // one pass over the rods adds them): per-particle 6 x 6 matrices for the whole body would
  // be the largest arrays of the run.
  ParticleFields out;
  out.stress.assign(n, SymTensor{});
  auto& moment = out.stress;
  const bool have_coef = r.force_coef.size() == r.size();
  auto axis = [&](std::size_t k) {
    const auto [i, j] = r.ends[k];
    Vec3 d = p.position[j] - p.position[i];
    periodic.wrap(d);
    return d;
  };
  if (have_coef)
    for (std::size_t k = 0; k < r.size(); ++k) {
      if (!r.intact[k]) continue;
      // Force on i = coef d at the midpoint d/2; on j = -coef d at -d/2: the same moment.
      const Vec3 d = axis(k), half = 0.5 * d, f = r.force_coef[k] * d;
      add_moment(moment[r.ends[k][0]], half, f);
      add_moment(moment[r.ends[k][1]], half, f);
    }
  if (contacts && contacts->enabled()) contacts->add_virial(p, moment);
  // The rod lists: the rods' own when they are current, else built here.
  RodRows rows;
  const bool current = r.row_start.size() == n + 1 && r.entries.size() == 2 * r.size();
  if (!current) build_rod_rows(r.ends, n, rows);
  const std::vector<std::int32_t>& row_start = current ? r.row_start : rows.row_start;
  const std::vector<Rods::Entry>& entries = current ? r.entries : rows.entries;

  out.plastic_strain.assign(n, 0.0);
  // Each rod's plastic strain from its state, as its law defines it, where a fit reads it (one
  // visit for all particles; an array of them for all rods was 8 B per rod of the run's last write).
  std::visit(
      [&](const auto& law) {
        for (std::size_t i = 0; i < n; ++i) {
          const double inv_v = 1.0 / particle_volume(p.radius[i]);
          for (int c = 0; c < 6; ++c) out.stress[i][c] = moment[i][c] * inv_v;
          Mat6 normal = Mat6::Zero();
          Vec6 rhs = Vec6::Zero();
          add_rods_to_fit(p.position, r, periodic, row_start, entries, i, normal, rhs,
                          [&](std::int32_t k) { return plastic_strain(law, r.shift[k]); });
          // (the least squares over the part the rods determine well: strain_fit.h)
          out.plastic_strain[i] = equivalent_strain(fit_strain(normal, rhs));
        }
      },
      r.law);
  return out;
}

}  // namespace swarf
