// bodies.h: rigid triangle meshes the particles touch. A mesh follows either a prescribed
// translation (a tool, a wall; written by the step's 'prescribe' stage) or the motion of a
// rigid body (rigid_body.h), which also turns it: then the step places it from the body's pose.
#pragma once

#include <string>
#include <vector>

#include "swarf/core/quat.h"
#include "swarf/core/vec3.h"
#include "swarf/laws/parting_rule.h"
#include "swarf/state/mesh.h"

namespace swarf {

/// A rigid triangle mesh with its current placement.
struct MeshBody {
  std::string name;
  TriangleMesh mesh;             ///< reference vertices, m
  double youngs_modulus = 0;     ///< Pa (inf = rigid)
  double poisson_ratio = 0;      ///< 1
  Vec3 offset = Vec3::Zero();    ///< current translation from the reference, m
  Vec3 velocity = Vec3::Zero();  ///< current velocity (of 'pivot' when it turns), m/s
  PartingRule parting;           ///< a parting line at the mesh's lowest point (off by default)
  // Turning meshes (those of a rigid body): x = pivot + offset + R(turn) (X - pivot) for a
  // reference vertex X. A mesh that only translates keeps x = X + offset, the expression the
  // contact code always used, so that prescribed tools give the same bits as before.
  bool turns = false;
  Vec3 pivot = Vec3::Zero();      ///< reference point it turns about (the body's centre of mass), m
  Quat turn{1.0, 0.0, 0.0, 0.0};  ///< rotation from the reference orientation
  Vec3 omega = Vec3::Zero();      ///< angular velocity, world frame, rad/s
  double reach = 0;               ///< largest |X - pivot| over the vertices, m
  std::vector<Vec3> placed;       ///< current vertices of a turning mesh, m (filled by place())

  /// Vertex v at the current placement, m.
  Vec3 vertex(int v) const { return turns ? placed[v] : Vec3(mesh.vertices[v] + offset); }
  /// Velocity of the mesh's material point now at x, m/s.
  Vec3 velocity_at(const Vec3& x) const { return turns ? Vec3(velocity + omega.cross(x - centre())) : velocity; }
  /// The turning point's current position, m.
  Vec3 centre() const { return pivot + offset; }
  /// Fills 'placed' (and 'reach') from 'turn', 'pivot' and 'offset' (turning meshes only).
  void place();
};

}  // namespace swarf
