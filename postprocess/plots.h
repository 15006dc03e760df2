// plots.h: PNG plots of a run, drawn by postprocess/plot_run.py (matplotlib).
#pragma once

#include <string>
#include <vector>

namespace swarf {

struct PlotResult {
  bool ok = false;
  std::string message;               ///< why it failed
  std::vector<std::string> files;    ///< PNG files written (relative to the run directory)
};

/// Runs the plot script on DIR/series.csv with the given summary file.
PlotResult make_plots(const std::string& dir, const std::string& summary_path);

}  // namespace swarf
