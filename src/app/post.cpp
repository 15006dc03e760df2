// post.cpp: end-of-cut outputs and 'swarf post DIR' (see post.h).
#include "app/post.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/plots.h"
#include "io/atomic_file.h"
#include "io/console.h"
#include "io/csv_cell.h"
#include "io/h5file.h"
#include "io/path_kind.h"
#include "io/results_format.h"
#include "io/vtk_output.h"
#include "postprocess/chip_surface.h"
#include "postprocess/cut_oxley.h"
#include "postprocess/json_number.h"
#include "postprocess/steady_stats.h"
#include "swarf/core/errors.h"
#include "swarf/core/nan_safe.h"

namespace swarf {
namespace {

// True if series.csv's header names the column.
bool has_column(const std::string& path, const std::string& name) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::stringstream ss(line);
  std::string h;
  while (std::getline(ss, h, ','))
    if (h == name) return true;
  return false;
}

// Columns of series.csv by name.
std::vector<std::vector<double>> read_columns(const std::string& path, const std::vector<std::string>& names) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("post: '{}' cannot be read (the run did not finish?)", path));
  std::string line;
  std::getline(in, line);
  std::vector<std::string> head;
  {
    std::stringstream ss(line);
    std::string h;
    while (std::getline(ss, h, ',')) head.push_back(h);
  }
  std::vector<int> idx;
  for (const auto& n : names) {
    const auto it = std::find(head.begin(), head.end(), n);
    if (it == head.end()) throw InputError(fmt::format("post: '{}' has no column '{}'", path, n));
    idx.push_back(static_cast<int>(it - head.begin()));
  }
  std::vector<std::vector<double>> out(names.size());
  std::size_t row = 1;
  while (std::getline(in, line)) {
    ++row;
    std::vector<double> v;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) {
      // The whole cell must be a number (as swarf writes them, nan and inf included): a cell
      // that is empty or has text in it is refused, not read as 0.
      double x = 0;
      if (!parse_csv_number(cell, x))
        throw InputError(fmt::format("post: '{}' line {} column {} ('{}') = '{}' is not a number", path, row,
                                     v.size() + 1, v.size() < head.size() ? head[v.size()] : "?", cell));
      v.push_back(x);
    }
    if (v.size() != head.size())
      throw InputError(fmt::format("post: '{}' line {} has {} values, the header {}", path, row, v.size(), head.size()));
    for (std::size_t k = 0; k < idx.size(); ++k) out[k].push_back(v[idx[k]]);
  }
  return out;
}

constexpr const char* kToolSpectrum = "tool_spectrum.csv";
constexpr const char* kChipSurface = "chip_surface.vtp";
constexpr const char* kChipPicture = "chip.png";         // (render_chip.py adds _<field> to the stem for the others)
constexpr const char* kChipTopPicture = "chip_top.png";  // a cut with free sides: seen from above

// The run's broken-rod fraction from results.h5 (broken_rod_fraction: over the lattice's own
// rods). Layouts before 4 have no /bonds/formed: without bond formation every rod is the
// lattice's own; with it, the run's own figure in summary.json stands (it was taken over the
// lattice's rods by the run, which knew which rods were formed).
double read_broken_rod_fraction(const H5File& f, const nlohmann::json& sum) {
  std::size_t r = 0, c = 0;
  const auto flags = [&](const char* name) {
    const auto v = f.read_ints(name, r, c);
    return std::vector<std::uint8_t>(v.begin(), v.end());
  };
  const std::vector<std::uint8_t> intact = flags("/bonds/intact");
  if (f.has("/bonds/formed")) {
    const std::vector<std::uint8_t> formed = flags("/bonds/formed");
    if (formed.size() != intact.size())
      throw InputError(fmt::format("post: '{}': /bonds/formed has {} rods, /bonds/intact {}", f.path(), formed.size(),
                                   intact.size()));
    return broken_rod_fraction(intact, formed);
  }
  if (results_format(f) >= 4) throw InputError(fmt::format("post: '{}' (layout 4) has no /bonds/formed", f.path()));
  const auto& results = sum.contains("results") ? sum["results"] : nlohmann::json::object();
  if (!results.contains("formed_rods")) return broken_rod_fraction(intact, {});  // no bond formation
  const auto& cutting = sum.contains("cutting") ? sum["cutting"] : nlohmann::json::object();
  if (!cutting.contains("broken_fraction") || !cutting["broken_fraction"].is_number())
    throw InputError(
        fmt::format("post: '{}' (layout {}) does not mark the rods formed during the run and summary.json has no "
                    "cutting.broken_fraction: the broken-rod fraction over the lattice's own rods cannot be recomputed",
                    f.path(), results_format(f)));
  return cutting["broken_fraction"].get<double>();
}

}  // namespace

