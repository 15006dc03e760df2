// mesh_file.h: triangle meshes from and to files: STL (ASCII or binary) and OBJ.
#pragma once

#include <string>

#include "swarf/state/mesh.h"

namespace swarf {

/// Reads .stl (ASCII or binary) or .obj; 'scale' multiplies coordinates (e.g. 1e-3 for mm).
TriangleMesh read_mesh(const std::string& path, double scale = 1.0);

/// Writes binary STL (atomically). Its coordinates are floats: 6e-8 of themselves.
void write_stl(const std::string& path, const TriangleMesh& mesh);

/// Writes OBJ (atomically) with every coordinate in its shortest exact decimal form: read back,
/// the mesh is the same, bit for bit.
void write_obj(const std::string& path, const TriangleMesh& mesh);

}  // namespace swarf
