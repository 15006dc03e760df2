// cut_probe.cpp: the orthogonal cut (see cut_probe.h).
#include "app/observers/cut_probe.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

#include "app/post.h"
#include "io/vtk_output.h"
#include "postprocess/chip.h"
#include "setup/material_presets.h"
#include "setup/model.h"
#include "swarf/simulation.h"

namespace swarf {

namespace {

// The work material for Oxley's reference (cut_oxley.h): the case's Johnson-Cook curve and
// factors, density and, from [heat] or the preset, heat capacity and conductivity.
CutMaterial cut_material(const CaseSettings& settings) {
  const MaterialSettings& mt = settings.material;
  CutMaterial m;
  // Hand-written rods name the material they stand for in material.reference.
  const std::string& name = mt.preset.empty() ? mt.reference : mt.preset;
  const MaterialPreset* preset = name.empty() ? nullptr : find_material_preset(name);
  const bool reference = !mt.reference.empty() && preset;
  if (!(mt.johnson_cook_a > 0) && !reference) {
    m.note =
        "the work material has no Johnson-Cook flow curve (material.preset, material.johnson_cook_* or, for "
        "hand-written rods, material.reference)";
    return m;
  }
  double c = settings.heat.present ? settings.heat.heat_capacity : 0.0;
  double k = settings.heat.present ? settings.heat.conductivity : 0.0;
  if (preset && !(c > 0)) c = preset->heat_capacity;
  if (preset && !(k > 0)) k = preset->conductivity;
  if (!(c > 0 && k > 0)) {
    m.note = "the work material's heat capacity and conductivity are not given ([heat] or material.preset)";
    return m;
  }
  m.known = true;
  m.name = reference                                      ? std::string(preset->name) + " (material.reference)"
           : preset && mt.johnson_cook_keys_given.empty() ? std::string(preset->name)
                                                          : "Johnson-Cook (case)";
  // Johnson-Cook's A, B, n, C, m, reference rate, T_ref, T_melt: the named material's for
  // hand-written rods, else the case's (which a preset has already filled).
  const std::array<double, 8> jc = reference
                                       ? std::array{preset->jc_a,
                                                    preset->jc_b,
                                                    preset->jc_n,
                                                    preset->jc_c,
                                                    preset->jc_m,
                                                    preset->reference_rate,
                                                    preset->reference_temperature,
                                                    preset->melt_temperature}
                                       : std::array{mt.johnson_cook_a,        mt.johnson_cook_b,  mt.johnson_cook_n,
                                                    mt.johnson_cook_c,        mt.johnson_cook_m,  mt.reference_rate,
                                                    mt.reference_temperature, mt.melt_temperature};
  OxleyMaterial& o = m.oxley;
  std::tie(o.jc_a, o.jc_b, o.jc_n, o.jc_c, o.jc_m, o.reference_strain_rate, o.t_ref, o.t_melt) = std::tuple_cat(jc);
  o.density = mt.density;
  o.heat_capacity = c;
  o.conductivity = k;
  m.initial_temperature = settings.heat.present ? settings.heat.initial_temperature : o.t_ref;
  return m;
}

// The tool's constant speed along x (m/s): "velocity" and the final velocity of "ramp"; 0 otherwise.
double cutting_speed(const MotionSettings& motion) {
  if (motion.kind != "velocity" && motion.kind != "ramp") return 0.0;
  return std::abs(motion.velocity[0]);
}

}  // namespace

std::unique_ptr<CutProbe> CutProbe::of(const Model& model) {
  const auto& settings = model.settings;
  int tool = -1;
  for (std::size_t k = 0; k < settings.meshes.size() && tool < 0; ++k)
    if (settings.meshes[k].tool) tool = static_cast<int>(k);
  if (tool < 0 || model.lattice_particles == 0) return nullptr;
  // The width and the uncut surface of the ordered lattice: a jittered block's extreme centres
  // stand up to jitter x R further out, a bias the same sign for every seed.
  double lo = HUGE_VAL, hi = -HUGE_VAL, top = -HUGE_VAL;  // m
  for (std::size_t i = 0; i < model.lattice_particles; ++i) {
    const Vec3& x0 = model.sites[i];
    lo = std::min(lo, x0[1]);
    hi = std::max(hi, x0[1]);
    top = std::max(top, x0[2]);
  }
  const auto& ms = settings.meshes[tool];
  CutSetup cs;
  cs.tool_mesh = ms.name;
  cs.width = hi - lo + 0.5 * model.derived.cell_edge;
  cs.steady_from = settings.output.steady_from >= 0 ? settings.output.steady_from : 0.5 * settings.integrator.end_time;
  cs.tool_tip = Vec3(ms.origin[0], ms.origin[1], ms.origin[2]);
  cs.rake_angle_deg = ms.rake_angle;
  cs.inclination_deg = ms.inclination_angle;
  cs.free_sides = !settings.workpiece.periodic_width;
  cs.side_y_lo = lo, cs.side_y_hi = hi;
  cs.face_length = ms.face_length;
  cs.uncut_surface_z = top;
  cs.radius = model.derived.radius;
  cs.lattice_particles = model.lattice_particles;
  cs.cutting_speed = cutting_speed(ms.motion);
  cs.material = cut_material(settings);
  // The World's mesh of that name (the case's [[mesh]] tables and the World's meshes meet by name).
  int mesh = -1;
  for (std::size_t k = 0; k < model.meshes.size() && mesh < 0; ++k)
    if (model.meshes[k].name == cs.tool_mesh) mesh = static_cast<int>(k);
  // A compliant tool: a rigid body on a spring along x and z to its holder.
  int body = -1;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const RigidBody& rb = model.bodies[b];
    if (static_cast<int>(rb.mesh) != mesh || !(rb.load.spring[0] > 0 && rb.load.spring[2] > 0)) continue;
    body = static_cast<int>(b);
    cs.mount = ToolMount{rb.load.spring[0] / cs.width, rb.load.spring[2] / cs.width, rb.mass / cs.width,
                         rb.load.force_damping / cs.width};
  }
  return std::make_unique<CutProbe>(model, cs, mesh, body);
}

