// study_table.cpp: the study table, its CSV and the plot data (see study_table.h).
#include "study/study_table.h"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "io/atomic_file.h"
#include "postprocess/script_dir.h"
#include "setup/result_keys.h"
#include "setup/toml_parse.h"
#include "study/sweep.h"
#include "swarf/core/errors.h"

namespace swarf {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The summary sections whose numbers become columns, in column order.
const std::vector<std::string> kSections{"results", "cutting", "chip", "oxley", "heat", "uniaxial", "run"};
// Keys of "run" that measure the machine, not the physics: timing.csv only.
const std::set<std::string> kTiming{"run.threads", "run.wall_time_s", "run.step_wall_time_s",
                                    "run.ns_per_particle_step"};

void flatten(const json& j, const std::string& name, std::vector<std::pair<std::string, std::string>>& out) {
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) flatten(it.value(), name + "." + it.key(), out);
  } else if (j.is_array()) {
    for (std::size_t k = 0; k < j.size(); ++k)
      flatten(j[k], name + "." + (j.size() == 3 ? std::string(1, char('x' + k)) : std::to_string(k)), out);
  } else if (j.is_number_float()) {
    out.emplace_back(name, fmt::format("{}", j.get<double>()));
  } else if (j.is_number_integer()) {
    out.emplace_back(name, j.dump());
  } else if (j.is_string()) {
    const std::string s = j.get<std::string>();  // summary.json writes non-finite numbers as strings
    if (s == "inf" || s == "-inf" || s == "nan") out.emplace_back(name, s);
  }
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string csv_cell(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

// A TOML value text as shown in the table (strings without their quotes).
std::string cell_text(const std::string& toml_text) {
  if (toml_text.empty() || toml_text.front() != '"') return toml_text;
  if (const auto t = parse_toml_value(toml_text))
    if (auto s = (*t)["v"].value<std::string>()) return *s;
  return toml_text;
}

// The numbers of a TOML value text: one for a number, its elements for an array of numbers.
std::optional<std::vector<double>> numbers_of(const std::string& toml_text) {
  const auto t = parse_toml_value(toml_text);
  if (!t) return std::nullopt;
  const toml::node& n = *t->get("v");
  if (auto v = n.value<double>(); v && !n.is_boolean()) return std::vector<double>{*v};
  if (auto a = n.as_array()) {
    std::vector<double> out;
    for (const auto& e : *a) {
      auto v = e.value<double>();
      if (!v || e.is_boolean()) return std::nullopt;
      out.push_back(*v);
    }
    return out;
  }
  return std::nullopt;
}

bool varies(const std::vector<std::optional<double>>& v) {
  std::set<double> seen;
  for (const auto& x : v)
    if (x) seen.insert(*x);
  return seen.size() > 1;
}

std::string file_part(const std::string& s) {
  std::string out;
  for (char c : s) out += std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' ? c : '_';
  return out;
}

std::string label(const std::string& name, const std::string& unit) {
  return unit.empty() ? name : fmt::format("{} [{}]", name, unit);
}

// A plot's x axis: name, unit, one value per row (none where the case has no number).
struct Axis {
  std::string name, unit;
  std::vector<std::optional<double>> x;
};

bool completed(const StudyTable& t, std::size_t r) { return t.status[r].state == CaseState::completed; }

// The largest spread of x within one class of cls (the completed rows with an x), as a
// fraction of x's whole range; 0 when x does not vary.
double spread_within(const StudyTable& t, const std::vector<std::string>& cls,
                     const std::vector<std::optional<double>>& x) {
  double lo = INFINITY, hi = -INFINITY, worst = 0.0;
  std::map<std::string, std::pair<double, double>> range;
  for (std::size_t r = 0; r < cls.size(); ++r) {
    if (!completed(t, r) || !x[r]) continue;
    lo = std::min(lo, *x[r]);
    hi = std::max(hi, *x[r]);
    auto [it, fresh] = range.try_emplace(cls[r], *x[r], *x[r]);
    it->second = {std::min(it->second.first, *x[r]), std::max(it->second.second, *x[r])};
  }
  for (const auto& [c, mm] : range) worst = std::max(worst, mm.second - mm.first);
  return hi > lo ? worst / (hi - lo) : 0.0;
}

struct PlotGroups {
  std::vector<int> of_row;          ///< per row: its group
  std::vector<std::string> labels;  ///< per group
};

// The groups of one axis a: the cases that agree in every varied key that does not go with the
// axis (not the seed: its cases are the scatter at one x). A key goes with the axis when the
// cases of each of its values spread over at most a tenth of the axis's range (the tool origin
// goes with the measured depth of cut, the end time with the speed), so a grid of depths times
// speeds plots one line per speed against the depth and one per depth against the speed. The
// label names another axis that is nearly constant within each group (its mean), else the keys'
// values.
PlotGroups plot_groups(const Study& study, const StudyTable& t, const std::vector<Axis>& axes, const Axis& a) {
  const std::size_t n = t.rows.size();
  std::vector<std::string> cls(n);
  bool any = false;
  for (const auto& p : study.parameters) {
    if (p == study.seed_key) continue;
    std::vector<std::string> by(n);
    for (std::size_t r = 0; r < n; ++r) {
      auto it = study.cases[r].values.find(p);
      by[r] = it == study.cases[r].values.end() ? "" : it->second;
    }
    if (p == a.name || a.name.rfind(p + "[", 0) == 0 || spread_within(t, by, a.x) <= 0.1) continue;
    any = true;
    for (std::size_t r = 0; r < n; ++r) cls[r] += p + " = " + cell_text(by[r]) + ", ";
  }
  PlotGroups g{std::vector<int>(n, 0), {""}};
  if (!any) return g;
  std::map<std::string, int> index;
  g.labels.clear();
  for (std::size_t r = 0; r < n; ++r) {
    if (!completed(t, r)) continue;
    auto [it, fresh] = index.try_emplace(cls[r], int(g.labels.size()));
    if (fresh) g.labels.push_back(cls[r].substr(0, cls[r].size() - 2));
    g.of_row[r] = it->second;
  }
  for (const auto& b : axes) {
    if (b.name == a.name || !varies(b.x) || spread_within(t, cls, b.x) > 0.1) continue;
    std::vector<double> sum(g.labels.size()), count(g.labels.size());
    for (std::size_t r = 0; r < n; ++r)
      if (completed(t, r) && b.x[r]) sum[g.of_row[r]] += *b.x[r], count[g.of_row[r]] += 1;
    for (std::size_t k = 0; k < g.labels.size(); ++k)
      if (count[k] > 0)
        g.labels[k] = fmt::format("{} = {:.3g}{}", b.name, sum[k] / count[k], b.unit.empty() ? "" : " " + b.unit);
    break;
  }
  return g;
}

}  // namespace

