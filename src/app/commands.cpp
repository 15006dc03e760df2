// commands.cpp: the subcommands of 'swarf', each its options and its action (see commands.h).
#include "app/commands.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

#include "app/bench.h"
#include "app/interrupt.h"
#include "app/material_lab.h"
#include "app/post.h"
#include "app/rod_driver.h"
#include "app/run.h"
#include "app/run_ranks.h"
#include "app/threads.h"
#include "io/console.h"
#include "io/mesh_file.h"
#include "io/vtk_output.h"
#include "lattice_gen/fcc_lattice.h"
#include "lattice_gen/lattice_file.h"
#include "postprocess/oxley.h"
#include "setup/case_config.h"
#include "setup/case_keys_doc.h"
#include "setup/rod_laws/rod_laws.h"
#include "study/mpi_comm.h"
#include "study/report.h"
#include "study/sweep.h"
#include "study/sweep_mpi.h"
#include "swarf/core/errors.h"
#include "swarf/state/mesh.h"
#include "tool_paths/tool_geometry.h"

namespace swarf {
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
      throw InputError(fmt::format("{} '{}': '{}' is not a number", option, text, item));
    }
  }
  return out;
}

// swarf lattice
struct LatticeCommand final : Command {
  std::string size_s, cells_s, out;
  double radius = 0, tol = 1e-6;
  explicit LatticeCommand(CLI::App& app) {
    sub = app.add_subcommand("lattice", "Generate an FCC lattice with nearest-neighbour rods (HDF5)");
    auto* o_size = sub->add_option("--size", size_s, "Box size LX,LY,LZ in m (every site in the closed box)");
    auto* o_cells = sub->add_option("--cells", cells_s, "Conventional cells NX,NY,NZ (4 NX NY NZ particles)");
    o_size->excludes(o_cells);
    sub->add_option("--radius", radius, "Particle radius R in m (rod length 2R)")->required();
    sub->add_option("--out", out, "Output HDF5 file")->required();
    sub->add_option("--bond-tolerance", tol, "Relative tolerance on the rod length 2R (default 1e-6)");
  }
  int run() override {
    FccSpec spec;
    spec.radius = radius;
    spec.bond_tolerance = tol;
    if (!size_s.empty()) {
      auto v = parse_list(size_s, "--size");
      if (v.size() != 3) throw InputError("--size: needs three lengths LX,LY,LZ in m, got '" + size_s + "'");
      spec.size = {v[0], v[1], v[2]};
    } else if (!cells_s.empty()) {
      auto v = parse_list(cells_s, "--cells");
      if (v.size() != 3) throw InputError("--cells: needs three integers NX,NY,NZ, got '" + cells_s + "'");
      for (int c = 0; c < 3; ++c) {
        if (v[c] != std::floor(v[c]) || v[c] < 1 || v[c] > 1e5)
          throw InputError("--cells: '" + cells_s + "' must be three positive integers");
        spec.cells[c] = static_cast<int>(v[c]);
      }
    } else {
      throw InputError("lattice: give --size LX,LY,LZ (m) or --cells NX,NY,NZ");
    }
    const auto lattice = generate_fcc(spec);
    write_lattice(out, lattice);
    fmt::print("wrote {}: {} particles, {} rods\n", out, lattice.position.size(), lattice.rods.size());
    return 0;
  }
};

// swarf rod
struct RodCommand final : Command {
  RodLaw law;
  std::string path_s;
  int steps = 100;
  explicit RodCommand(CLI::App& app) {
    sub = app.add_subcommand("rod", "Drive one rod along a strain path; CSV on stdout");
    law.yield_strain = kInf;
    law.tensile_strength = kInf;
    sub->add_option("--E", law.youngs_modulus, "Young's modulus of the rod, Pa")->required();
    sub->add_option("--yield-strain", law.yield_strain, "Yield strain eps_y, 1 (default inf: elastic)");
    sub->add_option("--hardening", law.hardening, "Hardening slope k, Pa (default 0)");
    sub->add_option("--tensile-strength", law.tensile_strength, "Tensile strength sigma_max, Pa (default inf)");
    sub->add_option("--path", path_s, "Strain turning points from 0, e.g. 0,0.004,-0.004,0.008")->required();
    sub->add_option("--steps", steps, "Increments per segment (default 100)");
  }
  int run() override {
    check_rod_options(law);
    write_rod_csv(std::cout, drive_rod(law, parse_list(path_s, "--path"), steps));
    return 0;
  }
};

