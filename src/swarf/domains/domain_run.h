// domain_run.h: one run over the ranks of a Comm by domain decomposition (issue 38), with the
// serial run's bits for any rank count: rods, groups, contacts and tools, the heat and bond
// formation under velocity Verlet.
//
// Why the bits are the serial ones: each particle's force is summed over its rods in rod order
// (state/reindex.h), and each rod is evaluated from its ends' state and its own. A domain's
// local World therefore holds
//   - the particles it owns (those in its slab, partition.h),
//   - ghost copies of the other ends of their rods,
//   - every rod with an owned end, in the GLOBAL rod order (each rod keyed by its index in the
//     serial run's rod list, carried with it),
// and all its particles in id order, so that a rod's ends keep their order (i < j) as in the
// serial run. An owned particle's force is then the same terms added in the same order as in
// the serial run, whatever the partition: the same bits, compared with == in the tests, not
// within a tolerance. A rod with ends on two domains is evaluated on both from identical inputs,
// so its plastic shift and breakage agree without being sent. Ghosts are stepped too (their
// forces are partial and wrong), and after every step the owners overwrite what the next step
// reads of them: the halo sends a ghost's position, velocity and acceleration (records.h), and
// a particle arriving as owned at a migration takes its old owner's whole record.
//
// Which domain owns a particle never changes the bits (ghosts follow the rods, not space); the
// slabs only decide where the work is done. Migration: every 'rebalance_every' steps with new
// cuts (unless fixed), and with the cuts kept once an owned particle strays more than 'skin'
// beyond its slab, every particle goes to the owner of its slab, point to point in one
// all-to-all, with its rods and the particles at their other ends (the new owner's ghosts). Each
// domain assembles its new local World from what it had and what it received and hands it to
// the Simulation's door (Simulation::replace_particles), which keeps the step's own state (time,
// counters, the plastic strain window: a migrant's open window is folded in by its new owner).
//
// Groups (grips, prescribed motions) act on each particle alone, owned or ghost; their work and
// reactions are booked exactly by the members' owners (GroupSystem::count_exactly). The energies and the broken rods
// are reduced over the ranks (sums()): each term counted by one owner and added exactly, which
// gives the serial run's bits because the serial run adds its energies exactly too. The rods'
// ledger lines (plastic, viscous, fracture) are booked per step by the owner of each rod's first
// end into exact sums beside the plain ones (RodSystem::count_exactly) and reduced by sums(): the
// same bits for any rank count; the plain sums of the serial run agree to round-off only (it adds
// in blocks, the cheaper way: exact adds in the rod kernel cost 11-20 % of the cut's step,
// validation/bench/README.md). The Simulation's own ledger stays per domain.
// Contacts make the ghosts spatial as well (every particle within reach of the slab; the layers
// made anew before a particle's drift would pass half the lists' skin) and travel as records with
// their friction histories; the heat and bond formation need the other domains midway through a
// step (systems/step_exchange.h; domain_formation.cpp); see docs/architecture.md.
// Not yet (refused by name, check_supported): rigid bodies, particle flows, tools that warm or
// conduct heat, the implicit Newmark step and the Newton solver.
// Setup: every rank builds the same global World (setup is deterministic) and keeps its part.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "swarf/core/comm.h"
#include "swarf/core/exact_sum.h"
#include "swarf/core/memory_archive.h"
#include "swarf/domains/partition.h"
#include "swarf/domains/records.h"
#include "swarf/integrate/step_settings.h"
#include "swarf/simulation.h"
#include "swarf/state/world.h"
#include "swarf/systems/step_exchange.h"