int StudyTable::column(const std::string& name) const {
  auto it = std::find(columns.begin(), columns.end(), name);
  return it == columns.end() ? -1 : int(it - columns.begin());
}

std::optional<double> StudyTable::number(std::size_t row, const std::string& name) const {
  const int c = column(name);
  if (c < 0 || rows[row][c].empty()) return std::nullopt;
  const std::string& s = rows[row][c];
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size()) return std::nullopt;
  return v;
}

std::string unit_of_key(const std::string& flat_key) {
  const ResultKey* k = find_result_key(flat_key);
  return k ? std::string(k->unit) : "?";
}

std::string ci95_key_of(const std::string& flat_key) {
  const ResultKey* k = find_result_key(flat_key);
  return k ? std::string(k->ci95) : "";
}

std::string oxley_key_of(const std::string& flat_key) {
  const ResultKey* k = find_result_key(flat_key);
  return k ? std::string(k->oxley) : "";
}

StudyTable collect_table(const Study& study, const std::string& out_dir, bool timing) {
  StudyTable t;
  const auto add = [&t](std::string name, std::string unit, std::string what) {
    t.columns.push_back(std::move(name));
    t.units.push_back(std::move(unit));
    t.descriptions.push_back(std::move(what));
  };
  add("case", "-", "the case's id; its outputs are in cases/<id>/");
  for (const auto& p : study.parameters) {
    auto u = study.units.find(p);
    add(p, u == study.units.end() ? "" : u->second,
        p == study.seed_key ? "the seed key: seed_start + repetition (TOML text)"
        : u == study.units.end()
            ? "varied case key: its value as TOML text (no unit: the study's [units] does not give one)"
            : "varied case key: its value as TOML text (unit from the study's [units])");
  }
  if (study.repetitions > 1) add("repetition", "1", "0-based repetition of the point");
  add("status", "-", "completed, failed (exit N), failed (signal N), interrupted or not run");
  t.first_metric = t.columns.size();

  std::vector<std::vector<std::pair<std::string, std::string>>> metrics(study.cases.size());
  std::set<std::pair<std::size_t, std::string>> names;  // (section, name): the column order
  for (std::size_t r = 0; r < study.cases.size(); ++r) {
    const StudyCase& c = study.cases[r];
    t.status.push_back(case_status(study, c, out_dir));
    std::vector<std::string> row{c.id};
    for (const auto& p : study.parameters) {
      auto v = c.values.find(p);
      row.push_back(v == c.values.end() ? "" : cell_text(v->second));
    }
    if (study.repetitions > 1) row.push_back(std::to_string(c.repetition));
    row.push_back(t.status.back().text());
    t.rows.push_back(row);
    if (t.status.back().state != CaseState::completed) continue;
    json sum;
    try {
      sum = json::parse(read_text((fs::path(case_dir(out_dir, c)) / "summary.json").string()));
    } catch (const std::exception&) {
      continue;
    }
    for (std::size_t s = 0; s < kSections.size(); ++s) {
      if (!sum.contains(kSections[s])) continue;
      std::vector<std::pair<std::string, std::string>> flat;
      flatten(sum[kSections[s]], kSections[s], flat);
      for (auto& [name, value] : flat) {
        if (kTiming.count(name) != timing) continue;
        names.emplace(s, name);
        metrics[r].emplace_back(name, value);
      }
    }
  }
  for (const auto& [s, name] : names)
    add(name, unit_of_key(name),
        fmt::format("summary.json's {} (docs/outputs.md); empty where the case did not complete or has none", name));
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    t.rows[r].resize(t.columns.size());
    for (const auto& [name, value] : metrics[r]) t.rows[r][t.column(name)] = value;
  }
  return t;
}