// swarf material
struct MaterialCommand final : Command {
  MaterialOptions mo;
  explicit MaterialCommand(CLI::App& app) {
    sub = app.add_subcommand("material",
                             "Virtual material tests of a case's bonded FCC lattice (homogeneous, quasi-static): "
                             "CSV, PNG, material.json; see docs/material-lab.md");
    sub->add_option("case", mo.case_path, "Case file (TOML) whose rod law is tested (default: the built-in case)");
    sub->add_option("--test", mo.test,
                    "tension100, tension110, compression100, shear100, shear45, cyclic100 or all (default all)");
    sub->add_option("--to", mo.to,
                    "End strain of the test, a magnitude: log strain (uniaxial; compression goes to -TO), shear "
                    "gamma, the cyclic amplitude (defaults 3, 3, 0.5, 2, 2, 0.02)");
    sub->add_option("--increment", mo.increment, "Strain step: log strain, or gamma in shear (default 1e-4)");
    sub->add_option(
        "--temperature", mo.temperature,
        fmt::format("Temperature (K) of every rod, for {} (default: the law's T_ref)", rod_laws_with_conditions()));
    sub->add_option(
        "--strain-rate", mo.strain_rate,
        fmt::format("Equivalent plastic strain rate (1/s) the rate factor reads, for {} (default: quasi-static)",
                    rod_laws_with_conditions()));
    sub->add_option("--out", mo.out_dir, "Output directory")->required();
    sub->add_option("--set", mo.overrides, "Override a case key: --set rod.failure_strain=0.5 (repeatable)")
        ->allow_extra_args(false);
  }
  int run() override {
    mo.to_given = sub->count("--to") > 0;
    return run_material(mo);
  }
};

// swarf run
struct RunCommand final : Command {
  RunOptions ro;
  explicit RunCommand(CLI::App& app) {
    sub = app.add_subcommand(
        "run",
        "Run a case (no case file: the built-in default case); under mpirun -n N one run over N "
        "ranks (explicit steps: rods, grips, contacts, tools, heat, bond formation; docs/cluster.md)");
    sub->add_option("case", ro.case_path, "Case file (TOML); see docs/case-reference.md");
    sub->add_option("--out", ro.out_dir, "Output directory (default swarf-out)");
    sub->add_option("--set", ro.overrides, "Override a case key: --set integrator.dt=2e-9 (repeatable)")
        ->allow_extra_args(false);
    sub->add_option(
        "--threads", ro.threads,
        "Threads (default: OpenMP's, OMP_NUM_THREADS; under mpirun the CPUs over the ranks on the machine)");
    sub->add_option("--rebalance-every", ro.rebalance_every,
                    "Under mpirun: steps between new cuts balancing the ranks' work (default 1000; the results do "
                    "not depend on it)");
    sub->add_option("--stray-check-every", ro.stray_check_every,
                    "Under mpirun: steps between the checks for particles that left their rank's region (default 10; "
                    "the results do not depend on it)");
    sub->add_option("--partition", ro.partition,
                    "Under mpirun: the ranks' regions, 'rcb' (boxes by Zoltan's recursive coordinate bisection; "
                    "the default where swarf was built with Zoltan) or 'slabs' along x (the results do not depend "
                    "on it)")
        ->check(CLI::IsMember({"rcb", "slabs"}));
    sub->add_flag("--force", ro.force, "Run even if the case's memory estimate exceeds the machine's memory");
    sub->add_flag("--allow-long", ro.allow_long,
                  "Run even if the case is estimated to need more steps than integrator.max_steps");
    sub->add_flag("--no-energy-check{false}", ro.energy_check,
                  "Run on when the energy error exceeds the external work and the energy held (a sign of an "
                  "unstable step; docs/outputs.md)");
    sub->add_option("--restart", ro.restart,
                    "Continue from a checkpoint (DIR/checkpoint.h5, written every output.checkpoint_every steps "
                    "and, with output.checkpoint_at_end, after the last); no case file; --set only "
                    "integrator.end_time (to extend the run) and output keys; --out defaults to its directory");
    sub->add_flag("--check", ro.check,
                  "Build the case and print its set-up (with what [cut] derives) without running or writing "
                  "anything");
  }
  int run() override {
    if (sub->count("--threads")) check_thread_count(ro.threads, "--threads");
    for (const auto& [option, v] :
         {std::pair{"--rebalance-every", ro.rebalance_every}, std::pair{"--stray-check-every", ro.stray_check_every}})
      if (v < 1 || v > 1000000000)
        throw InputError(fmt::format("{} {}: the step count must lie in [1, 1e9]", option, v));
    // Under mpirun: one run over the ranks by domain decomposition (run_ranks.h).
    if (MpiSession::launched()) return run_on_ranks();
    run_case(ro);
    return 0;
  }