Vec3 CutProbe::tool_tip() const { return setup_.tool_tip + model_.meshes[tool_mesh_].offset; }

CutSetup CutProbe::setup_now() const {
  CutSetup s = setup_;
  s.tool_tip = tool_tip();
  return s;
}

void CutProbe::columns(std::vector<Column>& out) const {
  out.insert(
      out.end(),
      {{"tool_travel", "m", "the tool's displacement along x from its initial placement"},
       {"cutting_force_per_width", "N/m", "cutting force Fc = -force_<tool>_x over the workpiece width"},
       {"thrust_force_per_width", "N/m", "thrust force Ft = force_<tool>_z over the workpiece width"},
       {"chip_thickness", "m",
        "chip thickness h_c at this row; 0 before the chip's head is h/2 past the section (2 h to 3 h up the face)"},
       {"contact_length", "m", "tool-chip contact length along the rake face (particles touching it)"}});
  if (setup_.free_sides)
    out.insert(out.end(),
               {{"passive_force_per_width", "N/m", "passive force Fp = force_<tool>_y over the workpiece width"},
                {"chip_flow_angle", "deg",
                 "eta_c: the chip's flow off the edge's normal in the rake face (Stabler: the inclination); 0 "
                 "before the chip reaches the section"},
                {"chip_width", "m", "the chip's width along the edge, h to 3 h up the face; 0 likewise"},
                {"cutting_force_per_width_middle", "N/m",
                 "Fc of the tool's contacts acting in the middle half of the width, over half the width: the force "
                 "away from the sides"},
                {"thrust_force_per_width_middle", "N/m", "Ft likewise"}});
  if (model_.heat.enabled)
    out.insert(out.end(), {{"chip_temperature", "K", "mean temperature of the chip particles; 0 without a chip"},
                           {"rake_face_temperature", "K",
                            "the hottest particle in the layer on the rake face (centres within 2 R of it)"}});
  if (tool_body_ >= 0)
    out.insert(out.end(), {{"tool_deflection_x", "m", "the compliant tool's centre minus its holder's anchor along x"},
                           {"tool_deflection_z", "m", "the compliant tool's centre minus its holder's anchor along z"}});
}

