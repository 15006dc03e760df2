// tool_measure.h: the cut's geometry read off a cutting tool's triangle mesh (a tool from
// CAD given as an STL or OBJ file), in the frame of tool_geometry.h: the tool cuts moving in
// +x, its cutting edge lies along y, z points away from the workpiece; the rake face's
// outward normal points +x (toward the chip, ahead of the tool), the flank's -z.
//
// The measurement works on the faces parallel to y (|n_y| < 1e-3: the edge along y within
// 0.06 deg), grouped into planes. Near the lowest point of the mesh (the edge's end of the
// tool: within 0.3 of the profile's extent in x-z, which holds a honed edge of up to a depth
// of cut on a tool 5 depths of cut long) the largest plane whose outward normal is within 45
// deg of +x or tilted up from it is the rake face, the largest whose normal is within 45 deg
// of -z or tilted back from it the flank:
//   rake angle gamma_o = atan2(n_z, n_x) of the rake face (ISO 3002: positive tilts the face
//   back from the normal to the cutting direction), clearance alpha_o = atan2(-n_x, -n_z) of
//   the flank. The tip is where the two planes meet (the sharp tip, the generated tool's
//   'origin'; a mesh vertex when the faces share one, so an exact mesh is placed exactly), at
//   the middle of the faces' common extent along y. A honed edge (the faces do not meet on
//   the mesh) is taken as a circular arc tangent to both: r_n = t tan(wedge / 2), t the mean
//   distance from the sharp tip to the faces' nearest vertices (the tangent points). A
//   chamfer or a land near the edge is not told apart from a hone: the estimate then is a
//   circle's with the same tangent points.
#pragma once

#include <string>

#include "swarf/state/mesh.h"

namespace swarf {

struct ToolMeasure {
  Vec3 tip{0, 0, 0};                 ///< sharp tip on the middle of the edge, m (mesh coordinates)
  double rake_angle_deg = 0.0;       ///< gamma_o (ISO 3002), deg
  double clearance_angle_deg = 0.0;  ///< alpha_o (ISO 3002), deg
  double edge_radius = 0.0;          ///< r_n estimated from the tangent points, m; 0 = sharp
  bool sharp = true;                 ///< the rake face and the flank share a vertex of the mesh
  double face_length = 0.0;          ///< the rake face's extent from the tip in x-z, m
  double flank_length = 0.0;         ///< the flank's extent from the tip in x-z, m
  double edge_length = 0.0;          ///< the common extent of both faces along y, m
};

/// Measures a cutting tool's mesh. Throws InputError saying what was found (or not) when the
/// mesh is not a tool in this frame: no faces along y, no rake face or flank near the lowest
/// point, faces that do not meet, a rake angle outside (-45, 45) deg or a clearance angle
/// outside (0, 45) deg.
ToolMeasure measure_tool(const TriangleMesh& mesh);

/// One line for printouts: "rake 6 deg, clearance 7 deg, edge radius 2 um (honed), ...".
std::string describe(const ToolMeasure& t);

}  // namespace swarf