 private:
  // An error on one rank stops them all (the others would wait for it in the next collective):
  // it is printed by the rank that met it, with its rank, and the job ends with main()'s exit
  // code for it. An error in setting the case up that every rank met (SetupAgreement) is printed
  // once, by rank 0, and an interruption is agreed on by all ranks after the same step: both end
  // normally.
  int run_on_ranks() {
    MpiSession session;
    MpiComm comm;
    ro.comm = &comm;
    ro.local_rank = session.local_rank();
    ro.local_size = session.local_size();
    // (without --threads or OMP_NUM_THREADS: the machine's CPUs shared among its ranks, not all
    // of them to each rank, which crawled on this project's machine: 100 s against 14)
    if (ro.threads == 0 && !std::getenv("OMP_NUM_THREADS")) ro.threads = threads_per_rank(session.local_size());
    try {
      run_case(ro);
    } catch (const Interrupted&) {
      throw;
    } catch (const std::exception& e) {
      if (session.size() == 1) throw;
      const auto* input = dynamic_cast<const InputError*>(&e);
      // (every rank met the same error in setting the case up: rank 0 says it once, all end normally)
      if (SetupAgreement::failed_everywhere()) {
        if (session.rank() == 0) throw;
        return input ? 2 : 1;
      }
      const auto* sim = dynamic_cast<const SimulationError*>(&e);
      eprint("swarf: {} (rank {} of {}): {}\n", sim ? "simulation stopped" : "error", session.rank(), session.size(),
             e.what());
      std::fflush(stderr);
      session.abort(input ? 2 : sim ? 3 : 1);
    }
    return 0;
  }
};

// swarf post
struct PostCommand final : Command {
  std::string dir;
  explicit PostCommand(CLI::App& app) {
    sub = app.add_subcommand("post", "Redo a cutting run's analysis (chip, forces, surface, plots, picture)");
    sub->add_option("dir", dir, "Run directory (with summary.json, series.csv, results.h5)")->required();
  }
  int run() override {
    post_run(dir);
    return 0;
  }
};

// swarf tool
struct ToolCommand final : Command {
  ToolSpec ts;
  std::string out, vtp;
  explicit ToolCommand(CLI::App& app) {
    sub = app.add_subcommand("tool", "Generate the cutting tool mesh (STL, and VTP for ParaView)");
    sub->add_option("--rake-angle", ts.rake_angle_deg, "Rake angle gamma_o (ISO 3002), deg (default 0)");
    sub->add_option("--clearance-angle", ts.clearance_angle_deg, "Clearance angle alpha_o (ISO 3002), deg (default 7)");
    sub->add_option("--edge-radius", ts.edge_radius, "Cutting-edge radius, m (default 0: sharp)");
    sub->add_option("--width", ts.width, "Width along the edge, m")->required();
    sub->add_option("--face-length", ts.face_length, "Length of the rake and flank faces, m")->required();
    sub->add_option("--inclination-angle", ts.inclination_angle_deg,
                    "Inclination lambda_s (ISO 3002), deg: the tool turned about z for an oblique cut (default 0)");
    sub->add_option("--out", out, "Output STL file")->required();
    sub->add_option("--vtp", vtp, "Also write this VTP file");
  }
  int run() override {
    const auto mesh = make_tool(ts);
    write_stl(out, mesh);
    if (!vtp.empty()) write_vtp(vtp, mesh);
    fmt::print("wrote {}{}: {} triangles, {} vertices\n", out, vtp.empty() ? "" : " and " + vtp, mesh.triangles.size(),
               mesh.vertices.size());
    return 0;
  }
};