namespace swarf {

struct DomainSettings {
  int rebalance_every = 100;       ///< steps between re-partitions and migrations (>= 1)
  std::vector<double> fixed_cuts;  ///< the slabs' cut planes along x, m (ranks - 1 of them); empty: balanced
  /// Makes the ranks' boxes at the start and at every rebalance (partition.h; Zoltan's RCB under
  /// MPI); null: balanced slabs along x. Not with fixed_cuts.
  std::shared_ptr<Partitioner> partitioner;
  /// How far an owned particle may stray beyond its slab before all particles go to the owners
  /// of their slabs, m (0: as soon as one leaves). Ownership never changes the bits, so a skin
  /// only trades a larger domain for fewer migrations (LAMMPS's reneighbouring skin).
  double skin = 0.0;
  /// Steps between the stray checks (>= 1): each scans the owned particles and costs one
  /// collective. Ownership never changes the bits here (ghosts follow the rods, not space), so
  /// a particle that strays between checks is still stepped right; the checks only keep the
  /// slabs compact and balanced. (With contacts, whose ghosts are spatial, the skin will have to
  /// cover the travel between checks, as LAMMPS's reneighbouring does.)
  int check_every = 1;
};
// With contacts the stray check is replaced: see domain_run.h's head (spatial ghosts).

class DomainRun : private StepExchange {
 public:
  /// This rank's domain of 'global' (the whole World, the same on every rank; ids and rods as
  /// the serial run has them), stepped with 'settings'. Collective. Throws InputError for a
  /// World or settings the domains do not support yet (check_supported).
  DomainRun(Comm& comm, const World& global, const StepSettings& settings, DomainSettings ds = {});
  /// This rank's domain of a run that goes on from where 'start' is (a serial Simulation, e.g.
  /// loaded from a checkpoint, or built over gather_world() with another run's step state): its
  /// World partitioned, each particle's and rod's record as it is there (not recomputed), and
  /// its step state (time, counters, the systems' own state; step_state.h). The sums go on
  /// from its ledger (rounded once: the checkpoint's doubles). Collective.
  /// 'ledger_digits' (read on rank 0; optional): the exact sums of the ledger lines up to
  /// 'start' as ledger_digits() gave them, so that a run that goes on from a checkpoint books
  /// on the unrounded sums and gives the uninterrupted run's bits; without them the sums go on
  /// from start's ledger (its doubles).
  DomainRun(Comm& comm, const Simulation& start, DomainSettings ds = {},
            const std::vector<std::int64_t>* ledger_digits = nullptr);
  DomainRun(const DomainRun&) = delete;
  DomainRun& operator=(const DomainRun&) = delete;

  /// One step of at most max_dt (s; the step's own size otherwise, as Simulation::step), the
  /// halo exchange, and a migration when due. Collective.
  void step(double max_dt = std::numeric_limits<double>::infinity());
  /// Called around every step of this rank's Simulation (not owned). Its World is the domain's:
  /// the time, counters and settings are the run's, the particles only this rank's and its ghosts.
  void add_listener(StepListener* l) { sim_->add_listener(l); }
  double time() const { return sim_->time(); }          ///< s
  std::int64_t steps() const { return sim_->steps(); }  ///< accepted steps

  /// Collective: every rank's owned particles, in id order, on every rank: the serial run's
  /// particles, bit for bit. O(N) on every rank: for outputs and checks, not for every step.
  Particles gather_owned();
  /// Collective: the whole World as the serial run has it, on every rank: the particles in id
  /// order (gather_owned), every rod once in the global rod order with its ends as indices into
  /// them, the groups' members from the particles' group indices, the configuration (law, area,
  /// motions, ...) the run's. What a checkpoint or an output of the run holds; O(N) per rank.
  World gather_world();
  /// Collective: a serial Simulation over gather_world() (held in 'storage', which must outlive
  /// it) at this run's step state, with the run's reduced sums as its ledger, reactions and
  /// broken rods: what a checkpoint of the run holds, readable by a run on any rank count
  /// (DomainRun(comm, start)) or by a serial one. The exact sums are rounded into it once.
  std::unique_ptr<Simulation> gather_simulation(World& storage);
  /// Collective: on rank 0, 'mirror' (a serial Simulation of the same case, over a World with the
  /// run's particles and rods, e.g. the one the run started from) takes the run's state as
  /// gather_simulation gives it: what the outputs of a run over ranks read. The records travel
  /// to rank 0 only and are written over the mirror's in place (Simulation::overwrite_records);
  /// the other ranks' mirrors take the step state and sums only.
  void gather_into(Simulation& mirror);

