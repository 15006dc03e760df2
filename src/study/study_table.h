// study_table.h: the table of a study (one row per case: varied keys, status, metrics from the
// case's summary.json), written as DIR/study.csv and DIR/timing.csv, their columns' units and
// meanings as DIR/study_columns.csv, and the plot data. The tables have one header line of
// names and nothing else before the numbers, so that numpy.genfromtxt(names=True) and
// pandas.read_csv read numbers; the units live in the sidecar.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "study/study.h"
#include "study/study_record.h"

namespace swarf {

struct StudyTable {
  std::vector<std::string> columns;            ///< names
  std::vector<std::string> units;              ///< one per column ("-" for text columns)
  std::vector<std::string> descriptions;       ///< one per column: what it holds
  std::vector<std::vector<std::string>> rows;  ///< cells as text, rows in case id order
  std::vector<CaseStatus> status;              ///< one per row
  std::size_t first_metric = 0;                ///< columns before this are case, keys, status

  int column(const std::string& name) const;  ///< -1 if absent
  /// The cell as a number (empty or text: none).
  std::optional<double> number(std::size_t row, const std::string& name) const;
};

/// Unit of a flattened summary key as the result table declares it (setup/result_keys.h):
/// cutting.cutting_force_per_width_mean_N_per_m -> "N/m", a vector's component as its vector;
/// "?" for a number no entry declares.
std::string unit_of_key(const std::string& flat_key);

/// The column of a metric's 95 % confidence half-width, as the result table declares it
/// (cutting.cutting_force_per_width_mean_N_per_m -> cutting.cutting_force_per_width_ci95_N_per_m,
/// chip.friction_angle_deg -> chip.friction_angle_ci95_deg); "" for a metric without one and
/// for a vector component.
std::string ci95_key_of(const std::string& flat_key);

/// The column of Oxley's figure of the same quantity (chip.thickness_m -> oxley.chip_thickness_m),
/// as the result table declares it; "" for a metric his theory does not give.
std::string oxley_key_of(const std::string& flat_key);

/// The study table (timing = false: DIR/study.csv; true: DIR/timing.csv, the wall times and
/// thread counts, which differ from run to run).
StudyTable collect_table(const Study& study, const std::string& out_dir, bool timing = false);
/// CSV: the names, then one line per row (the units are in columns_csv).
std::string table_csv(const StudyTable& table);
/// DIR/study_columns.csv: "column,unit,description", one line per column of study.csv, then
/// one per column that only timing.csv has.
std::string columns_csv(const StudyTable& study, const StudyTable& timing);

/// The metric columns plotted when the study does not list them (those present in the table).
std::vector<std::string> default_plot_metrics(const StudyTable& table);

/// One plot: a metric against a varied key (or a metric), over the completed cases.
struct PlotSeries {
  std::string file;  ///< PNG name in DIR/plots
  std::string x_name, x_unit, y_name, y_unit;
  std::vector<double> x, y;
  std::vector<double> y_err;  ///< 95 % half-widths of y (NaN: none), empty when the metric has no interval column
  std::vector<int> group;     ///< per point: its index in group_labels
  /// The lines of the plot: the cases that agree in the varied keys that do not go with x
  /// (one empty label when there are none).
  std::vector<std::string> group_labels;
  std::vector<double> reference;  ///< per point: Oxley's figure (NaN: none), empty when the metric has none
};
std::vector<PlotSeries> plot_series(const Study& study, const StudyTable& table);
/// Writes DIR/plots/plots.json and runs postprocess/study_plots.py on it. Returns "" or why
/// the plots could not be drawn.
std::string draw_plots(const Study& study, const StudyTable& table, const std::string& out_dir);

}  // namespace swarf