// swarf oxley
struct OxleyCommand final : Command {
  OxleyCut cut{.speed = 0.0, .uncut_thickness = 0.0, .width = 1e-3, .rake = 0.0, .initial_temperature = 293.15};
  double rake_deg = 0.0;
  explicit OxleyCommand(CLI::App& app) {
    sub = app.add_subcommand("oxley",
                             "Oxley's predictive machining theory for one orthogonal cut of AISI 1045 (Jaspers' "
                             "Johnson-Cook set): forces, shear angle, chip, temperatures; a cross-check, see "
                             "postprocess/oxley.h");
    sub->add_option("--speed", cut.speed, "Cutting speed, m/s")->required();
    sub->add_option("--uncut-thickness", cut.uncut_thickness, "Uncut chip thickness h, m")->required();
    sub->add_option("--rake-angle", rake_deg, "Rake angle, deg (default 0)");
    sub->add_option("--width", cut.width, "Width of cut, m (default 1e-3)");
    sub->add_option("--temperature", cut.initial_temperature, "Initial temperature of the work, K (default 293.15)");
  }
  int run() override {
    cut.rake = rake_deg * M_PI / 180.0;
    const OxleyResult r = oxley(cut, oxley_aisi1045_jaspers());
    if (!r.solved) {
      fmt::print(stderr, "swarf oxley: no solution: {}\n", r.reason);
      return 1;
    }
    fmt::print(
        "Oxley, AISI 1045 (Jaspers): V = {:.4g} m/s ({:.4g} m/min), h = {:.4g} m, rake {:.4g} deg, w = {:.4g} m\n",
        cut.speed, cut.speed * 60.0, cut.uncut_thickness, rake_deg, cut.width);
    fmt::print("| quantity | value | unit |\n|---|---|---|\n");
    fmt::print("| cutting force Fc | {:.4g} | N |\n", r.cutting_force);
    fmt::print("| thrust force Ft | {:.4g} | N |\n", r.thrust_force);
    fmt::print("| Fc per width | {:.4g} | N/m |\n", r.cutting_force_per_width);
    fmt::print("| specific cutting force kc | {:.4g} | N/mm^2 |\n",
               r.cutting_force / (cut.width * cut.uncut_thickness) * 1e-6);
    fmt::print("| Ft / Fc | {:.4g} | 1 |\n", r.thrust_force / r.cutting_force);
    fmt::print("| shear angle | {:.4g} | deg |\n", r.shear_angle * 180.0 / M_PI);
    fmt::print("| chip thickness h_c | {:.4g} | m |\n", r.chip_thickness);
    fmt::print("| chip ratio h / h_c | {:.4g} | 1 |\n", r.chip_ratio);
    fmt::print("| tool-chip contact length | {:.4g} | m |\n", r.contact_length);
    fmt::print("| primary shear zone temperature | {:.4g} | K |\n", r.primary_temperature);
    fmt::print("| rake face temperature | {:.4g} | K |\n", r.rake_temperature);
    return 0;
  }
};

// swarf bench
struct BenchCommand final : Command {
  BenchOptions bo;
  std::string threads_s = "1,2";
  explicit BenchCommand(CLI::App& app) {
    sub = app.add_subcommand("bench", "Time named scenes (case files) for several thread counts");
    sub->add_option("cases", bo.cases,
                    "Scene case files, e.g. validation/bench/w1.toml, or checkpoints (.h5: the stored case, continued "
                    "from its state)")
        ->required();
    sub->add_option("--threads", threads_s, "Thread counts, comma separated (default 1,2)");
    sub->add_option("--steps", bo.steps, "Steps (default: run to the case's end_time)");
    sub->add_option("--repeats", bo.repeats, "Repeats per row, median reported (default 3)");
    sub->add_flag("--stages", bo.stages, "Also print the time of each step stage (ns per particle-step)");
    sub->add_option("--preconditioner", bo.preconditioner,
                    "The Newton solve's CG preconditioner: block_jacobi (default) or amg (hypre's BoomerAMG on the "
                    "assembled tangent)")
        ->check(CLI::IsMember({"block_jacobi", "amg"}));
    sub->add_option("--amg-refresh", bo.amg_refresh, "With amg: a new hierarchy at every N-th tangent (default 1)")
        ->check(CLI::PositiveNumber);
    sub->add_option("--amg-threshold", bo.amg_threshold, "With amg: BoomerAMG's strong threshold, 1 (default 0.5)")
        ->check(CLI::Range(0.0, 1.0));
    sub->add_flag("--amg-nodal", bo.amg_nodal, "With amg: coarsen by particles (3x3 blocks) instead of by unknowns");
    sub->add_option("--set", bo.overrides, "Override a case key (repeatable)")->allow_extra_args(false);
  }
  int run() override {
    bo.threads.clear();
    for (double t : parse_list(threads_s, "--threads")) {
      if (t < 1 || t != std::floor(t)) throw InputError("--threads: '" + threads_s + "' must be positive integers");
      check_thread_count(static_cast<long long>(t), "--threads");
      bo.threads.push_back(static_cast<int>(t));
    }
    run_bench(bo);
    return 0;
  }
};