  /// The run's sums over all domains, each term counted once (a particle by its owner, a rod by
  /// the owner of its first end) and added exactly (core/exact_sum.h). Collective. The energies
  /// now are the serial run's values, bit for bit (it sums them exactly too); the rods' ledger
  /// lines (since the start: each step's terms booked by the owner then) are the same bits for
  /// any rank count, and agree with the serial run's plain sums to round-off; so do the groups'
  /// work and reactions. The Simulation's own ledger, with shared rods counted on both sides,
  /// stays per domain.
  struct Sums {
    double kinetic_energy = 0.0;   ///< of the particles, translational + rotational, J
    double elastic_energy = 0.0;   ///< of the intact rods, J
    double contact_energy = 0.0;   ///< in the touching contacts, J
    std::int64_t broken_rods = 0;  ///< rods broken now (the intact flags), of the serial rod list
    double plastic_work = 0.0;     ///< EnergyLedger::plastic_work, J
    double viscous_work = 0.0;     ///< EnergyLedger::viscous_work, J
    double fracture_energy = 0.0;  ///< EnergyLedger::fracture_energy, J
    double external_work = 0.0;    ///< EnergyLedger::external_work of the groups' and meshes' motions, J
    double contact_work = 0.0;     ///< EnergyLedger::contact_work, J
    double heat_plastic = 0.0, heat_friction = 0.0, heat_to_tools = 0.0, heat_to_clamps = 0.0;  ///< EnergyLedger's, J
    std::vector<Vec3> mesh_forces;  ///< per mesh, Simulation::mesh_force now, N
    std::vector<Vec3> reactions;    ///< per group, Simulation::group_reaction now, N
  };
  Sums sums();
  /// The exact sums of the ledger lines (plastic, viscous and fracture work, the groups' and
  /// meshes' external work, the contacts' line, the heat's plastic, friction, tools and clamps lines) as the last
  /// sums() reduced them: ExactSum::kWords int64 words each, the same on every rank; what a checkpoint keeps for
  /// DomainRun(comm, start, ds, digits).
  const std::vector<std::int64_t>& ledger_digits() const { return ledger_digits_; }
  static constexpr std::size_t kLedgerLines = 9;

  /// Throws InputError naming the first feature of 'w' or 's' that the domains do not support.
  static void check_supported(const World& w, const StepSettings& s);

  /// The local World: owned particles and ghosts, in id order.
  const World& world() const { return local_; }
  bool owned(std::size_t i) const { return owned_[i] != 0; }
  std::size_t owned_count() const;
  /// Per local rod: its index in the global (serial) rod order.
  const std::vector<std::int64_t>& rod_keys() const { return rod_key_; }
  const Partition& partition() const { return partition_; }
  const Simulation& simulation() const { return *sim_; }
  /// Particles that arrived at this rank as their new owner, over the run.
  std::int64_t arrivals() const { return arrivals_; }
  /// Migrations done (with new cuts or not).
  std::int64_t migrations() const { return migrations_; }
  /// Wall time spent after the steps in the halo exchange, the stray check and the migrations
  /// (what waits on the other ranks), s.
  double exchange_seconds() const { return exchange_seconds_; }
  /// Bytes this rank sent in the last halo exchange.
  std::size_t halo_bytes() const { return halo_bytes_; }