std::vector<RunFile> cut_files() {
  return {{kToolSpectrum},
          {kChipSurface},
          {kChipPicture},
          {"chip_plastic_strain.png"},
          {"chip_von_mises_stress.png"},
          {"chip_temperature.png"},
          {"chip_top_plastic_strain.png"}};
}

std::vector<std::string> render_pictures(const std::string& dir, const CutSetup& setup, std::string& message) {
  namespace fs = std::filesystem;
  // Debian's VTK renders through X only: without a display, a virtual one (xvfb-run).
  std::vector<std::string> prefix;
  if (!std::getenv("DISPLAY")) {
    if (!fs::exists("/usr/bin/xvfb-run")) {
      message = "no display and no xvfb-run (Debian package xvfb) to render the pictures";
      return {};
    }
    prefix = {"/usr/bin/xvfb-run", "-a", "-s", "-screen 0 1280x1024x24"};
  }
  std::vector<std::string> args{dir, dir + "/" + kChipPicture, "--tool", setup.tool_mesh};
  const double depth = setup.uncut_surface_z - setup.tool_tip.z();  // m
  if (depth > 0) args.insert(args.end(), {"--depth", fmt::format("{:.17g}", depth)});
  const ScriptRun run = run_postprocess_script("render_chip.py", args, prefix);
  std::vector<std::string> files;
  for (const auto& f : written_files(run.output))
    if (fs::exists(f)) files.push_back(fs::path(f).filename().string());
  if (!run.ok || files.empty()) {
    message = "render failed: " + run.output.substr(0, 400);
    return {};
  }
  if (setup.free_sides) {  // the view from above: the chip's flow across the edge and its spread
    args[1] = dir + "/" + kChipTopPicture;
    args.insert(args.end(), {"--view", "top", "--fields", "plastic_strain"});
    const ScriptRun top = run_postprocess_script("render_chip.py", args, prefix);
    for (const auto& f : written_files(top.output))
      if (fs::exists(f)) files.push_back(fs::path(f).filename().string());
    if (!top.ok) message = "top view not rendered: " + top.output.substr(0, 400);
  }
  return files;
}

