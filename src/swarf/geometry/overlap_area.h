// overlap_area.h: exact area of a circle intersected with a triangle (paper eqs. 18-19).
//
// A sphere cuts a triangle's plane in a circle; the part of that circle inside the triangle
// weights the triangle's Hertz force, so that coplanar triangles share a flat contact
// exactly (their weights sum to one) however the surface is triangulated and wherever the
// sphere sits: on a face, an edge or a vertex, all through the same computation.
//
// Construction: the intersection of a circle centred at the origin with a polygon is the
// sum over the polygon's edges (P, Q) of the signed area of circle ∩ triangle(O, P, Q).
// Each term is a combination of straight triangles (where the edge lies inside the circle)
// and circular sectors (where it lies outside); the paper's "eight overlap cases" are the
// cases of this construction. No case split on the triangle as a whole is needed.
#pragma once

#include <Eigen/Core>

#include "swarf/core/vec3.h"

namespace swarf {

using Vec2 = Eigen::Vector2d;

/// Signed area of {|x| <= r} ∩ triangle(0, a, b): positive when (a, b) turns counterclockwise.
double circle_wedge_area(const Vec2& a, const Vec2& b, double r);

/// Area of the circle of radius r centred at the origin intersected with triangle (a, b, c), m^2.
double circle_triangle_area(const Vec2& a, const Vec2& b, const Vec2& c, double r);

/// The point of triangle (a, b, c) closest to p (Ericson, Real-Time Collision Detection 5.1.5), m.
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// The geometry of a sphere against one triangle.
struct SphereTriangleHit {
  bool touching = false;
  double distance = 0;         ///< signed distance of the centre from the triangle's plane along its normal, m
  double overlap = 0;          ///< R - |distance|, m
  double weight = 0;           ///< (area of the cut circle inside the triangle) / (area of the cut circle), 1
  Vec3 normal = Vec3::Zero();  ///< unit normal of the plane pointing towards the centre
  Vec3 point = Vec3::Zero();   ///< centre of the cut circle (the centre projected on the plane), m
};

/// A triangle's unit normal n = e1 x e2 / |e1 x e2| (e1 = p1 - p0, e2 = p2 - p0) and unit
/// in-plane axes u = e1 / |e1|, v = n x u; constant for a rigidly translated triangle, so
/// computed once per mesh. 'ok' is false for a degenerate triangle.
struct TriangleFrame {
  Vec3 n = Vec3::Zero(), u = Vec3::Zero(), v = Vec3::Zero();
  bool ok = false;
};
TriangleFrame triangle_frame(const Vec3& p0, const Vec3& p1, const Vec3& p2);

/// Cuts the sphere (centre c, radius R) with the plane of triangle (p0, p1, p2); touching when
/// the triangle's closest point lies inside the sphere and the cut circle's area inside the
/// triangle is positive.
SphereTriangleHit sphere_triangle(const Vec3& c, double R, const Vec3& p0, const Vec3& p1, const Vec3& p2);
/// The same with the triangle's frame computed beforehand (the same result, bit for bit).
SphereTriangleHit sphere_triangle(const Vec3& c, double R, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                                  const TriangleFrame& f);

}  // namespace swarf
