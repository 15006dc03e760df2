// model.h: everything a run is made of, built from the case settings.
//
// The lattice becomes particles (structure of arrays) and rods (each stored once); the
// [[group]] tables and the [uniaxial] grips become groups with a prescribed motion.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "case_config.h"
#include "contacts.h"
#include "periodic.h"
#include "derived.h"
#include "fcc_lattice.h"
#include "particles.h"
#include "rods.h"

namespace swarf {

/// Prescribed rigid translation of a group or mesh: fixed, constant velocity, a linear ramp
/// up to a velocity, a piecewise-linear displacement table (constant past its end) or a
/// piecewise-linear velocity table (integrated exactly; the last velocity holds past its end).
struct Motion {
  enum class Kind { Fixed, Velocity, Ramp, Table, VelocityTable };
  Kind kind = Kind::Fixed;
  Vec3 velocity = Vec3::Zero();     ///< m/s (Velocity; final velocity of Ramp)
  double ramp_time = 0;             ///< s (Ramp)
  std::vector<double> time;         ///< s (Table, VelocityTable)
  std::vector<Vec3> displacement;   ///< m at each time (Table; for VelocityTable the integral at each time)
  std::vector<Vec3> table_velocity; ///< m/s at each time (VelocityTable, piecewise linear)

  /// Displacement from the start position at time t, m.
  Vec3 displacement_at(double t) const;
};

struct Group {
  std::string name;
  std::uint8_t dofs = 7;            ///< prescribed components, bit c = component c
  Motion motion;
  std::vector<std::int32_t> members;  ///< particle indices, ascending
};

/// The uniaxial test's geometry (when [uniaxial] is present).
struct UniaxialInfo {
  bool enabled = false;
  int axis = 0;                     ///< 0, 1, 2
  int grip_min = -1, grip_max = -1; ///< group indices
  double gauge_length = 0;          ///< initial distance between the innermost gripped layers, m
  double cross_section = 0;         ///< initial cross-section, m^2 (lattice extent + one layer spacing per side)
  /// Rods crossing the plane halfway between the grips, with +1 if their end i lies on the
  /// low side: the force they carry is the bar's internal force at mid-length.
  std::vector<std::pair<std::int32_t, int>> midplane_rods;
};

struct Model {
  CaseSettings settings;
  Derived derived;
  Particles particles;
  Rods rods;
  std::vector<Group> groups;
  UniaxialInfo uniaxial;
  Periodic periodic;                  ///< periodic width (y), if [workpiece] periodic_width
  std::size_t lattice_particles = 0;  ///< particles 0..this-1 come from the workpiece; free ones follow
  std::vector<MeshBody> meshes;       ///< rigid triangle meshes (placement updated by the simulation)
  std::vector<Motion> mesh_motion;    ///< prescribed translation of each mesh
  ContactParams contact;              ///< used when settings.contact.enabled
  Vec3 gravity = Vec3::Zero();        ///< m/s^2
};

/// Builds the model; throws InputError (naming the file and key) on anything inconsistent.
Model build_model(const CaseSettings& cs);

/// Selects the particles of 'layers' lattice layers at a face ("x-", "z+", ...).
std::vector<std::int32_t> select_side(const std::vector<Vec3>& position, const std::string& side, int layers,
                                      double layer_spacing);

}  // namespace swarf
