// group_system.cpp: prescribed motions of particle groups and their reactions (see group_system.h).
#include "swarf/systems/group_system.h"

#include "swarf/core/parallel.h"
#include "swarf/core/state_archive.h"

namespace swarf {

void GroupSystem::setup(const std::vector<Group>& groups, const Particles& p) {
  const std::size_t ng = groups.size();
  u_old_.assign(ng, Vec3::Zero());
  u_new_.assign(ng, Vec3::Zero());
  reaction_.assign(ng, Vec3::Zero());
  v_.assign(ng, Vec3::Zero());
  mass_.assign(ng, 0.0);
  for (std::size_t g = 0; g < ng; ++g)
    for (auto i : groups[g].members) mass_[g] += p.mass[i];
}

void GroupSystem::resize(const World& w) {
  const auto& groups = w.groups;
  const auto& p = w.particles;
  mass_.assign(groups.size(), 0.0);
  for (std::size_t g = 0; g < groups.size(); ++g)
    for (auto i : groups[g].members) mass_[g] += p.mass[i];
}

bool GroupSystem::prescribe(const StepContext& c) {
  const auto& groups = c.world.groups;
  auto& p = c.world.particles;
  const double t = c.t, h = c.h;
  const double t_new = t + h;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    u_old_[g] = groups[g].motion.displacement_at(t);
    u_new_[g] = groups[g].motion.displacement_at(t_new);
  }
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const Vec3 v = (u_new_[g] - u_old_[g]) / h;
    const std::uint8_t mask = groups[g].dofs;
    for (auto i : groups[g].members)
      for (int c = 0; c < 3; ++c)
        if (mask & (1u << c)) {
          p.position[i][c] = p.initial_position[i][c] + u_new_[g][c];
          p.velocity[i][c] = v[c];
        }
  }
  return true;
}

void GroupSystem::reactions(const std::vector<Group>& groups, const Particles& p, std::vector<Vec3>& out) {
  out.assign(groups.size(), Vec3::Zero());
  for (std::size_t g = 0; g < groups.size(); ++g)
    for (auto i : groups[g].members) out[g] -= p.force[i];
}

void GroupSystem::account(const StepContext& ctx) {
  const auto& groups = ctx.world.groups;
  const double h = ctx.h;
  EnergyLedger& ledger = ctx.ledger;
  const auto& p = ctx.world.particles;
  if (counted_) account_exactly(ctx);  // (first: v_ is still the last step's velocity)
  reaction_old_.swap(reaction_);
  reactions(groups, p, reaction_);
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const Vec3 du = u_new_[g] - u_old_[g];
    const Vec3 v = du / h;
    for (int c = 0; c < 3; ++c) {
      if (!(groups[g].dofs & (1u << c))) continue;
      // Work on the body through the reaction, plus the work that changes the prescribed
      // particles' own kinetic energy (a grip that starts or reverses accelerates them).
      ledger.external_work += 0.5 * (reaction_old_[g][c] + reaction_[g][c]) * du[c];
      ledger.external_work += 0.5 * mass_[g] * (v[c] * v[c] - v_[g][c] * v_[g][c]);
    }
    v_[g] = v;
  }
}

void GroupSystem::account_exactly(const StepContext& ctx) {
  const auto& groups = ctx.world.groups;
  const auto& p = ctx.world.particles;
  const double h = ctx.h;
  exact_.reaction.assign(groups.size(), {});
  // The start-of-step half: the forces booked at the last account, this step's displacement.
  for (const OldForce& o : old_forces_) {
    const Vec3 du = u_new_[o.group] - u_old_[o.group];
    for (int c = 0; c < 3; ++c)
      if (groups[o.group].dofs & (1u << c)) exact_.external_work.add(-0.5 * o.force[c] * du[c]);
  }
  // The end-of-step half and the members' own kinetic energy change, per counted member (the
  // plain ledger books the latter with the group's mass: the same up to round-off). Exact sums
  // over blocks of members (the same sums for any split).
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const Vec3 du = u_new_[g] - u_old_[g];
    const Vec3 v = du / h;
    const auto& members = groups[g].members;
    const unsigned dofs = groups[g].dofs;
    for (int c = 0; c < 3; ++c)
      exact_.reaction[g][c] = exact_sum_of(members.size(), [&](std::size_t k, ExactSum& s) {
        if (counted_[members[k]]) s.add(-p.force[members[k]][c]);
      });
    exact_.external_work.add(exact_sum_of(members.size(), [&](std::size_t k, ExactSum& s) {
      const auto i = members[k];
      if (!counted_[i]) return;
      for (int c = 0; c < 3; ++c) {
        if (!(dofs & (1u << c))) continue;
        s.add(-0.5 * p.force[i][c] * du[c]);
        s.add(0.5 * p.mass[i] * (v[c] * v[c] - v_[g][c] * v_[g][c]));
      }
    }));
  }
  book_old_forces(ctx.world);
}

void GroupSystem::book_old_forces(const World& w) {
  old_forces_.clear();
  const auto& f = w.particles.force;
  for (std::size_t g = 0; g < w.groups.size(); ++g)
    for (auto i : w.groups[g].members)
      if (counted_[i]) old_forces_.push_back({static_cast<std::int32_t>(g), f[i]});
}

void GroupSystem::count_exactly(const std::uint8_t* counted, const World& w) {
  // (on: the forces now are the first step's start, as init_reactions took them; again after a
  // migration: the forces this domain booked at the last account stay its to finish)
  const bool starting = counted_ == nullptr && counted != nullptr;
  counted_ = counted;
  if (starting) {
    exact_.reaction.assign(w.groups.size(), {});
    book_old_forces(w);
  }
}

void GroupSystem::visit_state(StateArchive& ar, World& w, EnergyLedger&) {
  const std::size_t ng = w.groups.size();
  ar.array("groups/u_old", u_old_, ng);
  ar.array("groups/u_new", u_new_, ng);
  ar.array("groups/reaction", reaction_, ng);
  // (not reaction_old_: the last step's reactions, scratch that account() overwrites before it
  // reads it; a checkpoint of a run over ranks could not hold it as the serial run has it)
  ar.array("groups/velocity", v_, ng);
}

}  // namespace swarf
