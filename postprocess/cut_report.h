// cut_report.h: what a cutting run reports at its end (and 'swarf post DIR' recomputes from
// the run's files): the steady-part statistics of the cutting and thrust forces per unit
// width, the chip metrics (chip.h), the broken-rod fraction overall and in the chip, and the
// short result table printed for the user.
//
// Every steady mean carries the half-width of its 95 % confidence interval (steady_stats.h:
// batch means, the autocorrelation time as a cross-check): the forces' directly, Ft/Fc and the
// friction and Merchant angles by the delta method over the same batches, h_c (a median) from
// batch medians and the compression ratio and shear angle from it. Unavailable intervals (fewer
// than 20 rows) are null in summary.json and "unavailable" in the table.
//
// The chip thickness is measured at every series row (column chip_thickness); the summary's
// h_c is the median over the steady part's rows, with its 10th and 90th percentiles: a
// segmented chip that curls and breaks changes its thickness from row to row, and one state
// (the last) was a sample of that noise, which changed by tens of % with rounding-level
// changes of the run.
#pragma once

#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "postprocess/chip.h"
#include "postprocess/cut_oxley.h"
#include "postprocess/tool_vibration.h"
#include "swarf/core/vec3.h"

namespace swarf {

class H5File;

/// The cut's geometry as the analysis needs it (stored in results.h5 under /cutting).
struct CutSetup {
  std::string tool_mesh;                ///< name of the tool's [[mesh]]
  double width = 0;                     ///< workpiece width (ordered lattice extent along y + a/2), m
  double steady_from = 0;               ///< force statistics over times >= this, s
  Vec3 tool_tip = Vec3::Zero();         ///< sharp tip of the tool at the end, m
  double rake_angle_deg = 0;            ///< deg (the normal rake of an inclined tool)
  double inclination_deg = 0;           ///< lambda_s of an oblique cut, deg (runs before 2026-12-06: 0)
  bool free_sides = false;              ///< a block of finite width (not plane strain's periodic slab)
  double side_y_lo = 0, side_y_hi = 0;  ///< the side faces' initial centres (ordered lattice), m
  double uncut_surface_z = 0;           ///< highest workpiece centre of the ordered lattice (before a jitter), m
  double radius = 0;                    ///< particle radius, m
  std::size_t lattice_particles = 0;    ///< the workpiece is particles [0, lattice_particles)
  double face_length = HUGE_VAL;  ///< the tool's rake face length from the tip, m (runs before 2026-12-01: unknown)
  ToolMount mount;                ///< a compliant tool's mount per width; mass 0: the tool follows its path
  double cutting_speed = 0;       ///< the tool's constant speed along x, m/s (0: none; runs before 2026-12-06: unknown)
  CutMaterial material;           ///< the work material for Oxley's reference (cut_oxley.h)
  bool compliant() const { return mount.mass > 0; }
  /// The cut's width along the edge, m: the workpiece's over cos(lambda).
  double edge_width() const { return width / std::cos(inclination_deg * M_PI / 180.0); }
  /// A cut with free sides: the middle half of the width along y, [lo, hi) in m, where the
  /// force away from the sides is taken (its width is width / 2).
  std::pair<double, double> middle_band() const {
    const double c = 0.5 * (side_y_lo + side_y_hi);
    return {c - 0.25 * width, c + 0.25 * width};
  }
};

/// The run's data the analysis reads.
struct CutData {
  std::vector<double> time, fc, ft;     ///< series rows: s, N/m, N/m
  std::vector<double> chip_thickness;   ///< series rows: the chip's thickness then (measure_chip), m; 0 = not measured;
                                        ///< empty for runs of earlier versions (then the last state's is used)
  std::vector<Vec3> position;           ///< workpiece particle centres at the end, m
  std::vector<double> broken_fraction;  ///< per workpiece particle: broken rods / rods, 1
  double broken_rod_fraction = 0;       ///< broken_rod_fraction(): the lattice's own rods broken / its own rods, 1
  std::vector<double> tool_deflection_x, tool_deflection_z;  ///< series rows of a compliant tool, m (else empty)
  /// Optional series rows by column name (empty: the column is not in the run's series):
  /// contact_length (m); with [heat] chip_temperature and rake_face_temperature (K).
  std::vector<double> contact_length, chip_temperature, rake_face_temperature;
  /// A cut with free sides (CutSetup::free_sides): passive_force (N/m), chip_flow_angle (deg) and
  /// chip_width (m) by row; empty otherwise (and for runs before 2026-12-06).
  std::vector<double> passive_force, chip_flow_angle, chip_width;
  /// A cut with free sides: Fc and Ft of the middle half of the width (CutSetup::middle_band) per
  /// its width, N/m, by row; empty otherwise (and for runs before 2026-12-06).
  std::vector<double> fc_middle, ft_middle;
};

struct CutResult {
  nlohmann::json cutting;  ///< summary.json "cutting"
  nlohmann::json chip;     ///< summary.json "chip"
  ChipMetrics metrics;
};

CutResult analyze_cut(const CutSetup& setup, const CutData& data);

/// The broken-rod fraction of a run, the one definition that the run's series and summary and
/// 'swarf post' share: the lattice's own rods that are broken over the lattice's own rods. Rods
/// formed during the run (bond formation) are in neither count: they are not part of the
/// material that was cut, their number grows with the chip's contacts, and a broken one is
/// removed, so counting them would make the fraction depend on when it is taken. 'intact[k]'
/// is rod k's flag (1 intact), 'formed[k]' 1 for a formed rod (empty: none was formed); no
/// rods give 0. Throws InputError when the two sizes differ.
double broken_rod_fraction(std::span<const std::uint8_t> intact, std::span<const std::uint8_t> formed);

/// The chip analysis' input for the workpiece centres 'position' (m) with the tool's sharp tip at
/// 'tool_tip' (m): the setup's geometry, the depth of cut from the tip; an inclined tool's
/// positions turned about the tip into its frame (to_tool_frame, chip.h).
ChipInput chip_input(const CutSetup& setup, std::vector<Vec3> position, const Vec3& tool_tip);

/// The short result table (Fc, Ft, chip thickness, ratio, shear angle, broken-rod fraction).
std::string cut_table(const nlohmann::json& cutting, const nlohmann::json& chip, double broken_rod_fraction);

void write_cut_setup(H5File& f, const CutSetup& s);
/// Reads /cutting from results.h5; returns false if the run had no tool.
bool read_cut_setup(const H5File& f, CutSetup& s);

}  // namespace swarf
