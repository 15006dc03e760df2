// uniaxial_probe.cpp: the uniaxial bar against the rod law (see uniaxial_probe.h).
#include "app/observers/uniaxial_probe.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "app/summary.h"
#include "io/console.h"
#include "setup/model.h"
#include "swarf/simulation.h"

namespace swarf {
namespace {

double deviation_percent(double measured, double predicted) { return 100.0 * (measured - predicted) / predicted; }

// The uniaxial part of summary.json: geometry, prediction, the quasi-static check ('qs', 1)
// and, when the loop could be fitted, the measurement and its deviations.
nlohmann::json uniaxial_json(const UniaxialInfo& ux, const Derived& d, const LoopMeasurement& lm, double qs) {
  nlohmann::json u;
  u["axis"] = std::string(1, char('x' + ux.axis));
  u["gauge_length_m"] = ux.gauge_length;
  u["cross_section_m2"] = ux.cross_section;
  u["predicted"] = {{"youngs_modulus_Pa", d.youngs_modulus_100},
                    {"yield_stress_Pa", number(d.bar_yield_stress)},
                    {"yield_strain", number(d.bar_yield_strain)},
                    {"hardening_tangent_Pa", d.bar_hardening_tangent},
                    {"reverse_elastic_range_Pa", number(2.0 * d.bar_yield_stress)}};
  u["quasi_static"] = {{"max_midplane_mismatch", qs},
                       {"note",
                        "max over samples of |stress at the grips - stress through the mid-plane| / max |stress|: "
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
  return u;
}

void print_table(const Derived& d, const LoopMeasurement& lm, double qs) {
  say("\n  uniaxial [100] bar          measured        predicted   deviation\n");
  if (lm.ok) {
    say("  Young's modulus   {:>14.5g} Pa {:>14.5g} Pa   {:+.2f} %\n", lm.modulus, d.youngs_modulus_100,
        deviation_percent(lm.modulus, d.youngs_modulus_100));
    say("  yield stress      {:>14.5g} Pa {:>14.5g} Pa   {:+.2f} %\n", lm.yield_stress, d.bar_yield_stress,
        deviation_percent(lm.yield_stress, d.bar_yield_stress));
    say("  hardening tangent {:>14.5g} Pa {:>14.5g} Pa   {:+.2f} %\n", lm.hardening_tangent, d.bar_hardening_tangent,
        deviation_percent(lm.hardening_tangent, d.bar_hardening_tangent));
    if (lm.reverse_ok)
      say("  reverse elastic range {:>10.5g} Pa {:>14.5g} Pa   {:+.2f} %  (Bauschinger)\n",
          lm.turn_stress - lm.reverse_yield_stress, 2.0 * d.bar_yield_stress,
          deviation_percent(lm.turn_stress - lm.reverse_yield_stress, 2.0 * d.bar_yield_stress));
  }
  if (!lm.note.empty()) say("  note: {}\n", lm.note);
  say("  quasi-static check: grip and mid-plane stress differ by at most {:.3g} of the peak stress\n", qs);
}

}  // namespace

UniaxialProbe::UniaxialProbe(const Model& model)
    : model_(model), prediction_(model.derived.law, model.derived.bar_stress_factor) {}

double UniaxialProbe::bar_strain(double t) const {
  const UniaxialInfo& ux = model_.uniaxial;
  const auto& gmin = model_.groups[ux.grip_min].motion;
  const auto& gmax = model_.groups[ux.grip_max].motion;
  return (gmax.displacement_at(t)[ux.axis] - gmin.displacement_at(t)[ux.axis]) / ux.gauge_length;
}

double UniaxialProbe::bar_stress(const Simulation& sim) const {
  const UniaxialInfo& ux = model_.uniaxial;
  return 0.5 * (sim.group_reaction(ux.grip_max)[ux.axis] - sim.group_reaction(ux.grip_min)[ux.axis]) / ux.cross_section;
}

double UniaxialProbe::midplane_stress() const {
  const UniaxialInfo& ux = model_.uniaxial;
  double f = 0.0;
  const auto& x = model_.particles.position;
  for (const auto& [rod, sign] : ux.midplane_rods) {
    const auto [i, j] = model_.rods.ends[rod];
    f += sign * model_.rods.force_coef[rod] * (x[j][ux.axis] - x[i][ux.axis]);
  }
  return f / ux.cross_section;
}

int UniaxialProbe::segment_at(double t) const {
  const std::vector<double>& path_times = model_.groups[model_.uniaxial.grip_max].motion.time;
  int seg = 0;
  while (seg + 2 < int(path_times.size()) && t > path_times[seg + 1]) ++seg;
  return seg;
}

void UniaxialProbe::columns(std::vector<Column>& out) const {
  out.insert(out.end(), {{"strain", "1", "nominal bar strain from the grips' motion"},
                         {"stress", "Pa", "nominal bar stress from the grips' reactions, positive in tension"},
                         {"stress_predicted", "Pa", "the rod law through the FCC relations, without viscosity"},
                         {"stress_midplane", "Pa", "axial force of the rods crossing the mid-plane over A_0"}});
}

void UniaxialProbe::row(const Simulation& sim, std::vector<double>& values) {
  values.insert(values.end(), {bar_strain(sim.time()), bar_stress(sim), predicted_, midplane_stress()});
}

void UniaxialProbe::after_step(Simulation& sim) { predicted_ = prediction_.stress(bar_strain(sim.time())); }

void UniaxialProbe::visit_state(StateArchive& ar) {
  double shift = prediction_.shift();
  bool broken = prediction_.broken();
  ar.scalar("stress_predicted_Pa", predicted_);
  ar.scalar("prediction_plastic_shift", shift);
  ar.scalar("prediction_broken", broken);
  if (ar.loading()) prediction_.set_state(shift, broken);
}

void UniaxialProbe::finish(const RunEnd& end, nlohmann::json& summary) {
  // The loop's samples are the series rows (restored ones too), by column name.
  const std::vector<double> time = end.series["time"], strain = end.series["strain"], stress = end.series["stress"],
                            midplane = end.series["stress_midplane"];
  std::vector<int> segments;
  double max_stress = 0, max_mismatch = 0;  // Pa
  for (std::size_t r = 0; r < time.size(); ++r) {
    segments.push_back(segment_at(time[r]));
    max_stress = std::max(max_stress, std::abs(stress[r]));
    max_mismatch = std::max(max_mismatch, std::abs(stress[r] - midplane[r]));
  }
  const Derived& d = model_.derived;
  const double ey = std::isfinite(d.bar_yield_strain) ? d.bar_yield_strain : 1.0;
  const LoopMeasurement lm = analyze_loop(strain, stress, segments, ey);
  const double qs = max_stress > 0 ? max_mismatch / max_stress : 0.0;
  summary["uniaxial"] = uniaxial_json(model_.uniaxial, d, lm, qs);
  print_table(d, lm, qs);
}

}  // namespace swarf
