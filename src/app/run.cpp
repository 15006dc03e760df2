// run.cpp: the run driver: case -> model -> observers -> time loop -> outputs (see run.h).
//
// The loop only steps and asks: the observers (app/observers/) measure, RunOutputs writes
// rows, frames and checkpoints at their times, and the end collects the observers' parts of
// summary.json around the head (summary.h).
#include "app/run.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>

#include "app/build_info.h"
#include "app/interrupt.h"
#include "app/observers/case_observers.h"
#include "app/observers/exact_ledger.h"
#include "app/observers/observer_set.h"
#include "app/plots.h"
#include "app/progress.h"
#include "app/run_directory.h"
#include "app/run_limits.h"
#include "app/run_outputs.h"
#include "app/run_ranks.h"
#include "app/setup_report.h"
#include "app/summary.h"
#include "io/atomic_file.h"
#include "io/checkpoint.h"
#include "io/console.h"
#include "io/h5file.h"
#include "setup/case_keys.h"
#include "setup/model.h"
#include "study/zoltan_rcb.h"
#include "swarf/core/comm.h"
#include "swarf/core/errors.h"
#include "swarf/domains/domain_run.h"
#include "swarf/simulation.h"

namespace swarf {
namespace {

// Its files in the run directory (run_case_files() declares them).
constexpr const char* kSummary = "summary.json";
constexpr const char* kPlotSummary = "summary.json.plotting";
constexpr const char* kResults = "results.h5";
constexpr const char* kLog = "run.log";

// The case to run: the checkpoint's own on a restart, else the case file (or the built-in
// default) with the overrides; 'stored' receives it as a checkpoint records it.
CaseSettings read_case(const RunOptions& opt, CheckpointCase& stored) {
  if (!opt.restart.empty()) {
    if (!opt.case_path.empty())
      throw InputError(
          fmt::format("--restart {}: a restart continues the checkpoint's own case; give no case "
                      "file (got '{}')",
                      opt.restart, opt.case_path));
    // An extension: only the keys flagged restartable in the key table (the end time and the
    // outputs) may change. Every other key made the state the checkpoint holds, and a different
    // value would not continue that run.
    const std::vector<std::string> extendable = restartable_keys();
    for (const auto& o : opt.overrides) {
      const std::string key = o.substr(0, o.find('='));
      auto trimmed = key;
      while (!trimmed.empty() && trimmed.back() == ' ') trimmed.pop_back();
      if (std::find(extendable.begin(), extendable.end(), trimmed) == extendable.end()) {
        std::string list;
        for (const auto& k : extendable) list += (list.empty() ? "" : ", ") + k;
        throw InputError(
            fmt::format("--restart {}: --set {}: key '{}' cannot change on a restart (the checkpoint's "
                        "state was made with the case's value); a restart may set only {}",
                        opt.restart, o, trimmed, list));
      }
    }
    stored = read_checkpoint_case(opt.restart);
    stored.overrides.insert(stored.overrides.end(), opt.overrides.begin(), opt.overrides.end());
    try {
      return parse_case(stored.toml, stored.source, stored.overrides, stored.directory);
    } catch (const InputError& e) {
      // (the text is the checkpoint's copy: blamed on the case file, the message sent the
      // user to a file that may have changed or gone since)
      throw InputError(
          fmt::format("--restart {}: the case stored in the checkpoint (read from {} when the run began): {}",
                      opt.restart, stored.source, e.what()));
    }
  }
  CaseSettings cs = opt.case_path.empty() ? parse_case(kDefaultCaseToml, "<built-in default case>", opt.overrides)
                                          : load_case(opt.case_path, opt.overrides);
  stored.toml = cs.text;
  stored.source = cs.source;
  stored.directory = cs.directory;
  stored.overrides = cs.overrides;
  return cs;
}

// The plots of the run (the script reads the summary, so it is written for it first); their
// files or the reason they are missing go into the summary.
void add_plots(const std::string& dir, nlohmann::json& sum) {
  const std::string plotting = dir + "/" + kPlotSummary;
  write_text_atomic(plotting, sum.dump(2));
  const PlotResult pr = make_plots(dir, plotting);
  std::filesystem::remove(plotting);
  sum["plots"] = pr.files;
  if (!pr.ok) {
    sum["plot_error"] = pr.message;
    eprint("swarf: warning: plots not written: {}\n", pr.message);
  }
}

// The end of the run: series.csv closed, results.h5, the observers' report and summary parts,
// the plots, summary.json and the list of outputs.
void finish_run(const std::string& dir, const Model& model, Simulation& sim, RunOutputs& outputs,
                ObserverSet& observers, const RunProvenance& prov, const std::string& restarted_from) {
  const int threads = prov.threads;
  const RunOutputs::WallTimes wall = outputs.finish();
  write_results_h5(dir + "/" + kResults, sim, model.settings.output.fields, [&](H5File& f) {
    write_disorder_attributes(f, model.derived);
    write_provenance_attributes(f, prov);
    write_series_datasets(f, observers.column_specs(), outputs.series());
    observers.write_results(f);
    outputs.write_field_history(f);
  });
  outputs.write_field_history_sidecar(kResults);  // (after results.h5, which it points into)
  nlohmann::json sum = summary_head(model, sim, restarted_from);
  sum["provenance"] = provenance_json(prov);
  const SeriesColumns series = outputs.series();
  const bool plots = model.settings.output.plots;
  observers.finish(
      RunEnd{sim, series, dir, outputs.vtk(), plots, threads, wall.wall_s, wall.wall_s - wall.output_s, prov.ranks},
      sum);
  if (plots) add_plots(dir, sum);
  write_text_atomic(dir + "/" + kSummary, sum.dump(2) + "\n");
  std::string pictures;
  for (const char* key : {"pictures", "plots"})
    if (sum.contains(key))
      for (const auto& f : sum[key]) pictures += (pictures.empty() ? "" : ", ") + f.get<std::string>();
  // (the chip surface only when it was written: a run that ends before the chip forms has none)
  const bool surface = sum.contains("chip") && sum["chip"].contains("surface_file");
  say("\n  outputs in {}/: summary.json, series.csv, results.h5{}{}{}\n", dir,
      outputs.vtk() ? std::string(", results.xdmf (the frames as one series), particles.pvd (open in ParaView") +
                          (surface ? "; chip_surface.vtp)" : ")")
                    : "",
      outputs.checkpoints() ? ", checkpoint.h5" : "", pictures.empty() ? "" : "\n  pictures: " + pictures);
}

// A signal arrived: the step it interrupted is finished; a checkpoint keeps the place when
// checkpoints are on. No summary.json: the run did not complete (series.csv stays .part).
// (A run over ranks: the mirror holds the gathered state; rank 0 writes, 'outputs' is null on the others.)
[[noreturn]] void stop_interrupted(int signal, const std::string& dir, const Simulation& sim, RunOutputs* outputs) {
  const char* name = signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "a signal";
  std::string where = fmt::format("at t = {:.6g} s after step {}", sim.time(), sim.steps());
  if (!outputs) throw Interrupted(signal, fmt::format("interrupted by {} {}", name, where));
  if (outputs->checkpoints()) {
    outputs->write_checkpoint_now();
    where += fmt::format("; checkpoint written: continue with 'swarf run --restart {}/checkpoint.h5'", dir);
  } else {
    where += "; no checkpoint (output.checkpoint_every = 0): the run is lost";
  }
  throw Interrupted(signal, fmt::format("interrupted by {} {}", name, where));
}

// Under mpirun: the case must be one the domains run (else a clear error before anything is
// written), with nothing attached to the steps from outside.
void check_ranks(const RunOptions& opt, const Model& model) {
  if (!opt.comm) return;
  const std::string what = fmt::format("swarf run under mpirun with {} rank{}", opt.comm->size(),
                                       opt.comm->size() == 1 ? "" : "s");
  if (!opt.listeners.empty())
    throw InputError(what + ": listeners attached to the steps (co-simulation) need one process");
  try {
    DomainRun::check_supported(model, model.step);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", what, e.what()));
  }
}

}  // namespace

std::vector<RunFile> run_case_files() {
  return {{kSummary}, {kPlotSummary}, {kResults}, {kLog, RunFile::Keep::on_restart}};
}

void run_case(const RunOptions& opt) {
  // Under mpirun every rank runs this, and the first alone prints and writes.
  const bool root = !opt.comm || opt.comm->rank() == 0;
  if (!root) set_quiet(true);
  SetupAgreement agreement(opt.comm);  // (over ranks: every rank's setup done, or all stop)
  CheckpointCase stored;
  const CaseSettings cs = read_case(opt, stored);
  check_memory(cs, opt.force);
  Model model = build_model(cs);
  check_ranks(opt, model);
  double t_start = 0.0;        // s
  if (!opt.restart.empty()) {  // (before the run directory is touched)
    const double t = H5File(opt.restart, H5File::Mode::Read).read_double_attribute("time_s");
    if (model.settings.integrator.end_time < t)
      throw InputError(
          fmt::format("--restart {}: key 'integrator.end_time' = {:.6g} s lies before the "
                      "checkpoint's time {:.6g} s",
                      opt.restart, model.settings.integrator.end_time, t));
    t_start = t;
  }
  check_run_length(model, opt.allow_long, opt.force, t_start);
  const int threads = set_threads(opt.threads, opt.local_rank, opt.local_size);
  RunProvenance prov = run_provenance(threads);
  prov.ranks = opt.comm ? opt.comm->size() : 1;
  print_setup(model, threads);
  if (const std::string w = thread_placement_warning(threads); !w.empty()) say("  {}\n", w);
  const std::string partition = !opt.partition.empty() ? opt.partition : ZoltanRcb::available() ? "rcb" : "slabs";
  if (opt.comm && prov.ranks > 1)
    say("  ranks {} (one run by domain decomposition: {}, made anew every {} steps; rank 0 writes the outputs)\n",
        prov.ranks, partition == "rcb" ? "boxes by Zoltan's recursive coordinate bisection" : "slabs along x",
        opt.rebalance_every);
  else if (opt.comm)
    say("  ranks 1 (one domain: the domain decomposition's path on one rank)\n");
  if (opt.check) {
    agreement.passed();
    say("\n  --check: the case builds; nothing was run and nothing was written\n");
    return;
  }
  std::string dir;
  if (root) {
    dir = prepare_run_directory(opt);
    // DIR/run.log: what this run prints (a restart appends to the log of the run it continues).
    if (!open_transcript(dir + "/" + kLog, !opt.restart.empty()))
      eprint("swarf: warning: cannot write {}/run.log; the run goes on without a log\n", dir);
  }

  // Over ranks, this is the mirror of the whole run that rank 0's outputs read (run_ranks.h).
  Simulation sim(model, model.step);
  for (StepListener* l : opt.listeners) sim.add_listener(l);
  std::vector<std::unique_ptr<Observer>> observing = observers_for(model, opt.energy_check);
  auto exact_ledger = std::make_unique<ExactLedger>();  // (over ranks: the ledger's exact sums in checkpoints)
  ExactLedger& ledger = *exact_ledger;
  if (opt.comm) observing.push_back(std::move(exact_ledger));
  ObserverSet observers(sim, std::move(observing));
  std::unique_ptr<RunOutputs> outputs = root ? std::make_unique<RunOutputs>(dir, model, sim, observers, stored)
                                             : nullptr;
  // The ordered sites served the selections and the observers' setup, all done now; the
  // step and the outputs do not read them, and they are the size of the positions.
  std::vector<Vec3>().swap(model.sites);
  if (outputs && opt.restart.empty()) {
    outputs->begin();
  } else if (outputs) {
    outputs->restore(opt.restart);
  } else if (!opt.restart.empty()) {  // (another rank: the state only)
    RunRecord rec;
    read_checkpoint(opt.restart, sim, rec, nullptr);
  }
  std::fflush(stdout);
  agreement.passed();
  // (the slabs balanced anew every rebalance_every steps and checked for strays every
  // stray_check_every: each check is a collective, each migration rebuilds the domains, 37 ms
  // for the bar's 27,648 particles on 2 ranks; ownership never changes the bits)
  DomainSettings balance;
  balance.rebalance_every = static_cast<int>(opt.rebalance_every);
  balance.check_every = static_cast<int>(opt.stray_check_every);
  if (opt.comm && opt.comm->size() > 1 && partition == "rcb") balance.partitioner = std::make_shared<ZoltanRcb>();
  const std::unique_ptr<RankSteps> ranks = opt.comm ? std::make_unique<RankSteps>(
                                                          *opt.comm, sim, observers.step_listeners(), ledger, balance)
                                                    : nullptr;

  const double end_time = model.settings.integrator.end_time;  // s
  Progress progress(model.settings.output.progress && root, end_time);
  const double t_end = end_time * (1.0 - 1e-12);  // (a last step that lands within round-off of the end is the last)
  install_interrupt_handlers();
  if (!ranks) {
    while (sim.time() < t_end) {
      sim.step(end_time - sim.time());
      outputs->after_step(sim.time() >= t_end);
      progress.update(sim.time(), sim.steps());
      if (const int s = interrupt_signal(); s != 0) stop_interrupted(s, dir, sim, outputs.get());
    }
  } else {
    while (ranks->time() < t_end) {
      ranks->step(end_time - ranks->time());
      const bool last = ranks->time() >= t_end;
      const RankSteps::After a = ranks->agree(outputs && outputs->due(ranks->time(), ranks->steps(), last),
                                              interrupt_signal());
      if (a.output || a.signal != 0) ranks->gather();
      if (outputs && a.output) outputs->after_step(last);
      progress.update(ranks->time(), ranks->steps());
      if (a.signal != 0) stop_interrupted(a.signal, dir, sim, outputs.get());
    }
  }
  progress.done(sim.time(), sim.steps());
  if (ranks)
    if (const std::string cost = ranks->cost_report(); !cost.empty()) say("  {}\n", cost);
  if (outputs) finish_run(dir, model, sim, *outputs, observers, prov, opt.restart);
}

}  // namespace swarf
