// mesh_forces.cpp: the meshes' forces (see mesh_forces.h).
#include "app/observers/mesh_forces.h"

#include <fmt/format.h>

#include "swarf/simulation.h"

namespace swarf {

void MeshForces::columns(std::vector<Column>& out) const {
  for (const auto& m : meshes_)
    for (char c : {'x', 'y', 'z'})
      out.push_back({fmt::format("force_{}_{}", m.name, c), "N",
                     fmt::format("{} component of the force the particles exert on mesh '{}'", c, m.name)});
}

void MeshForces::row(const Simulation& sim, std::vector<double>& values) {
  for (std::size_t k = 0; k < meshes_.size(); ++k)
    for (int c = 0; c < 3; ++c) values.push_back(sim.mesh_force(k)[c]);
}

}  // namespace swarf
