// overlap_area.cpp: circle-triangle intersection area (see overlap_area.h).
#include "swarf/geometry/overlap_area.h"

#include <cmath>

namespace swarf {
namespace {

inline double cross(const Vec2& u, const Vec2& v) { return u[0] * v[1] - u[1] * v[0]; }

// Signed area of the sector of radius r from direction u to direction v (the shorter way).
inline double sector(const Vec2& u, const Vec2& v, double r) { return 0.5 * r * r * std::atan2(cross(u, v), u.dot(v)); }

}  // namespace

double circle_wedge_area(const Vec2& a, const Vec2& b, double r) {
  const double r2 = r * r;
  const double a2 = a.squaredNorm(), b2 = b.squaredNorm();
  const bool a_in = a2 <= r2, b_in = b2 <= r2;
  if (a_in && b_in) return 0.5 * cross(a, b);
  // Points a + t (b - a) on the circle: |d|^2 t^2 + 2 (a.d) t + |a|^2 - r^2 = 0.
  const Vec2 d = b - a;
  const double A = d.squaredNorm();
  if (A == 0.0) return 0.0;
  const double B = a.dot(d), C = a2 - r2;
  const double disc = B * B - A * C;
  if (a_in) {  // leaves the circle once
    const double t = (-B + std::sqrt(std::max(0.0, disc))) / A;
    const Vec2 p = a + t * d;
    return 0.5 * cross(a, p) + sector(p, b, r);
  }
  if (b_in) {  // enters the circle once
    const double t = (-B - std::sqrt(std::max(0.0, disc))) / A;
    const Vec2 p = a + t * d;
    return sector(a, p, r) + 0.5 * cross(p, b);
  }
  // Both outside: the segment may cross the circle twice.
  if (disc > 0.0) {
    const double s = std::sqrt(disc);
    const double t1 = (-B - s) / A, t2 = (-B + s) / A;
    if (t1 > 0.0 && t2 < 1.0) {
      const Vec2 p1 = a + t1 * d, p2 = a + t2 * d;
      return sector(a, p1, r) + 0.5 * cross(p1, p2) + sector(p2, b, r);
    }
  }
  return sector(a, b, r);
}

double circle_triangle_area(const Vec2& a, const Vec2& b, const Vec2& c, double r) {
  // A circle inside the triangle, at least r from each edge's line (the usual case of a sphere
  // on a face): the whole disc, without the wedges' three arc tangents.
  const double orient = cross(b - a, c - a), r2 = r * r;
  auto clear_of = [&](const Vec2& p, const Vec2& q) {  // centre on the inner side, r or more from the line
    const double side = orient > 0.0 ? cross(q - p, -p) : cross(p - q, -q);
    return side > 0.0 && side * side >= r2 * (q - p).squaredNorm();
  };
  if (orient != 0.0 && clear_of(a, b) && clear_of(b, c) && clear_of(c, a)) return M_PI * r2;
  const double s = circle_wedge_area(a, b, r) + circle_wedge_area(b, c, r) + circle_wedge_area(c, a, r);
  return std::abs(s);
}

// Closest point of triangle (a, b, c) to p (Ericson, Real-Time Collision Detection 5.1.5).
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

TriangleFrame triangle_frame(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  TriangleFrame f;
  const Vec3 e1 = p1 - p0, e2 = p2 - p0;
  Vec3 n = e1.cross(e2);
  const double n_len = n.norm();
  if (!(n_len > 0.0)) return f;  // degenerate (meshes are checked on reading)
  f.n = n / n_len;
  f.u = e1 / e1.norm();
  f.v = f.n.cross(f.u);
  f.ok = true;
  return f;
}

SphereTriangleHit sphere_triangle(const Vec3& c, double R, const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  return sphere_triangle(c, R, p0, p1, p2, triangle_frame(p0, p1, p2));
}

SphereTriangleHit sphere_triangle(const Vec3& c, double R, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                                  const TriangleFrame& f) {
  SphereTriangleHit h;
  if (!f.ok) return h;
  const Vec3& n = f.n;
  const double dist = (c - p0).dot(n);
  if (std::abs(dist) >= R) return h;
  // The exact test of contact: the triangle reaches into the sphere. (The area below is a sum
  // of signed wedges; for a circle that misses a thin triangle it can round to a tiny positive
  // number: such a spurious contact pushed with ~1e-18 of a force and made results depend on
  // when the contact lists were rebuilt.)
  if (!((closest_on_triangle(c, p0, p1, p2) - c).squaredNorm() < R * R)) return h;
  const double rho2 = R * R - dist * dist;
  const Vec3 centre = c - dist * n;
  // In-plane coordinates relative to the circle centre.
  const Vec3 &u = f.u, &v = f.v;
  auto to2 = [&](const Vec3& p) { return Vec2((p - centre).dot(u), (p - centre).dot(v)); };
  const double area = circle_triangle_area(to2(p0), to2(p1), to2(p2), std::sqrt(rho2));
  if (!(area > 0.0)) return h;
  h.touching = true;
  h.distance = dist;
  h.overlap = R - std::abs(dist);
  h.weight = area / (M_PI * rho2);
  h.normal = dist >= 0.0 ? n : Vec3(-n);
  h.point = centre;
  return h;
}

}  // namespace swarf