namespace {

// The steady-part means and intervals of the optional columns (contact length, temperatures),
// as the forces', over the rows where each was measured (> 0), into summary.json "chip";
// returns the report's line ("" without any of them).
std::string steady_extras(const CutSetup& setup, const CutData& data, nlohmann::json& chip) {
  std::string line;
  const auto steady = [&](const char* col, const std::vector<double>& v, const char* key, const char* ci_key,
                          double scale, const char* unit, int digits) {
    if (v.empty()) return;
    std::vector<double> x;
    for (std::size_t k = 0; k < data.time.size() && k < v.size(); ++k)
      if (data.time[k] >= setup.steady_from && v[k] > 0.0) x.push_back(v[k]);
    const SteadyStats st = steady_stats(x);
    chip[key] = x.empty() ? nlohmann::json() : nlohmann::json(st.mean);
    chip[ci_key] = st.has_interval() ? nlohmann::json(st.ci95) : nlohmann::json();
    line += line.empty() ? "  steady part: " : ", ";
    if (x.empty()) {
      line += fmt::format("{}: no steady rows", col);
      return;
    }
    line += fmt::format("{} {:.{}f} {}", col, scale * st.mean, digits, unit);
    line += st.has_interval() ? fmt::format(" (95 % CI +- {:.{}f} {})", scale * st.ci95, digits, unit)
                              : std::string(" (95 % CI unavailable: fewer than 20 rows)");
  };
  steady("contact_length", data.contact_length, "contact_length_m", "contact_length_ci95_m", 1e3, "mm", 3);
  steady("chip_temperature", data.chip_temperature, "chip_temperature_K", "chip_temperature_ci95_K", 1.0, "K", 0);
  steady("rake_face_temperature", data.rake_face_temperature, "rake_face_temperature_K", "rake_face_temperature_ci95_K",
         1.0, "K", 0);
  return line;
}

// A cut with free sides: the passive force, the side burr, the chip's flow angle beside Stabler's
// rule and its width (analyze_cut's free-side figures); "" for plane strain.
std::string free_side_line(const nlohmann::json& cutting, const nlohmann::json& chip) {
  if (!chip.contains("inclination_deg")) return "";
  const auto num = json_number;
  const auto ci = [&](const nlohmann::json& j, const char* k, double scale) {
    const double v = num(j, k);
    return std::isfinite(v) ? fmt::format(" +- {:.2g}", scale * v) : std::string(" (95 % CI unavailable)");
  };
  const double lambda = num(chip, "inclination_deg");
  std::string line = fmt::format("  free sides, inclination lambda {:.4g} deg: passive force Fp/w {:.4g}{} kN/m",
                                 lambda, nan_safe(num(cutting, "passive_force_per_width_mean_N_per_m") * 1e-3),
                                 ci(cutting, "passive_force_per_width_ci95_N_per_m", 1e-3));
  if (cutting.contains("cutting_force_per_width_middle_mean_N_per_m"))
    line += fmt::format("; away from the sides (middle half of the width) Fc/w {:.4g}{} kN/m",
                        nan_safe(num(cutting, "cutting_force_per_width_middle_mean_N_per_m") * 1e-3),
                        ci(cutting, "cutting_force_per_width_middle_ci95_N_per_m", 1e-3));
  if (chip.contains("side_burr_m"))
    line += fmt::format("; side burr {:.3g} mm", nan_safe(num(chip, "side_burr_m") * 1e3));
  if (chip.contains("flow_angle_deg"))
    line += fmt::format(
        "; chip flow angle eta_c {:.3g}{} deg (Stabler's rule: {:.4g}); chip width {:.3g}{} mm, {:.3g} of "
        "the cut's",
        nan_safe(num(chip, "flow_angle_deg")), ci(chip, "flow_angle_ci95_deg", 1.0), lambda,
        nan_safe(num(chip, "width_m") * 1e3), ci(chip, "width_ci95_m", 1e3), nan_safe(num(chip, "width_to_cut_width")));
  else
    line += "; " + chip.value("flow_note", std::string());
  if (lambda != 0.0) line += "\n  (Oxley's figures below are the orthogonal cut's at the same normal rake)";
  return line;
}

}  // namespace

