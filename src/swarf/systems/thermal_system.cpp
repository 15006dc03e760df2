// thermal_system.cpp: the heat's stages (see thermal_system.h; laws/heat_conduction.h).
#include "swarf/systems/thermal_system.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "swarf/core/errors.h"
#include "swarf/core/parallel.h"
#include "swarf/core/state_archive.h"
#include "swarf/laws/heat_conduction.h"

namespace swarf {

namespace {

// Conduction sub-steps allowed within one mechanical step before the run stops.
constexpr double kMaxConductionSubsteps = 1000.0;

void assign(std::vector<double>& v, std::size_t n) { v.assign(n, 0.0); }

}  // namespace

void ThermalSystem::setup(World& w) {
  const HeatParams& hp = w.heat;
  enabled_ = hp.enabled;
  // (the temperature array only with heat: 8 B per particle; without it the rods' and contacts'
  // kernels take their temperature-free paths, which a World of 0 K gave them bit for bit)
  ParticleLayout layout = w.particles.layout;
  layout.temperature = enabled_;
  w.particles.set_layout(layout);
  if (!enabled_) return;
  auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  if (!positive(hp.heat_capacity) || !positive(hp.conductivity))
    throw InputError(
        fmt::format("heat: the workpiece needs a heat capacity (J/(kg K)) and a conductivity "
                    "(W/(m K)) above zero, got {} and {}",
                    hp.heat_capacity, hp.conductivity));
  if (!(hp.taylor_quinney >= 0.0 && hp.taylor_quinney <= 1.0))
    throw InputError(fmt::format("heat: the Taylor-Quinney fraction {} is not within [0, 1]", hp.taylor_quinney));
  if (!positive(hp.initial_temperature) || !positive(hp.tool_temperature))
    throw InputError(fmt::format("heat: temperatures are absolute (K) and above zero, got {} K and {} K",
                                 hp.initial_temperature, hp.tool_temperature));
  if (!(hp.stability_fraction > 0.0 && hp.stability_fraction <= 1.0))
    throw InputError(fmt::format("heat: stability_fraction {} is not within (0, 1]", hp.stability_fraction));
  if (!(hp.tool_heat_capacity >= 0.0 && std::isfinite(hp.tool_heat_capacity)) ||
      !(hp.tool_conductivity >= 0.0 && std::isfinite(hp.tool_conductivity)))
    throw InputError(fmt::format("heat: the tools' heat capacity {} J/K and conductivity {} W/(m K) must be >= 0",
                                 hp.tool_heat_capacity, hp.tool_conductivity));
  if (!(hp.tool_friction_share >= 0.0 && hp.tool_friction_share <= 1.0))
    throw InputError(fmt::format("heat: tool_friction_share {} is not within [0, 1]", hp.tool_friction_share));
  tool_t_.assign(w.meshes.size(), hp.tool_temperature);
  resize(w);
  interval_ = 0.0;  // (the first conduction measures the limit)
}

void ThermalSystem::resize(World& w) {
  if (!enabled_) return;
  // 0 K marks a particle that has no temperature yet: built before the system, or new at the door.
  auto& p = w.particles;
  const auto& held = w.heat.held;
  held_.assign(p.size(), 0);
  held_list_.clear();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::int32_t g = p.group[i];
    held_[i] = g >= 0 && static_cast<std::size_t>(g) < held.size() && held[g];
    if (held_[i]) held_list_.push_back(static_cast<std::int32_t>(i));
    if (p.temperature[i] == 0.0) p.temperature[i] = w.heat.initial_temperature;
  }
  if (tool_t_.size() != w.meshes.size()) tool_t_.resize(w.meshes.size(), w.heat.tool_temperature);
}

void ThermalSystem::fluxes(const World& w, const ContactSystem& contacts, double ds) {
  const auto& p = w.particles;
  const auto& r = w.rods;
  const std::size_t n = p.size(), nm = w.meshes.size();
  assign(out_.friction, n);
  assign(out_.flux, n);
  assign(out_.conductance, n);
  assign(out_.mesh_friction, nm);
  assign(out_.mesh_flux, nm);
  assign(out_.mesh_conductance, nm);
  const double k = w.heat.conductivity;
  const double* T = p.temperature.data();
  double* flux = out_.flux.data();
  double* cond = out_.conductance.data();
  if (r.row_start.size() == n + 1) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      double q = 0.0, g = 0.0;
      for (std::int32_t e = r.row_start[i]; e < r.row_start[i + 1]; ++e) {
        const Rods::Entry en = r.entries[e];
        if (!r.intact[en.rod]) continue;
        const double G = rod_conductance(k, r.rest_length[en.rod]);
        q += G * (T[en.other] - T[i]);
        g += G;
      }
      flux[i] = q;
      cond[i] = g;
    }
  }
  if (w.heat.contact_conduction || w.heat.tool_conductivity > 0.0) {
    ContactSystem::HeatInput in;
    in.temperature = T;
    in.conductivity = w.heat.contact_conduction ? k : 0.0;
    in.mesh_temperature = tool_t_.data();
    in.mesh_conductivity = w.heat.tool_conductivity;
    in.friction = false;
    in.counted = x_ ? x_->counted() : nullptr;  // (the heat into the tools over the sub-step ds)
    in.scale = ds;
    contacts.heat(p, in, out_);
  }
}

