// fcc_lattice.cpp: FCC site generation and bonding (see fcc_lattice.h).
#include "lattice_gen/fcc_lattice.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "swarf/core/errors.h"
#include "swarf/neighbors/neighbor_pairs.h"

namespace swarf {

Lattice generate_fcc(const FccSpec& spec) {
  if (!(spec.radius > 0.0) || !std::isfinite(spec.radius))
    throw InputError(fmt::format("lattice: radius must be a positive length in m, got {}", spec.radius));
  const double d = 2.0 * spec.radius;
  const double a = d * std::sqrt(2.0);
  const double h = 0.5 * a;
  const bool by_cells = spec.cells[0] > 0 || spec.cells[1] > 0 || spec.cells[2] > 0;
  std::array<long, 3> count{};  // number of half-cell steps per axis
  for (int c = 0; c < 3; ++c) {
    if (by_cells) {
      if (spec.cells[c] <= 0)
        throw InputError(fmt::format("lattice: cells must be three positive integers, got {},{},{}", spec.cells[0],
                                     spec.cells[1], spec.cells[2]));
      count[c] = 2L * spec.cells[c];
    } else {
      if (!(spec.size[c] > 0.0) || !std::isfinite(spec.size[c]))
        throw InputError(fmt::format("lattice: size must be three positive lengths in m, got {},{},{}", spec.size[0],
                                     spec.size[1], spec.size[2]));
      count[c] = static_cast<long>(std::floor(spec.size[c] / h * (1.0 + 1e-9))) + 1;
    }
  }
  const double n_sites = 0.5 * double(count[0]) * double(count[1]) * double(count[2]);
  if (n_sites > 2.0e9) throw InputError(fmt::format("lattice: {:.3g} particles is more than swarf indexes", n_sites));
  Lattice lat;
  lat.cell_edge = a;
  if (by_cells) lat.cells = spec.cells;
  lat.position.reserve(static_cast<std::size_t>(n_sites) + 1);
  if (spec.rotation_y == 0.0) {
    for (long k = 0; k < count[2]; ++k)
      for (long j = 0; j < count[1]; ++j)
        for (long i = 0; i < count[0]; ++i)
          if ((i + j + k) % 2 == 0) lat.position.emplace_back(double(i) * h, double(j) * h, double(k) * h);
  } else {
    if (!std::isfinite(spec.rotation_y))
      throw InputError(fmt::format("lattice: the rotation must be a finite angle, got {} rad", spec.rotation_y));
    // The turned lattice's sites inside the same box as the unturned one, [0, (count - 1) h]
    // in x and z (a small tolerance keeps sites on the faces); y is unchanged. Sorted by
    // (z, y, x) layers as the unturned generator gives them.
    const double c = std::cos(spec.rotation_y), s = std::sin(spec.rotation_y);
    const double lx = double(count[0] - 1) * h, lz = double(count[2] - 1) * h, eps = 1e-9 * h;
    const long reach = static_cast<long>(std::ceil((lx + lz) / h)) + 2;
    std::vector<std::array<double, 3>> sites;
    for (long k = -reach; k <= reach; ++k)
      for (long i = -reach; i <= reach; ++i) {
        // Site (i, ., k) h turned about y: x' = c x + s z, z' = -s x + c z.
        const double x = c * double(i) * h + s * double(k) * h, z = -s * double(i) * h + c * double(k) * h;
        if (x < -eps || x > lx + eps || z < -eps || z > lz + eps) continue;
        for (long j = 0; j < count[1]; ++j)
          if (((i + j + k) % 2 + 2) % 2 == 0) sites.push_back({z, double(j) * h, x});
      }
    std::sort(sites.begin(), sites.end());
    for (const auto& q : sites) lat.position.emplace_back(q[2], q[1], q[0]);
  }
  if (lat.position.empty()) throw InputError("lattice: the box holds no lattice site");
  lat.radius.assign(lat.position.size(), spec.radius);
  bond_nearest_neighbours(lat, d, spec.bond_tolerance);
  return lat;
}

void bond_nearest_neighbours(Lattice& lat, double nominal_distance, double tolerance) {
  if (!(tolerance >= 0.0 && tolerance < 0.2))
    throw InputError(fmt::format("lattice: bond tolerance must lie in [0, 0.2), got {}", tolerance));
  lat.rods = find_pairs_in_range(lat.position, nominal_distance * (1.0 - tolerance),
                                 nominal_distance * (1.0 + tolerance));
  lat.rods.shrink_to_fit();  // (found one by one: up to twice the room; the rods take it over)
  lat.rest_length.resize(lat.rods.size());
  for (std::size_t b = 0; b < lat.rods.size(); ++b)
    lat.rest_length[b] = (lat.position[lat.rods[b][1]] - lat.position[lat.rods[b][0]]).norm();
}

}  // namespace swarf
