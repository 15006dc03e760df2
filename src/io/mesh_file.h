// mesh_file.h: triangle meshes from and to files: STL (ASCII or binary) and OBJ.
#pragma once

#include <string>

#include "swarf/state/mesh.h"

namespace swarf {

/// Reads .stl (ASCII or binary) or .obj; 'scale' multiplies coordinates (e.g. 1e-3 for mm).
TriangleMesh read_mesh(const std::string& path, double scale = 1.0);

/// Writes binary STL (atomically).
void write_stl(const std::string& path, const TriangleMesh& mesh);

}  // namespace swarf
