// lattice_file.cpp: HDF5 reading and writing of a lattice (see lattice_file.h).
#include "lattice_gen/lattice_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "io/atomic_file.h"
#include "io/h5file.h"
#include "swarf/core/bounds.h"
#include "swarf/core/errors.h"
#include "swarf/core/nan_safe.h"
#include "swarf/version.h"

namespace swarf {

void write_lattice(const std::string& path, const Lattice& lat) {
  const std::string tmp = path + ".part";
  {
    H5File f(tmp, H5File::Mode::Create);
    f.write("/particles/position", lat.position.empty() ? nullptr : lat.position[0].data(), lat.position.size(), 3);
    f.write("/particles/radius", lat.radius.data(), lat.radius.size());
    std::vector<std::int64_t> pairs(2 * lat.rods.size());
    for (std::size_t b = 0; b < lat.rods.size(); ++b) {
      pairs[2 * b] = lat.rods[b][0];
      pairs[2 * b + 1] = lat.rods[b][1];
    }
    f.write("/bonds/pairs", pairs.data(), lat.rods.size(), 2);
    f.write("/bonds/rest_length", lat.rest_length.data(), lat.rest_length.size());
    f.write_attribute("generator", std::string("swarf ") + SWARF_VERSION + " fcc");
    f.write_attribute("cell_edge", lat.cell_edge);
    f.close();  // (a failed close throws before the rename)
  }
  commit_file(tmp, path);
}

Lattice read_lattice(const std::string& path) {
  if (!std::filesystem::exists(path)) throw InputError(fmt::format("lattice file '{}' does not exist", path));
  H5File f(path, H5File::Mode::Read);
  Lattice lat;
  std::size_t rows = 0, cols = 0;
  auto pos = f.read_doubles("/particles/position", rows, cols);
  if (cols != 3) throw InputError(fmt::format("'{}': /particles/position must be N x 3, is {} x {}", path, rows, cols));
  const std::size_t n = rows;
  if (n == 0)
    throw InputError(fmt::format("'{}': /particles/position has no rows: the lattice has no particles", path));
  lat.position.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    lat.position[i] = Vec3(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]);
    if (!all_finite(lat.position[i]))
      throw InputError(fmt::format("'{}': /particles/position row {} is not finite", path, i));
    if (lat.position[i].cwiseAbs().maxCoeff() > kMaxMeshCoordinate)
      throw InputError(fmt::format("'{}': /particles/position row {} lies beyond {:g} m", path, i, kMaxMeshCoordinate));
  }
  lat.radius = f.read_doubles("/particles/radius", rows, cols);
  if (rows != n || cols != 1) throw InputError(fmt::format("'{}': /particles/radius must have {} entries", path, n));
  for (std::size_t i = 0; i < n; ++i)
    if (!finite_bits(lat.radius[i]) || !(lat.radius[i] >= kMinRadius && lat.radius[i] <= kMaxRadius))
      throw InputError(fmt::format("'{}': /particles/radius[{}] = {} is not a radius from {:g} to {:g} m", path, i,
                                   nan_safe(lat.radius[i]), kMinRadius, kMaxRadius));
  auto pairs = f.read_ints("/bonds/pairs", rows, cols);
  if (cols != 2 && rows > 0) throw InputError(fmt::format("'{}': /bonds/pairs must be M x 2", path));
  const std::size_t m = rows;
  lat.rods.resize(m);
  for (std::size_t b = 0; b < m; ++b) {
    std::int64_t i = pairs[2 * b], j = pairs[2 * b + 1];
    if (i < 0 || j < 0 || i >= std::int64_t(n) || j >= std::int64_t(n) || i == j)
      throw InputError(fmt::format("'{}': /bonds/pairs row {} = ({}, {}) is not a pair of distinct particles 0..{}",
                                   path, b, i, j, n - 1));
    lat.rods[b] = {static_cast<std::int32_t>(std::min(i, j)), static_cast<std::int32_t>(std::max(i, j))};
  }
  // A pair listed twice would be two rods in parallel: twice the stiffness, silently.
  {
    std::vector<std::size_t> order(m);
    for (std::size_t b = 0; b < m; ++b) order[b] = b;
    std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return lat.rods[x] < lat.rods[y]; });
    for (std::size_t k = 1; k < m; ++k)
      if (lat.rods[order[k]] == lat.rods[order[k - 1]])
        throw InputError(fmt::format("'{}': /bonds/pairs rows {} and {} both bond particles ({}, {}): each pair once",
                                     path, std::min(order[k - 1], order[k]), std::max(order[k - 1], order[k]),
                                     lat.rods[order[k]][0], lat.rods[order[k]][1]));
  }
  lat.rest_length = f.read_doubles("/bonds/rest_length", rows, cols);
  if (rows != m || cols != 1) throw InputError(fmt::format("'{}': /bonds/rest_length must have {} entries", path, m));
  for (std::size_t b = 0; b < m; ++b)
    if (!finite_bits(lat.rest_length[b]) || !(lat.rest_length[b] >= kMinRadius && lat.rest_length[b] <= 4 * kMaxRadius))
      throw InputError(fmt::format("'{}': /bonds/rest_length[{}] = {} is not a length from {:g} to {:g} m", path, b,
                                   nan_safe(lat.rest_length[b]), kMinRadius, 4 * kMaxRadius));
  // (0: not known; the derived quantities then take the FCC cell of the smallest radius)
  if (f.has_attribute("cell_edge")) lat.cell_edge = f.read_double_attribute("cell_edge");
  if (!finite_bits(lat.cell_edge) ||
      !(lat.cell_edge == 0.0 || (lat.cell_edge >= kMinRadius && lat.cell_edge <= 4 * kMaxRadius)))
    throw InputError(
        fmt::format("'{}': attribute cell_edge = {} is neither 0 (unknown) nor a length from {:g} to {:g} m", path,
                    nan_safe(lat.cell_edge), kMinRadius, 4 * kMaxRadius));
  return lat;
}

}  // namespace swarf