void ThermalSystem::heat(const StepContext& c, const ContactSystem& contacts, const RodSystem::WorkList& plastic) {
  if (!enabled_) return;
  World& w = c.world;
  auto& p = w.particles;
  const HeatParams& hp = w.heat;
  const std::size_t n = p.size(), nm = w.meshes.size();
  const double h = c.h;
  // Sources. The plastic work of the rods that flowed (the commit's list, in rod order: the same
  // sums for any thread count), half per end.
  assign(plastic_, n);
  double plastic_heat = 0.0;
  if (hp.taylor_quinney > 0.0) {
    const double half_beta = 0.5 * hp.taylor_quinney;
    double* q = plastic_.data();
    for (const RodSystem::RodWork& r : plastic) {
      const double e = half_beta * r.work;
      q[r.ends[0]] += e;
      q[r.ends[1]] += e;
      plastic_heat += 2.0 * e;  // (the ledger's sum over the same list: no pass over the particles)
      if (x_ && x_->counted()[r.ends[0]]) exact_.plastic.add(2.0 * e);  // (a rod: its first end's owner's)
    }
  }
  // Friction over the step: half to each particle of a pair, heat.tool_friction_share of a tool
  // contact's to the tool (over domains from the ghosts' own velocities).
  assign(out_.friction, n);
  assign(out_.mesh_friction, nm);
  if (contacts.enabled()) {
    if (x_) x_->motions();
    ContactSystem::HeatInput in;  // (friction only: no flux written)
    in.mesh_share = hp.tool_friction_share;
    in.counted = x_ ? x_->counted() : nullptr;
    in.scale = h;
    contacts.heat(p, in, out_);
  }
  const double c_heat = hp.heat_capacity;
  double* T = p.temperature.data();
  const double* m = p.mass.data();
  const double* qp = plastic_.data();
  const double* qf = out_.friction.data();
  const std::uint8_t* held = held_.data();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i)
    if (m[i] > 0.0 && !held[i]) T[i] += (qp[i] + h * qf[i]) / (m[i] * c_heat);
  double clamped = 0.0;  // (over the clamps' particles only, in index order)
  for (const std::int32_t i : held_list_) clamped += qp[i] + h * qf[i];
  c.ledger.heat_to_clamps += clamped;
  c.ledger.heat_plastic += plastic_heat;
  const double particle_friction = deterministic_sum(n, [&](std::size_t i) { return qf[i]; });
  double tool_friction = 0.0;
  for (std::size_t k = 0; k < nm; ++k) {
    const double q = h * out_.mesh_friction[k];
    tool_friction += q;
    if (hp.tool_heat_capacity > 0.0) tool_t_[k] += q / hp.tool_heat_capacity;
  }
  c.ledger.heat_friction += h * particle_friction + tool_friction;
  c.ledger.heat_to_tools += tool_friction;
  if (x_) {
    const std::uint8_t* owned = x_->counted();
    for (const std::int32_t i : held_list_)
      if (owned[i]) exact_.to_clamps.add(qp[i] + h * qf[i]);
    for (std::size_t i = 0; i < n; ++i)
      if (owned[i] && qf[i] != 0.0) exact_.friction.add(h * qf[i]);  // (most particles touch nothing)
    for (const ExactSum& q : out_.mesh_friction_exact) {             // (empty without contacts)
      exact_.friction.add(q);
      exact_.to_tools.add(q);
    }
  }
  // Conduction, when it is due.
  pending_ += h;
  if (pending_ >= interval_) {
    conduct(w, contacts, pending_, c.ledger);
    pending_ = 0.0;
  }
}

