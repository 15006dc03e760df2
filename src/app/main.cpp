// main.cpp: the 'swarf' command line: lattice, rod, run, post, tool, bench, sweep, report, case keys.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <iostream>
#include <sstream>

#include "app/bench.h"
#include "app/post.h"
#include "app/rod_driver.h"
#include "app/run.h"
#include "io/mesh_file.h"
#include "io/vtk_output.h"
#include "lattice_gen/fcc_lattice.h"
#include "lattice_gen/lattice_file.h"
#include "setup/case_config.h"
#include "setup/case_keys_doc.h"
#include "study/report.h"
#include "study/sweep.h"
#include "swarf/core/errors.h"
#include "swarf/state/mesh.h"
#include "swarf/version.h"
#include "tool_paths/tool_geometry.h"

namespace {

std::vector<double> parse_list(const std::string& text, const char* option) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    try {
      std::size_t used = 0;
      out.push_back(std::stod(item, &used));
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw swarf::InputError(fmt::format("{} '{}': '{}' is not a number", option, text, item));
    }
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"swarf: DEM simulation of orthogonal metal cutting (bonded FCC workpiece, Bauschinger rods)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("swarf ") + SWARF_VERSION);

  // swarf lattice
  auto* lat = app.add_subcommand("lattice", "Generate an FCC lattice with nearest-neighbour bonds (HDF5)");
  std::string size_s, cells_s, lat_out;
  double radius = 0, tol = 1e-6;
  auto* o_size = lat->add_option("--size", size_s, "Box size LX,LY,LZ in m (every site in the closed box)");
  auto* o_cells = lat->add_option("--cells", cells_s, "Conventional cells NX,NY,NZ (4 NX NY NZ particles)");
  o_size->excludes(o_cells);
  lat->add_option("--radius", radius, "Particle radius R in m (bond length 2R)")->required();
  lat->add_option("--out", lat_out, "Output HDF5 file")->required();
  lat->add_option("--bond-tolerance", tol, "Relative tolerance on the bond length 2R (default 1e-6)");

  // swarf rod
  auto* rod = app.add_subcommand("rod", "Drive one rod along a strain path; CSV on stdout");
  swarf::RodLaw law;
  law.yield_strain = swarf::kInf;
  law.tensile_strength = swarf::kInf;
  std::string path_s;
  int steps = 100;
  rod->add_option("--E", law.youngs_modulus, "Young's modulus of the rod, Pa")->required();
  rod->add_option("--yield-strain", law.yield_strain, "Yield strain eps_y, 1 (default inf: elastic)");
  rod->add_option("--hardening", law.hardening, "Hardening slope k, Pa (default 0)");
  rod->add_option("--tensile-strength", law.tensile_strength, "Tensile strength sigma_max, Pa (default inf)");
  rod->add_option("--path", path_s, "Strain turning points from 0, e.g. 0,0.004,-0.004,0.008")->required();
  rod->add_option("--steps", steps, "Increments per segment (default 100)");

  // swarf run
  auto* run = app.add_subcommand("run", "Run a case (no case file: the built-in default case)");
  swarf::RunOptions ro;
  run->add_option("case", ro.case_path, "Case file (TOML); see docs/case-reference.md");
  run->add_option("--out", ro.out_dir, "Output directory (default swarf-out)");
  run->add_option("--set", ro.overrides, "Override a case key: --set integrator.dt=2e-9 (repeatable)")
      ->allow_extra_args(false);
  run->add_option("--threads", ro.threads, "Threads (default: OpenMP's, OMP_NUM_THREADS)");
  run->add_option("--restart", ro.restart,
                  "Continue from a checkpoint (DIR/checkpoint.h5, written every "
                  "output.checkpoint_every steps); no case file or --set then; --out defaults to its directory");

  // swarf post
  auto* post = app.add_subcommand("post", "Redo a cutting run's analysis (chip, forces, surface, plots, picture)");
  std::string post_dir;
  post->add_option("dir", post_dir, "Run directory (with summary.json, series.csv, results.h5)")->required();

  // swarf tool
  auto* tool = app.add_subcommand("tool", "Generate the cutting tool mesh (STL, and VTP for ParaView)");
  swarf::ToolSpec ts;
  std::string tool_out, tool_vtp;
  tool->add_option("--rake-angle", ts.rake_angle_deg, "Rake angle alpha, deg (default 0)");
  tool->add_option("--clearance-angle", ts.clearance_angle_deg, "Clearance angle gamma, deg (default 7)");
  tool->add_option("--edge-radius", ts.edge_radius, "Cutting-edge radius, m (default 0: sharp)");
  tool->add_option("--width", ts.width, "Width along the edge, m")->required();
  tool->add_option("--face-length", ts.face_length, "Length of the rake and flank faces, m")->required();
  tool->add_option("--out", tool_out, "Output STL file")->required();
  tool->add_option("--vtp", tool_vtp, "Also write this VTP file");

