// rod_system.h: the rods' part of the step: the kernel over the law, the meshes' parting lines,
// the commit of plasticity and breakage, bond formation and neighbour exchange, and the rods'
// energy.
//
// Stages (integrate/integration.h):
//   forces      every intact rod evaluated from its COMMITTED state (forces/rod_forces.h):
//               trial shift, trial break flag, force coefficient; then the rods on a mesh's
//               parting line break in this trial (laws/parting_rule.h)
//   commit      the final evaluation's shifts and breaks written back, per fixed block of rods
//               (plastic work and fracture energy summed in block order: the same bits for any
//               thread count); the broken rods' pairs handed back to become contact candidates
//   form        after the commit, with contacts: pressed unbonded lattice pairs form rods
//               (laws/bond_formation.h), a particle at the coordination giving up its most
//               stretched rod (neighbour exchange)
//   account     the viscous power of the last evaluation over the step
//   visit_state the counters (the rods' own arrays are the World's: Rods::for_each_field)
// The rods themselves (Rods) are the World's; the system owns the per-block scratch, the
// meshes' parting edges, bond formation's scratch and the counters of broken and formed rods.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "swarf/core/exact_sum.h"
#include "swarf/core/vec3.h"
#include "swarf/forces/density_floor.h"
#include "swarf/forces/plastic_volume.h"
#include "swarf/state/world.h"
#include "swarf/systems/energy_ledger.h"
#include "swarf/systems/step_context.h"
#include "swarf/systems/step_exchange.h"

namespace swarf {

class ContactSystem;
class StateArchive;

class RodSystem {
 public:
  using PairList = std::vector<std::array<std::int32_t, 2>>;
  /// A rod that flowed in a committed step: its plastic work, J, with its ends (the heat's
  /// source), and its plastic strain increment (the accumulated plastic strain's source).
  struct RodWork {
    std::array<std::int32_t, 2> ends;
    double work;
    std::int32_t rod;       ///< the rod's index
    double plastic_strain;  ///< the law's plastic strain after the step minus before, 1 (of L0)
  };
  using WorkList = std::vector<RodWork>;

  /// Marks the rods as the lattice's own if the World does not say, finds the meshes' parting
  /// edges and sizes the per-block scratch.
  void setup(World& w);
  /// The per-block scratch and the counters again after the door changed the particles or rods.
  void resize(const World& w);

  /// Evaluates every intact rod (the trial state; nothing committed changes). With rate_x and
  /// rate_v, a rate-scaled law (Johnson-Cook) takes its rate factor's rate from them (the Newton
  /// solve's lagged rate: RodKernelView::rate_x).
  void forces(World& w, const Vec3* rate_x = nullptr, const Vec3* rate_v = nullptr);
  /// Commits the final evaluation: shifts, breaks, plastic work and fracture energy. Returns
  /// the pairs whose rods broke now (in rod order). With 'work', also the rods whose shift moved,
  /// their plastic work and plastic strain increment, in rod order (the heat's and the
  /// accumulated plastic strain's sources: only the rods that flowed, which the commit visits
  /// anyway, instead of a pass over every particle's rods).
  PairList commit(World& w, EnergyLedger& ledger, WorkList* work = nullptr);
  /// Bond formation and neighbour exchange after the commit (with contacts only): new rods
  /// between pressed lattice pairs; the contact lists lose the formed pairs and gain the
  /// exchanged ones. Returns the pairs whose particles gained or lost a rod.
  PairList form(World& w, ContactSystem& contacts, EnergyLedger& ledger);
  /// The viscous work of the step's last evaluation over the step.
  void account(const StepContext& c);

  /// The compaction floor's force on each particle from the last evaluation (N; null when the
  /// floor is off): the gather adds it (forces/density_floor.h).
  const Vec3* floor_force(const World& w) const {
    return w.rods.compaction_modulus > 0.0 && w.rods.size() > 0 ? floor_.force() : nullptr;
  }
  const DensityFloor& floor() const { return floor_; }
  /// Recoverable elastic energy of the intact rods (and of the compaction floor), J.
  double elastic_energy(const World& w) const;
  /// Over the rods k with counted[k] (all when null), summed exactly (core/exact_sum.h), J.
  ExactSum elastic_energy_exact(const World& w, const std::uint8_t* counted = nullptr) const;
  /// The lattice's own rods that are broken (Rods::broken_count, kept up to date by the stages).
  std::size_t broken() const { return broken_; }
  /// Rods formed (or formed again) during the run by bond formation.
  std::size_t formed() const { return formed_; }
  void visit_state(StateArchive& ar, World& w, EnergyLedger& ledger);

