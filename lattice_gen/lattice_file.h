// lattice_file.h: the lattice HDF5 file written by 'swarf lattice' and read by 'swarf run'.
//
// Layout: /particles/position (N x 3, m), /particles/radius (N, m), /bonds/pairs (M x 2,
// zero-based int64), /bonds/rest_length (M, m); root attributes 'generator' and
// 'cell_edge' (m).
#pragma once

#include <string>

#include "lattice_gen/fcc_lattice.h"

namespace swarf {

/// Writes atomically: to 'path.part', then renamed, so a kill never leaves a complete-looking file.
void write_lattice(const std::string& path, const Lattice& lattice);
/// Reads and checks the file (shapes, index range, each pair once, radii and rest lengths
/// within 1 nm..1 m and 4 m, positions within 1e6 m, at least one particle).
Lattice read_lattice(const std::string& path);

}  // namespace swarf