std::string table_csv(const StudyTable& t) {
  std::string out;
  auto line = [&](const std::vector<std::string>& cells) {
    for (std::size_t k = 0; k < cells.size(); ++k) {
      if (k) out += ',';
      out += csv_cell(cells[k]);
    }
    out += "\n";
  };
  line(t.columns);
  for (const auto& r : t.rows) line(r);
  return out;
}

std::string columns_csv(const StudyTable& study, const StudyTable& timing) {
  std::string out = "column,unit,description\n";
  auto line = [&out](const StudyTable& t, std::size_t c, const char* prefix) {
    out += csv_cell(t.columns[c]) + ',' + csv_cell(t.units[c]) + ',' + csv_cell(prefix + t.descriptions[c]) + '\n';
  };
  for (std::size_t c = 0; c < study.columns.size(); ++c) line(study, c, "");
  for (std::size_t c = 0; c < timing.columns.size(); ++c)
    if (study.column(timing.columns[c]) < 0) line(timing, c, "timing.csv only: ");
  return out;
}

std::vector<std::string> default_plot_metrics(const StudyTable& t) {
  static const std::vector<std::string> wanted{"cutting.cutting_force_per_width_mean_N_per_m",
                                               "cutting.specific_cutting_force_N_per_mm2",
                                               "cutting.thrust_force_per_width_mean_N_per_m",
                                               "cutting.cutting_force_per_width_std_N_per_m",
                                               "cutting.thrust_force_per_width_std_N_per_m",
                                               "cutting.thrust_to_cutting_force_ratio",
                                               "chip.thickness_m",
                                               "chip.compression_ratio",
                                               "chip.shear_angle_deg",
                                               "chip.friction_angle_deg",
                                               "chip.merchant_shear_angle_deg",
                                               "chip.contact_length_m",
                                               "chip.chip_temperature_K",
                                               "chip.rake_face_temperature_K",
                                               "results.broken_fraction",
                                               "results.plastic_work_J",
                                               "results.external_work_J",
                                               "uniaxial.measured.youngs_modulus_Pa",
                                               "uniaxial.measured.yield_stress_Pa",
                                               "uniaxial.measured.hardening_tangent_Pa"};
  std::vector<std::string> out;
  for (const auto& m : wanted)
    if (t.column(m) >= 0) out.push_back(m);
  return out;
}

