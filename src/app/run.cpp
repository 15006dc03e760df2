// run.cpp: the run driver: case -> model -> time loop -> outputs (see run.h).
#include "app/run.h"
#include "swarf/version.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>

#include "io/atomic_file.h"
#include "io/checkpoint.h"
#include "io/h5file.h"
#include "app/post.h"
#include "postprocess/cut_report.h"
#include "swarf/core/errors.h"
#include "postprocess/hysteresis.h"
#include "app/plots.h"
#include "app/progress.h"
#include "app/run_directory.h"
#include "app/setup_report.h"
#include "io/series.h"
#include "setup/model.h"
#include "swarf/simulation.h"
#include "app/summary.h"
#include "io/vtk_output.h"

namespace swarf {

namespace {

double deviation_percent(double measured, double predicted) { return 100.0 * (measured - predicted) / predicted; }

// The uniaxial bar's loop against the rod-law prediction: summary "uniaxial" and the printed table.
void report_uniaxial(const Model& model, const RunRecord& rec, nlohmann::json& sum) {
  const UniaxialInfo& ux = model.uniaxial;
  const std::vector<int> segments(rec.s_segment.begin(), rec.s_segment.end());
  const Derived& d = model.derived;
  const double ey = std::isfinite(d.bar_yield_strain) ? d.bar_yield_strain : 1.0;
  const LoopMeasurement lm = analyze_loop(rec.s_strain, rec.s_stress, segments, ey);
  nlohmann::json u;
  u["axis"] = std::string(1, char('x' + ux.axis));
  u["gauge_length_m"] = ux.gauge_length;
  u["cross_section_m2"] = ux.cross_section;
  u["predicted"] = {{"youngs_modulus_Pa", d.youngs_modulus_100},
                    {"yield_stress_Pa", number(d.bar_yield_stress)},
                    {"yield_strain", number(d.bar_yield_strain)},
                    {"hardening_tangent_Pa", d.bar_hardening_tangent},
                    {"reverse_elastic_range_Pa", number(2.0 * d.bar_yield_stress)}};
  const double qs = rec.max_stress > 0 ? rec.max_mismatch / rec.max_stress : 0.0;
  u["quasi_static"] = {{"max_midplane_mismatch", qs},
                       {"note", "max over samples of |stress at the grips - stress through the mid-plane| / max |stress|: "
                                "0 for a static bar; inertia makes it grow with the strain rate"}};
  if (lm.ok) {
    u["measured"] = {{"youngs_modulus_Pa", lm.modulus},
                     {"yield_stress_Pa", lm.yield_stress},
                     {"yield_strain", lm.yield_strain},
                     {"hardening_tangent_Pa", lm.hardening_tangent}};
    u["deviation_percent"] = {{"youngs_modulus", deviation_percent(lm.modulus, d.youngs_modulus_100)},
                              {"yield_stress", deviation_percent(lm.yield_stress, d.bar_yield_stress)},
                              {"hardening_tangent", deviation_percent(lm.hardening_tangent, d.bar_hardening_tangent)}};
    if (lm.reverse_ok) {
      const double range = lm.turn_stress - lm.reverse_yield_stress;
      u["measured"]["turn_stress_Pa"] = lm.turn_stress;
      u["measured"]["reverse_yield_stress_Pa"] = lm.reverse_yield_stress;
      u["measured"]["reverse_elastic_range_Pa"] = range;
      u["deviation_percent"]["reverse_elastic_range"] = deviation_percent(range, 2.0 * d.bar_yield_stress);
    }
  }
  if (!lm.note.empty()) u["note"] = lm.note;
  sum["uniaxial"] = u;
  fmt::print("\n  uniaxial [100] bar          measured        predicted   deviation\n");
  if (lm.ok) {
    fmt::print("  Young's modulus   {:>14.5g} Pa {:>14.5g} Pa   {:+.2f} %\n", lm.modulus, d.youngs_modulus_100,
               deviation_percent(lm.modulus, d.youngs_modulus_100));
    fmt::print("  yield stress      {:>14.5g} Pa {:>14.5g} Pa   {:+.2f} %\n", lm.yield_stress, d.bar_yield_stress,
               deviation_percent(lm.yield_stress, d.bar_yield_stress));
    fmt::print("  hardening tangent {:>14.5g} Pa {:>14.5g} Pa   {:+.2f} %\n", lm.hardening_tangent,
               d.bar_hardening_tangent, deviation_percent(lm.hardening_tangent, d.bar_hardening_tangent));
    if (lm.reverse_ok)
      fmt::print("  reverse elastic range {:>10.5g} Pa {:>14.5g} Pa   {:+.2f} %  (Bauschinger)\n",
                 lm.turn_stress - lm.reverse_yield_stress, 2.0 * d.bar_yield_stress,
                 deviation_percent(lm.turn_stress - lm.reverse_yield_stress, 2.0 * d.bar_yield_stress));
  }
  if (!lm.note.empty()) fmt::print("  note: {}\n", lm.note);
  fmt::print("  quasi-static check: grip and mid-plane stress differ by at most {:.3g} of the peak stress\n", qs);
}

// The cut's setup at the start of the run (tool tip moves with the tool's mesh).
bool cut_setup(const Model& model, CutSetup& cs) {
  const auto& settings = model.settings;
  int tool = -1;
  for (std::size_t k = 0; k < settings.meshes.size() && tool < 0; ++k)
    if (settings.meshes[k].tool) tool = static_cast<int>(k);
  if (tool < 0 || model.lattice_particles == 0) return false;
  double lo = HUGE_VAL, hi = -HUGE_VAL, top = -HUGE_VAL;
  for (std::size_t i = 0; i < model.lattice_particles; ++i) {
    const Vec3& x0 = model.particles.initial_position[i];
    lo = std::min(lo, x0[1]);
    hi = std::max(hi, x0[1]);
    top = std::max(top, x0[2]);
  }
  const auto& ms = settings.meshes[tool];
  cs.tool_mesh = ms.name;
  cs.width = hi - lo + 0.5 * model.derived.cell_edge;
  cs.steady_from = settings.output.steady_from >= 0 ? settings.output.steady_from : 0.5 * settings.integrator.end_time;
  cs.tool_tip = Vec3(ms.origin[0], ms.origin[1], ms.origin[2]);
  cs.rake_angle_deg = ms.rake_angle;
  cs.face_length = ms.face_length;
  cs.uncut_surface_z = top;
  cs.radius = model.derived.radius;
  cs.lattice_particles = model.lattice_particles;
  return true;
}

int mesh_index(const Model& model, const std::string& name) {
  for (std::size_t k = 0; k < model.meshes.size(); ++k)
    if (model.meshes[k].name == name) return static_cast<int>(k);
  return -1;
}

}  // namespace

void run_case(const RunOptions& opt) {
  namespace fs = std::filesystem;
  const bool restarting = !opt.restart.empty();
  CheckpointCase stored;
  CaseSettings cs;
  if (restarting) {
    if (!opt.case_path.empty() || !opt.overrides.empty())
      throw InputError(fmt::format("--restart {}: a restart continues the checkpoint's own case; give no case file "
                                   "and no --set (got '{}'{})", opt.restart, opt.case_path,
                                   opt.overrides.empty() ? "" : " and --set " + opt.overrides.front()));
    stored = read_checkpoint_case(opt.restart);
    cs = parse_case(stored.toml, stored.source, stored.overrides, stored.directory);
  } else {
    cs = opt.case_path.empty() ? parse_case(kDefaultCaseToml, "<built-in default case>", opt.overrides)
                               : load_case(opt.case_path, opt.overrides);
    stored.toml = cs.text;
    stored.source = cs.source;
    stored.directory = cs.directory;
    stored.overrides = cs.overrides;
  }
  Model model = build_model(cs);
  const int threads = set_threads(opt.threads);
  print_setup(model, threads);

  const std::string dir = prepare_run_directory(opt);

  Simulation sim(model, model.step);
  RunRecord rec;
  const auto& settings = model.settings;
  const double end_time = settings.integrator.end_time;
  const double series_interval = settings.output.series_interval > 0 ? settings.output.series_interval : end_time / 2000;
  const double frame_interval = settings.output.frame_interval;

  const UniaxialInfo& ux = model.uniaxial;
  std::vector<std::string> cols{"time"};
  if (ux.enabled) cols.insert(cols.end(), {"strain", "stress", "stress_predicted", "stress_midplane"});
  cols.insert(cols.end(), {"step", "dt", "iterations", "kinetic_energy", "rotational_energy", "elastic_energy",
                           "contact_energy", "contact_work", "potential_energy",
                           "external_work", "plastic_work", "viscous_work", "fracture_energy", "energy_error",
                           "broken_rods", "broken_fraction", "contacts"});
  for (const auto& g : model.groups)
    for (char c : {'x', 'y', 'z'}) cols.push_back(fmt::format("reaction_{}_{}", g.name, c));
  for (const auto& mb : model.meshes)
    for (char c : {'x', 'y', 'z'}) cols.push_back(fmt::format("force_{}_{}", mb.name, c));
  // The first generated tool: cutting force Fc (against the cutting direction +x of the tool
  // frame) and thrust force Ft (+z, away from the workpiece), per unit width of the workpiece.
  CutSetup cut;
  const bool cutting = cut_setup(model, cut);
  const int tool_mesh = cutting ? mesh_index(model, cut.tool_mesh) : -1;
  if (cutting)
    cols.insert(cols.end(), {"tool_travel", "cutting_force_per_width", "thrust_force_per_width", "chip_thickness"});
  // The chip's thickness at a row (m; 0 when fewer than 10 chip particles have left the edge region).
  auto chip_thickness_now = [&]() {
    const auto& x = model.particles.position;
    // (cut.tool_tip: the tip at the start; it moves with the tool's mesh)
    return measure_chip(chip_input(cut, std::vector<Vec3>(x.begin(), x.begin() + cut.lattice_particles),
                                   cut.tool_tip + model.meshes[tool_mesh].offset))
        .thickness;
  };
  rec.columns = cols.size();

  BarPrediction prediction(model.derived.law, model.derived.bar_stress_factor);
  std::vector<double> path_times;
  if (ux.enabled) path_times = model.groups[ux.grip_max].motion.time;
  auto bar_strain = [&](double t) {
    const auto& gmin = model.groups[ux.grip_min].motion;
    const auto& gmax = model.groups[ux.grip_max].motion;
    return (gmax.displacement_at(t)[ux.axis] - gmin.displacement_at(t)[ux.axis]) / ux.gauge_length;
  };
  auto bar_stress = [&]() {
    return 0.5 * (sim.group_reaction(ux.grip_max)[ux.axis] - sim.group_reaction(ux.grip_min)[ux.axis]) /
           ux.cross_section;
  };
  auto midplane_stress = [&]() {
    double f = 0.0;
    const auto& x = model.particles.position;
    for (const auto& [rod, sign] : ux.midplane_rods) {
      const auto [i, j] = model.rods.ends[rod];
      f += sign * model.rods.force_coef[rod] * (x[j][ux.axis] - x[i][ux.axis]);
    }
    return f / ux.cross_section;
  };

  const double total_rods = std::max<double>(1.0, double(model.rods.size()));
  std::unique_ptr<SeriesWriter> series;
  auto write_row = [&]() {
    std::vector<double> row{sim.time()};
    if (ux.enabled) {
      const double e = bar_strain(sim.time()), s = bar_stress(), s_mid = midplane_stress();
      row.insert(row.end(), {e, s, rec.predicted, s_mid});
      int seg = 0;
      while (seg + 2 < int(path_times.size()) && sim.time() > path_times[seg + 1]) ++seg;
      rec.s_strain.push_back(e);
      rec.s_stress.push_back(s);
      rec.s_segment.push_back(seg);
      rec.max_stress = std::max(rec.max_stress, std::abs(s));
      rec.max_mismatch = std::max(rec.max_mismatch, std::abs(s - s_mid));
    }
    const double ke = sim.kinetic_energy(), ee = sim.elastic_energy(), pe = sim.potential_energy();
    const auto& L = sim.ledger();
    const double err =
        L.external_work - (ke + ee + pe - rec.e0 + L.plastic_work + L.viscous_work + L.fracture_energy + L.contact_work);
    row.insert(row.end(), {double(sim.steps()), sim.last_dt(), double(sim.stats().last_iterations), ke,
                           sim.rotational_energy(), ee, sim.contact_energy(), L.contact_work, pe,
                           L.external_work, L.plastic_work, L.viscous_work, L.fracture_energy, err,
                           double(sim.broken_rods()), double(sim.broken_rods()) / total_rods,
                           double(sim.contacts().enabled() ? sim.contacts().touching() : 0)});
    for (std::size_t g = 0; g < model.groups.size(); ++g)
      for (int c = 0; c < 3; ++c) row.push_back(sim.group_reaction(g)[c]);
    for (std::size_t k = 0; k < model.meshes.size(); ++k)
      for (int c = 0; c < 3; ++c) row.push_back(sim.mesh_force(k)[c]);
    if (cutting) {
      const Vec3 f = sim.mesh_force(tool_mesh);
      row.push_back(model.meshes[tool_mesh].offset[0]);
      row.push_back(-f[0] / cut.width);
      row.push_back(f[2] / cut.width);
      row.push_back(chip_thickness_now());
    }
    series->row(row);
    rec.rows.insert(rec.rows.end(), row.begin(), row.end());
  };

  std::unique_ptr<VtkSeries> vtk;
  if (settings.output.vtk) vtk = std::make_unique<VtkSeries>(dir, settings.output.rods_in_vtk, settings.output.orientations);
  if (vtk) vtk->set_periodic(model.periodic);
  series = std::make_unique<SeriesWriter>(dir + "/series.csv", cols);
  if (restarting) {
    read_checkpoint(opt.restart, sim, rec);
    if (rec.columns != cols.size())
      throw InputError(fmt::format("--restart {}: the checkpoint's series has {} columns, this case {}", opt.restart,
                                   rec.columns, cols.size()));
    for (std::size_t r = 0; r * rec.columns < rec.rows.size(); ++r)
      series->row(std::vector<double>(rec.rows.begin() + r * rec.columns, rec.rows.begin() + (r + 1) * rec.columns));
    prediction.set_state(rec.bar_shift, rec.bar_broken != 0.0);
    if (vtk) {
      vtk->resume(rec.frame_times);
      carry_frames(fs::path(opt.restart).parent_path(), dir, rec.frame_times.size());
    }
    fmt::print("  restarted from {} at t = {:.6g} s, step {} ({} series rows, {} frames)\n", opt.restart, sim.time(),
               sim.steps(), rec.rows.size() / rec.columns, rec.frame_times.size());
  } else {
    // The balance counts changes from the initial state (free particles may start moving).
    rec.e0 = sim.kinetic_energy() + sim.elastic_energy() + sim.potential_energy();
    write_row();
    if (vtk) vtk->write_frame(0.0, model.particles, model.rods, model.meshes);
    rec.next_row = series_interval;
    rec.next_frame = frame_interval > 0 ? frame_interval : HUGE_VAL;
  }
  std::fflush(stdout);

  Progress progress(settings.output.progress, end_time);
  const auto t0 = std::chrono::steady_clock::now();
  const double wall_before = rec.wall_s, output_before = rec.output_s;
  double output_seconds = output_before;
  const int checkpoint_every = settings.output.checkpoint_every;
  const std::string checkpoint_path = dir + "/checkpoint.h5";
  // Rows and frames are written at the first step that reaches each output time.
  const double t_end = end_time * (1.0 - 1e-12);
  while (sim.time() < t_end) {
    sim.step(end_time - sim.time());
    if (ux.enabled) rec.predicted = prediction.stress(bar_strain(sim.time()));
    const bool last = sim.time() >= t_end;
    const bool row = sim.time() >= rec.next_row * (1.0 - 1e-12) || last;
    const bool frame = vtk && (sim.time() >= rec.next_frame * (1.0 - 1e-12) || last);
    const bool checkpoint = checkpoint_every > 0 && !last && sim.steps() % checkpoint_every == 0;
    if (row || frame || checkpoint) {
      const auto o0 = std::chrono::steady_clock::now();
      if (row) write_row();
      if (frame) vtk->write_frame(sim.time(), model.particles, model.rods, model.meshes);
      while (rec.next_row <= sim.time() * (1.0 + 1e-12)) rec.next_row += series_interval;
      while (rec.next_frame <= sim.time() * (1.0 + 1e-12)) rec.next_frame += frame_interval;
      if (checkpoint) {
        rec.bar_shift = prediction.shift();
        rec.bar_broken = prediction.broken() ? 1.0 : 0.0;
        if (vtk) rec.frame_times = vtk->times();
        rec.wall_s = wall_before + std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        rec.output_s = output_seconds;
        write_checkpoint(checkpoint_path, sim, rec, stored);
      }
      output_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - o0).count();
    }
    progress.update(sim.time(), sim.steps());
  }
  progress.done(sim.time(), sim.steps());
  const double wall = wall_before + std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double step_seconds = wall - output_seconds;
  series->finish();
  if (cutting) cut.tool_tip += model.meshes[tool_mesh].offset;
  write_results_h5(dir + "/results.h5", sim, [&](H5File& f) {
    if (cutting) write_cut_setup(f, cut);
  });

