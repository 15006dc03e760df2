// material_lab.cpp: 'swarf material' (see material_lab.h).
//
// The rod law, cell edge and rod area come from the case through the setup code (build_model's
// Derived), so the lab tests exactly the lattice a run of that case would build. Each test is
// the homogeneous crystal of lattice_material.h; beside its curve the CSV carries the
// small-strain mapping of the test (the rod law scaled by the lattice relations, driven along
// the same path), which is what a calibration by those relations assumes.
#include "app/material_lab.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>

#include "app/plots.h"
#include "app/summary.h"
#include "io/atomic_file.h"
#include "io/console.h"
#include "lattice_gen/cauchy_born.h"
#include "lattice_gen/lattice_material.h"
#include "lattice_gen/material_summary.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "setup/rod_laws/rod_laws.h"
#include "swarf/core/errors.h"

namespace swarf {

namespace {

struct LabTest {
  const char* name;
  bool shear;
  std::array<double, 3> direction;  ///< loading direction, or the shear direction s
  std::array<double, 3> normal;     ///< shear plane normal m
  double default_to;                ///< end strain (magnitude) or cyclic amplitude
  double sign;                      ///< -1: compression
  bool cyclic;
  const char* what;
};

const std::vector<LabTest>& lab_tests() {
  static const std::vector<LabTest> tests{
      {"tension100", false, {1, 0, 0}, {}, 3.0, 1, false, "uniaxial tension along [100] to failure"},
      {"tension110", false, {1, 1, 0}, {}, 3.0, 1, false, "uniaxial tension along [110] to failure"},
      {"compression100", false, {1, 0, 0}, {}, 0.5, -1, false, "uniaxial compression along [100]"},
      {"shear100", true, {1, 0, 0}, {0, 0, 1}, 2.0, 1, false, "simple shear on the cube plane, s = [100], m = [001]"},
      {"shear45",
       true,
       {1, 0, 1},
       {-1, 0, 1},
       2.0,
       1,
       false,
       "simple shear on the 45-degree plane, s = [101]/sqrt2, m = [-101]/sqrt2"},
      {"cyclic100", false, {1, 0, 0}, {}, 0.02, 1, true, "cyclic uniaxial stress along [100], 0 -> A -> -A -> A"},
  };
  return tests;
}

nlohmann::json value(double v) {
  if (std::isnan(v)) return nullptr;  // not reached
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return v;
}

double ratio(double a, double b) { return std::isfinite(a) && std::isfinite(b) && b != 0 ? a / b : NAN; }

// The small-strain mapping of a test: sigma = factor * sigma_rod(r * strain), the rod driven
// along the test's path (committed per increment, like the lattice). docs/physics.md section 1 and
// the tests' comments: [100] factor 3 E100/E = 4 kb/(a E), r = 1/3; [110] E110/E = 2 kb/(a E),
// r = 1 (only the axial rod strains); cube shear 2 kb/(a E), r = 1/2; 45-degree shear
// 2 kb/(a E), r = 1/4.
std::vector<double> small_strain_mapping(const LabTest& t, const CauchyBornCrystal& c,
                                         const std::vector<MaterialPoint>& curve) {
  const AnyRodLaw& law = c.law();
  const double g = c.rod_stiffness() / (c.cell_edge() * elastic_modulus(law));
  double factor = 4 * g, r = 1.0 / 3.0;
  if (t.shear) {
    factor = 2 * g;
    r = t.normal[0] == 0 ? 0.5 : 0.25;
  } else if (t.direction[1] != 0) {
    factor = 2 * g;
    r = 1.0;
  }
  std::vector<double> out;
  double shift = 0;
  bool broken = false;
  for (const auto& p : curve) {
    double s = 0;
    if (!broken) {
      const RodResponse resp = evaluate(law, r * p.strain, 0.0, shift);
      broken = resp.broken;
      if (!broken) {
        shift = resp.shift;
        s = resp.stress;
      }
    }
    out.push_back(factor * s);
  }
  return out;
}

std::string curve_csv(const std::vector<MaterialPoint>& curve, const std::vector<double>& small, double l0,
                      double bulk_modulus) {
  std::string
      s = "strain_1,stress_Pa,equivalent_strain_1,equivalent_stress_Pa,plastic_strain_1,volume_ratio_1,mean_stress_Pa,"
          "sigma_11_Pa,sigma_22_Pa,sigma_33_Pa,sigma_23_Pa,sigma_13_Pa,sigma_12_Pa,"
          "F_11_1,F_12_1,F_13_1,F_21_1,F_22_1,F_23_1,F_31_1,F_32_1,F_33_1,"
          "broken_rods_1,closest_unbonded_m,closest_unbonded_over_2R_1,max_rod_strain_1,plastic_volume_strain_1,"
          "small_strain_stress_Pa\n";
  for (std::size_t i = 0; i < curve.size(); ++i) {
    const auto& p = curve[i];
    s += fmt::format("{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.12g},{:.10g}", p.strain, p.stress, p.equivalent_strain,
                     p.equivalent_stress, p.plastic_strain, p.volume_ratio, p.mean_stress);
    for (double v : p.sigma) s += fmt::format(",{:.10g}", v);
    for (double v : p.deformation) s += fmt::format(",{:.12g}", v);
    s += fmt::format(",{},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n", p.broken, p.closest_unbonded,
                     p.closest_unbonded / l0, p.max_rod_strain, std::log(p.volume_ratio) - p.mean_stress / bulk_modulus,
                     small[i]);
  }
  return s;
}

nlohmann::json summary_json(const LabTest& t, const std::vector<double>& path, double mode_modulus,
                            const CurveSummary& s, const std::vector<MaterialPoint>& curve,
                            const std::vector<double>& small) {
  nlohmann::json j;
  j["what"] = t.what;
  j["kind"] = t.shear ? "simple_shear" : "uniaxial";
  j["direction"] = t.direction;
  if (t.shear) j["normal"] = t.normal;
  j["path"] = path;
  j["points"] = curve.size();
  j["mode_modulus_Pa"] = mode_modulus;
  j["initial_modulus_Pa"] = value(s.initial_modulus);
  j["yield_stress_Pa"] = value(s.yield_stress);
  j["yield_test_stress_Pa"] = value(s.yield_test_stress);
  j["yield_strain"] = value(s.yield_strain);
  nlohmann::json flow, flow_test;
  for (std::size_t k = 0; k < kFlowPlasticStrains.size(); ++k) {
    const std::string key = fmt::format("{:g}", kFlowPlasticStrains[k]);
    flow[key] = value(s.flow_stress[k]);
    flow_test[key] = value(s.flow_test_stress[k]);
  }
  j["flow_stress_Pa"] = flow;
  j["flow_test_stress_Pa"] = flow_test;
  j["failed"] = s.failed;
  j["failure_strain"] = value(s.failure_strain);
  j["peak_equivalent_stress_Pa"] = s.peak_stress;
  j["peak_strain"] = s.peak_strain;
  j["end_strain"] = s.end_strain;
  j["end_volume_ratio"] = s.end_volume_ratio;
  j["end_plastic_volume_strain"] = s.end_plastic_volume_strain;
  j["contact_strain"] = value(s.contact_strain);
  j["collapsed"] = s.collapsed;
  if (!t.shear) j["poisson_ratios"] = {value(s.lateral_ratio[0]), value(s.lateral_ratio[1])};
  // The finite-strain curve over the small-strain mapping at given strains (monotonic tests).
  if (!t.cyclic) {
    nlohmann::json r;
    for (double e : {0.01, 0.1, 0.5, 1.0}) {
      const double target = t.sign * e;
      double v = NAN;
      for (std::size_t i = 1; i < curve.size(); ++i)
        if (std::abs(curve[i].strain) >= e && std::abs(curve[i - 1].strain) < e) {
          const double f = (target - curve[i - 1].strain) / (curve[i].strain - curve[i - 1].strain);
          v = ratio(curve[i - 1].stress + f * (curve[i].stress - curve[i - 1].stress),
                    small[i - 1] + f * (small[i] - small[i - 1]));
          break;
        }
      r[fmt::format("{:g}", e)] = value(v);
    }
    j["over_small_strain_mapping"] = r;
  }
  return j;
}

}  // namespace

std::vector<std::string> material_test_names() {
  std::vector<std::string> names;
  for (const auto& t : lab_tests()) names.push_back(t.name);
  return names;
}

int run_material(const MaterialOptions& o) {
  std::vector<const LabTest*> chosen;
  for (const auto& t : lab_tests())
    if (o.test == "all" || o.test == t.name) chosen.push_back(&t);
  if (chosen.empty()) {
    std::string names;
    for (const auto& n : material_test_names()) names += n + ", ";
    throw InputError(fmt::format("--test: unknown test '{}' (the tests: {}all)", o.test, names));
  }
  if (o.to_given && chosen.size() > 1)
    throw InputError("--to: give it with one --test; --test all runs each test to its own default end");
  if (o.to_given && !(o.to > 0 && o.to <= 10))
    throw InputError(fmt::format("--to: must be a strain magnitude in (0, 10], got {}", o.to));
  if (!(o.increment > 0 && o.increment <= 0.1))
    throw InputError(fmt::format("--increment: must be a strain step in (0, 0.1], got {}", o.increment));
  if (o.out_dir.empty()) throw InputError("--out: needs a directory");

  const CaseSettings cs = o.case_path.empty() ? parse_case(kDefaultCaseToml, "<built-in default case>", o.overrides)
                                              : load_case(o.case_path, o.overrides);
  const Model model = build_model(cs);
  const Derived& d = model.derived;
  if (model.rods.ends.empty()) throw InputError(cs.source + ": the case has no bonded workpiece to test");
  // A law that reads a temperature or a rate runs at fixed ones (setup/rod_laws/).
  const RodLawSetup& law_setup = rod_law_setup_of(d.law);
  const bool conditions = o.temperature != 0 || o.strain_rate != 0;
  if (conditions && !law_setup.at_conditions)
    throw InputError("--temperature, --strain-rate: need " + rod_laws_with_conditions());
  if (!(o.temperature >= 0 && o.temperature < 1e4))
    throw InputError(fmt::format("--temperature: must be a temperature in [0, 1e4) K, got {}", o.temperature));
  if (!(o.strain_rate >= 0 && std::isfinite(o.strain_rate)))
    throw InputError(fmt::format("--strain-rate: must be a rate >= 0 (1/s), got {}", o.strain_rate));
  std::optional<RodLawAtConditions> at;
  if (law_setup.at_conditions) at = law_setup.at_conditions(d.law, o.temperature, o.strain_rate);
  const AnyRodLaw law = at ? at->law : d.law;
  const CauchyBornCrystal crystal(law, d.cell_edge, d.rod_area);
  const auto C = crystal.elastic_constants();
  const double l0 = crystal.rest_length(), K = (C(0, 0) + 2 * C(0, 1)) / 3;
  const double e100 = directional_youngs_modulus(C, {1, 0, 0}), e110 = directional_youngs_modulus(C, {1, 1, 0});
  std::filesystem::create_directories(o.out_dir);

  nlohmann::json doc;
  doc["case"] = cs.source;
  doc["overrides"] = o.overrides;
  doc["increment"] = o.increment;
  doc["strain_rate_per_s"] = o.strain_rate;
  if (at)
    for (const auto& [key, value] : at->record) doc[key] = value;
  doc["rod_law"] = rod_law_to_json(d.law, "");
  doc["lattice"] = {{"cell_edge_m", d.cell_edge},
                    {"rest_length_m", l0},
                    {"rod_area_m2", d.rod_area},
                    {"rod_stiffness_N_per_m", crystal.rod_stiffness()},
                    {"C11_Pa", C(0, 0)},
                    {"C12_Pa", C(0, 1)},
                    {"C44_Pa", C(3, 3)},
                    {"bulk_modulus_Pa", K},
                    {"E100_Pa", e100},
                    {"E110_Pa", e110},
                    {"zener_ratio", 2 * C(3, 3) / (C(0, 0) - C(0, 1))}};

  std::map<std::string, std::vector<MaterialPoint>> curves;
  std::map<std::string, CurveSummary> sums;
  std::vector<std::string> names;
  for (const LabTest* t : chosen) {
    const double to = o.to_given ? o.to : t->default_to;
    std::vector<double> path{0.0, t->sign * to};
    if (t->cyclic) path = {0.0, to, -to, to};
    std::vector<MaterialPoint> curve;
    double mode = 0;
    if (t->shear) {
      curve = simple_shear_test(law, d.cell_edge, d.rod_area, t->direction, t->normal, to, o.increment);
      const Eigen::Vector3d s = Eigen::Vector3d(t->direction[0], t->direction[1], t->direction[2]).normalized();
      const Eigen::Vector3d m = Eigen::Vector3d(t->normal[0], t->normal[1], t->normal[2]).normalized();
      mode = 3 * simple_shear_modulus(C, s, m);
    } else {
      curve = uniaxial_test(law, d.cell_edge, d.rod_area, t->direction, path, o.increment);
      mode = directional_youngs_modulus(C, {t->direction[0], t->direction[1], t->direction[2]});
    }
    if (curve.size() > 1 && curve[1].plastic_strain > 1e-3 * curve[1].equivalent_strain)
      eprint(
          "swarf: warning: {}: the first increment already flows plastically: the initial modulus is a secant "
          "(lower --increment below the yield strain)\n",
          t->name);
    const auto small = small_strain_mapping(*t, crystal, curve);
    write_text_atomic(o.out_dir + "/" + t->name + ".csv", curve_csv(curve, small, l0, K));
    const CurveSummary s = summarize_curve(curve, l0, K, t->shear);
    doc["tests"][t->name] = summary_json(*t, path, mode, s, curve, small);
    curves[t->name] = curve;
    sums[t->name] = s;
    names.push_back(t->name);
  }

  // The anisotropy: ratios between orientations, and shear against tension at equal equivalent
  // plastic strain (von Mises: tau/sigma = 1/sqrt3 = 0.577; Tresca: 0.5).
  nlohmann::json an = nlohmann::json::object();
  auto has = [&](const char* n) { return sums.count(n) > 0; };
  std::vector<double> eps{kYieldOffset};
  eps.insert(eps.end(), kFlowPlasticStrains.begin(), kFlowPlasticStrains.end());
  if (has("tension100") && has("tension110")) {
    const auto &a = sums["tension100"], &b = sums["tension110"];
    an["E110_over_E100"] = value(ratio(b.initial_modulus, a.initial_modulus));
    an["yield_110_over_100"] = value(ratio(b.yield_stress, a.yield_stress));
    for (std::size_t k = 0; k < kFlowPlasticStrains.size(); ++k)
      an["flow_110_over_100"][fmt::format("{:g}", kFlowPlasticStrains[k])] = value(
          ratio(b.flow_stress[k], a.flow_stress[k]));
  }
  if (has("shear100") && has("shear45")) {
    an["zener_ratio"] = value(ratio(sums["shear100"].initial_modulus, sums["shear45"].initial_modulus));
    an["yield_shear45_over_shear100"] = value(ratio(sums["shear45"].yield_stress, sums["shear100"].yield_stress));
  }
  for (const char* sh : {"shear100", "shear45"})
    if (has(sh) && has("tension100"))
      for (double e : eps)
        an["tau_over_sigma"][sh][fmt::format("{:g}", e)] = value(ratio(
            stress_at_plastic_strain(curves[sh], e, false), stress_at_plastic_strain(curves["tension100"], e, false)));
  if (has("compression100") && has("tension100"))
    for (double e : eps)
      an["compression_over_tension_100"][fmt::format("{:g}", e)] = value(
          ratio(std::abs(stress_at_plastic_strain(curves["compression100"], e, false)),
                stress_at_plastic_strain(curves["tension100"], e, false)));
  doc["anisotropy"] = an;
  write_text_atomic(o.out_dir + "/material.json", doc.dump(2) + "\n");

  fmt::print(
      "material lab: {} (E_rod = {:.4g} Pa, a = {:.4g} m, A = {:.4g} m^2); lattice E100 = {:.4g} Pa, "
      "E110 = {:.4g} Pa, C44 = {:.4g} Pa\n",
      cs.source, elastic_modulus(d.law), d.cell_edge, d.rod_area, e100, e110, C(3, 3));
  if (at) fmt::print("{}", at->echo);
  fmt::print("{:<15} {:>10} {:>10} {:>10} {:>10} {:>10} {:>9} {:>9} {:>9}\n", "test", "E [GPa]", "yield", "flow0.1",
             "flow0.5", "flow1", "failure", "dV_p/V", "contact");
  fmt::print("{:<15} {:>10} {:>10} {:>10} {:>10} {:>10} {:>9} {:>9} {:>9}\n", "", "", "[MPa]", "[MPa]", "[MPa]",
             "[MPa]", "strain", "end", "strain");
  auto mpa = [](double v) { return std::isnan(v) ? std::string("-") : fmt::format("{:.1f}", v / 1e6); };
  auto num = [](double v) { return std::isnan(v) ? std::string("-") : fmt::format("{:.4g}", v); };
  for (const auto& n : names) {
    const auto& s = sums[n];
    fmt::print("{:<15} {:>10.2f} {:>10} {:>10} {:>10} {:>10} {:>9} {:>9} {:>9}\n", n, s.initial_modulus / 1e9,
               mpa(s.yield_stress), mpa(s.flow_stress[0]), mpa(s.flow_stress[1]), mpa(s.flow_stress[2]),
               num(s.failure_strain), num(s.end_plastic_volume_strain), num(s.contact_strain));
  }
  fmt::print(
      "(stresses: von Mises equivalents at equivalent plastic strain 0.002 (yield), 0.1, 0.5, 1; strains: the "
      "test's own)\n");

  std::vector<std::string> args{o.out_dir};
  args.insert(args.end(), names.begin(), names.end());
  const ScriptRun plot = run_postprocess_script("plot_material.py", args);
  if (!plot.ok) eprint("swarf: warning: the plots were not drawn: {}\n", plot.output.substr(0, 400));
  fmt::print("wrote {}/material.json and {} curves (CSV{})\n", o.out_dir, names.size(), plot.ok ? ", PNG" : "");
  return 0;
}

}  // namespace swarf
