// mesh_forces.h: the force the particles exert on each mesh (N, x y z) per row.
#pragma once

#include "app/observers/observer.h"

namespace swarf {

struct MeshBody;

class MeshForces final : public Observer {
 public:
  /// The meshes of the World the simulation steps (names only: held by reference).
  explicit MeshForces(const std::vector<MeshBody>& meshes) : meshes_(meshes) {}
  std::string_view name() const override { return "mesh_forces"; }
  void columns(std::vector<Column>& out) const override;
  void row(const Simulation& sim, std::vector<double>& values) override;

 private:
  const std::vector<MeshBody>& meshes_;
};

}  // namespace swarf