  /// The rods' ledger lines summed exactly (core/exact_sum.h) over the rods whose first end has
  /// counted[i] != 0, J: what a domain books so that the sums over the ranks are the same for
  /// any partition (issue 38). Kept beside the EnergyLedger's plain sums, which it leaves as
  /// they are.
  struct ExactLedger {
    ExactSum plastic_work, viscous_work, fracture_energy;
  };
  /// Turns the exact ledger on over the particles with counted[i] != 0 (a domain's owned ones;
  /// the array must outlive the next step and be set again when the particles change), or off
  /// (nullptr). 'keys' (per rod: its place in the global rod order; nullptr: the rods are the
  /// global list) group the viscous work for its exact adds. Costs a pass over the rods per
  /// step and a store per rod in the kernel.
  /// A domain's link to the others (null: a run in one process): form() hands bond formation to it.
  void set_exchange(StepExchange* x) { x_ = x; }
  /// After a domain's bond formation changed the rods (StepExchange::form_rods): 'formed' rods
  /// formed over the run in this step, the lattice rods it broke less those it revived; the
  /// rows are brought up to date from 'first_changed', the first rod appended or moved (as the
  /// serial form() does).
  void formation_applied(World& w, std::size_t formed, std::int64_t broken_change, std::size_t first_changed);
  void count_exactly(const std::uint8_t* counted, const std::int64_t* keys = nullptr) {
    counted_ = counted;
    keys_ = keys;
  }
  const ExactLedger& exact_ledger() const { return exact_; }

  // Domains (issue 38): a rod is computed once, by the rank that owns its first particle; that
  // rank needs a copy of the other end.
  static constexpr Sharing sharing = Sharing::PerRod;
  /// How far beyond its region a rank needs copies of particles: the longest intact rod now, m.
  double ghost_reach(const World& w) const;

 private:
  void part(World& w);  // rods on the meshes' parting lines break in this trial

  const std::uint8_t* counted_ = nullptr;  // per particle: its first-end rods count in exact_ (null: off)

  const std::int64_t* keys_ = nullptr;  // per rod, the global order (count_exactly)
  StepExchange* x_ = nullptr;           // a domain's link to the others (not owned)
  ExactLedger exact_;
  std::vector<double> rod_viscous_;              // with counted_: per rod, viscous power of the last evaluation, W
  std::vector<double> runs_;                     // with counted_: the step's viscous power by run of rods (account), W
  std::vector<std::vector<double>> block_runs_;  // (viscous_runs' per-block runs, kept for their memory)
  bool runs_ready_ = false;                      // runs_ taken this step (before bond formation changed the rods)
  void viscous_runs(const World& w);             // runs_ from rod_viscous_
  std::vector<ExactLedger> block_exact_;         // with counted_: commit's scratch per rod block
  std::size_t broken_ = 0;
  std::size_t formed_ = 0;               // state: 'formed_rods'
  std::vector<Vec3> mesh_edge_;          // per mesh: its lowest reference vertex (parting lines), m; empty: none
  std::vector<std::uint8_t> lattice_;    // per particle: 1 if built with a rod (bond formation's candidates)
  std::vector<int> intact_count_;        // form's scratch: a particle's intact rods, -1 = not counted yet
  DensityFloor floor_;                   // with Rods::compaction_modulus (forces/density_floor.h)
  PlasticVolumeScratch plastic_volume_;  // with Rods::isochoric (forces/plastic_volume.h)
  std::vector<double> block_viscous_;    // per rod block: viscous power of the last evaluation, W
  std::vector<int> block_changed_;       // per rod block: a trial shift or break to commit
  std::vector<WorkList>
      block_work_;  // commit's scratch per rod block: the rods that flowed (kept: no allocation per step)
};

}  // namespace swarf
