// particle_file.cpp: see particle_file.h.
#include "io/particle_file.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "swarf/core/errors.h"

namespace swarf {

std::vector<FreeParticleRow> read_particle_file(const std::string& path) {
  std::vector<FreeParticleRow> rows;
  std::ifstream in(path);
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    double id, x, y, z, vx, vy, vz;
    if (!(ls >> id >> x >> y >> z >> vx >> vy >> vz) || !std::isfinite(x + y + z + vx + vy + vz))
      throw InputError(
          fmt::format("{}:{}: expected 'id x y z vx vy vz' (SI units), got '{}'", path, lineno, line.substr(0, 80)));
    rows.push_back({Vec3(x, y, z), Vec3(vx, vy, vz)});
  }
  return rows;
}

}  // namespace swarf
