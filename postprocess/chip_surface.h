// chip_surface.h: the chip's surface as a closed triangle mesh and its volume, built with OpenVDB.
//
// The particles (centres and radii, m) are rasterised into a narrow-band signed-distance level
// set of the UNION OF THEIR SPHERES (openvdb::tools::ParticlesToLevelSet), each radius
// optionally grown by a dilation d; the zero isosurface is extracted with
// openvdb::tools::volumeToMesh (no adaptivity), each vertex moved onto the exact surface of
// the union of spheres (volumeToMesh leaves it up to h^2/(4R) inside), and the quads split into
// triangles along the shorter diagonal. The mesh is closed (every edge in two triangles, once
// each way) and counterclockwise seen from outside (outward normals).
//
// What the volumes mean (all m^3):
//  - volume_m3: the volume enclosed by the triangle mesh, by the divergence theorem (sum of
//    the signed volumes of the tetrahedra spanned by each triangle and the mesh centroid).
//    This is the number to report: the volume of the union of the (dilated) spheres, up to
//    the voxel size h. Its vertices lie on the spheres, so on a convex surface the flat
//    facets cut off about 3 h^2 / (8 R^2): a single sphere comes out 5 % low at h = R/3,
//    1.6 % at R/5, 0.6 % at R/8. Where neighbours touch, the grid cannot resolve the narrow
//    neck and fills it over about a voxel, which adds volume: an FCC block of touching
//    spheres (d = 0) measures 1.085 times the spheres' volume at R/3, 1.03 at R/5.
//  - level_set_volume_m3: the same region measured on the level set itself
//    (openvdb::tools::levelSetVolume, a smeared Heaviside), a cross-check: a single sphere
//    comes out 7 % high at R/3, 2.5 % at R/5; an FCC block within 10 % of volume_m3.
//  - sphere_volume_m3: sum of 4/3 pi r^3 over the particles (undilated). Touching spheres of
//    a bonded FCC lattice (centres 2R apart) do not overlap, so for an intact lattice this is
//    the exact union volume with d = 0; overlapping particles make the union smaller.
//  - packing_volume_m3: sum of 4 sqrt(2) r^3 over the particles, the volume each particle
//    occupies in an FCC packing (cell edge a = 2 sqrt(2) R, 4 particles per a^3; packing
//    fraction pi / (3 sqrt 2) = 0.7405). This is the MATERIAL volume of the chip if it is
//    still a dense packing: the estimate to compare with h * width * length of cut.
// The union of touching spheres has gaps between them and a bumpy surface, so with d = 0,
// volume_m3 is about 0.74 times the packing volume (0.76-0.80 at R/5-R/3 for a block of 108
// particles). A dilation closes the gaps: at d = (sqrt 2 - 1) R = 0.414 R the dilated
// spheres cover the FCC Voronoi cells (rhombic dodecahedra) entirely, and the mesh encloses
// the packing volume plus a skin about 0.4 R thick over the free surface; at d = 0.1 R a
// 108-particle block measures 0.96-0.97 times its packing volume, at d = 0.2 R 1.08.
//
// Voxel size: 0 = automatic, the median particle radius / 3. ParticlesToLevelSet silently
// skips spheres smaller than 1.5 voxels; here the voxel is shrunk instead so that the
// smallest (dilated) sphere spans at least 1.6 voxels, and the note says so. Too fine a grid
// (more than max_voxels estimated narrow-band voxels) is an InputError, never a silent skip.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "swarf/core/vec3.h"
#include "swarf/state/mesh.h"

namespace swarf {

struct ChipSurface {
  TriangleMesh mesh;               ///< closed surface, m; triangles counterclockwise from outside; name "chip_surface"
  double volume_m3 = 0;            ///< enclosed by the mesh (divergence theorem), m^3: THE chip volume reported
  double level_set_volume_m3 = 0;  ///< the same from openvdb::tools::levelSetVolume, m^3 (cross-check)
  double sphere_volume_m3 = 0;     ///< sum of 4/3 pi r^3 (undilated), m^3
  double packing_volume_m3 = 0;    ///< sum of 4 sqrt(2) r^3: FCC volume per particle, m^3
  double voxel_m = 0;              ///< voxel edge used, m
  double dilation_m = 0;           ///< added to every radius, m
  std::size_t particles = 0;       ///< particles given
  std::string note;                ///< empty, or why the surface is empty or the voxel changed
};

struct ChipSurfaceOptions {
  double voxel_size = 0;    ///< m; 0 = median radius / 3
  double dilation = 0;      ///< m, >= 0, added to every radius before rasterising
  double max_voxels = 2e8;  ///< upper bound on the estimated narrow-band voxel count
};

/// Builds the surface of the union of spheres (centres[i], radii[i] + dilation), m.
/// Empty input gives an empty mesh with a note. Throws InputError on mismatched sizes,
/// non-finite centres, non-positive or non-finite radii, a negative voxel size or
/// dilation, or a grid too fine for max_voxels.
ChipSurface build_chip_surface(const std::vector<Vec3>& centres, const std::vector<double>& radii,
                               const ChipSurfaceOptions& options = {});
/// Shorthand: voxel_size (m, 0 = auto) and dilation (m).
ChipSurface build_chip_surface(const std::vector<Vec3>& centres, const std::vector<double>& radii, double voxel_size,
                               double dilation = 0);

/// Signed volume enclosed by a closed triangle mesh (positive for outward normals), m^3.
double mesh_volume(const TriangleMesh& mesh);

namespace detail {
/// The OpenVDB part (its own translation unit, chip_surface_vdb.cpp: ParticlesToLevelSet is
/// slow to compile). Rasterises the spheres at the given voxel edge (m) and extracts the zero
/// isosurface. Radii already include any dilation.
struct VdbSurface {
  std::vector<Vec3> points;                   ///< m
  std::vector<std::array<int, 3>> triangles;  ///< as volumeToMesh gives them
  std::vector<std::array<int, 4>> quads;      ///< as volumeToMesh gives them
  double level_set_volume = 0;                ///< m^3
  std::size_t skipped_small = 0;              ///< spheres ParticlesToLevelSet ignored (< Rmin voxels)
  std::size_t skipped_large = 0;              ///< spheres ParticlesToLevelSet ignored (> Rmax voxels)
};
VdbSurface vdb_sphere_surface(const std::vector<Vec3>& centres, const std::vector<double>& radii, double voxel,
                              double rmin_voxels, double rmax_voxels);
}  // namespace detail

}  // namespace swarf