  // Summary.
  nlohmann::json sum;
  sum["swarf_version"] = SWARF_VERSION;
  sum["status"] = "completed";
  // 64-bit hash of the final state (Simulation::state_hash, every field bit for bit): two runs
  // ended in the same state if and only if (up to collisions) their hashes agree.
  sum["state_hash"] = fmt::format("{:016x}", sim.state_hash());
  sum["case_file"] = settings.source;
  sum["overrides"] = settings.overrides;
  if (restarting) sum["restarted_from"] = opt.restart;
  sum["case"] = case_to_json(settings);
  sum["derived"] = derived_to_json(model.derived);
  sum["counts"] = {{"particles", model.particles.size()}, {"rods", model.rods.size()}, {"groups", model.groups.size()}};
  for (const auto& g : model.groups) sum["counts"]["group_" + g.name] = g.members.size();
  const auto& L = sim.ledger();
  const double ke = sim.kinetic_energy(), ee = sim.elastic_energy(), pe = sim.potential_energy();
  const StepStats& st = sim.stats();
  sum["run"] = {{"threads", threads},
                {"scheme", sim.implicit() ? "newmark" : "verlet"},
                {"steps", sim.steps()},
                {"steps_rejected", st.rejected},
                {"iterations_per_step_mean", double(st.iterations) / double(std::max<std::int64_t>(1, st.accepted))},
                {"iterations_per_step_max", st.max_iterations},
                {"force_evaluations", st.force_evaluations},
                {"force_evaluations_per_us", double(st.force_evaluations) / (sim.time() * 1e6)},
                {"dt_last_s", sim.last_dt()},
                {"simulated_time_s", sim.time()},
                {"end_time_s", end_time},
                {"wall_time_s", wall},
                {"step_wall_time_s", step_seconds},
                {"ns_per_particle_step", step_seconds * 1e9 / (double(sim.steps()) * double(model.particles.size()))}};
  const double energy_error =
      L.external_work - (ke + ee + pe - rec.e0 + L.plastic_work + L.viscous_work + L.fracture_energy + L.contact_work);
  sum["results"] = {{"kinetic_energy_J", ke},
                    {"elastic_energy_J", ee},
                    {"external_work_J", L.external_work},
                    {"plastic_work_J", L.plastic_work},
                    {"viscous_work_J", L.viscous_work},
                    {"fracture_energy_J", L.fracture_energy},
                    {"potential_energy_J", pe},
                    {"contact_energy_J", sim.contact_energy()},
                    {"contact_work_J", L.contact_work},
                    {"energy_error_J", energy_error},
                    {"broken_rods", sim.broken_rods()},
                    {"broken_fraction", double(sim.broken_rods()) / total_rods}};
  for (std::size_t g = 0; g < model.groups.size(); ++g) {
    const Vec3 r = sim.group_reaction(g);
    sum["results"]["reaction_" + model.groups[g].name + "_N"] = {r[0], r[1], r[2]};
  }
  if (ux.enabled) report_uniaxial(model, rec, sum);
  fmt::print("\n  {} steps ({}), simulated {:.4g} s, wall {:.2f} s ({:.1f} ns per particle-step, {} threads)\n",
             sim.steps(), sim.implicit() ? "newmark" : "verlet", sim.time(), wall,
             step_seconds * 1e9 / (double(sim.steps()) * double(model.particles.size())), threads);
  if (sim.implicit())
    fmt::print("  newmark: {} steps rejected, sweeps per step mean {:.2f} max {}, {:.4g} force evaluations per us\n",
               st.rejected, double(st.iterations) / double(std::max<std::int64_t>(1, st.accepted)), st.max_iterations,
               double(st.force_evaluations) / (sim.time() * 1e6));
  fmt::print("  broken rods {} of {} ({:.4g} %), energy error {:.3g} J of external work {:.4g} J\n", sim.broken_rods(),
             model.rods.size(), 100.0 * sim.broken_rods() / total_rods, energy_error, L.external_work);