std::vector<PlotSeries> plot_series(const Study& study, const StudyTable& t) {
  const std::size_t n = t.rows.size();
  std::vector<Axis> axes;
  auto param_axis = [&](const std::string& key, int component) -> std::optional<Axis> {
    Axis a{key, study.units.count(key) ? study.units.at(key) : "", std::vector<std::optional<double>>(n)};
    std::vector<std::vector<double>> vals(n);
    std::size_t size = 0;
    for (std::size_t r = 0; r < n; ++r) {
      auto it = study.cases[r].values.find(key);
      if (it == study.cases[r].values.end()) continue;
      auto v = numbers_of(it->second);
      if (!v) return std::nullopt;
      vals[r] = *v;
      size = std::max(size, v->size());
    }
    if (size > 1 && component < 0) {
      // An array key: the axis is its one varying component, if only one varies.
      int found = -1;
      for (std::size_t k = 0; k < size; ++k) {
        std::vector<std::optional<double>> xs(n);
        for (std::size_t r = 0; r < n; ++r)
          if (k < vals[r].size()) xs[r] = vals[r][k];
        if (varies(xs)) {
          if (found >= 0) return std::nullopt;
          found = int(k);
        }
      }
      if (found < 0) return std::nullopt;
      component = found;
    }
    if (size > 1) a.name = fmt::format("{}[{}]", key, component);
    const std::size_t k = component < 0 ? 0 : std::size_t(component);
    for (std::size_t r = 0; r < n; ++r)
      if (k < vals[r].size() && completed(t, r)) a.x[r] = vals[r][k];
    return a;
  };
  auto axis_named = [&](const std::string& name) -> std::optional<Axis> {
    if (std::find(study.parameters.begin(), study.parameters.end(), name) != study.parameters.end())
      return param_axis(name, -1);
    const auto br = name.find('[');
    if (br != std::string::npos && name.back() == ']') {
      const std::string key = name.substr(0, br);
      if (std::find(study.parameters.begin(), study.parameters.end(), key) != study.parameters.end())
        return param_axis(key, std::atoi(name.substr(br + 1).c_str()));
    }
    if (t.column(name) < int(t.first_metric)) return std::nullopt;
    Axis a{name, unit_of_key(name), std::vector<std::optional<double>>(n)};
    for (std::size_t r = 0; r < n; ++r) a.x[r] = t.number(r, name);
    return a;
  };
  if (study.plot_against.empty()) {
    for (const auto& p : study.parameters)
      if (p != study.seed_key)
        if (auto a = axis_named(p)) axes.push_back(*a);
  } else {
    for (const auto& name : study.plot_against)
      if (auto a = axis_named(name)) axes.push_back(*a);
  }
  const std::vector<std::string> metrics = study.plot_metrics.empty() ? default_plot_metrics(t) : study.plot_metrics;

  std::vector<PlotSeries> out;
  for (const auto& a : axes) {
    if (!varies(a.x)) continue;
    const PlotGroups groups = plot_groups(study, t, axes, a);
    for (const auto& m : metrics) {
      if (t.column(m) < int(t.first_metric) || m == a.name) continue;
      PlotSeries p;
      p.file = file_part(m) + "_vs_" + file_part(a.name) + ".png";
      p.x_name = a.name, p.x_unit = a.unit, p.y_name = m, p.y_unit = unit_of_key(m);
      p.group_labels = groups.labels;
      const std::string ci = ci95_key_of(m), oxley = oxley_key_of(m);
      bool any_ci = false, any_reference = false;
      for (std::size_t r = 0; r < n; ++r) {
        auto y = t.number(r, m);
        if (a.x[r] && y) {
          p.x.push_back(*a.x[r]);
          p.y.push_back(*y);
          p.group.push_back(groups.of_row[r]);
          const auto e = ci.empty() ? std::nullopt : t.number(r, ci);
          p.y_err.push_back(e ? *e : NAN);
          any_ci = any_ci || e.has_value();
          const auto o = oxley.empty() ? std::nullopt : t.number(r, oxley);
          p.reference.push_back(o ? *o : NAN);
          any_reference = any_reference || o.has_value();
        }
      }
      if (!any_ci) p.y_err.clear();
      if (!any_reference) p.reference.clear();
      if (!p.x.empty()) out.push_back(std::move(p));
    }
  }
  return out;
}

