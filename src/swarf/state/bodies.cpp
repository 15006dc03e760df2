// bodies.cpp: placement of a turning mesh (see bodies.h).
#include "swarf/state/bodies.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace swarf {

void MeshBody::place() {
  if (!turns) return;
  const auto& X = mesh.vertices;
  placed.resize(X.size());
  // One rotation matrix for all the vertices (a quaternion sandwich per vertex costs 4x more).
  const Eigen::Matrix3d R = Eigen::Quaterniond(turn[0], turn[1], turn[2], turn[3]).toRotationMatrix();
  const Vec3 c = centre();
  double r2 = 0.0;
  for (std::size_t v = 0; v < X.size(); ++v) {
    const Vec3 d = X[v] - pivot;
    r2 = std::max(r2, d.squaredNorm());
    placed[v] = c + R * d;
  }
  reach = std::sqrt(r2);
}

}  // namespace swarf