  if (cutting) {
    CutData data;
    const std::size_t cc = rec.columns;
    for (std::size_t r = 0; r * cc < rec.rows.size(); ++r) {
      data.time.push_back(rec.rows[r * cc]);
      data.fc.push_back(rec.rows[r * cc + cc - 3]);
      data.ft.push_back(rec.rows[r * cc + cc - 2]);
      data.chip_thickness.push_back(rec.rows[r * cc + cc - 1]);
    }
    const auto bf = broken_fraction_per_particle(model.particles, model.rods);
    data.position.assign(model.particles.position.begin(), model.particles.position.begin() + cut.lattice_particles);
    data.broken_fraction.assign(bf.begin(), bf.begin() + cut.lattice_particles);
    data.broken_rod_fraction = double(sim.broken_rods()) / total_rods;
    finish_cut(dir, cut, data, sum, vtk.get(), settings.output.plots);
  }
  if (settings.output.plots) {
    // The summary must exist for the plot script; it is rewritten below with the plot list.
    write_text_atomic(dir + "/summary.json.plotting", sum.dump(2));
    const PlotResult pr = make_plots(dir, dir + "/summary.json.plotting");
    fs::remove(dir + "/summary.json.plotting");
    sum["plots"] = pr.files;
    if (!pr.ok) {
      sum["plot_error"] = pr.message;
      fmt::print(stderr, "swarf: warning: plots not written: {}\n", pr.message);
    }
  }
  write_text_atomic(dir + "/summary.json", sum.dump(2) + "\n");
  std::string pictures;
  for (const char* key : {"pictures", "plots"})
    if (sum.contains(key))
      for (const auto& f : sum[key]) pictures += (pictures.empty() ? "" : ", ") + f.get<std::string>();
  fmt::print("\n  outputs in {}/: summary.json, series.csv, results.h5{}{}{}\n", dir,
             vtk ? std::string(", particles.pvd (open in ParaView") + (cutting ? "; chip_surface.vtp)" : ")") : "",
             checkpoint_every > 0 ? ", checkpoint.h5" : "",
             pictures.empty() ? "" : "\n  pictures: " + pictures);
}

}  // namespace swarf