 private:
  struct Local;        // a local World's particles, rods and contacts before the Simulation takes them
  struct ContactPool;  // contact records by their particles' ids, as a migration gathers them
  // exact[k]: pool entry k is its owner's copy (a ghost's is exact in the halo's fields only).
  Local assemble(Particles& pool, const std::vector<std::uint8_t>& exact, RodPool& rods,
                 const std::vector<std::int64_t>& owned_ids, const ContactPool& contacts) const;
  // The contacts this rank computes exactly (of an owned particle: a pair with an owned end if
  // 'any_end', else with an owned first end), by the particles' ids.
  ContactPool own_contacts(bool any_end) const;
  // Collective: per step, the meshes' forces and the contacts' power over the owned particles,
  // reduced exactly; the meshes' work and the contacts' line booked from them (not at 'start').
  void book_contacts(bool start);
  // Collective: every rank's contacts (own_contacts(false)) on every rank (all) or on rank 0,
  // as records of the particles with these ids (ascending).
  ContactSystem::Records gather_contacts(const std::vector<std::int64_t>& ids, bool all);
  void adopt(Local&& l);  // into the Simulation (built on the first call)
  void plan_halo();       // who sends which owned particle to whom after each step
  void exchange_halo();   // after each step: the halo's fields of this run
  void exchange_halo(HaloFields fields);
  // StepExchange: what this domain's step needs of the others midway (the heat's conduction).
  void temperatures() override;
  void motions() override { exchange_halo(); }
  double min_all(double v) override;
  const std::uint8_t* counted() const override { return owned_.data(); }
  std::vector<std::array<std::int32_t, 2>> form_rods(RodSystem& rods, World& w, ContactSystem& contacts) override;
  void migrate(bool recut);                   // recut: choose the cuts again (unless fixed)
  void load_sums_into(Simulation& out);       // collective: this rank's step state and the run's sums
  MemoryArchive sums_archive();               // collective: that step state, to load (broken_rods not set)
  std::vector<std::int64_t> weights() const;  // per local particle: 1 + its intact rods

  Comm& comm_;
  DomainSettings ds_;
  StepSettings settings_;
  World local_;
  std::unique_ptr<Simulation> sim_;
  std::vector<std::uint8_t> owned_;    // per local particle
  std::vector<std::int64_t> rod_key_;  // per local rod
  Partition partition_;
  /// New boxes (or slabs) for the owned particles at x with weights w (collective).
  void repartition(const std::vector<Vec3>& x, const std::vector<std::int64_t>& w);
  std::vector<std::vector<std::int32_t>> send_, recv_;  // per rank: local indices, in the halo's order
  std::int64_t arrivals_ = 0, migrations_ = 0, steps_ = 0;
  double exchange_seconds_ = 0.0;
  // Per ledger line, booked on rank 0 only (zeros elsewhere): what the run booked before it
  // started here, and what the domains book from reduced sums (the meshes' work, the contacts' line).
  std::vector<ExactSum> base_ = std::vector<ExactSum>(kLedgerLines);
  std::vector<std::int64_t> ledger_digits_;
  Bytes gather_out_;  // gather_into's buffers, kept (an output gathers the whole state)
  std::vector<Bytes> gather_in_;
  std::size_t halo_bytes_ = 0;
  // Contacts (spatial ghosts): the reach of the ghost layer (contact distance of the two largest
  // spheres plus the lists' skin, m), the lists' skin (m), where the local particles were at the
  // last migration, and the reduced meshes' forces (N) and contacts' power (W) of the last step.
  bool contacts_ = false;
  double reach_ = 0.0, contact_skin_ = 0.0;
  std::vector<Vec3> x_migrated_;
  // Bond formation: the ids of the lattice's particles (built with rods: the candidates),
  // ascending, and the number of rods of the whole run (the next formed rod's key).
  std::vector<std::int64_t> lattice_ids_;
  std::vector<std::uint8_t> lattice_local_;  // per local particle: its id is in lattice_ids_ (made in adopt)
  std::int64_t global_rods_ = 0;
  std::vector<Vec3> mesh_force_;
  double contact_power_ = 0.0;
};

}  // namespace swarf
