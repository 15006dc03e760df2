// paraview_script.cpp: DIR/open_in_paraview.py from its template (see paraview_script.h).
#include "app/paraview_script.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/observers/cut_probe.h"
#include "app/plots.h"
#include "io/atomic_file.h"
#include "setup/model.h"
#include "swarf/version.h"

namespace swarf {
namespace {

constexpr const char* kScript = "open_in_paraview.py";

}  // namespace

std::vector<RunFile> paraview_script_files() { return {{kScript}}; }

std::string write_paraview_script(const std::string& dir, const Model& model) {
  const std::string tpl = postprocess_path("open_in_paraview.py");
  std::ifstream in(tpl);
  if (!in) return "template not found: " + tpl;
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const std::string marker = "\nSWARF_RUN = {}\n";
  const auto at = text.find(marker);
  if (at == std::string::npos) return "template " + tpl + " has no line 'SWARF_RUN = {}'";
  // A Python literal: JSON of strings, numbers, lists and objects (no true, false or null) reads
  // as Python.
  nlohmann::json run = {{"swarf_version", SWARF_VERSION},
                        {"run_dir", std::filesystem::absolute(dir).lexically_normal().string()},
                        {"fields", model.settings.output.fields}};
  // The view's description (fields, units, ranges, colour maps), shared with the pictures:
  // carried in the copy so that a run directory moved to a machine without swarf still opens.
  const std::string view_path = postprocess_path("chip_view.json");
  std::ifstream view_in(view_path);
  if (!view_in) return "view description not found: " + view_path;
  try {
    run["view"] = nlohmann::json::parse(view_in);
  } catch (const nlohmann::json::exception& e) {
    return "view description " + view_path + " unreadable: " + e.what();
  }
  if (const auto cut = CutProbe::of(model)) {
    run["tool_mesh"] = cut->setup().tool_mesh;
    run["depth_of_cut_m"] = cut->setup().uncut_surface_z - cut->setup().tool_tip.z();
  }
  text.replace(at, marker.size(), "\nSWARF_RUN = " + run.dump() + "\n");
  write_text_atomic(dir + "/" + kScript, text);
  return "";
}

}  // namespace swarf
