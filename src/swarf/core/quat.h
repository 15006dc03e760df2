// quat.h: unit quaternions for orientations, [q0 (scalar), q1, q2, q3], body to world.
//
// Pure algebra with no integrator in it: the particles, the rigid bodies, the meshes and the
// state archive hold orientations, while only the integrator (laws/rotation.h) turns them
// with Euler's equations. Keeping the type here lets those lower floors hold a Quat without
// reaching up to integrate/.
#pragma once

#include <Eigen/Core>

#include "swarf/core/vec3.h"

namespace swarf {

using Quat = Eigen::Vector4d;  ///< [q0 (scalar), q1, q2, q3]

/// Quaternion product a (x) b.
inline Quat qmul(const Quat& a, const Quat& b) {
  return Quat(
      a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3], a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
      a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1], a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]);
}
inline Quat qconj(const Quat& q) { return Quat(q[0], -q[1], -q[2], -q[3]); }
inline Quat pure(const Vec3& v) { return Quat(0.0, v[0], v[1], v[2]); }
inline Vec3 vec(const Quat& q) { return Vec3(q[1], q[2], q[3]); }

/// Rotates a body-frame vector into the world frame: q (x) [0, v] (x) q*.
inline Vec3 to_world(const Quat& q, const Vec3& v) { return vec(qmul(qmul(q, pure(v)), qconj(q))); }
/// Rotates a world-frame vector into the body frame: q* (x) [0, v] (x) q.
inline Vec3 to_body(const Quat& q, const Vec3& v) { return vec(qmul(qmul(qconj(q), pure(v)), q)); }

}  // namespace swarf
