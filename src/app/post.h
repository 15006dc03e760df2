// post.h: the end of a cutting run and 'swarf post DIR', which redoes it from the run's files:
// force statistics and chip metrics into summary.json ("cutting", "chip"), the chip surface
// (chip_surface.vtp), the plots and the rendered pictures (chip.png by damage,
// chip_plastic_strain.png, chip_von_mises_stress.png), and the result table.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/run_file.h"
#include "postprocess/cut_report.h"

namespace swarf {

class VtkSeries;

/// Analyses the cut into sum["cutting"] and sum["chip"], writes the chip surface (listed in the
/// ParaView series when 'vtk' is given) and, if 'pictures', renders the chip pictures; prints
/// the result table.
void finish_cut(const std::string& dir, const CutSetup& setup, const CutData& data, nlohmann::json& sum, VtkSeries* vtk,
                bool pictures);

/// The files finish_cut may write: tool_spectrum.csv (a compliant tool), chip_surface.vtp and
/// the pictures of render_pictures.
std::vector<RunFile> cut_files();

/// Renders the last frame headless (xvfb-run + VTK) as DIR/chip.png (damage),
/// chip_plastic_strain.png and chip_von_mises_stress.png (those whose field the frames hold),
/// the camera on the tool's tip ('setup': the tool's name and the depth of cut); returns the
/// files written (names in DIR), empty with 'message' set when none was.
std::vector<std::string> render_pictures(const std::string& dir, const CutSetup& setup, std::string& message);

/// 'swarf post DIR': recomputes the cut's analysis, surface, plots and picture from DIR's
/// summary.json, series.csv and results.h5 and rewrites summary.json. Throws InputError.
void post_run(const std::string& dir);

}  // namespace swarf
