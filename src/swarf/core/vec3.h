// vec3.h: the 3-vector type used for particle fields (Eigen, double precision).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace swarf {
using Vec3 = Eigen::Vector3d;
}  // namespace swarf
