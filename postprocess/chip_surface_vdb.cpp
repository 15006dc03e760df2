// chip_surface_vdb.cpp: the OpenVDB part of the chip surface: spheres to a narrow-band level set
// (ParticlesToLevelSet), the level set to quads (volumeToMesh) and its volume (levelSetVolume).
//
// Kept in a translation unit of its own and free of swarf logic: ParticlesToLevelSet takes
// 40-55 s and 1.5 GB to compile, so this file should rarely change. The checks, the voxel
// choice and the triangle mesh are in chip_surface.cpp.
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetMeasure.h>
#include <openvdb/tools/ParticlesToLevelSet.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <mutex>

#include "postprocess/chip_surface.h"

namespace swarf::detail {

namespace {

/// The particle-list interface ParticlesToLevelSet asks for.
struct SphereList {
  using PosType = openvdb::Vec3R;
  const std::vector<Vec3>& c;
  const std::vector<double>& r;
  std::size_t size() const { return c.size(); }
  void getPos(std::size_t n, openvdb::Vec3R& xyz) const { xyz = openvdb::Vec3R(c[n].x(), c[n].y(), c[n].z()); }
  void getPosRad(std::size_t n, openvdb::Vec3R& xyz, openvdb::Real& radius) const {
    getPos(n, xyz);
    radius = r[n];
  }
};

void initialize_once() {
  static std::once_flag flag;
  std::call_once(flag, [] { openvdb::initialize(); });
}

}  // namespace

VdbSurface vdb_sphere_surface(const std::vector<Vec3>& centres, const std::vector<double>& radii, double voxel,
                              double rmin_voxels, double rmax_voxels) {
  initialize_once();
  VdbSurface out;
  if (centres.empty()) return out;
  // Work in voxel units (voxel edge 1, index space = world space): OpenVDB refuses transforms
  // whose determinant is below 3e-15 (a voxel under 14 micrometres in metres) and its mesh
  // points are floats.
  std::vector<Vec3> c(centres.size());
  std::vector<double> r(radii.size());
  for (std::size_t i = 0; i < c.size(); ++i) {
    c[i] = centres[i] / voxel;
    r[i] = radii[i] / voxel;
  }
  // Narrow band of 3 voxels on either side (OpenVDB's default for level sets).
  openvdb::FloatGrid::Ptr grid = openvdb::createLevelSet<openvdb::FloatGrid>(1.0, openvdb::LEVEL_SET_HALF_WIDTH);
  openvdb::tools::ParticlesToLevelSet<openvdb::FloatGrid> raster(*grid);
  raster.setRmin(rmin_voxels);
  raster.setRmax(rmax_voxels);
  raster.rasterizeSpheres(SphereList{c, r});
  raster.finalize(/*prune=*/true);
  out.skipped_small = raster.getMinCount();
  out.skipped_large = raster.getMaxCount();

  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*grid, points, triangles, quads, /*isovalue=*/0.0, /*adaptivity=*/0.0);

  // Vertices back in metres; chip_surface.cpp moves them onto the exact spheres.
  out.points.reserve(points.size());
  for (const auto& p : points) out.points.push_back(Vec3(p.x(), p.y(), p.z()) * voxel);
  out.triangles.reserve(triangles.size());
  for (const auto& t : triangles) out.triangles.push_back({int(t[0]), int(t[1]), int(t[2])});
  out.quads.reserve(quads.size());
  for (const auto& q : quads) out.quads.push_back({int(q[0]), int(q[1]), int(q[2]), int(q[3])});
  if (grid->activeVoxelCount() > 0)
    out.level_set_volume = openvdb::tools::levelSetVolume(*grid, /*useWorldUnits=*/true) * voxel * voxel * voxel;
  return out;
}

}  // namespace swarf::detail