  // swarf bench
  auto* bench = app.add_subcommand("bench", "Time named scenes (case files) for several thread counts");
  swarf::BenchOptions bo;
  std::string threads_s = "1,2";
  bench->add_option("cases", bo.cases, "Scene case files, e.g. validation/bench/w1.toml")->required();
  bench->add_option("--threads", threads_s, "Thread counts, comma separated (default 1,2)");
  bench->add_option("--steps", bo.steps, "Steps (default: run to the case's end_time)");
  bench->add_option("--repeats", bo.repeats, "Repeats per row, median reported (default 3)");
  bench->add_flag("--stages", bo.stages, "Also print the time of each step stage (ns per particle-step)");
  bench->add_option("--set", bo.overrides, "Override a case key (repeatable)")->allow_extra_args(false);

  // swarf sweep
  auto* sweep = app.add_subcommand("sweep", "Run a parameter study; under mpirun the ranks share the cases");
  swarf::SweepOptions so;
  sweep->add_option("study", so.study_path, "Study file (TOML); see docs/studies.md")->required();
  sweep->add_option("--out", so.out_dir, "Study directory: cases/, study.csv, plots/ (re-run to resume)")->required();
  sweep->add_option("--jobs", so.jobs, "Cases run at once (per MPI rank; default 1)");
  sweep->add_option("--threads", so.threads, "Threads per case (default max(1, cores / (jobs x ranks on the machine)))");
  sweep->add_flag("--list", so.list_only,
                  "Check the study and list its cases (id, state, --set overrides); run nothing");

  // swarf report
  auto* report = app.add_subcommand("report", "Write DIR/report.md for a study directory of 'swarf sweep'");
  std::string report_dir;
  report->add_option("dir", report_dir, "Study directory")->required();

  // swarf case keys
  auto* case_cmd = app.add_subcommand("case", "Describe the case file format");
  case_cmd->require_subcommand(1);
  auto* keys = case_cmd->add_subcommand("keys", "List every case key: table.key, type, unit, default");
  bool keys_markdown = false;
  std::string keys_update;
  keys->add_flag("--markdown", keys_markdown, "Print the key tables of docs/case-reference.md, with their marker lines");
  keys->add_option("--update", keys_update, "Rewrite the key tables between the marker lines of this markdown file");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }

  try {
    if (*lat) {
      swarf::FccSpec spec;
      spec.radius = radius;
      spec.bond_tolerance = tol;
      if (!size_s.empty()) {
        auto v = parse_list(size_s, "--size");
        if (v.size() != 3) throw swarf::InputError("--size: needs three lengths LX,LY,LZ in m, got '" + size_s + "'");
        spec.size = {v[0], v[1], v[2]};
      } else if (!cells_s.empty()) {
        auto v = parse_list(cells_s, "--cells");
        if (v.size() != 3) throw swarf::InputError("--cells: needs three integers NX,NY,NZ, got '" + cells_s + "'");
        for (int c = 0; c < 3; ++c) {
          if (v[c] != std::floor(v[c]) || v[c] < 1 || v[c] > 1e5)
            throw swarf::InputError("--cells: '" + cells_s + "' must be three positive integers");
          spec.cells[c] = static_cast<int>(v[c]);
        }
      } else {
        throw swarf::InputError("lattice: give --size LX,LY,LZ (m) or --cells NX,NY,NZ");
      }
      const auto lattice = swarf::generate_fcc(spec);
      swarf::write_lattice(lat_out, lattice);
      fmt::print("wrote {}: {} particles, {} bonds\n", lat_out, lattice.position.size(), lattice.bonds.size());
    } else if (*rod) {
      auto samples = swarf::drive_rod(law, parse_list(path_s, "--path"), steps);
      swarf::write_rod_csv(std::cout, samples);
    } else if (*run) {
      swarf::run_case(ro);
    } else if (*post) {
      swarf::post_run(post_dir);
    } else if (*tool) {
      const auto mesh = swarf::make_tool(ts);
      swarf::write_stl(tool_out, mesh);
      if (!tool_vtp.empty()) swarf::write_vtp(tool_vtp, mesh);
      fmt::print("wrote {}{}: {} triangles, {} vertices\n", tool_out, tool_vtp.empty() ? "" : " and " + tool_vtp,
                 mesh.triangles.size(), mesh.vertices.size());
    } else if (*bench) {
      bo.threads.clear();
      for (double t : parse_list(threads_s, "--threads")) {
        if (t < 1 || t != std::floor(t))
          throw swarf::InputError("--threads: '" + threads_s + "' must be positive integers");
        bo.threads.push_back(static_cast<int>(t));
      }
      swarf::run_bench(bo);
    } else if (*sweep) {
      return swarf::run_sweep(so);
    } else if (*report) {
      fmt::print("wrote {}\n", swarf::write_report(report_dir));
    } else if (*keys) {
      if (!keys_update.empty()) {
        swarf::update_key_tables_file(keys_update);
        fmt::print("updated the key tables of {}\n", keys_update);
      } else {
        fmt::print("{}", keys_markdown ? swarf::key_tables_markdown() : swarf::key_list_text());
      }
    }
  } catch (const swarf::InputError& e) {
    fmt::print(stderr, "swarf: error: {}\n", e.what());
    return 2;
  } catch (const swarf::SimulationError& e) {
    fmt::print(stderr, "swarf: simulation stopped: {}\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    fmt::print(stderr, "swarf: error: {}\n", e.what());
    return 1;
  }
  return 0;
}
