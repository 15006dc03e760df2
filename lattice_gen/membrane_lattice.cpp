// membrane_lattice.cpp: the triangular sheet and its relations (see membrane_lattice.h).
#include "lattice_gen/membrane_lattice.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "swarf/core/errors.h"

namespace swarf {

double membrane_site_count(double length, double width, double radius) {
  const double d = 2.0 * radius, row = 0.5 * std::sqrt(3.0) * d;
  const double tol = 1e-9 * d;  // (as the generator's: the sites on the far edges count)
  return (std::floor((width + tol) / row) + 1.0) * (std::floor((length + tol) / d) + 1.0);
}

Lattice generate_membrane(const MembraneSpec& spec) {
  if (!(spec.radius > 0.0) || !std::isfinite(spec.radius))
    throw InputError(fmt::format("key 'membrane.radius' must be a positive length in m, got {}", spec.radius));
  if (!(spec.length > 0.0) || !std::isfinite(spec.length) || !(spec.width > 0.0) || !std::isfinite(spec.width))
    throw InputError(
        fmt::format("keys 'membrane.length' and 'membrane.width' must be positive lengths in m, got {}, {}",
                    spec.length, spec.width));
  if (!(spec.pre_strain > -0.5 && spec.pre_strain < 1.0))
    throw InputError(fmt::format("key 'membrane.pre_tension' gives the rods a pre-strain of {}, outside (-0.5, 1)",
                                 spec.pre_strain));
  const double d = 2.0 * spec.radius, row = 0.5 * std::sqrt(3.0) * d;
  const double tol = 1e-9 * d;  // keeps sites on the far edges
  const double sites = membrane_site_count(spec.length, spec.width, spec.radius);
  if (sites > 2.0e9)
    throw InputError(fmt::format(
        "keys 'membrane.length', 'membrane.width' and 'membrane.radius' make {:.3g} particles, more than swarf indexes",
        sites));
  const long rows = static_cast<long>(std::floor((spec.width + tol) / row)) + 1;
  const long cols = static_cast<long>(std::floor((spec.length + tol) / d)) + 1;
  Lattice lat;
  const Vec3 o(spec.origin[0], spec.origin[1], spec.origin[2]);
  for (long j = 0; j < rows; ++j) {
    const double shift = (j % 2) ? 0.5 * d : 0.0;
    for (long i = 0; i < cols; ++i) {
      const double x = shift + double(i) * d;
      if (x > spec.length + tol) break;
      lat.position.push_back(o + Vec3(x, double(j) * row, 0.0));
    }
  }
  if (lat.position.size() < 3)
    throw InputError(
        "keys 'membrane.length' and 'membrane.width' make a sheet of fewer than 3 sites at membrane.radius: enlarge "
        "it");
  lat.radius.assign(lat.position.size(), spec.radius);
  bond_nearest_neighbours(lat, d, 1e-6);
  // The rest length: shorter than the spacing by the pre-strain (the sheet is generated taut).
  for (double& l : lat.rest_length) l /= 1.0 + spec.pre_strain;
  return lat;
}

MembraneRelations membrane_relations(const MembraneMaterial& mt) {
  auto positive = [](double v, const char* what) {
    if (!(v > 0.0) || !std::isfinite(v)) throw InputError(fmt::format("membrane: {} = {} must be positive", what, v));
  };
  positive(mt.spacing, "the spacing 2R (m)");
  positive(mt.modulus_2d, "the in-plane modulus E t (N/m)");
  positive(mt.areal_density, "the areal density (kg/m^2)");
  if (std::abs(mt.poisson_ratio - 1.0 / 3.0) > 1e-6)
    throw InputError(fmt::format(
        "membrane: Poisson ratio {} cannot be represented: a triangular lattice of central springs has nu = 1/3 "
        "in the plane, fixed (give 1/3 or leave the key out)",
        mt.poisson_ratio));
  if (!(mt.pre_tension >= 0.0) || !std::isfinite(mt.pre_tension))
    throw InputError(fmt::format("membrane: the pre-tension {} N/m must be >= 0 and finite", mt.pre_tension));
  MembraneRelations r;
  const double d = mt.spacing, s3 = std::sqrt(3.0);
  const double k = 0.5 * s3 * mt.modulus_2d;
  r.bond_stiffness = k;
  r.site_area = 0.5 * s3 * d * d;
  r.particle_mass = mt.areal_density * r.site_area;
  // T = sqrt(3) f / d and f = k d eps0 / (1 + eps0): eps0 = s / (1 - s) with s = T / (sqrt(3) k).
  const double s = mt.pre_tension / (s3 * k);
  if (!(s < 0.5))
    throw InputError(
        fmt::format("membrane: the pre-tension {} N/m needs a rod pre-strain of {:.3g}; at most 1 (T < {:.4g} N/m)",
                    mt.pre_tension, s / (1.0 - s), 0.5 * s3 * k));
  r.pre_strain = s / (1.0 - s);
  r.bond_force = mt.pre_tension * d / s3;
  r.lambda = r.mu = 0.25 * s3 * k;
  const double m = r.particle_mass, f_d = r.bond_force / d;
  r.wave_longitudinal = d * std::sqrt((9.0 * k + 3.0 * f_d) / (8.0 * m));
  r.wave_shear = d * std::sqrt((3.0 * k + 9.0 * f_d) / (8.0 * m));
  r.wave_transverse = std::sqrt(1.5 * r.bond_force * d / m);
  r.omega_max = std::sqrt(6.0 * (k + f_d) / m);
  r.dt_stable = 2.0 / r.omega_max;
  r.dt_cfl = d / std::max({r.wave_longitudinal, r.wave_shear, r.wave_transverse});
  return r;
}

std::vector<std::int32_t> membrane_edge(const Lattice& lat) {
  std::vector<int> count(lat.position.size(), 0);
  for (const auto& b : lat.rods) {
    ++count[b[0]];
    ++count[b[1]];
  }
  std::vector<std::int32_t> edge;
  for (std::size_t i = 0; i < count.size(); ++i)
    if (count[i] < 6) edge.push_back(static_cast<std::int32_t>(i));
  return edge;
}

}  // namespace swarf