void ThermalSystem::conduct(World& w, const ContactSystem& contacts, double dt, EnergyLedger& ledger) {
  auto& p = w.particles;
  const HeatParams& hp = w.heat;
  const std::size_t n = p.size(), nm = w.meshes.size();
  const double c_heat = hp.heat_capacity;
  const double* m = p.mass.data();
  double* T = p.temperature.data();
  int sub = 1;
  for (int s = 0; s < sub; ++s) {
    if (x_) x_->temperatures();  // (the ghosts': their owners added this step's sources, or the last sub-step)
    fluxes(w, contacts, dt / sub);
    if (s == 0) {
      // The explicit limit of this pass: min_i C_i / sum_j G_ij (and the heated tools'); over
      // the domains, of the owned particles (a ghost's conductance lacks its other rods).
      double limit = HUGE_VAL;
      const std::uint8_t* owned = x_ ? x_->counted() : nullptr;
      for (std::size_t i = 0; i < n; ++i)
        if (out_.conductance[i] > 0.0 && m[i] > 0.0 && !held_[i] && (!owned || owned[i]))
          limit = std::min(limit, m[i] * c_heat / out_.conductance[i]);
      if (x_) limit = x_->min_all(limit);
      const double particle_limit = limit;
      if (hp.tool_heat_capacity > 0.0)
        for (std::size_t k = 0; k < nm; ++k)
          if (out_.mesh_conductance[k] > 0.0) limit = std::min(limit, hp.tool_heat_capacity / out_.mesh_conductance[k]);
      limit_ = limit;
      const double allowed = hp.stability_fraction * limit;
      const double wanted = std::isfinite(allowed) ? std::ceil(dt / allowed) : 1.0;
      // A conduction far faster than the motion (a tiny heated tool, a diffusivity no solid
      // has) would sub-step without end: stop and say which limit it is.
      if (!(wanted <= kMaxConductionSubsteps))
        throw SimulationError(fmt::format(
            "heat: conduction needs {:.4g} sub-steps of {:.4g} s within one step of {:.4g} s (at most {}): its "
            "explicit limit m c / G is set by {}; raise heat.{} or lower the conductivities",
            wanted, allowed, dt, kMaxConductionSubsteps,
            limit < particle_limit ? "a tool (heat.tool_heat_capacity over its contact conductance)"
                                   : "the particles (heat.heat_capacity, heat.conductivity)",
            limit < particle_limit ? "tool_heat_capacity" : "heat_capacity"));
      sub = std::max(1, static_cast<int>(wanted));
      last_step_ = dt / sub;
      if (x_ && sub > 1) fluxes(w, contacts, dt / sub);  // (the same fluxes; the tools' exact heat over the sub-step)
      // Nothing conducts yet (no rod, no touching contact): look again at the next step.
      interval_ = std::isfinite(allowed) ? allowed : 0.0;
    }
    const double ds = dt / sub;
    const double* q = out_.flux.data();
    const std::uint8_t* held = held_.data();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i)
      if (m[i] > 0.0 && !held[i]) T[i] += ds * q[i] / (m[i] * c_heat);
    ledger.heat_to_clamps += ds * deterministic_sum(n, [&](std::size_t i) { return held[i] ? q[i] : 0.0; });
    for (std::size_t k = 0; k < nm; ++k) {
      const double in = ds * out_.mesh_flux[k];
      ledger.heat_to_tools += in;
      if (hp.tool_heat_capacity > 0.0) tool_t_[k] += in / hp.tool_heat_capacity;
    }
    if (x_) {
      const std::uint8_t* owned = x_->counted();
      for (const std::int32_t i : held_list_)
        if (owned[i]) exact_.to_clamps.add(ds * q[i]);
      for (const ExactSum& in : out_.mesh_flux_exact) exact_.to_tools.add(in);
    }
  }
  ++conductions_;
}

double ThermalSystem::carried(const World& w, const std::vector<std::uint8_t>& remove) const {
  if (!enabled_) return 0.0;
  const auto& p = w.particles;
  const double c = w.heat.heat_capacity, t0 = w.heat.initial_temperature;
  double q = 0.0;
  for (std::size_t i = 0; i < remove.size() && i < p.size(); ++i)
    if (remove[i]) q += p.mass[i] * c * (p.temperature[i] - t0);
  return q;
}

double ThermalSystem::stored_heat(const World& w) const {
  if (!enabled_) return 0.0;
  const auto& p = w.particles;
  const double c = w.heat.heat_capacity, t0 = w.heat.initial_temperature;
  return deterministic_sum(p.size(), [&](std::size_t i) { return p.mass[i] * c * (p.temperature[i] - t0); });
}

void ThermalSystem::visit_state(StateArchive& ar, World& w, EnergyLedger& ledger) {
  if (!enabled_) return;
  ar.array("heat/tool_temperature", tool_t_, ar.loading() ? StateArchive::kAnySize : tool_t_.size());
  if (ar.loading() && tool_t_.size() != w.meshes.size())
    throw InputError(fmt::format("state field 'heat/tool_temperature' has {} entries for {} meshes", tool_t_.size(),
                                 w.meshes.size()));
  ar.scalar("heat/pending", pending_);
  ar.scalar("heat/interval", interval_);
  ar.scalar("heat/conductions", conductions_);
  ar.scalar("ledger/heat_plastic", ledger.heat_plastic);
  ar.scalar("ledger/heat_friction", ledger.heat_friction);
  ar.scalar("ledger/heat_to_tools", ledger.heat_to_tools);
  ar.scalar("ledger/heat_outflow", ledger.heat_outflow);
  ar.scalar("ledger/heat_to_clamps", ledger.heat_to_clamps);
}

}  // namespace swarf