void finish_cut(const std::string& dir, const CutSetup& setup, const CutData& data, nlohmann::json& sum, VtkSeries* vtk,
                bool pictures) {
  const CutResult res = analyze_cut(setup, data);
  if (res.cutting.contains("steady_note"))
    eprint("swarf: warning: the steady forces are missing (null in summary.json): {}\n",
           res.cutting["steady_note"].get<std::string>());
  sum["cutting"] = res.cutting;
  sum["chip"] = res.chip;
  std::string tool_line;
  if (setup.compliant() && !data.tool_deflection_x.empty()) {
    const ToolVibration tv = analyze_tool(
        setup.mount, ToolSeries{data.time, data.tool_deflection_x, data.tool_deflection_z, data.fc, data.ft},
        setup.steady_from);
    sum["tool"] = tv.summary;
    if (!tv.spectra.frequency.empty()) write_text_atomic(dir + "/" + kToolSpectrum, tool_spectrum_csv(tv.spectra));
    const auto& t = tv.summary;
    const auto um = [&](const char* key) {
      return t[key].is_number() ? fmt::format("{:.3g}", 1e6 * t[key].get<double>()) : std::string("-");
    };
    const auto khz = [&](const char* key) {
      return t[key].is_number() ? fmt::format("{:.4g}", 1e-3 * t[key].get<double>()) : std::string("-");
    };
    tool_line = fmt::format(
        "  compliant tool: deflection x {} um (static -Fc/k {} um), z {} um (Ft/k {} um); f_n {} kHz, spectrum peaks "
        "x {} kHz, z {} kHz (resolution {} kHz)\n",
        um("deflection_x_mean_m"), um("static_deflection_x_m"), um("deflection_z_mean_m"), um("static_deflection_z_m"),
        khz("natural_frequency_x_Hz"), khz("deflection_x_peak_frequency_Hz"), khz("deflection_z_peak_frequency_Hz"),
        khz("spectrum_resolution_Hz"));
  }
  // The chip's surface: the union of its particles' spheres (radius grown by R/10 to close
  // the necks between touching neighbours) as a level set, meshed (OpenVDB).
  std::vector<Vec3> centres;
  for (auto i : res.metrics.members) centres.push_back(data.position[i]);
  const std::vector<double> radii(centres.size(), setup.radius);
  ChipSurface surf;
  try {
    surf = build_chip_surface(centres, radii, 0.0, 0.1 * setup.radius);
  } catch (const InputError& e) {  // e.g. a chip too large for the voxel budget: the rest stands
    surf = ChipSurface{};
    surf.particles = centres.size();
    surf.note = std::string("no surface: ") + e.what();
    eprint("swarf: warning: chip surface not built: {}\n", e.what());
  }
  nlohmann::json& chip = sum["chip"];
  chip["surface_particles"] = surf.particles;
  chip["surface_volume_m3"] = surf.volume_m3;
  chip["packing_volume_m3"] = surf.packing_volume_m3;
  chip["surface_voxel_m"] = surf.voxel_m;
  chip["surface_dilation_m"] = surf.dilation_m;
  if (!surf.note.empty()) chip["surface_note"] = surf.note;
  if (!surf.mesh.triangles.empty()) {
    write_vtp(dir + "/" + kChipSurface, surf.mesh);
    chip["surface_file"] = kChipSurface;
    chip["surface_triangles"] = surf.mesh.triangles.size();
    if (vtk) vtk->add_final_part("chip_surface", kChipSurface);
  }
  if (pictures) {
    std::string message;
    const std::vector<std::string> pngs = render_pictures(dir, setup, message);
    if (!pngs.empty()) {
      sum["pictures"] = pngs;
    } else {
      sum["picture_error"] = message;
      eprint("swarf: warning: picture not rendered: {}\n", message);
    }
  }
  say("{}{}", cut_table(sum["cutting"], sum["chip"], data.broken_rod_fraction), tool_line);
  if (const std::string line = steady_extras(setup, data, sum["chip"]); !line.empty()) say("{}\n", line);
  if (const std::string line = free_side_line(sum["cutting"], sum["chip"]); !line.empty()) say("{}\n", line);
  // Oxley's theory at the same cut, beside swarf's steady figures (about half a second).
  const double depth = sum["chip"].contains("depth_of_cut_m") && sum["chip"]["depth_of_cut_m"].is_number()
                           ? sum["chip"]["depth_of_cut_m"].get<double>()
                           : 0.0;
  sum["oxley"] = oxley_beside(setup.material, CutConditions{.speed = setup.cutting_speed,
                                                            .depth_of_cut = depth,
                                                            .rake_angle_deg = setup.rake_angle_deg,
                                                            .width = setup.width});
  say("{}", oxley_table(sum["oxley"], sum["cutting"], sum["chip"]));
  std::fflush(stdout);
}

