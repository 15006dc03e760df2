// chip_surface.cpp: checks, voxel choice, triangle mesh and volumes of the chip surface
// (see chip_surface.h); the OpenVDB rasterisation itself is in chip_surface_vdb.cpp.
#include "postprocess/chip_surface.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <unordered_map>

#include "swarf/core/bounds.h"
#include "swarf/core/errors.h"

namespace swarf {

namespace {

/// Smallest sphere radius in voxels that is rasterised: OpenVDB's own cutoff (Rmin) is 1.5;
/// the voxel is chosen so that every sphere spans at least kMinVoxels > 1.5.
constexpr double kRminVoxels = 1.5;
constexpr double kMinVoxels = 1.6;
/// Narrow band on either side of the surface, voxels (OpenVDB's LEVEL_SET_HALF_WIDTH).
constexpr double kHalfWidth = 3.0;

void add_note(std::string& note, const std::string& more) {
  if (!note.empty()) note += "; ";
  note += more;
}

void check_input(const std::vector<Vec3>& centres, const std::vector<double>& radii, const ChipSurfaceOptions& o) {
  if (centres.size() != radii.size())
    throw InputError(fmt::format("chip surface: {} centres but {} radii", centres.size(), radii.size()));
  if (!std::isfinite(o.voxel_size) || o.voxel_size < 0)
    throw InputError(fmt::format("chip surface: voxel size {} m must be >= 0 (0 = automatic)", o.voxel_size));
  if (!std::isfinite(o.dilation) || o.dilation < 0)
    throw InputError(fmt::format("chip surface: dilation {} m must be >= 0", o.dilation));
  if (!(o.max_voxels > 0)) throw InputError(fmt::format("chip surface: max_voxels {} must be > 0", o.max_voxels));
  for (std::size_t i = 0; i < centres.size(); ++i) {
    if (!all_finite(centres[i])) throw InputError(fmt::format("chip surface: particle {} has a non-finite centre", i));
    if (!std::isfinite(radii[i]) || !(radii[i] > 0))
      throw InputError(fmt::format("chip surface: particle {} has radius {} m (must be > 0)", i, radii[i]));
  }
}

/// Moves every vertex onto the exact surface of the union of spheres (centres c, radii r, the
/// frame of the vertices): volumeToMesh places one vertex per voxel at the mean of the edge
/// crossings of the trilinear interpolant, inside a convex surface by about h^2/(4R) (a
/// sphere of 5 voxels lost 4.6 % of its volume). Newton steps on phi(x) = min_i |x - c_i| - r_i
/// along the gradient of the nearest sphere, at most one voxel each; spheres looked up in a
/// hash grid of cells wider than the largest radius plus two voxels.
void project_onto_spheres(std::vector<Vec3>& pts, const std::vector<Vec3>& c, const std::vector<double>& r,
                          double voxel) {
  if (pts.empty()) return;
  const double r_max = *std::max_element(r.begin(), r.end());
  const double cell = r_max + 2.0 * voxel;
  auto cell_of = [&](const Vec3& x) {
    return std::array<std::int64_t, 3>{std::int64_t(std::floor(x.x() / cell)), std::int64_t(std::floor(x.y() / cell)),
                                       std::int64_t(std::floor(x.z() / cell))};
  };
  auto key = [](std::int64_t i, std::int64_t j, std::int64_t k) {
    return (std::uint64_t(i + (1 << 20)) << 42) | (std::uint64_t(j + (1 << 20)) << 21) | std::uint64_t(k + (1 << 20));
  };
  std::unordered_map<std::uint64_t, std::vector<int>> bins;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const auto q = cell_of(c[i]);
    bins[key(q[0], q[1], q[2])].push_back(int(i));
  }
  const std::int64_t n = static_cast<std::int64_t>(pts.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t v = 0; v < n; ++v) {
    Vec3 x = pts[v];
    for (int it = 0; it < 4; ++it) {
      const auto q = cell_of(x);
      double phi = HUGE_VAL;
      int best = -1;
      for (std::int64_t i = q[0] - 1; i <= q[0] + 1; ++i)
        for (std::int64_t j = q[1] - 1; j <= q[1] + 1; ++j)
          for (std::int64_t k = q[2] - 1; k <= q[2] + 1; ++k) {
            const auto b = bins.find(key(i, j, k));
            if (b == bins.end()) continue;
            for (int s : b->second) {
              const double f = (x - c[s]).norm() - r[s];
              if (f < phi) phi = f, best = s;
            }
          }
      if (best < 0) break;
      const Vec3 dir = x - c[best];
      const double len = dir.norm();
      if (!(len > 1e-9 * voxel)) break;
      double step = -phi;  // along dir / len
      if (std::abs(step) > voxel) step = std::copysign(voxel, step);
      x += dir * (step / len);
      if (std::abs(phi) < 1e-9 * voxel) break;
    }
    pts[v] = x;
  }
}

}  // namespace