void CutProbe::row(const Simulation& sim, std::vector<double>& values) {
  const Vec3 f = sim.mesh_force(tool_mesh_);
  const auto& x = model_.particles.position;
  const std::vector<Vec3> workpiece(x.begin(), x.begin() + setup_.lattice_particles);
  const ChipInput in = chip_input(setup_, workpiece, tool_tip());
  const ChipMetrics chip = measure_chip(in);
  values.insert(values.end(), {model_.meshes[tool_mesh_].offset[0], -f[0] / setup_.width, f[2] / setup_.width,
                               chip.thickness, rake_contact_length(in)});
  if (setup_.free_sides) {
    // Velocities relative to the tool, in its frame (as the positions are).
    const Vec3 tool_v = model_.meshes[tool_mesh_].velocity;
    std::vector<Vec3> u(setup_.lattice_particles);
    for (std::size_t i = 0; i < u.size(); ++i)
      u[i] = to_tool_frame(model_.particles.velocity[i] - tool_v, setup_.inclination_deg);
    const ChipFlow flow = measure_chip_flow(in, chip, u, setup_.edge_width());
    const auto [lo, hi] = setup_.middle_band();
    const Vec3 fm = sim.contacts().mesh_force_in_band(tool_mesh_, 1, lo, hi);
    const double half = 0.5 * setup_.width;
    values.insert(values.end(), {f[1] / setup_.width, flow.flow_angle_deg, flow.width, -fm[0] / half, fm[2] / half});
  }
  if (model_.heat.enabled) {
    const ChipHeat heat = chip_heat(in, chip, sim.world().particles.temperature);
    values.insert(values.end(), {heat.chip_mean, heat.rake_face_max});
  }
  if (tool_body_ >= 0) {
    const RigidBody& rb = model_.bodies[tool_body_];
    const Vec3 d = rb.state.position - rb.load.anchor - sim.time() * rb.load.holder_velocity;
    values.insert(values.end(), {d[0], d[2]});
  }
}

void CutProbe::write_results(H5File& f) const { write_cut_setup(f, setup_now()); }

void CutProbe::finish(const RunEnd& end, nlohmann::json& summary) {
  CutData data;
  data.time = end.series["time"];
  data.fc = end.series["cutting_force_per_width"];
  data.ft = end.series["thrust_force_per_width"];
  data.chip_thickness = end.series["chip_thickness"];
  const std::size_t n = setup_.lattice_particles;
  const auto bf = broken_fraction_per_particle(model_.particles, model_.rods);
  data.position.assign(model_.particles.position.begin(), model_.particles.position.begin() + n);
  data.broken_fraction.assign(bf.begin(), bf.begin() + n);
  data.broken_rod_fraction = broken_rod_fraction(model_.rods.intact, model_.rods.formed);
  if (tool_body_ >= 0) {
    data.tool_deflection_x = end.series["tool_deflection_x"];
    data.tool_deflection_z = end.series["tool_deflection_z"];
  }
  data.contact_length = end.series["contact_length"];
  if (setup_.free_sides) {
    data.passive_force = end.series["passive_force_per_width"];
    data.chip_flow_angle = end.series["chip_flow_angle"];
    data.chip_width = end.series["chip_width"];
    data.fc_middle = end.series["cutting_force_per_width_middle"];
    data.ft_middle = end.series["thrust_force_per_width_middle"];
  }
  if (model_.heat.enabled) {
    data.chip_temperature = end.series["chip_temperature"];
    data.rake_face_temperature = end.series["rake_face_temperature"];
  }
  finish_cut(end.dir, setup_now(), data, summary, end.vtk, end.pictures);
}

}  // namespace swarf
