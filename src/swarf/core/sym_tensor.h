// sym_tensor.h: a symmetric 3x3 tensor as six numbers, and the moment of a force.
//
// The contacts add their forces' moments to the per-particle stress (contacts/contact_virial.cpp)
// and the measures sum them (measure/particle_fields.cpp): the type lives below both, so
// neither floor includes the other's folder.
#pragma once

#include <array>

#include "swarf/core/vec3.h"

namespace swarf {

/// A symmetric tensor as xx, yy, zz, xy, yz, xz (ParaView's order for 6 components).
using SymTensor = std::array<double, 6>;

/// t += sym(a (x) b): a force's moment about the particle's centre, a its arm, b the force.
inline void add_moment(SymTensor& t, const Vec3& a, const Vec3& b) {
  t[0] += a[0] * b[0];
  t[1] += a[1] * b[1];
  t[2] += a[2] * b[2];
  t[3] += 0.5 * (a[0] * b[1] + a[1] * b[0]);
  t[4] += 0.5 * (a[1] * b[2] + a[2] * b[1]);
  t[5] += 0.5 * (a[0] * b[2] + a[2] * b[0]);
}

}  // namespace swarf
