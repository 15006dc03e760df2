// bench.cpp: the benchmark driver (see bench.h). Only the step loop is timed; model
// building and the initial force evaluation are not.
#include "bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>

#include "case_config.h"
#include "errors.h"
#include "model.h"
#include "run.h"
#include "simulation.h"

namespace swarf {

void run_bench(const BenchOptions& opt) {
  fmt::print("| scene | scheme | particles | rods | steps | force evaluations | threads | median s (min-max) | "
             "ns/particle-step | ns/particle-evaluation | broken rods | kinetic energy J |\n");
  fmt::print("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::fflush(stdout);
  for (const auto& path : opt.cases) {
    const CaseSettings cs = load_case(path, opt.overrides);
    std::string scene = std::filesystem::path(path).stem().string();
    std::transform(scene.begin(), scene.end(), scene.begin(), ::toupper);
    for (int th : opt.threads) {
      const int used = set_threads(th);
      std::vector<double> secs;
      std::size_t broken = 0, np = 0, nr = 0;
      double ke = 0;
      bool implicit = false;
      long long n = 0, evals = 0;
      for (int rep = 0; rep < std::max(1, opt.repeats); ++rep) {
        Model model = build_model(cs);
        Simulation sim(model);
        const double end = model.settings.integrator.end_time;
        const auto t0 = std::chrono::steady_clock::now();
        if (opt.steps > 0)
          for (long long s = 0; s < opt.steps; ++s) sim.step();
        else
          while (sim.time() < end * (1 - 1e-12)) sim.step(end - sim.time());
        n = sim.steps();
        evals = sim.stats().force_evaluations;
        secs.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        broken = sim.broken_rods();
        ke = sim.kinetic_energy();
        np = model.particles.size();
        nr = model.rods.size();
        implicit = sim.implicit();
      }
      std::sort(secs.begin(), secs.end());
      const double med = secs[secs.size() / 2];
      fmt::print("| {} | {} | {} | {} | {} | {} | {} | {:.3f} ({:.3f}-{:.3f}) | {:.1f} | {:.1f} | {} | {:.6g} |\n", scene,
                 implicit ? "newmark" : "verlet", np, nr, n, evals, used, med, secs.front(), secs.back(),
                 med * 1e9 / (double(np) * double(n)), med * 1e9 / (double(np) * double(evals)), broken, ke);
      std::fflush(stdout);
    }
  }
}

}  // namespace swarf
