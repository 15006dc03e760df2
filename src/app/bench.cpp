// bench.cpp: the benchmark driver (see bench.h). Only the step loop is timed; model
// building and the initial force evaluation are not.
#include "app/bench.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "app/run.h"
#include "io/checkpoint.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "study/hypre_amg.h"
#include "swarf/core/errors.h"
#include "swarf/simulation.h"

namespace swarf {
namespace {

// A row of the stage table: each stage's ns per particle-step (its share of the step in %).
std::string stage_row(const std::string& scene, int threads, const StageClock& c, double particle_steps,
                      std::size_t list_builds) {
  const double total = c.total();
  std::string row = fmt::format("| {} | {} |", scene, threads);
  for (int s = 0; s < static_cast<int>(Stage::Count); ++s) {
    const double t = c.seconds(static_cast<Stage>(s));
    row += fmt::format(" {:.1f} ({:.0f} %) |", t * 1e9 / particle_steps, total > 0 ? 100.0 * t / total : 0.0);
  }
  return row + fmt::format(" {:.1f} | {} |\n", total * 1e9 / particle_steps, list_builds);
}

// A scene is a case file, or a checkpoint (.h5) whose stored case is rebuilt and whose state is
// restored, so that a late part of a run (a cut with its chip) can be timed without the steps
// that lead there. The options' overrides apply to the case either way.
bool is_checkpoint(const std::string& path) { return std::filesystem::path(path).extension() == ".h5"; }

CaseSettings scene_case(const std::string& path, const std::vector<std::string>& overrides) {
  if (!is_checkpoint(path)) return load_case(path, overrides);
  CheckpointCase c = read_checkpoint_case(path);
  c.overrides.insert(c.overrides.end(), overrides.begin(), overrides.end());
  return parse_case(c.toml, c.source, c.overrides, c.directory);
}

}  // namespace

void run_bench(const BenchOptions& opt) {
  // A passive wait policy puts the threads to sleep at every barrier: it cost the cut its second
  // thread (1.2 times one thread against 1.8, validation/bench/README.md), so a table measured
  // under it says so.
  if (const char* policy = std::getenv("OMP_WAIT_POLICY"); policy && (policy[0] == 'p' || policy[0] == 'P'))
    fmt::print(
        "(OMP_WAIT_POLICY={}: the threads sleep at every barrier; rows with 2 or more threads read slower than under "
        "the default policy, the cut's by a third)\n",
        policy);
  fmt::print(
      "| scene | scheme | particles | rods | steps | force evaluations | Newton iterations | CG iterations | threads | "
      "median s (min-max) | ns/particle-step | ns/particle-evaluation | broken rods | kinetic energy J | "
      "parallel efficiency |\n");
  fmt::print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::fflush(stdout);
  std::vector<std::string> stage_rows;
  for (const auto& path : opt.cases) {
    const CaseSettings cs = scene_case(path, opt.overrides);
    std::string scene = std::filesystem::path(path).stem().string();
    std::transform(scene.begin(), scene.end(), scene.begin(), ::toupper);
    // Parallel efficiency of each row against the scene's first (its thread count, usually 1):
    // (t_first x threads_first) / (t x threads), 1 for perfect scaling.
    double first_cost = 0.0;  // s x threads
    for (int th : opt.threads) {
      const int used = set_threads(th);
      std::vector<double> secs;
      std::size_t broken = 0, np = 0, nr = 0;
      double ke = 0;
      bool implicit = false;
      long long n = 0, evals = 0, solves = 0, cg = 0;
      bool newton = false;
      std::size_t builds = 0;
      StageClock stages;
      std::string amg_note;
      for (int rep = 0; rep < std::max(1, opt.repeats); ++rep) {
        Model model = build_model(cs);
        Simulation sim(model, model.step);
        std::shared_ptr<HypreAmg> amg;
        if (opt.preconditioner == "amg" && !(model.step.solver == Solver::Newton && model.step.implicit()))
          throw InputError(fmt::format(
              "--preconditioner amg: scene '{}' is not solved by Newton's method (integrator.scheme = \"newmark\" "
              "and integrator.solver = \"newton\"): only the Newton solve's CG takes a preconditioner",
              path));
        if (opt.preconditioner == "amg") {
          amg = std::make_shared<HypreAmg>(HypreAmgSettings{opt.amg_refresh, opt.amg_threshold, opt.amg_nodal});
          sim.set_newton_preconditioner(amg);
        }
        // From a checkpoint, the counters restart at the stored state: only this repeat's
        // steps, evaluations and list builds are counted.
        long long steps0 = 0, evals0 = 0, solves0 = 0, cg0 = 0;
        std::size_t builds0 = 0;
        if (is_checkpoint(path)) {
          RunRecord rec;
          read_checkpoint(path, sim, rec, {});
          steps0 = sim.steps();
          evals0 = sim.stats().force_evaluations;
          solves0 = sim.newton_stats().solves;
          cg0 = sim.newton_stats().krylov_iterations;
          builds0 = sim.contacts().list_builds();
        }
        sim.stage_clock().enable(opt.stages);
        const double end = model.settings.integrator.end_time;
        const auto t0 = std::chrono::steady_clock::now();
        if (opt.steps > 0)
          for (long long s = 0; s < opt.steps; ++s) sim.step();
        else
          while (sim.time() < end * (1 - 1e-12)) sim.step(end - sim.time());
        n = sim.steps() - steps0;
        evals = sim.stats().force_evaluations - evals0;
        solves = sim.newton_stats().solves - solves0;
        cg = sim.newton_stats().krylov_iterations - cg0;
        newton = model.step.solver == Solver::Newton && model.step.implicit();
        secs.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        broken = sim.broken_rods();
        ke = sim.kinetic_energy();
        np = model.particles.size();
        nr = model.rods.size();
        implicit = sim.implicit();
        stages = sim.stage_clock();
        if (amg)
          amg_note = fmt::format("BoomerAMG: {} hierarchies, {:.3f} s in their setup, {:.3f} s in the cycles",
                                 amg->setups(), amg->setup_seconds(), amg->apply_seconds());
        builds = sim.contacts().list_builds() - builds0;
      }
      std::sort(secs.begin(), secs.end());
      const double med = secs[secs.size() / 2];
      const std::string iters = newton ? fmt::format("{} | {}", solves, cg) : std::string("- | -");
      if (first_cost == 0.0) first_cost = med * used;
      fmt::print(
          "| {} | {} | {} | {} | {} | {} | {} | {} | {:.3f} ({:.3f}-{:.3f}) | {:.1f} | {:.1f} | {} | {:.6g} | {:.2f} "
          "|\n",
          scene, implicit ? "newmark" : "verlet", np, nr, n, evals, iters, used, med, secs.front(), secs.back(),
          med * 1e9 / (double(np) * double(n)), med * 1e9 / (double(np) * double(evals)), broken, ke,
          med > 0.0 ? first_cost / (med * used) : 1.0);
      if (!amg_note.empty()) fmt::print("  ({}; last repeat)\n", amg_note);
      if (opt.stages) stage_rows.push_back(stage_row(scene, used, stages, double(np) * double(n), builds));
      std::fflush(stdout);
    }
  }
  if (!opt.stages) return;
  // Where the time of the last repeat went (wall time of each stage, all threads together).
  std::string head = "\n| scene | threads |", rule = "|---|---|";
  for (const char* name : kStageNames) {
    head += fmt::format(" {} |", name);
    rule += "---|";
  }
  fmt::print("{} total | contact list builds |\n{}---|---|\n", head, rule);
  for (const auto& row : stage_rows) fmt::print("{}", row);
}

}  // namespace swarf
