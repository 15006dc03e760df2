// shapes.h: closed triangle meshes of simple solids, oriented outwards, for rigid bodies
// (rigid_body.h) and for tests of their mass properties.
#pragma once

#include "swarf/core/vec3.h"
#include "swarf/state/mesh.h"

namespace swarf {

/// A box with edges 'size' (m) along x, y, z, centred on 'centre': 12 triangles.
TriangleMesh box_mesh(const Vec3& centre, const Vec3& size);

/// A cylinder of 'radius' and 'length' (m) along 'axis' (unit), centred on 'centre', its
/// round face cut into 'segments' >= 3 flat sides (a prism inscribed in the cylinder) and
/// its ends into fans about their centres: 4 segments triangles.
TriangleMesh cylinder_mesh(const Vec3& centre, const Vec3& axis, double radius, double length, int segments);

}  // namespace swarf
