// shapes.cpp: generated closed meshes (see shapes.h).
#include "swarf/geometry/shapes.h"

#include <cmath>
#include <numbers>

namespace swarf {

TriangleMesh box_mesh(const Vec3& centre, const Vec3& size) {
  TriangleMesh m;
  for (int k = 0; k < 8; ++k)
    m.vertices.push_back(
        centre + 0.5 * Vec3((k & 1) ? size[0] : -size[0], (k & 2) ? size[1] : -size[1], (k & 4) ? size[2] : -size[2]));
  // Two triangles per face, counterclockwise seen from outside.
  m.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6},   // z-, z+
                 {0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3},   // y-, y+
                 {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};  // x-, x+
  return m;
}

TriangleMesh cylinder_mesh(const Vec3& centre, const Vec3& axis, double radius, double length, int segments) {
  const Vec3 e = axis.normalized();
  // Two unit vectors across the axis.
  const Vec3 u = (std::abs(e[0]) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(e).normalized(), v = e.cross(u);
  TriangleMesh m;
  const int n = segments;
  for (int s = 0; s < 2; ++s) {
    const Vec3 c = centre + (s == 0 ? -0.5 : 0.5) * length * e;
    for (int k = 0; k < n; ++k) {
      const double a = 2.0 * std::numbers::pi * k / n;
      m.vertices.push_back(c + radius * (std::cos(a) * u + std::sin(a) * v));
    }
  }
  const int c0 = 2 * n, c1 = 2 * n + 1;  // the ends' centres
  m.vertices.push_back(centre - 0.5 * length * e);
  m.vertices.push_back(centre + 0.5 * length * e);
  for (int k = 0; k < n; ++k) {
    const int k1 = (k + 1) % n;
    m.triangles.push_back({k, k1, n + k1});  // side (u, v, e right-handed: outwards)
    m.triangles.push_back({k, n + k1, n + k});
    m.triangles.push_back({c0, k1, k});  // bottom end, seen from -e
    m.triangles.push_back({c1, n + k, n + k1});
  }
  return m;
}

}  // namespace swarf
