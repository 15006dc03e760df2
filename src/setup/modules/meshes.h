// meshes.h: the meshes' module of setup: [[mesh]]'s settings, key table, rules (a file, a rectangle,
// a generated tool or a closed shape; a tool from a file measured; a rigid body's keys), its build into
// the World's meshes, their motions and rigid bodies, and its lines of the setup printout. Listed once
// in each central list: parse_case (case_config.cpp), the key rows (case_key_text.cpp), the case echo
// (app/case_echo.cpp), build_model (model.cpp) and the setup printout (app/setup_report.cpp). Its
// motion keys are motion.h's.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "setup/key.h"
#include "setup/modules/motion.h"

namespace swarf {

struct CaseInput;
struct CaseSettings;
struct Model;

/// [[mesh]]: a rigid triangle mesh (wall, tool) from a file or a built-in rectangle.
struct MeshSettings {
  std::string name;
  std::string file;                       ///< .stl or .obj; empty = rectangle
  double scale = 1.0;                     ///< coordinate factor applied to the file (e.g. 1e-3 for mm), 1
  std::array<double, 3> origin{0, 0, 0};  ///< rectangle corner, m
  std::array<double, 3> edge1{0, 0, 0};   ///< rectangle edge, m
  std::array<double, 3> edge2{0, 0, 0};   ///< rectangle edge, m (normal = edge1 x edge2)
  std::array<int, 2> divisions{1, 1};     ///< rectangle cells along edge1, edge2 (2 triangles each)
  // Generated cutting tool (tool_geometry.h), placed with its sharp tip at 'origin':
  bool tool = false;             ///< true when rake_angle is given
  double rake_angle = 0.0;       ///< deg
  double clearance_angle = 7.0;  ///< deg
  double edge_radius = 0.0;      ///< m
  double width = 0.0;            ///< m
  double face_length = 0.0;      ///< m
  double inclination_angle = 0;  ///< lambda_s, deg: the tool turned about z (oblique cutting)
  // A cutting tool from 'file' (tool_tip given): measured (tool_measure.h) when the case is
  // read, the fields above set from the measurement, 'origin' = tool_tip, and the mesh moved
  // so that its measured tip 'file_tip' lands there.
  bool tool_from_file = false;              ///< true when tool_tip is given with file
  std::array<double, 3> tool_tip{0, 0, 0};  ///< where the file's sharp tip is placed, m
  std::array<double, 3> file_tip{0, 0, 0};  ///< the sharp tip measured in the file (times scale), m
  MotionSettings motion;                    ///< as for groups
  double youngs_modulus = kInf;             ///< Pa; inf = rigid
  double poisson_ratio = 0.3;               ///< 1
  double parting_lead = kInf;               ///< parting line at the lowest point: reach ahead of it, m; inf = none
  // Generated closed shapes, centred on 'origin' (for rigid bodies):
  std::array<double, 3> box_size{0, 0, 0};       ///< m; all > 0 makes a box
  double cylinder_radius = 0.0;                  ///< m; > 0 makes a cylinder
  double cylinder_length = 0.0;                  ///< m
  std::array<double, 3> cylinder_axis{0, 1, 0};  ///< direction of the cylinder's axis
  int cylinder_segments = 32;                    ///< flat sides of the faceted round face
  // dynamics = "rigid_body": the mesh moves as a rigid body (swarf/state/rigid_body.h).
  std::string dynamics = "prescribed";              ///< "prescribed" or "rigid_body"
  double density = 0.0;                             ///< kg/m^3 (0: from 'mass')
  double mass = 0.0;                                ///< kg (0: from 'density')
  std::array<double, 3> centre_of_mass{0, 0, 0};    ///< m, mesh coordinates (with 'inertia')
  std::vector<double> inertia;                      ///< Ixx Iyy Izz Ixy Iyz Ixz about it, kg m^2 (empty: from the mesh)
  std::array<double, 3> initial_velocity{0, 0, 0};  ///< m/s, of the centre of mass
  std::array<double, 3> angular_velocity{0, 0, 0};  ///< rad/s, world frame
  std::string rotation = "free";                    ///< "free", "hinge" or "prescribed"
  std::array<double, 3> hinge_axis{0, 1, 0};        ///< hinge direction, world frame
  std::array<double, 3> hinge_point{0, 0, 0};       ///< a point of the hinge's axis, m (if given)
  bool hinge_at_point = false;                      ///< hinge_point given: the axis is fixed there
  std::string fixed;                                ///< translation components held: a subset of "xyz"
  std::array<double, 3> force{0, 0, 0};             ///< constant external force, N
  std::array<double, 3> torque{0, 0, 0};            ///< constant external torque, N m
  std::array<double, 3> spring_stiffness{0, 0, 0};  ///< mount's stiffness along x, y, z, N/m
  std::array<double, 3> holder_velocity{0, 0, 0};   ///< the mount's anchor moves at it, m/s
  double damping = 0.0;                             ///< force -damping v, N s/m
  double torque_damping = 0.0;                      ///< torque -torque_damping omega, N m s/rad
};

const std::vector<Key<MeshSettings>>& mesh_keys();

/// Reads the [[mesh]] tables (with their motion keys) and checks their rules; a tool from a file is
/// measured here (tool_measure.h).
void read_meshes(const CaseInput& in, CaseSettings& cs);

/// The World's meshes with their motions, and the rigid bodies among them (their mounts checked
/// against the derived step).
void build_meshes(const CaseSettings& cs, Model& model);

/// The setup printout's lines on the rigid bodies and the tools measured from files.
std::string meshes_echo(const Model& m);

}  // namespace swarf
