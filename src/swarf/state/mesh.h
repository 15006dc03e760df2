// mesh.h: triangle meshes for tools and walls (io/mesh_file.h reads them from STL or OBJ).
//
// Each triangle is an element of its own in the contact search (paper section 4.2). A mesh
// that is empty, has a non-finite vertex or a degenerate triangle (zero area, or an index
// out of range) is rejected with the file and the triangle named.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "swarf/core/vec3.h"

namespace swarf {

struct TriangleMesh {
  std::string name;                           ///< for messages and outputs
  std::vector<Vec3> vertices;                 ///< m
  std::vector<std::array<int, 3>> triangles;  ///< vertex indices, counterclockwise seen from outside

  /// Throws InputError (naming 'source') if the mesh is empty, non-finite or degenerate.
  void validate(const std::string& source) const;
};

}  // namespace swarf
