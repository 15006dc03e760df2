// chip.h: the chip of an orthogonal cut and the quantities a machining engineer reads off it.
//
// Chip identification: the workpiece particles whose centre lies above the uncut surface
// (more than one radius above the initial top of the workpiece). Material can only get there
// by flowing up the tool, so these are the chip (with side burrs, if any).
// Chip thickness h_c: the spread of the chip particles' distances from the rake-face plane,
// between the 2nd and 98th percentiles (robust to stray fragments), plus one particle
// diameter (the centres lie a radius inside each free surface), measured on a section of the
// chip that lies on the face: from 2 to 3 depths of cut from the tip along the face, and not
// past the face's end (past the edge region, before the chip curls away from the face; the chip beyond, lifted off the
// face by its curl, made the spread grow with the length of the chip: 0.66 to 1.37 mm over the second half of the
// default cut, against 0.65 to 0.79 mm in the section). A state is measured only once the chip's head (its particle
// farthest along the face) lies at least h/2 past the section's end: while the head crosses the section it holds only
// part of the chip's thickness (the default cut's section read 0.23, 0.27, 0.31 mm at 1.0, 1.2, 1.4 mm of travel, its
// head 0.47, 0.55, 0.62 mm along the face, and 0.326-0.332 mm once the head was 0.1 mm and more past 0.6 mm), and
// these rows made the steady median 3 % thin. Then, with h the depth of cut (uncut chip thickness) and gamma
// the rake angle:
//   compression ratio r = h / h_c,  shear angle phi: tan(phi) = r cos(gamma) / (1 - r sin(gamma)),
//   friction angle beta = gamma + atan(Ft / Fc),  Merchant: phi_M = 45 deg + gamma/2 - beta/2.
//
// Chip curl radius R_u (measure_chip_curl): the radius of curvature of the chip's centreline where it has left the
// rake face, in the cut's plane x-z (plane strain: y, the width, is dropped). The free part starts at s0 =
// max(contact length, 3 h) along the face: past the last particle that touches the face and past the thickness
// section. Its centreline is traced by marching: from the mid-thickness point of the chip's last slab on the face
// before s0 (one step long), step by two particle diameters (4 R) along the current direction, take the chip
// particles in a slab across the chip there (one step wide, plus and minus one local thickness long), and put the
// next point midway between the 2nd and 98th percentiles of their positions across the slab: midway between the
// chip's two free surfaces, as h_c measures between them, so the inner and outer surfaces weigh equally (the mean
// position would be the area centroid, t^2/(12 R_u) outside the centreline: 3 % for t = 0.3 mm, R_u = 0.5 mm).
// Stray particles count only within the slab's window, and there a single one beyond a surface does not move the
// point when the slab holds at least 51 particles (the 98th percentile then lies below the largest of them; the
// tests' slabs hold about 84, the default cut's about 100: 1655 chip particles along 0.87 mm of chip, with the
// layers across the width); in a smaller slab it moves the point by a fraction of its distance from the surface,
// and the fit over all the points averages that out. Marching needs no first guess of the circle (bins of angle
// around a first circle fitted to all the particles would fail for a straight chip, whose circle of least algebraic
// error is centred on the chip itself) and follows a chip that turns through any angle. It stops where a slab holds
// fewer than 3 particles or a third of the first slab's (the chip's end; a gap before a stray fragment), where one step
// turns by more than 30 deg (the march leaving the chip at its end, pulled aside by a few end particles and strays;
// a radius under about 8 R is not resolved), or after one full turn; the trailing slabs with less than 3/4 of the
// median slab's particles are dropped (at the chip's end a slab is partly filled, and unevenly across). The points
// are fitted with a circle: Kasa's algebraic least squares, then Gauss-Newton on the geometric distance (kept when
// it lowers the rms residual). Not measured (a note says why) with fewer than 5 points, when the points cover less
// than 30 deg of their circle (a nearly straight chip, whose radius is not defined: a fit gives a large, noisy
// number), or when the circle's centre lies on the tool's side of the first point (the centreline bends back
// towards the face: a rounded chip head thinning to its end, not an up-curl).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "swarf/core/vec3.h"