double mesh_volume(const TriangleMesh& mesh) {
  if (mesh.vertices.empty()) return 0.0;
  // Tetrahedra from a point near the mesh (its vertex mean) keep the sum well conditioned.
  Vec3 o = Vec3::Zero();
  for (const auto& v : mesh.vertices) o += v;
  o /= double(mesh.vertices.size());
  double six_v = 0;
  for (const auto& t : mesh.triangles)
    six_v += (mesh.vertices[t[0]] - o).dot((mesh.vertices[t[1]] - o).cross(mesh.vertices[t[2]] - o));
  return six_v / 6.0;
}

ChipSurface build_chip_surface(const std::vector<Vec3>& centres, const std::vector<double>& radii,
                               const ChipSurfaceOptions& options) {
  check_input(centres, radii, options);
  ChipSurface s;
  s.mesh.name = "chip_surface";
  s.particles = centres.size();
  s.dilation_m = options.dilation;
  if (centres.empty()) {
    s.note = "no particles: the chip surface is empty";
    return s;
  }

  double r_min = HUGE_VAL, r_max = 0;
  for (double r : radii) {
    s.sphere_volume_m3 += 4.0 / 3.0 * std::numbers::pi * r * r * r;
    s.packing_volume_m3 += 4.0 * std::numbers::sqrt2 * r * r * r;
    r_min = std::min(r_min, r);
    r_max = std::max(r_max, r);
  }
  const double d = options.dilation;

  // Voxel: given, or the median radius / 3; shrunk so the smallest sphere is not skipped.
  double voxel = options.voxel_size;
  if (voxel == 0) {
    std::vector<double> sorted = radii;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    voxel = sorted[sorted.size() / 2] / 3.0;
  }
  if (r_min + d < kMinVoxels * voxel) {
    const double finer = (r_min + d) / kMinVoxels;
    add_note(s.note, fmt::format("voxel {:.4g} m shrunk to {:.4g} m: the smallest sphere (radius {:.4g} m) must span "
                                 "at least {} voxels or OpenVDB would skip it",
                                 voxel, finer, r_min + d, kRminVoxels));
    voxel = finer;
  }
  // Narrow-band voxels, counted as if the spheres did not overlap (an upper bound).
  double estimate = 0;
  for (double r : radii) estimate += 4.0 * std::numbers::pi * std::pow((r + d) / voxel, 2) * 2.0 * kHalfWidth;
  if (estimate > options.max_voxels)
    throw InputError(
        fmt::format("chip surface: voxel {:.4g} m is too fine for {} particles of radius {:.4g} to {:.4g} m "
                    "(about {:.3g} narrow-band voxels, limit {:.3g}): use a larger voxel size",
                    voxel, centres.size(), r_min, r_max, estimate, options.max_voxels));
  s.voxel_m = voxel;

  // Rasterise relative to the lower corner of the centres: OpenVDB's mesh points are floats.
  Vec3 origin = centres[0];
  for (const auto& c : centres) origin = origin.cwiseMin(c);
  std::vector<Vec3> local(centres.size());
  std::vector<double> grown(radii.size());
  for (std::size_t i = 0; i < centres.size(); ++i) {
    local[i] = centres[i] - origin;
    grown[i] = radii[i] + d;
  }
  const double rmax_voxels = 2.0 * (r_max + d) / voxel + 10.0;  // never skip a large sphere
  detail::VdbSurface v = detail::vdb_sphere_surface(local, grown, voxel, kRminVoxels, rmax_voxels);
  if (v.skipped_small + v.skipped_large > 0)
    add_note(s.note, fmt::format("OpenVDB skipped {} spheres below {} voxels and {} above {:.3g} voxels",
                                 v.skipped_small, kRminVoxels, v.skipped_large, rmax_voxels));

  project_onto_spheres(v.points, local, grown, voxel);
  s.mesh.vertices.reserve(v.points.size());
  for (const auto& p : v.points) s.mesh.vertices.push_back(p + origin);
  s.mesh.triangles = v.triangles;
  s.mesh.triangles.reserve(v.triangles.size() + 2 * v.quads.size());
  for (const auto& q : v.quads) {
    // Split along the shorter diagonal (better shaped triangles).
    const auto& P = s.mesh.vertices;
    if ((P[q[0]] - P[q[2]]).squaredNorm() <= (P[q[1]] - P[q[3]]).squaredNorm()) {
      s.mesh.triangles.push_back({q[0], q[1], q[2]});
      s.mesh.triangles.push_back({q[0], q[2], q[3]});
    } else {
      s.mesh.triangles.push_back({q[0], q[1], q[3]});
      s.mesh.triangles.push_back({q[1], q[2], q[3]});
    }
  }
  s.volume_m3 = mesh_volume(s.mesh);
  if (s.volume_m3 < 0) {  // make the normals point outward
    for (auto& t : s.mesh.triangles) std::swap(t[1], t[2]);
    s.volume_m3 = -s.volume_m3;
  }
  s.level_set_volume_m3 = v.level_set_volume;
  if (s.mesh.triangles.empty()) add_note(s.note, "OpenVDB produced no surface");
  return s;
}

ChipSurface build_chip_surface(const std::vector<Vec3>& centres, const std::vector<double>& radii, double voxel_size,
                               double dilation) {
  ChipSurfaceOptions o;
  o.voxel_size = voxel_size;
  o.dilation = dilation;
  return build_chip_surface(centres, radii, o);
}

}  // namespace swarf