std::string draw_plots(const Study& study, const StudyTable& table, const std::string& out_dir) {
  const fs::path dir = fs::path(out_dir) / "plots";
  fs::create_directories(dir);
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".png") fs::remove(e.path());
  const auto series = plot_series(study, table);
  json j;
  j["title"] = study.title.empty() ? study.file : study.title;
  j["plots"] = json::array();
  for (const auto& p : series) {
    j["plots"].push_back({{"file", p.file},
                          {"x_label", label(p.x_name, p.x_unit)},
                          {"y_label", label(p.y_name, p.y_unit)},
                          {"x", p.x},
                          {"y", p.y},
                          {"group", p.group},
                          {"group_labels", p.group_labels}});
    // Per-case numbers with gaps: NaN (a case without one) written as null.
    const auto with_nulls = [](const std::vector<double>& v) {
      json e = json::array();
      for (double x : v) e.push_back(std::isfinite(x) ? json(x) : json(nullptr));
      return e;
    };
    if (!p.y_err.empty()) {  // the 95 % half-widths
      j["plots"].back()["y_err"] = with_nulls(p.y_err);
      j["plots"].back()["y_err_label"] = "95 % CI of the steady mean (batch means)";
    }
    if (!p.reference.empty()) {  // Oxley's figure at each case's conditions
      j["plots"].back()["reference"] = with_nulls(p.reference);
      j["plots"].back()["reference_label"] = "Oxley's theory at each case's material, speed, depth and rake";
    }
  }
  write_text_atomic((dir / "plots.json").string(), j.dump(1) + "\n");
  if (series.empty()) return "nothing to plot (no numeric varied key with completed cases)";
  const std::string script = postprocess_path("study_plots.py");
  if (!fs::exists(script)) return "plot script not found: " + script;
  const std::string py = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "/usr/bin/env";
  std::vector<std::string> argv{py};
  if (py == "/usr/bin/env") argv.push_back("python3");
  argv.insert(argv.end(), {script, (dir / "plots.json").string()});
  const std::string log = (dir / "plots_log.txt").string();
  const int code = run_logged(argv, log);
  if (code == 0) return "";
  return fmt::format("the plot script failed (exit {}), see {}", code, log);
}

}  // namespace swarf