namespace swarf {

/// A vector (or a point relative to the tool's tip) in the tool's own frame of an oblique cut:
/// turned about z by -lambda (tool_geometry.h), so that the edge runs along y there. The chip's
/// analysis below works in that frame: chip_input (cut_report.h) turns the positions into it.
Vec3 to_tool_frame(const Vec3& v, double inclination_deg);

struct ChipInput {
  std::vector<Vec3> position;     ///< current particle centres, m (in the tool's frame, to_tool_frame)
  double radius = 0;              ///< particle radius, m
  double uncut_surface_z = 0;     ///< initial top of the workpiece (highest centre), m
  Vec3 tool_tip = Vec3::Zero();   ///< sharp tip of the tool now, m (the tool cuts in +x, z up)
  double rake_angle_deg = 0;      ///< deg
  double depth_of_cut = 0;        ///< h = uncut_surface_z - tool tip z, m
  double face_length = HUGE_VAL;  ///< the rake face's length from the tip, m: the measured section ends there
};

struct ChipMetrics {
  std::size_t chip_particles = 0;      ///< particles above the uncut surface
  std::size_t measured_particles = 0;  ///< of these, those in the measured section
  double head = 0;                     ///< the chip's reach: its farthest particle along the face from the tip, m
  double thickness = 0;                ///< h_c, m (0 if too few particles)
  double compression_ratio = 0;        ///< r = h / h_c, 1
  double shear_angle_deg = 0;          ///< from r and the rake angle, deg
  std::vector<std::size_t> members;    ///< indices (into ChipInput::position) of the chip particles
};

/// Identifies the chip and measures it.
ChipMetrics measure_chip(const ChipInput& in);

/// The tool-chip contact length along the rake face, m: the largest distance from the tip,
/// along the face and not past its end, of a workpiece particle that touches the face's plane
/// (centre less than R from it); 0 when none does.
double rake_contact_length(const ChipInput& in);

/// The chip's up-curl (see the header comment): the circle through its centreline past the face.
struct ChipCurl {
  bool measured = false;         ///< false: radius, fit_rms are 0 and note says why
  double radius = 0;             ///< R_u, the centreline's radius of curvature, m
  double fit_rms = 0;            ///< rms distance of the centreline points from the circle, m
  double arc_deg = 0;            ///< angle the points cover around the circle's centre, deg (0 without a circle)
  std::size_t points = 0;        ///< centreline points (the first on the face, before the free part)
  double start = 0;              ///< s0: where the free part starts, m along the face from the tip
  Vec3 centre = Vec3::Zero();    ///< the circle's centre (x, 0, z), m
  std::vector<Vec3> centreline;  ///< the points (x, 0, z), m, from the face outwards
  std::string note;              ///< why it is not measured (empty when it is)
};
/// Traces the centreline of the chip m.members past the face and fits its circle.
ChipCurl measure_chip_curl(const ChipInput& in, const ChipMetrics& m);

/// The chip's temperatures ([heat]), K; 0 where there is no particle to measure.
struct ChipHeat {
  double chip_mean = 0;      ///< mean over the chip particles (ChipMetrics::members)
  double rake_face_max = 0;  ///< maximum over the layer on the rake face: centres less than 2 R from the
                             ///< face's plane, from the tip to the face's end (the secondary shear zone)
};
/// temperature is per particle of ChipInput::position, K.
ChipHeat chip_heat(const ChipInput& in, const ChipMetrics& m, const std::vector<double>& temperature);

/// The chip's flow over the rake face of a cut with free sides (an oblique cut; issue 38 item 4),
/// measured from 1 to 3 h along the face (past the edge region, as h_c's section, but reached
/// by the chip a depth of cut earlier), in the tool's frame:
/// - the chip flow angle eta_c: the direction of the section's mean velocity relative to the tool,
///   in the rake face, off the edge's normal, positive towards +y of the tool's frame (where an
///   inclination lambda > 0 sends the work material; Stabler's rule eta_c = lambda), over the
///   particles in the middle half of the edge's length in the cut (away from the side flow);
/// - the chip's width along the edge: the spread of those particles along y between the
///   2nd and 98th percentiles plus one diameter (as h_c across it), m.
struct ChipFlow {
  double flow_angle_deg = 0;  ///< eta_c, deg (0 when fewer than 10 particles are measured)
  double width = 0;           ///< the chip's width along the edge, m (0 likewise)
  std::size_t particles = 0;  ///< particles in the section (the flow angle's: those of the middle half)
};
/// velocity: per particle of ChipInput::position, in the tool's frame, relative to the tool (m/s);
/// cut_width: the workpiece's width along the edge (m; its middle is the tool tip's y).
ChipFlow measure_chip_flow(const ChipInput& in, const ChipMetrics& m, const std::vector<Vec3>& velocity,
                           double cut_width);

/// The side burr of a cut with free sides: how far the machined part's material stands out of the
/// block's side faces. Over the workpiece particles that are not chip (centre at most R above
/// the uncut surface), behind the edge (more than h behind it along the edge's normal, in the
/// tool's frame) and not below the tip's depth by more than 2 h: the largest distance of a centre
/// beyond the side faces' initial centres, y < y_lo or y > y_hi (m), world frame; 0 when none stands
/// out. A particle more than 5 h out is a stray fragment, not a burr, and is not counted.
/// world_position: the centres in the world frame (not turned); in: the chip input (for the tip,
/// h, R and the tool frame); inclination_deg: lambda.
double side_burr(const std::vector<Vec3>& world_position, const ChipInput& in, double inclination_deg, double y_lo,
                 double y_hi);

/// The q-quantile (q in [0, 1]) of v, linear between order statistics; v must not be empty.
double quantile(std::vector<double> v, double q);

/// Shear angle (deg) from the compression ratio r = h/h_c and the rake angle (deg).
double shear_angle_deg(double compression_ratio, double rake_angle_deg);
/// Friction angle (deg) on the rake face from the cutting and thrust forces and the rake angle.
double friction_angle_deg(double cutting_force, double thrust_force, double rake_angle_deg);
/// Merchant's shear angle 45 + gamma/2 - beta/2 (deg).
double merchant_shear_angle_deg(double rake_angle_deg, double friction_angle_deg);

}  // namespace swarf
