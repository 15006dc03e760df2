// mesh.cpp: the checks of a triangle mesh (see mesh.h).
#include "swarf/state/mesh.h"

#include <fmt/format.h>

#include <cmath>

#include "swarf/core/bounds.h"
#include "swarf/core/errors.h"

namespace swarf {

void TriangleMesh::validate(const std::string& source) const {
  if (triangles.empty()) throw InputError(fmt::format("mesh '{}' has no triangles", source));
  Vec3 lo = Vec3::Constant(HUGE_VAL), hi = Vec3::Constant(-HUGE_VAL);
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    if (!all_finite(vertices[v])) throw InputError(fmt::format("mesh '{}': vertex {} is not finite", source, v));
    if (vertices[v].cwiseAbs().maxCoeff() > kMaxMeshCoordinate)
      throw InputError(
          fmt::format("mesh '{}': vertex {} = ({}, {}, {}) m lies beyond {:g} m (a unit or scale mistake?)", source, v,
                      vertices[v][0], vertices[v][1], vertices[v][2], kMaxMeshCoordinate));
    lo = lo.cwiseMin(vertices[v]);
    hi = hi.cwiseMax(vertices[v]);
  }
  const double size = (hi - lo).norm();
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k)
      if (triangles[t][k] < 0 || triangles[t][k] >= static_cast<int>(vertices.size()))
        throw InputError(fmt::format("mesh '{}': triangle {} refers to vertex {} of {}", source, t, triangles[t][k],
                                     vertices.size()));
    const Vec3& a = vertices[triangles[t][0]];
    const double area2 = (vertices[triangles[t][1]] - a).cross(vertices[triangles[t][2]] - a).norm();
    if (!(area2 > 1e-12 * size * size))
      throw InputError(fmt::format("mesh '{}': triangle {} is degenerate (area {:.3g} m^2)", source, t, 0.5 * area2));
  }
}

}  // namespace swarf
