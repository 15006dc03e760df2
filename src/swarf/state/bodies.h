// bodies.h: rigid bodies the particles touch. Today one kind: a triangle mesh that follows a
// prescribed translation (a tool, a wall); its placement is written by the step's
// 'prescribe' stage.
#pragma once

#include <string>

#include "swarf/core/vec3.h"
#include "swarf/laws/parting_rule.h"
#include "swarf/state/mesh.h"

namespace swarf {

/// A rigid triangle mesh with its current placement (rigid translation of the reference).
struct MeshBody {
  std::string name;
  TriangleMesh mesh;             ///< reference vertices, m
  double youngs_modulus = 0;     ///< Pa (inf = rigid)
  double poisson_ratio = 0;      ///< 1
  Vec3 offset = Vec3::Zero();    ///< current translation from the reference, m
  Vec3 velocity = Vec3::Zero();  ///< current velocity, m/s
  PartingRule parting;           ///< a parting line at the mesh's lowest point (off by default)
};

}  // namespace swarf