void post_run(const std::string& dir) {
  namespace fs = std::filesystem;
  const std::string summary_path = dir + "/summary.json";
  if (path_kind(summary_path).kind != PathKind::File)
    throw InputError(
        fmt::format("post: '{}' does not exist: the run in '{}' did not finish (or this is not a run "
                    "directory)",
                    summary_path, dir));
  nlohmann::json sum;
  try {
    std::ifstream in(summary_path);
    sum = nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    throw InputError(fmt::format("post: '{}' is not valid JSON: {}", summary_path, e.what()));
  }
  if (sum.value("status", "") != "completed")
    throw InputError(fmt::format("post: '{}' does not record a completed run", summary_path));
  H5File f(dir + "/results.h5", H5File::Mode::Read);
  CutSetup setup;
  if (!read_cut_setup(f, setup))
    throw InputError(
        fmt::format("post: '{}/results.h5' has no /cutting setup: the run had no tool mesh "
                    "(a [[mesh]] tool: the built-in one with rake_angle, or a tool file with tool_tip) and a workpiece",
                    dir));
  CutData data;
  const auto cols = read_columns(dir + "/series.csv", {"time", "cutting_force_per_width", "thrust_force_per_width"});
  data.time = cols[0];
  data.fc = cols[1];
  data.ft = cols[2];
  // Layout 1 (runs before 2026-12-01) may lack the per-row chip thickness; the report then
  // takes the last state's. From layout 2 on the column is required.
  if (results_format(f) >= 2 || has_column(dir + "/series.csv", "chip_thickness"))
    data.chip_thickness = read_columns(dir + "/series.csv", {"chip_thickness"})[0];
  for (auto [name, column] :
       {std::pair{"contact_length", &data.contact_length}, std::pair{"chip_temperature", &data.chip_temperature},
        std::pair{"rake_face_temperature", &data.rake_face_temperature},
        std::pair{"passive_force_per_width", &data.passive_force}, std::pair{"chip_flow_angle", &data.chip_flow_angle},
        std::pair{"chip_width", &data.chip_width}, std::pair{"cutting_force_per_width_middle", &data.fc_middle},
        std::pair{"thrust_force_per_width_middle", &data.ft_middle}})
    if (has_column(dir + "/series.csv", name)) *column = read_columns(dir + "/series.csv", {name})[0];
  if (setup.compliant()) {
    const auto d = read_columns(dir + "/series.csv", {"tool_deflection_x", "tool_deflection_z"});
    data.tool_deflection_x = d[0];
    data.tool_deflection_z = d[1];
  }
  std::size_t r = 0, c = 0;
  const auto x = f.read_doubles("/particles/position", r, c);
  const auto bf = f.read_doubles("/particles/broken_fraction", r, c);
  const std::size_t n = std::min(setup.lattice_particles, bf.size());
  for (std::size_t i = 0; i < n; ++i) {
    data.position.emplace_back(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
    data.broken_fraction.push_back(bf[i]);
  }
  data.broken_rod_fraction = read_broken_rod_fraction(f, sum);
  const bool pictures = sum["case"].contains("output") ? sum["case"]["output"].value("plots", true) : true;
  for (const char* stale : {"pictures", "picture_error", "plots", "plot_error", "tool", "oxley"}) sum.erase(stale);
  finish_cut(dir, setup, data, sum, nullptr, pictures);
  if (pictures) {
    write_text_atomic(summary_path, sum.dump(2) + "\n");  // the plot script reads the new analysis
    const PlotResult pr = make_plots(dir, summary_path);
    sum["plots"] = pr.files;
    if (!pr.ok) sum["plot_error"] = pr.message;
  }
  write_text_atomic(summary_path, sum.dump(2) + "\n");
  say("  post: rewrote {} (cutting, chip{})\n", summary_path, sum.contains("pictures") ? ", pictures" : "");
}

}  // namespace swarf
