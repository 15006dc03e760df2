// body_states.h: the pose, velocities and contact torque of each rigid body per row
// (swarf/state/rigid_body.h); its contact force is the mesh's force_<name>_* column.
#pragma once

#include "app/observers/observer.h"

namespace swarf {

struct MeshBody;
struct RigidBody;

class BodyStates final : public Observer {
 public:
  /// The bodies and meshes of the World the simulation steps (held by reference).
  BodyStates(const std::vector<RigidBody>& bodies, const std::vector<MeshBody>& meshes)
      : bodies_(bodies), meshes_(meshes) {}
  std::string_view name() const override { return "body_states"; }
  void columns(std::vector<Column>& out) const override;
  void row(const Simulation& sim, std::vector<double>& values) override;

 private:
  const std::vector<RigidBody>& bodies_;
  const std::vector<MeshBody>& meshes_;
};

}  // namespace swarf
