// world.h (state/): everything the step reads and writes, in SI units.
//
// A World is plain data: particles (structure of arrays), rods (each stored once), groups of
// particles with prescribed motions, rigid meshes with their motions or as rigid bodies, the periodic width,
// gravity and the contact parameters. It knows no file, no case key and no output: setup/
// fills it from a case file, tests and embedding programs fill it in code.
#pragma once

#include <vector>

#include "swarf/core/periodic.h"
#include "swarf/core/vec3.h"
#include "swarf/laws/contact_params.h"
#include "swarf/laws/heat_params.h"
#include "swarf/state/bodies.h"
#include "swarf/state/motion.h"
#include "swarf/state/particle_flows.h"
#include "swarf/state/particles.h"
#include "swarf/state/rigid_body.h"
#include "swarf/state/rods.h"

namespace swarf {

struct World {
  Particles particles;
  Rods rods;
  std::vector<Group> groups;        ///< particles whose components follow a prescribed motion
  Periodic periodic;                ///< periodic width along y (off unless set)
  std::vector<MeshBody> meshes;     ///< rigid triangle meshes (placement updated by the step)
  std::vector<Motion> mesh_motion;  ///< prescribed translation of each mesh (none for a body's)
  std::vector<RigidBody> bodies;    ///< meshes that move as rigid bodies under the contacts (rigid_body.h)
  bool contacts = false;            ///< Hertz contacts and friction between unbonded particles and with meshes
  ContactParams contact;            ///< used when 'contacts'
  HeatParams heat;                  ///< temperatures and heat (off unless heat.enabled)
  Vec3 gravity = Vec3::Zero();      ///< m/s^2
  std::vector<Inflow> inflows;      ///< regions creating particles (particle_flows.h)
  std::vector<Outflow> outflows;    ///< regions removing particles
};

}  // namespace swarf