// swarf sweep
struct SweepCommand final : Command {
  SweepOptions so;
  explicit SweepCommand(CLI::App& app) {
    sub = app.add_subcommand("sweep", "Run a parameter study; under mpirun the ranks share the cases");
    sub->add_option("study", so.study_path, "Study file (TOML); see docs/studies.md")->required();
    sub->add_option("--out", so.out_dir, "Study directory: cases/, study.csv, plots/ (re-run to resume)")->required();
    sub->add_option("--jobs", so.jobs, "Cases run at once (per MPI rank; default 1)");
    sub->add_option("--threads", so.threads, "Threads per case (default max(1, cores / (jobs x ranks on the machine)))");
    sub->add_flag("--list", so.list_only,
                  "Check the study and list its cases (id, state, --set overrides); run nothing");
  }
  int run() override {
    if (so.threads > 0) check_thread_count(so.threads, "--threads");  // (0: the default, cores / jobs)
    return run_sweep(so);
  }
};

// swarf report
struct ReportCommand final : Command {
  std::string dir;
  explicit ReportCommand(CLI::App& app) {
    sub = app.add_subcommand("report", "Write DIR/report.md for a study directory of 'swarf sweep'");
    sub->add_option("dir", dir, "Study directory")->required();
  }
  int run() override {
    fmt::print("wrote {}\n", write_report(dir));
    return 0;
  }
};

// swarf case keys
struct CaseKeysCommand final : Command {
  bool markdown = false;
  std::string update;
  explicit CaseKeysCommand(CLI::App& case_cmd) {
    sub = case_cmd.add_subcommand("keys", "List every case key: table.key, type, unit, default");
    sub->add_flag("--markdown", markdown, "Print the key tables of docs/case-reference.md, with their marker lines");
    sub->add_option("--update", update, "Rewrite the key tables between the marker lines of this markdown file");
  }
  int run() override {
    if (!update.empty()) {
      update_key_tables_file(update);
      fmt::print("updated the key tables of {}\n", update);
    } else {
      fmt::print("{}", markdown ? key_tables_markdown() : key_list_text());
    }
    return 0;
  }
};

// swarf case fields
struct CaseFieldsCommand final : Command {
  std::string update;
  explicit CaseFieldsCommand(CLI::App& case_cmd) {
    sub = case_cmd.add_subcommand("fields",
                                  "Print the table of the per-particle output fields (output.fields) of "
                                  "docs/outputs.md, with its marker lines");
    sub->add_option("--update", update, "Rewrite the fields' table between the marker lines of this markdown file");
  }
  int run() override {
    if (!update.empty()) {
      update_output_fields_file(update);
      fmt::print("updated the output fields' table of {}\n", update);
    } else {
      fmt::print("{}\n", output_fields_markdown());
    }
    return 0;
  }
};

// swarf case default
struct CaseDefaultCommand final : Command {
  bool cut = false;
  explicit CaseDefaultCommand(CLI::App& case_cmd) {
    sub = case_cmd.add_subcommand("default",
                                  "Print the built-in default case (what 'swarf run' runs without a case file) as a "
                                  "case file to start from");
    sub->add_flag("--cut", cut, "Print the same cut in cutting terms: a [cut] table (docs/case-reference.md)");
  }
  int run() override {
    fmt::print("{}", cut ? kDefaultCutTableToml : kDefaultCaseToml);
    return 0;
  }
};

}  // namespace

std::vector<std::unique_ptr<Command>> make_commands(CLI::App& app) {
  std::vector<std::unique_ptr<Command>> c;
  c.push_back(std::make_unique<LatticeCommand>(app));
  c.push_back(std::make_unique<RodCommand>(app));
  c.push_back(std::make_unique<RunCommand>(app));
  c.push_back(std::make_unique<MaterialCommand>(app));
  c.push_back(std::make_unique<PostCommand>(app));
  c.push_back(std::make_unique<ToolCommand>(app));
  c.push_back(std::make_unique<BenchCommand>(app));
  c.push_back(std::make_unique<OxleyCommand>(app));
  c.push_back(std::make_unique<SweepCommand>(app));
  c.push_back(std::make_unique<ReportCommand>(app));
  CLI::App* case_cmd = app.add_subcommand("case", "Describe the case file format; print the default case");
  case_cmd->require_subcommand(1);
  c.push_back(std::make_unique<CaseKeysCommand>(*case_cmd));
  c.push_back(std::make_unique<CaseFieldsCommand>(*case_cmd));
  c.push_back(std::make_unique<CaseDefaultCommand>(*case_cmd));
  return c;
}

}  // namespace swarf
