// post.h: the end of a cutting run and 'swarf post DIR', which redoes it from the run's files:
// force statistics and chip metrics into summary.json ("cutting", "chip"), the chip surface
// (chip_surface.vtp), the plots and the rendered picture (chip.png), and the result table.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "postprocess/cut_report.h"

namespace swarf {

class VtkSeries;

/// Analyses the cut into sum["cutting"] and sum["chip"], writes the chip surface (listed in the
/// ParaView series when 'vtk' is given) and, if 'pictures', renders DIR/chip.png; prints the
/// result table.
void finish_cut(const std::string& dir, const CutSetup& setup, const CutData& data, nlohmann::json& sum, VtkSeries* vtk,
                bool pictures);

/// Renders DIR/chip.png headless (xvfb-run + VTK); returns the file or an empty string with
/// 'message' set.
std::string render_picture(const std::string& dir, std::string& message);

/// 'swarf post DIR': recomputes the cut's analysis, surface, plots and picture from DIR's
/// summary.json, series.csv and results.h5 and rewrites summary.json. Throws InputError.
void post_run(const std::string& dir);

}  // namespace swarf
