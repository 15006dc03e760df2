// tool_geometry.h: the cutting tool of orthogonal cutting as a closed triangle mesh.
//
// Frame: the cutting edge lies along y; the tool cuts moving in +x; z points away from the
// workpiece. The origin is where the rake and flank face planes meet (the tip of the sharp
// tool). The rake face leaves the edge upwards, tilted back from +z by the rake angle gamma
// (ISO 3002 gamma_o; positive gamma: a sharper wedge); the flank face leaves it backwards, tilted up from -x by
// the clearance angle alpha (ISO 3002 alpha_o). The wedge angle is 90 deg - gamma - alpha. An edge radius r > 0
// replaces the tip by a circular arc tangent to both faces, split finely enough to resolve
// it (at most 'max_arc_step_deg' per segment). The profile is extruded over the width. A tool
// from a file is read in this frame and measured by tool_measure.h.
//
// Oblique cutting: an inclination angle lambda (ISO 3002 lambda_s) turns the whole tool about the
// vertical (z) through the origin, so that the edge runs along (-sin lambda, cos lambda, 0) while
// the tool still moves along +x. The profile stays the section normal to the edge: the rake and
// clearance angles above are the normal angles (gamma_n, alpha_n) of the oblique tool. Positive
// lambda puts the edge's +y end behind the origin; the work material then slides along the edge
// towards +y relative to the tool (Stabler's rule: the chip flows at eta_c = lambda off the edge's
// normal in the rake face).
#pragma once

#include "swarf/state/mesh.h"

namespace swarf {

/// The largest inclination |lambda| a generated tool takes, deg (Stabler's rule is measured to
/// about 40 deg; beyond 60 the edge is more along the cut than across it).
constexpr double kMaxInclinationDeg = 60.0;

struct ToolSpec {
  double rake_angle_deg = 0.0;       ///< gamma (ISO 3002 gamma_o), deg
  double clearance_angle_deg = 7.0;  ///< alpha (ISO 3002 alpha_o), deg
  double edge_radius = 0.0;          ///< m; 0 = sharp
  double width = 0.0;                ///< extent along y, m (centred on y = 0)
  double face_length = 0.0;          ///< length of the rake and flank faces from the (sharp) tip, m
  double max_arc_step_deg = 5.0;     ///< finest angular step of the edge arc, deg
  double inclination_angle_deg = 0;  ///< lambda_s, deg: the tool turned about z (oblique cutting)
};

/// Builds the closed, outward-oriented mesh; throws InputError on impossible angles or sizes.
TriangleMesh make_tool(const ToolSpec& spec);

/// The profile of the tool in the (x, z) plane, counterclockwise seen from -y (for tests).
std::vector<Eigen::Vector2d> tool_profile(const ToolSpec& spec);

}  // namespace swarf
