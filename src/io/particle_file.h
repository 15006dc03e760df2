// particle_file.h: free particles from a text file, one per line: 'id x y z vx vy vz' (SI
// units: m, m/s); blank lines and lines starting with '#' are skipped.
#pragma once

#include <string>
#include <vector>

#include "swarf/core/vec3.h"

namespace swarf {

struct FreeParticleRow {
  Vec3 position;  ///< m
  Vec3 velocity;  ///< m/s
};

/// Reads the file; throws InputError naming the file and line of a malformed or non-finite row.
std::vector<FreeParticleRow> read_particle_file(const std::string& path);

}  // namespace swarf
