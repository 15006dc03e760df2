// tool_measure.cpp: a cutting tool's angles, tip and edge read off its mesh (see tool_measure.h).
#include "tool_paths/tool_measure.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "swarf/core/errors.h"

namespace swarf {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kAlongY = 1e-3;  // |n_y| of a face parallel to y (the edge along y within 0.06 deg)
// One plane: normals within 1e-4 rad (a float STL's coordinates, 6e-8 of themselves, scatter the
// normals of a 2 mm face 0.2 m from the origin by 1e-5 rad; a honed edge's facets are degrees
// apart) and offsets within 1e-6 of the coordinates' size (extent plus distance from the origin).
constexpr double kSameNormal = 1e-4;
constexpr double kSameOffset = 1e-6;
constexpr double kNear = 0.3;  // of the profile's extent: a face near the lowest point

// A plane of the profile: faces parallel to y with one normal and offset in x-z.
struct Plane {
  double nx = 0, nz = 0;  // area-weighted sum of the faces' normals (x, z), then unit
  double offset = 0;      // n . p, m
  double area = 0;        // m^2
  std::vector<int> vertices;
};

double dist_xz(const Vec3& a, double x, double z) { return std::hypot(a.x() - x, a.z() - z); }

}  // namespace

ToolMeasure measure_tool(const TriangleMesh& m) {
  if (m.vertices.empty() || m.triangles.empty()) throw InputError("the mesh has no triangles");
  double xlo = HUGE_VAL, xhi = -HUGE_VAL, zlo = HUGE_VAL, zhi = -HUGE_VAL;
  for (const Vec3& v : m.vertices) {
    xlo = std::min(xlo, v.x()), xhi = std::max(xhi, v.x());
    zlo = std::min(zlo, v.z()), zhi = std::max(zhi, v.z());
  }
  const double extent = std::hypot(xhi - xlo, zhi - zlo);  // of the profile in x-z, m
  if (!(extent > 0)) throw InputError("the mesh is flat in x-z");
  const double size = extent + std::max({std::abs(xlo), std::abs(xhi), std::abs(zlo), std::abs(zhi)});  // m

  // The planes of the faces parallel to y.
  std::vector<Plane> planes;
  for (const auto& t : m.triangles) {
    const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
    const Vec3 n = (b - a).cross(c - a);
    const double len = n.norm();
    if (!(len > 0) || std::abs(n.y()) > kAlongY * len) continue;
    const double nx = n.x() / len, nz = n.z() / len, s = std::hypot(nx, nz);
    const double ux = nx / s, uz = nz / s, d = ux * a.x() + uz * a.z();
    auto same = [&](const Plane& p) {
      const double l = std::hypot(p.nx, p.nz);
      const double px = p.nx / l, pz = p.nz / l;
      return px * ux + pz * uz > 0 && std::abs(px * uz - pz * ux) < kSameNormal &&
             std::abs(p.offset - d) < kSameOffset * size;
    };
    auto it = std::find_if(planes.begin(), planes.end(), same);
    if (it == planes.end()) {
      planes.push_back(Plane{0, 0, d, 0, {}});
      it = planes.end() - 1;
    }
    it->nx += 0.5 * n.x(), it->nz += 0.5 * n.z(), it->area += 0.5 * len;
    for (int k : t) it->vertices.push_back(k);
  }
  if (planes.empty())
    throw InputError(
        "no face is parallel to y: the cutting edge must lie along y (the tool cuts along +x, its rake face facing "
        "+x)");
  for (Plane& p : planes) {
    const double l = std::hypot(p.nx, p.nz);
    p.nx /= l, p.nz /= l;
    std::sort(p.vertices.begin(), p.vertices.end());
    p.vertices.erase(std::unique(p.vertices.begin(), p.vertices.end()), p.vertices.end());
  }

  // The lowest point, the most forward of the lowest.
  double px = -HUGE_VAL;
  for (const Vec3& v : m.vertices)
    if (v.z() <= zlo + kSameOffset * size) px = std::max(px, v.x());
  const double pz = zlo;

  // The largest rake-like and flank-like planes near it.
  const Plane *rake = nullptr, *flank = nullptr;
  for (const Plane& p : planes) {
    double near = HUGE_VAL;
    for (int k : p.vertices) near = std::min(near, dist_xz(m.vertices[k], px, pz));
    if (near > kNear * extent) continue;
    const bool lower = p.nz < 0;
    const bool rake_like = p.nx > 0 && (!lower || p.nx > -p.nz);  // gamma in (-45, 90) deg
    const bool flank_like = lower && !rake_like;                  // alpha in [-45, 90) deg
    if (rake_like && (!rake || p.area > rake->area)) rake = &p;
    if (flank_like && (!flank || p.area > flank->area)) flank = &p;
  }
  const auto where = fmt::format("near the lowest point (x = {:.6g}, z = {:.6g}) m", px, pz);
  if (!rake && !flank)
    throw InputError(
        fmt::format("no cutting edge found: neither a rake face (outward normal toward +x) nor a flank "
                    "(outward normal toward -z) {}",
                    where));
  if (!rake)
    throw InputError(fmt::format(
        "no rake face found: no face with an outward normal toward +x (within 45 deg below it or up to 90 deg above) "
        "{}; the rake face must face the cutting direction +x",
        where));
  if (!flank)
    throw InputError(fmt::format(
        "no flank found: no face with an outward normal toward -z (within 45 deg ahead of it or up to 90 deg back) "
        "{}",
        where));

  ToolMeasure t;
  t.rake_angle_deg = std::atan2(rake->nz, rake->nx) / kDeg + 0.0;  // (+ 0: no "-0 deg" in messages)
  t.clearance_angle_deg = std::atan2(-flank->nx, -flank->nz) / kDeg + 0.0;
  const std::string angles = fmt::format("measured rake {:.6g} deg and clearance {:.6g} deg", t.rake_angle_deg,
                                         t.clearance_angle_deg);

  // The sharp tip: a vertex of both faces (the lowest), else where their planes meet.
  int shared = -1;
  for (int k : rake->vertices)
    if (std::binary_search(flank->vertices.begin(), flank->vertices.end(), k) &&
        (shared < 0 || m.vertices[k].z() < m.vertices[shared].z()))
      shared = k;
  double tx = 0, tz = 0;
  t.sharp = shared >= 0;
  if (t.sharp) {
    tx = m.vertices[shared].x(), tz = m.vertices[shared].z();
  } else {
    const double det = rake->nx * flank->nz - rake->nz * flank->nx;
    if (!(std::abs(det) > 1e-6))
      throw InputError(fmt::format("tip not identifiable: the rake face and the flank are parallel ({})", angles));
    tx = (rake->offset * flank->nz - rake->nz * flank->offset) / det;
    tz = (rake->nx * flank->offset - rake->offset * flank->nx) / det;
  }
  if (dist_xz(Vec3(px, 0, pz), tx, tz) > kNear * extent)
    throw InputError(fmt::format(
        "tip not identifiable: the rake face and the flank meet at x = {:.6g}, z = {:.6g} m, far from the lowest "
        "point {} ({})",
        tx, tz, where, angles));
  if (!(t.rake_angle_deg > -45 && t.rake_angle_deg < 45))
    throw InputError(fmt::format("{}: the rake angle must lie in (-45, 45) deg", angles));
  if (!(t.clearance_angle_deg > 0 && t.clearance_angle_deg < 45))
    throw InputError(
        fmt::format("{}: the clearance angle must lie in (0, 45) deg (a flat bottom, a box, has 0)", angles));

  // Faces' extents from the tip, tangent points and the edge along y.
  double ylo = -HUGE_VAL, yhi = HUGE_VAL;
  double tangent = 0;
  for (const Plane* p : {rake, flank}) {
    double lo = HUGE_VAL, hi = -HUGE_VAL, nearest = HUGE_VAL, farthest = 0;
    for (int k : p->vertices) {
      const Vec3& v = m.vertices[k];
      lo = std::min(lo, v.y()), hi = std::max(hi, v.y());
      nearest = std::min(nearest, dist_xz(v, tx, tz));
      farthest = std::max(farthest, dist_xz(v, tx, tz));
    }
    ylo = std::max(ylo, lo), yhi = std::min(yhi, hi);
    tangent += 0.5 * nearest;
    (p == rake ? t.face_length : t.flank_length) = farthest;
  }
  if (!(yhi > ylo))
    throw InputError(
        fmt::format("no cutting edge found: the rake face and the flank do not overlap along y ({})", angles));
  const double wedge = (90.0 - t.rake_angle_deg - t.clearance_angle_deg) * kDeg;
  t.edge_radius = t.sharp ? 0.0 : tangent * std::tan(0.5 * wedge);
  t.tip = Vec3(tx, 0.5 * (ylo + yhi), tz);
  t.edge_length = yhi - ylo;
  return t;
}

std::string describe(const ToolMeasure& t) {
  return fmt::format(
      "rake {:.6g} deg, clearance {:.6g} deg, edge radius {}, rake face {:.4g} mm, flank {:.4g} mm, edge {:.4g} mm "
      "long",
      t.rake_angle_deg, t.clearance_angle_deg,
      t.sharp ? std::string("0 (sharp)") : fmt::format("{:.4g} um (honed, estimated)", t.edge_radius * 1e6),
      t.face_length * 1e3, t.flank_length * 1e3, t.edge_length * 1e3);
}

}  // namespace swarf
