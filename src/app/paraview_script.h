// paraview_script.h: DIR/open_in_paraview.py, the ParaView view of a run (issue 17, item 3).
//
// The run copies the template postprocess/open_in_paraview.py (found as the plot scripts are,
// plots.h) into its directory with the line 'SWARF_RUN = {}' filled in: the run directory,
// the per-particle fields written, and for a cut the tool's mesh and the depth of cut, which
// the script uses to frame the view on the tool's tip. docs/outputs.md says how to open it.
#pragma once

#include <string>
#include <vector>

#include "app/run_file.h"

namespace swarf {

struct Model;

/// Writes DIR/open_in_paraview.py (atomically) for a run of 'model' with ParaView frames.
/// Returns an empty string, or why it could not (the template missing or unreadable): the run
/// goes on without it.
std::string write_paraview_script(const std::string& dir, const Model& model);
/// The file it writes: open_in_paraview.py.
std::vector<RunFile> paraview_script_files();

}  // namespace swarf
