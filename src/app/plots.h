// plots.h: PNG plots of a run, drawn by postprocess/plot_run.py (matplotlib).
#pragma once

#include <string>
#include <vector>

#include "app/run_file.h"
#include "postprocess/script_dir.h"

namespace swarf {

struct PlotResult {
  bool ok = false;
  std::string message;             ///< why it failed
  std::vector<std::string> files;  ///< PNG files written (relative to the run directory)
};

/// Runs the plot script on DIR/series.csv with the given summary file.
PlotResult make_plots(const std::string& dir, const std::string& summary_path);
/// The files the plot script (postprocess/plot_run.py) may write: forces.png,
/// tool_vibration.png, stress_strain.png, energy.png, each when the run has its columns.
std::vector<RunFile> plot_files();

/// Result of running one of postprocess/'s Python scripts.
struct ScriptRun {
  bool ok = false;     ///< started and exited with status 0
  std::string output;  ///< stdout and stderr together (or why it could not start)
};

/// The paths a script reported, one "wrote PATH" line each, in order.
std::vector<std::string> written_files(const std::string& output);

/// Runs postprocess_path(NAME) with /usr/bin/python3 and the arguments, started directly
/// (posix_spawn, no shell: an argument is passed as it is, whatever characters it holds);
/// 'prefix' is a program with its arguments that goes before the interpreter (e.g. xvfb-run).
/// Its stdout and stderr are returned in 'output'; a missing script is reported there.
ScriptRun run_postprocess_script(const std::string& name, const std::vector<std::string>& args,
                                 const std::vector<std::string>& prefix = {});

}  // namespace swarf
