// summary.cpp: JSON and HDF5 result writers (see summary.h).
#include "app/summary.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include "app/case_echo.h"
#include "io/atomic_file.h"
#include "io/h5file.h"
#include "io/output_fields.h"
#include "io/results_format.h"
#include "io/vtk_output.h"
#include "setup/case_keys.h"
#include "setup/model.h"
#include "swarf/measure/particle_fields.h"
#include "swarf/version.h"

namespace swarf {
namespace {
constexpr std::size_t kFieldStrip = 65536;  // particles per strip of a results.h5 field (3 MB of tensors)
}  // namespace

nlohmann::json number(double v) {
  if (std::isfinite(v)) return v;
  if (std::isnan(v)) return "nan";
  return v > 0 ? "inf" : "-inf";
}

nlohmann::json rod_law_to_json(const AnyRodLaw& law, const std::string& prefix) {
  // The units a law's parameters carry, as key suffixes (study_table.cpp reads them back).
  static const std::map<std::string, std::string> suffix{
      {"1", ""}, {"Pa", "_Pa"}, {"Pa s", "_Pa_s"}, {"1/s", "_per_s"}, {"K", "_K"}};
  const RodLawDescription d = describe(law);
  nlohmann::json j{{prefix + "law", d.name}};
  for (const LawParameter& p : d.parameters) {
    const std::string key = prefix + p.name + suffix.at(p.unit);
    if (!p.table) {
      j[key] = number(p.values[0]);
      continue;
    }
    j[key] = nlohmann::json::array();
    for (double v : p.values) j[key].push_back(number(v));
  }
  return j;
}

nlohmann::json derived_to_json(const Derived& d) {
  nlohmann::json j{
      {"radius_m", d.radius},
      {"nn_distance_m", d.nn_distance},
      {"cell_edge_m", d.cell_edge},
      {"particle_mass_kg", d.particle_mass},
      {"bulk_density_kg_per_m3", d.bulk_density},
      {"rod_area_m2", d.rod_area},
      {"rod_stiffness_N_per_m", d.rod_stiffness},
      {"rod_law_from_material", d.converted},
      {"calibration_shear_mismatch", d.calibration_mismatch},
      {"calibration_shear_points_reached", d.calibration_points},
      {"rod_damping_N_s_per_m", d.rod_damping},
      {"rod_viscosity_Pa_s", d.rod_viscosity},
      {"omega_max_rad_per_s", d.omega_max},
      {"disorder_seed", d.disorder_seed},
      {"position_jitter", d.position_jitter},
      {"position_jitter_m", d.position_jitter * d.radius},
      {"rod_stiffness_max_N_per_m", d.rod_stiffness_max},
      {"dt_stable_s", number(d.dt_stable)},
      {"dt_s", d.dt},
      {"scheme", d.implicit ? "newmark" : "verlet"},
      {"dt_min_s", d.implicit ? nlohmann::json(d.dt_min) : nlohmann::json(nullptr)},
      {"dt_max_s", d.implicit ? nlohmann::json(d.dt_max) : nlohmann::json(nullptr)},
      {"wave_speed_100_m_per_s", d.wave_speed},
      {"rayleigh_time_s", d.rayleigh_time},
      {"C11_Pa", d.c11},
      {"C12_Pa", d.c12},
      {"C44_Pa", d.c12},
      {"youngs_modulus_100_Pa", d.youngs_modulus_100},
      {"poisson_ratio_100", d.poisson_ratio_100},
      {"youngs_modulus_voigt_Pa", d.youngs_modulus_voigt},
      {"bar_yield_strain", number(d.bar_yield_strain)},
      {"bar_yield_stress_Pa", number(d.bar_yield_stress)},
      {"bar_hardening_tangent_Pa", d.bar_hardening_tangent},
      {"bar_failure_stress_Pa", number(d.bar_failure_stress)},
      {"membrane", d.membrane},
      {"membrane_modulus_2d_N_per_m", d.membrane_modulus_2d},
      {"membrane_areal_density_kg_per_m2", d.membrane_areal_density},
      {"membrane_tension_N_per_m", d.membrane_tension},
      {"membrane_pre_strain", d.membrane_pre_strain},
      {"membrane_wave_longitudinal_m_per_s", d.membrane_wave_longitudinal},
      {"membrane_wave_shear_m_per_s", d.membrane_wave_shear},
      {"membrane_wave_transverse_m_per_s", d.membrane_wave_transverse},
      {"membrane_dt_cfl_s", d.membrane_dt_cfl},
  };
  j.update(rod_law_to_json(d.law, "rod_"));  // (its viscosity is rod_viscosity_Pa_s above, the same number)
  return j;
}

nlohmann::json summary_head(const Model& model, const Simulation& sim, const std::string& restarted_from) {
  const CaseSettings& settings = model.settings;
  nlohmann::json sum;
  sum["swarf_version"] = SWARF_VERSION;
  sum["status"] = "completed";
  // 64-bit hash of the final state (Simulation::state_hash, every field bit for bit): two runs
  // ended in the same state if and only if (up to collisions) their hashes agree.
  sum["state_hash"] = fmt::format("{:016x}", sim.state_hash());
  sum["case_file"] = settings.source;
  sum["overrides"] = settings.overrides;
  if (!restarted_from.empty()) sum["restarted_from"] = restarted_from;
  sum["case"] = case_json(settings);
  sum["case_effective"] = case_effective_json(settings);
  sum["case_units"] = case_key_units();  // (every key's unit, from the key table)
  sum["derived"] = derived_to_json(model.derived);
  sum["counts"] = {{"particles", model.particles.size()}, {"rods", model.rods.size()}, {"groups", model.groups.size()}};
  for (const auto& g : model.groups) sum["counts"]["group_" + g.name] = g.members.size();
  return sum;
}

void write_disorder_attributes(H5File& f, const Derived& d) {
  f.write_attribute("disorder_seed", static_cast<double>(d.disorder_seed));  // (exact: seeds are below 2^31)
  f.write_attribute("position_jitter", d.position_jitter);
}

void write_results_h5(const std::string& path, const Simulation& sim, const std::vector<std::string>& fields,
                      const std::function<void(H5File&)>& extra) {
  const auto& p = sim.world().particles;
  const auto& r = sim.world().rods;
  const std::string tmp = path + ".part";
  {
    H5File f(tmp, H5File::Mode::Create);
    const std::size_t n = p.size(), m = r.size();
    // Each dataset with its unit and meaning (docs/outputs.md has the full definitions).
    auto put = [&f](const std::string& name, const auto* data, std::size_t rows, std::size_t cols,
                    const std::string& unit, const std::string& what) {
      f.write(name, data, rows, cols);
      f.describe(name, unit, what);
    };
    put("/particles/position", n ? p.position[0].data() : nullptr, n, 3, "m", "particle centre at the end");
    // The table's rows (io/output_fields.h): the chosen ones, and those results.h5 always holds.
    ParticleFields measured;
    if (needs_particle_fields(fields)) measured = particle_fields(p, r, sim.world().periodic, &sim.contacts());
    const FieldInput in{p, r, needs_particle_fields(fields) ? &measured : nullptr};
    for (const OutputField* field : output_fields_in_write_order()) {
      const bool chosen = field->choice == FieldChoice::Always || field->results_always ||
                          has_field(fields, field->name);
      if (!chosen || (field->results_with_heat && !sim.world().heat.enabled)) continue;
      // (in strips: a whole field's copy was up to 48 B per particle on top of the run's state)
      const std::string name = "/particles/" + std::string(field->name);
      f.write_strips(name, n, static_cast<std::size_t>(field->components), kFieldStrip,
                     [&](std::size_t b, std::size_t e, std::vector<double>& v) {
                       compute_output_field_rows(*field, in, b, e, v);
                     });
      f.describe(name, std::string(field->unit), std::string(field->description));
    }
    put("/particles/mass", p.mass.data(), n, 1, "kg", "particle mass");
    if (sim.settings().sphere_orientations) {
      put("/particles/orientation", n ? p.orientation[0].data() : nullptr, n, 4, "1",
          "unit quaternion [q0 (scalar), q1, q2, q3], body to world");
      put("/particles/angular_velocity", n ? p.omega[0].data() : nullptr, n, 3, "rad/s",
          "angular velocity, world frame");
    }
    put("/particles/group", p.group.data(), n, 1, "1",
        "index into /groups/name of the particle's prescribed group, -1 for none");
    put("/particles/id", p.id.data(), n, 1, "1", "the particle's stable id (its index when the run started)");
    std::vector<std::string> group_names;
    for (const auto& g : sim.world().groups) group_names.push_back(g.name);
    f.write_strings("/groups/name", group_names);
    f.describe("/groups/name", "", "group names; /particles/group indexes this list");
    put("/bonds/pairs", m ? r.ends[0].data() : nullptr, m, 2, "1", "the rod's two particles, rows of /particles");
    put("/bonds/rest_length", r.rest_length.data(), m, 1, "m", "the rod's length at rest");
    put("/bonds/plastic_shift", r.shift.data(), m, 1, "1",
        "shift eps0 of the rod's elastic range (kinematic hardening); plastic strain (E - k)/E eps0");
    f.write("/bonds/intact", r.intact.data(), m);
    f.describe("/bonds/intact", "1", "1 intact, 0 broken");
    // (Rods::formed is empty when bond formation is off: then no rod was formed)
    const std::vector<std::uint8_t> formed = r.formed.size() == m ? r.formed : std::vector<std::uint8_t>(m, 0);
    f.write("/bonds/formed", formed.data(), m);
    f.describe("/bonds/formed", "1",
               "1 for a rod formed during the run (bond formation), 0 for the lattice's own; the broken-rod "
               "fraction counts only the lattice's own rods");
    put("/bonds/stress", r.stress.data(), m, 1, "Pa", "axial stress of the rod, positive in tension");
    f.write_attribute("time_s", sim.time());
    f.write_attribute("steps", static_cast<double>(sim.steps()));
    f.write_attribute("generator", std::string("swarf ") + SWARF_VERSION);
    f.write_attribute("format", kResultsFormat);
    if (extra) extra(f);
    f.close();  // (a failed close throws: the .part file is never renamed into place)
  }
  commit_file(tmp, path);
}

}  // namespace swarf
