// step_counters.cpp: the integrator's counters (see step_counters.h).
#include "app/observers/step_counters.h"

#include <fmt/format.h>

#include <algorithm>

#include "io/console.h"
#include "swarf/simulation.h"

namespace swarf {

void StepCounters::columns(std::vector<Column>& out) const {
  out.insert(out.end(), {{"step", "1", "steps done"},
                         {"dt", "s", "size of the last accepted step"},
                         {"iterations", "1", "force evaluations (sweeps or Newton iterations) of the last step"}});
}

void StepCounters::row(const Simulation& sim, std::vector<double>& values) {
  values.insert(values.end(), {double(sim.steps()), sim.last_dt(), double(sim.stats().last_iterations)});
}

void StepCounters::finish(const RunEnd& end, nlohmann::json& summary) {
  const Simulation& sim = end.sim;
  const StepStats& st = sim.stats();
  const double sweeps_mean = double(st.iterations) / double(std::max<std::int64_t>(1, st.accepted));
  const double evaluations_per_us = double(st.force_evaluations) / (sim.time() * 1e6);
  // With inflows and outflows the count changes: the mean over the series' rows.
  double particles = double(particles_);
  if (!sim.world().inflows.empty() || !sim.world().outflows.empty()) {
    const std::vector<double> n = end.series["particles"];
    particles = 0.0;
    for (double v : n) particles += v / double(n.size());
  }
  // (a run with no particle-steps, a flow whose inflow created none yet, has no cost per
  // particle-step: null and the reason, not inf, which trapped as a division by zero)
  const double particle_steps = double(sim.steps()) * particles;
  const double ns_per_particle_step = particle_steps > 0.0 ? end.step_wall_s * 1e9 / particle_steps : 0.0;
  summary["run"] = {{"threads", end.threads},
                    {"scheme", sim.implicit() ? "newmark" : "verlet"},
                    {"steps", sim.steps()},
                    {"steps_rejected", st.rejected},
                    {"iterations_per_step_mean", sweeps_mean},
                    {"iterations_per_step_max", st.max_iterations},
                    {"force_evaluations", st.force_evaluations},
                    {"force_evaluations_per_us", evaluations_per_us},
                    {"dt_last_s", sim.last_dt()},
                    {"simulated_time_s", sim.time()},
                    {"end_time_s", end_time_},
                    {"wall_time_s", end.wall_s},
                    {"step_wall_time_s", end.step_wall_s},
                    {"ns_per_particle_step", ns_per_particle_step}};
  if (!(particle_steps > 0.0)) {
    summary["run"]["ns_per_particle_step"] = nullptr;
    summary["run"]["ns_per_particle_step_reason"] = "no particle-steps: no particle was present at any series row";
  }
  const bool newton = sim.implicit() && sim.settings().solver == Solver::Newton;
  if (newton) {
    // (only for the Newton solver: the default run's summary keeps its keys)
    const NewtonStats& ns = sim.newton_stats();
    summary["run"]["solver"] = "newton";
    summary["run"]["newton_solves"] = ns.solves;
    summary["run"]["tangent_products"] = ns.tangent_products;
    summary["run"]["krylov_iterations"] = ns.krylov_iterations;
    summary["run"]["krylov_capped"] = ns.krylov_capped;
    summary["run"]["steps_rejected_indefinite"] = ns.indefinite;
  }
  say("\n  {} steps ({}), simulated {:.4g} s, wall {:.2f} s ({} ns per particle-step, {}{} thread{})\n", sim.steps(),
      sim.implicit() ? "newmark" : "verlet", sim.time(), end.wall_s,
      particle_steps > 0.0 ? fmt::format("{:.1f}", ns_per_particle_step) : std::string("no"),
      end.ranks > 1 ? fmt::format("{} ranks x ", end.ranks) : std::string(), end.threads, end.threads == 1 ? "" : "s");
  if (sim.implicit())
    say("  newmark: {} steps rejected, sweeps per step mean {:.2f} max {}, {:.4g} force evaluations per us\n",
        st.rejected, sweeps_mean, st.max_iterations, evaluations_per_us);
  if (newton)
    say("  newton: {} linear solves, {} tangent products ({:.1f} per step), {} solves stopped at "
        "krylov_max_iterations, {} steps rejected on an indefinite tangent\n",
        sim.newton_stats().solves, sim.newton_stats().tangent_products,
        double(sim.newton_stats().tangent_products) / double(std::max<std::int64_t>(1, sim.steps())),
        sim.newton_stats().krylov_capped, sim.newton_stats().indefinite);
}

}  // namespace swarf
