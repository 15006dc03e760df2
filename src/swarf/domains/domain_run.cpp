// domain_run.cpp: the domains' setup, halo exchange and migration (see domain_run.h).
#include "swarf/domains/domain_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <numeric>
#include <stdexcept>

#include "swarf/core/errors.h"
#include "swarf/domains/step_state.h"

namespace swarf {

struct DomainRun::Local {
  Particles particles;
  Rods rods;
  std::vector<std::uint8_t> owned;
  std::vector<std::int64_t> key;
  ContactSystem::Records contacts;  // (indices into 'particles')
};

// Contact records with their particles' ids (the records' own indices are the sender's).
struct DomainRun::ContactPool {
  std::vector<std::array<std::int64_t, 2>> pair_ids;
  std::vector<ContactSystem::PairRecord> pairs;
  std::vector<std::int64_t> tri_ids;
  std::vector<ContactSystem::TriangleRecord> tris;
  void put(Bytes& out) const;      // appends the pool: counts, then the records
  void get(const std::byte*& in);  // appends the records at 'in'
};

namespace {

// The World's configuration (law, area, gravity, ...) without its particles and rods; the
// groups with their motions (their members are rebuilt from the particles' group indices).
void copy_configuration(const World& from, World& to) {
  to.meshes = from.meshes;
  to.mesh_motion = from.mesh_motion;
  to.contacts = from.contacts;
  to.rods.law = from.rods.law;
  to.rods.area = from.rods.area;
  to.rods.formation = from.rods.formation;
  to.rods.isochoric = from.rods.isochoric;
  to.rods.compaction_modulus = from.rods.compaction_modulus;
  to.rods.compaction_onset = from.rods.compaction_onset;
  to.gravity = from.gravity;
  to.periodic = from.periodic;
  to.contact = from.contact;
  to.heat = from.heat;
  to.groups = from.groups;
}

// Buffers: a count, then that many records.
void put_count(Bytes& out, std::uint64_t n) {
  const std::size_t at = out.size();
  out.resize(at + sizeof n);
  std::memcpy(out.data() + at, &n, sizeof n);
}
std::uint64_t get_count(const std::byte*& in) {
  std::uint64_t n;
  std::memcpy(&n, in, sizeof n);
  in += sizeof n;
  return n;
}

bool contains(const std::vector<std::int64_t>& sorted, std::int64_t v) {
  return std::binary_search(sorted.begin(), sorted.end(), v);
}

// A contact record as bytes: its particles' ids, then the record (its indices the sender's).
template <class Record>
void put_record(Bytes& out, const std::int64_t* ids, int n_ids, const Record& r) {
  const std::size_t at = out.size();
  out.resize(at + n_ids * sizeof(std::int64_t) + sizeof(Record));
  std::memcpy(out.data() + at, ids, n_ids * sizeof(std::int64_t));
  std::memcpy(out.data() + at + n_ids * sizeof(std::int64_t), static_cast<const void*>(&r), sizeof(Record));
}
template <class Record>
void get_record(const std::byte*& in, std::int64_t* ids, int n_ids, Record& r) {
  std::memcpy(ids, in, n_ids * sizeof(std::int64_t));
  std::memcpy(static_cast<void*>(&r), in + n_ids * sizeof(std::int64_t), sizeof(Record));
  in += n_ids * sizeof(std::int64_t) + sizeof(Record);
}

}  // namespace

void DomainRun::ContactPool::put(Bytes& out) const {
  put_count(out, pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) put_record(out, pair_ids[k].data(), 2, pairs[k]);
  put_count(out, tris.size());
  for (std::size_t k = 0; k < tris.size(); ++k) put_record(out, &tri_ids[k], 1, tris[k]);
}

void DomainRun::ContactPool::get(const std::byte*& in) {
  for (std::uint64_t n = get_count(in), q = 0; q < n; ++q) {
    pair_ids.emplace_back();
    pairs.emplace_back();
    get_record(in, pair_ids.back().data(), 2, pairs.back());
  }
  for (std::uint64_t n = get_count(in), q = 0; q < n; ++q) {
    tri_ids.emplace_back();
    tris.emplace_back();
    get_record(in, &tri_ids.back(), 1, tris.back());
  }
}

void DomainRun::check_supported(const World& w, const StepSettings& s) {
  const char* what = nullptr;
  if (s.implicit())
    what = s.solver == Solver::Newton ? "the Newton solver" : "the implicit Newmark step (integrator.scheme)";
  else if (!w.bodies.empty())
    what = "rigid bodies";
  else if (w.rods.isochoric)
    what =
        "rods whose plastic flow keeps the volume (rod.isochoric_plasticity: a ghost's mean needs its rods on the "
        "other rank)";
  else if (w.rods.compaction_modulus > 0.0)
    what = "a floor under the rods' volume (rod.compaction_modulus: a ghost's volume needs its rods on the other rank)";
  else if (!w.inflows.empty() || !w.outflows.empty())
    what = "particle inflows and outflows";
  else if (w.heat.enabled && (w.heat.tool_heat_capacity > 0.0 || w.heat.tool_conductivity > 0.0))
    what = "tools that warm or conduct heat (heat.tool_heat_capacity, heat.tool_conductivity)";
  // A group's members are found again from the particles' group indices after a migration.
  for (std::size_t g = 0; g < w.groups.size() && !what; ++g)
    for (const std::int32_t i : w.groups[g].members)
      if (w.particles.group[i] != static_cast<std::int32_t>(g)) what = "groups whose members' Particles::group differ";
  std::size_t members = 0, grouped = 0;
  for (const Group& g : w.groups) members += g.members.size();
  for (const std::int32_t g : w.particles.group) grouped += g >= 0 ? 1 : 0;
  if (!what && members != grouped) what = "groups whose members' Particles::group differ";
  if (what)
    throw InputError(
        fmt::format("domain decomposition does not support {} yet: run this case in one process, on "
                    "threads (swarf run --threads N)",
                    what));
}

DomainRun::DomainRun(Comm& comm, const World& global, const StepSettings& settings, DomainSettings ds)
    : comm_(comm), ds_(std::move(ds)), settings_(settings) {
  check_supported(global, settings);
  const int rank = comm_.rank(), size = comm_.size();
  if (!(ds_.skin >= 0.0)) throw InputError(fmt::format("domains: skin = {} m must be at least 0", ds_.skin));
  if (ds_.rebalance_every < 1)
    throw InputError(fmt::format("domains: rebalance_every = {} must be at least 1", ds_.rebalance_every));
  if (ds_.check_every < 1)
    throw InputError(fmt::format("domains: check_every = {} must be at least 1", ds_.check_every));
  if (!ds_.fixed_cuts.empty() && ds_.partitioner)
    throw InputError("domains: fixed cut planes and a partitioner are exclusive");
  if (!ds_.fixed_cuts.empty() && static_cast<int>(ds_.fixed_cuts.size()) != size - 1)
    throw InputError(
        fmt::format("domains: {} cut planes for {} ranks (one fewer than the ranks)", ds_.fixed_cuts.size(), size));
  contacts_ = global.contacts;
  if (contacts_) {
    // Every particle within reach of a rank's box is a copy there: a contact of an owned particle
    // then always has both ends at hand, as long as no particle moves more than half the lists'
    // skin between migrations (step()).
    double largest = 0.0;
    for (const double r : global.particles.radius) largest = std::max(largest, r);
    contact_skin_ = global.contact.skin;
    reach_ = 2.0 * largest + contact_skin_;
  }
  copy_configuration(global, local_);  // (no particles and no rods yet: adopt brings them)
  global_rods_ = static_cast<std::int64_t>(global.rods.size());
  if (global.rods.formation.enabled()) {
    for (std::size_t k = 0; k < global.rods.size(); ++k)
      if (k >= global.rods.formed.size() || !global.rods.formed[k])
        for (const std::int32_t i : global.rods.ends[k]) lattice_ids_.push_back(global.particles.id[i]);
    std::sort(lattice_ids_.begin(), lattice_ids_.end());
    lattice_ids_.erase(std::unique(lattice_ids_.begin(), lattice_ids_.end()), lattice_ids_.end());
  }
  local_.particles.next_id = global.particles.next_id;
  Particles& gp = const_cast<Particles&>(global.particles);  // (records are read through for_each_field)
  Rods& gr = const_cast<Rods&>(global.rods);
  const std::size_t n = gp.size();
  // Per global particle: 1 + its intact rods (the partition's weight).
  std::vector<std::int64_t> w(n, 1);
  for (std::size_t k = 0; k < gr.size(); ++k)
    if (gr.intact[k]) ++w[gr.ends[k][0]], ++w[gr.ends[k][1]];
  if (!ds_.fixed_cuts.empty()) {
    partition_ = Partition::slabs(ds_.fixed_cuts);
  } else {
    // Each rank contributes a share of the global particles (any split gives the same slabs).
    const std::size_t a = n * rank / size, b = n * (rank + 1) / size;
    repartition(std::vector<Vec3>(gp.position.begin() + a, gp.position.begin() + b),
                std::vector<std::int64_t>(w.begin() + a, w.begin() + b));
  }
  // This rank's particles, their rods and the rods' other ends, from the global World.
  std::vector<std::int64_t> owned_ids;
  std::vector<std::uint8_t> needed(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (partition_.owner(gp.position[i]) == rank) {
      owned_ids.push_back(gp.id[i]);
      needed[i] = 1;
    }
    if (contacts_ && partition_.near(gp.position[i], rank, reach_)) needed[i] = 1;  // (a spatial ghost)
  }
  std::sort(owned_ids.begin(), owned_ids.end());
  RodPool rods;
  Bytes buf;
  for (std::size_t k = 0; k < gr.size(); ++k) {
    const auto [i, j] = gr.ends[k];
    if (partition_.owner(gp.position[i]) != rank && partition_.owner(gp.position[j]) != rank) continue;
    buf.clear();
    pack_rod(buf, gr, k, static_cast<std::int64_t>(k), {gp.id[i], gp.id[j]});
    unpack_rod(buf.data(), rods);
    needed[i] = needed[j] = 1;
  }
  Particles pool;
  pool.layout = gp.layout;  // (a record holds the groups its source holds)
  for (std::size_t i = 0; i < n; ++i)
    if (needed[i]) {
      buf.clear();
      pack_particle(buf, gp, i);
      unpack_new_particle(buf.data(), pool);
    }
  adopt(assemble(pool, std::vector<std::uint8_t>(pool.size(), 1), rods, owned_ids, ContactPool{}));
  exchange_halo();  // (the Simulation's first evaluation gave the ghosts partial forces)
  if (contacts_) book_contacts(true);
}

DomainRun::DomainRun(Comm& comm, const Simulation& start, DomainSettings ds,
                     const std::vector<std::int64_t>* ledger_digits)
    : DomainRun(comm, start.world(), start.settings(), std::move(ds)) {
  // The local Simulation's construction evaluated the forces of the state as it is: right for a
  // run's first step, not for one that goes on (an acceleration is the last step's, made with
  // its half-step velocities). Every local particle takes its record from 'start' again.
  // So do the contacts (their friction histories): those of start with an owned end here.
  Particles& gp = const_cast<Particles&>(start.world().particles);
  const Particles& p = local_.particles;
  const auto global_index = [&](std::int64_t id) {
    return static_cast<std::size_t>(std::lower_bound(gp.id.begin(), gp.id.end(), id) - gp.id.begin());
  };
  ContactSystem::Records contacts;
  if (contacts_) {
    // start's index -> local index (-1: not here)
    std::vector<std::int32_t> local(gp.size(), -1);
    for (std::size_t i = 0; i < p.size(); ++i) local[global_index(p.id[i])] = static_cast<std::int32_t>(i);
    const ContactSystem::Records all = start.contacts().records();
    for (ContactSystem::PairRecord q : all.pairs) {
      q.i = local[q.i];
      q.j = local[q.j];
      if (q.i >= 0 && q.j >= 0 && (owned_[q.i] || owned_[q.j])) contacts.pairs.push_back(q);
    }
    for (ContactSystem::TriangleRecord q : all.triangles) {
      q.i = local[q.i];
      if (q.i >= 0 && owned_[q.i]) contacts.triangles.push_back(q);
    }
  }
  sim_->overwrite_records(
      [&](Particles& lp, Rods&) {
        Bytes buf;
        for (std::size_t i = 0; i < lp.size(); ++i) {
          buf.clear();
          pack_particle(buf, gp, global_index(lp.id[i]));
          unpack_particle(buf.data(), lp, i);
        }
      },
      &contacts);
  copy_step_state(start, *sim_);
  if (contacts_) {
    mesh_force_.resize(start.world().meshes.size());
    for (std::size_t k = 0; k < mesh_force_.size(); ++k) mesh_force_[k] = start.mesh_force(k);
    contact_power_ = start.contact_power();
  }
  sim_->count_exactly(nullptr);  // (the grips' exact share starts from the forces as they are now)
  sim_->count_exactly(owned_.data(), rod_key_.data());
  if (comm_.rank() == 0) {
    // The exact sums a checkpoint of a run over ranks kept (of the first four lines only if
    // written before the contacts' line joined them), the rest from start's doubles.
    const std::size_t lines = ledger_digits ? ledger_digits->size() / ExactSum::kWords : 0;
    if (ledger_digits && (ledger_digits->size() % ExactSum::kWords != 0 || (lines != kLedgerLines && lines != 4)))
      throw std::logic_error(fmt::format("domains: {} words of ledger digits, {} expected", ledger_digits->size(),
                                         kLedgerLines * ExactSum::kWords));
    for (std::size_t k = 0; k < lines; ++k) base_[k] = ExactSum::from_digits(*ledger_digits, k * ExactSum::kWords);
    const EnergyLedger& l = start.ledger();
    const double plain[kLedgerLines] = {l.plastic_work,  l.viscous_work,  l.fracture_energy,
                                        l.external_work, l.contact_work,  l.heat_plastic,
                                        l.heat_friction, l.heat_to_tools, l.heat_to_clamps};
    for (std::size_t k = lines; k < kLedgerLines; ++k) base_[k].add(plain[k]);
  }
}

std::size_t DomainRun::owned_count() const {
  return static_cast<std::size_t>(std::count(owned_.begin(), owned_.end(), std::uint8_t{1}));
}

DomainRun::Local DomainRun::assemble(Particles& pool, const std::vector<std::uint8_t>& exact, RodPool& rods,
                                     const std::vector<std::int64_t>& owned_ids, const ContactPool& contacts) const {
  Local l;
  l.particles.layout = pool.layout;
  // The rods with an owned end, once each, in the global order.
  std::vector<std::size_t> ro(rods.key.size());
  std::iota(ro.begin(), ro.end(), std::size_t{0});
  std::stable_sort(ro.begin(), ro.end(), [&](std::size_t a, std::size_t b) { return rods.key[a] < rods.key[b]; });
  std::vector<std::size_t> keep;
  std::vector<std::int64_t> ids = owned_ids;
  for (std::size_t q = 0; q < ro.size(); ++q) {
    const std::size_t k = ro[q];
    if (q > 0 && rods.key[ro[q - 1]] == rods.key[k]) continue;  // (copies of one rod are identical)
    const auto [a, b] = rods.end_id[k];
    if (!contains(owned_ids, a) && !contains(owned_ids, b)) continue;
    keep.push_back(k);
    ids.push_back(a);
    ids.push_back(b);
  }
  // With contacts, every particle within reach of the box (its owner sent it).
  if (contacts_)
    for (std::size_t q = 0; q < pool.size(); ++q)
      if (partition_.near(pool.position[q], comm_.rank(), reach_)) ids.push_back(pool.id[q]);
  // The particles: the owned ones, the rods' other ends and the spatial ghosts, once each, in id order.
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  std::vector<std::size_t> po(pool.size());
  std::iota(po.begin(), po.end(), std::size_t{0});
  std::stable_sort(po.begin(), po.end(), [&](std::size_t a, std::size_t b) { return pool.id[a] < pool.id[b]; });
  Bytes buf;
  std::size_t q = 0;
  for (const std::int64_t id : ids) {
    while (q < po.size() && pool.id[po[q]] < id) ++q;
    if (q == po.size() || pool.id[po[q]] != id)
      throw std::logic_error(fmt::format("domain {}: particle {} is needed but was not sent", comm_.rank(), id));
    // Of several copies, an exact one (its owner's): a ghost's copy is exact only in the fields
    // the halo sends, and a particle arriving here as owned must bring all of them.
    std::size_t pick = po[q];
    for (std::size_t c = q; c < po.size() && pool.id[po[c]] == id; ++c)
      if (exact[po[c]]) {
        pick = po[c];
        break;
      }
    buf.clear();
    pack_particle(buf, pool, pick);
    unpack_new_particle(buf.data(), l.particles);
    l.owned.push_back(contains(owned_ids, id) ? 1 : 0);
  }
  l.particles.next_id = local_.particles.next_id;
  // The rods, their ends as local indices (ascending, as in the serial run: the particles are in id order).
  const auto local = [&](std::int64_t id) {
    return static_cast<std::int32_t>(std::lower_bound(ids.begin(), ids.end(), id) - ids.begin());
  };
  for (const std::size_t k : keep) {
    l.key.push_back(rods.key[k]);
    l.rods.ends.push_back({local(rods.end_id[k][0]), local(rods.end_id[k][1])});
  }
  l.rods.for_each_field_with(rods.rods, [&](auto& mine, auto& theirs) {  // (field by field: one walk of the fields)
    mine.reserve(keep.size());
    for (const std::size_t k : keep) mine.push_back(theirs[k]);
  });
  // The contacts of the owned particles (every record in the pool is its owner's: copies of one
  // contact are identical), once each, sorted as the lists are: by the particles' ids.
  std::vector<std::size_t> co(contacts.pairs.size());
  std::iota(co.begin(), co.end(), std::size_t{0});
  std::sort(co.begin(), co.end(),
            [&](std::size_t a, std::size_t b) { return contacts.pair_ids[a] < contacts.pair_ids[b]; });
  for (std::size_t q = 0; q < co.size(); ++q) {
    const std::size_t k = co[q];
    const auto [a, b] = contacts.pair_ids[k];
    if (q > 0 && contacts.pair_ids[co[q - 1]] == contacts.pair_ids[k]) continue;
    if (!contains(owned_ids, a) && !contains(owned_ids, b)) continue;
    if (!contains(ids, a) || !contains(ids, b))
      throw std::logic_error(fmt::format("domain {}: contact ({}, {}) has an end that is not here", comm_.rank(), a, b));
    ContactSystem::PairRecord r = contacts.pairs[k];
    r.i = local(a);
    r.j = local(b);
    l.contacts.pairs.push_back(r);
  }
  std::vector<std::size_t> to(contacts.tris.size());
  std::iota(to.begin(), to.end(), std::size_t{0});
  const auto tri_key = [&](std::size_t k) { return std::pair{contacts.tri_ids[k], contacts.tris[k].tri}; };
  std::sort(to.begin(), to.end(), [&](std::size_t a, std::size_t b) { return tri_key(a) < tri_key(b); });
  for (std::size_t q = 0; q < to.size(); ++q) {
    const std::size_t k = to[q];
    if (q > 0 && tri_key(to[q - 1]) == tri_key(k)) continue;
    if (!contains(owned_ids, contacts.tri_ids[k])) continue;
    ContactSystem::TriangleRecord r = contacts.tris[k];
    r.i = local(contacts.tri_ids[k]);
    l.contacts.triangles.push_back(r);
  }
  return l;
}

DomainRun::ContactPool DomainRun::own_contacts(bool any_end) const {
  ContactPool out;
  if (!contacts_) return out;
  const Particles& p = local_.particles;
  const ContactSystem::Records r = sim_->contacts().records();
  for (const ContactSystem::PairRecord& q : r.pairs)
    if (owned_[q.i] || (any_end && owned_[q.j])) {
      out.pair_ids.push_back({p.id[q.i], p.id[q.j]});
      out.pairs.push_back(q);
    }
  for (const ContactSystem::TriangleRecord& q : r.triangles)
    if (owned_[q.i]) {
      out.tri_ids.push_back(p.id[q.i]);
      out.tris.push_back(q);
    }
  return out;
}

ContactSystem::Records DomainRun::gather_contacts(const std::vector<std::int64_t>& ids, bool all) {
  Bytes mine;
  own_contacts(false).put(mine);
  std::vector<Bytes> parts;
  if (all) {
    parts = comm_.all_gather(std::move(mine));
  } else {
    comm_.gather_to_root(mine, parts);
    if (comm_.rank() != 0) return {};
    parts[0] = std::move(mine);
  }
  ContactPool pool;
  for (const Bytes& b : parts) {
    const std::byte* at = b.data();
    pool.get(at);
  }
  const auto index = [&](std::int64_t id) {
    const auto it = std::lower_bound(ids.begin(), ids.end(), id);
    if (it == ids.end() || *it != id)
      throw std::logic_error(fmt::format("domains: a contact's particle, id {}, is owned by no rank", id));
    return static_cast<std::int32_t>(it - ids.begin());
  };
  ContactSystem::Records out;
  for (std::size_t k = 0; k < pool.pairs.size(); ++k) {
    out.pairs.push_back(pool.pairs[k]);
    out.pairs.back().i = index(pool.pair_ids[k][0]);
    out.pairs.back().j = index(pool.pair_ids[k][1]);
  }
  for (std::size_t k = 0; k < pool.tris.size(); ++k) {
    out.triangles.push_back(pool.tris[k]);
    out.triangles.back().i = index(pool.tri_ids[k]);
  }
  // (each contact once: a pair from the owner of its first end; sorted as the lists are)
  std::sort(out.pairs.begin(), out.pairs.end(), [](const auto& a, const auto& b) {
    return std::pair{a.i, a.j} < std::pair{b.i, b.j};
  });
  std::sort(out.triangles.begin(), out.triangles.end(), [](const auto& a, const auto& b) {
    return std::pair{a.i, a.tri} < std::pair{b.i, b.tri};
  });
  return out;
}

void DomainRun::book_contacts(bool start) {
  std::vector<ExactSum> parts = sim_->contacts().mesh_forces_exact(owned_.data());
  parts.push_back(sim_->contact_power_exact(owned_.data()));
  const std::vector<ExactSum> total = comm_.sum_exact(parts);
  const std::size_t nm = local_.meshes.size();
  std::vector<Vec3> force(nm);
  for (std::size_t k = 0; k < nm; ++k)
    for (int c = 0; c < 3; ++c) force[k][c] = total[3 * k + c].value();
  // (the contacts' power on the particles and, as integrate::contact_power adds it, on the meshes)
  double power = total.back().value();
  for (std::size_t k = 0; k < nm; ++k) power += force[k].dot(local_.meshes[k].velocity);
  if (!start && comm_.rank() == 0) {
    // As the step's account books them (integrate/stages.cpp), from the reduced sums: the same
    // bits for any rank count.
    const double h = sim_->last_dt();
    for (std::size_t k = 0; k < nm; ++k)
      base_[3].add(-(0.5 * (mesh_force_[k] + force[k]).dot(local_.meshes[k].velocity * h)));
    base_[4].add(-(0.5 * (contact_power_ + power) * h));
  }
  mesh_force_ = std::move(force);
  contact_power_ = power;
}

void DomainRun::adopt(Local&& l) {
  owned_ = std::move(l.owned);
  rod_key_ = std::move(l.key);
  if (!sim_) {
    local_.particles = std::move(l.particles);
    local_.rods.ends = std::move(l.rods.ends);
    local_.rods.for_each_field_with(l.rods, [](auto& mine, auto& theirs) { mine = std::move(theirs); });
    local_.rods.build_rows(local_.particles.size());
    for (Group& g : local_.groups) g.members.clear();  // (as Simulation::replace_particles finds them)
    for (std::size_t i = 0; i < local_.particles.size(); ++i)
      if (const std::int32_t g = local_.particles.group[i]; g >= 0)
        local_.groups[g].members.push_back(static_cast<std::int32_t>(i));
    sim_ = std::make_unique<Simulation>(local_, settings_);
    sim_->set_exchange(this);
  } else {
    sim_->replace_particles(std::move(l.particles), std::move(l.rods), contacts_ ? &l.contacts : nullptr);
  }
  sim_->count_exactly(owned_.data(), rod_key_.data());  // (each rod booked by its first end's owner)
  if (local_.rods.formation.enabled()) {                // (its candidates, asked for every contact pair of every step)
    const auto& id = local_.particles.id;
    lattice_local_.resize(id.size());
    for (std::size_t i = 0; i < id.size(); ++i)
      lattice_local_[i] = std::binary_search(lattice_ids_.begin(), lattice_ids_.end(), id[i]);
  }
  if (contacts_) x_migrated_ = local_.particles.position;
  plan_halo();
}

void DomainRun::plan_halo() {
  const int size = comm_.size(), rank = comm_.rank();
  const Particles& p = local_.particles;
  // Ask each owner for the ghosts it owns (by id, in local order).
  std::vector<std::vector<std::int64_t>> want(size);
  recv_.assign(size, {});
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (owned_[i]) continue;
    const int o = partition_.owner(p.position[i]);
    if (o == rank) throw std::logic_error(fmt::format("domain {}: ghost {} lies in its own box", rank, p.id[i]));
    want[o].push_back(p.id[i]);
    recv_[o].push_back(static_cast<std::int32_t>(i));
  }
  std::vector<Bytes> ask(size);
  for (int r = 0; r < size; ++r) ask[r] = Comm::to_bytes(want[r]);
  const std::vector<Bytes> asked = comm_.all_to_all(std::move(ask));
  send_.assign(size, {});
  for (int r = 0; r < size; ++r)
    for (const std::int64_t id : Comm::from_bytes<std::int64_t>(asked[r])) {
      const auto it = std::lower_bound(p.id.begin(), p.id.end(), id);  // (local particles are in id order)
      if (it == p.id.end() || *it != id || !owned_[it - p.id.begin()])
        throw std::logic_error(fmt::format("domain {}: rank {} asks for particle {}, not owned here", rank, r, id));
      send_[r].push_back(static_cast<std::int32_t>(it - p.id.begin()));
    }
}

void DomainRun::exchange_halo() { exchange_halo(HaloFields{sim_->rotations(), local_.heat.enabled}); }

void DomainRun::temperatures() { exchange_halo(HaloFields{false, true, false}); }

double DomainRun::min_all(double v) { return -comm_.max_all(-v); }

void DomainRun::exchange_halo(HaloFields fields) {
  const int size = comm_.size();
  Particles& p = local_.particles;
  std::vector<Bytes> out(size);
  const std::size_t record = fields.bytes();
  for (int r = 0; r < size; ++r) {
    out[r].reserve(send_[r].size() * record);
    for (const std::int32_t i : send_[r]) pack_kinematics(out[r], p, i, fields);
  }
  halo_bytes_ = 0;
  for (const Bytes& b : out) halo_bytes_ += b.size();
  // (the sizes are the plan's: point to point with the neighbours only)
  std::vector<std::size_t> expect(size);
  for (int r = 0; r < size; ++r) expect[r] = recv_[r].size() * record;
  const std::vector<Bytes> in = comm_.exchange(std::move(out), expect);
  for (int r = 0; r < size; ++r) {
    if (in[r].size() != expect[r])
      throw std::logic_error(
          fmt::format("domains: halo from rank {}: {} bytes, {} expected", r, in[r].size(), expect[r]));
    const std::byte* at = in[r].data();
    for (const std::int32_t i : recv_[r]) at += unpack_kinematics(at, p, i, fields);
  }
}

Particles DomainRun::gather_owned() {
  Particles& p = local_.particles;
  Bytes mine;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (owned_[i]) pack_particle(mine, p, i);
  Particles all;
  all.layout = p.layout;
  for (const Bytes& b : comm_.all_gather(std::move(mine)))
    for (const std::byte* at = b.data(); at != b.data() + b.size();) at += unpack_new_particle(at, all);
  std::vector<std::size_t> order(all.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return all.id[a] < all.id[b]; });
  Particles out;
  out.layout = p.layout;
  Bytes buf;
  for (const std::size_t i : order) {
    buf.clear();
    pack_particle(buf, all, i);
    unpack_new_particle(buf.data(), out);
  }
  out.next_id = p.next_id;
  return out;
}

DomainRun::Sums DomainRun::sums() {
  const Rods& r = local_.rods;
  std::vector<std::uint8_t> first_end_owned(r.size());
  std::int64_t broken = 0;
  for (std::size_t k = 0; k < r.size(); ++k) {
    first_end_owned[k] = owned_[r.ends[k][0]];
    if (first_end_owned[k] && !r.intact[k]) ++broken;
  }
  const RodSystem::ExactLedger& x = sim_->exact_ledger();
  const GroupSystem::ExactShare& gx = sim_->exact_group_share();
  const ThermalSystem::ExactShare& hx = sim_->thermal().exact_share();
  std::vector<ExactSum> parts = {sim_->particle_kinetic_energy(owned_.data()),
                                 sim_->rod_elastic_energy(first_end_owned.data()),
                                 contacts_ ? sim_->contacts().elastic_energy_exact(owned_.data()) : ExactSum{},
                                 x.plastic_work,
                                 x.viscous_work,
                                 x.fracture_energy,
                                 gx.external_work,
                                 ExactSum{},
                                 hx.plastic,
                                 hx.friction,
                                 hx.to_tools,
                                 hx.to_clamps};
  constexpr std::size_t kLine = 3;  // parts[kLine + k]: ledger line k
  // (what rank 0 booked: before the run started here, and the meshes' and contacts' lines)
  for (std::size_t k = 0; k < kLedgerLines; ++k) parts[kLine + k].add(base_[k]);
  const std::size_t ng = local_.groups.size();
  for (std::size_t g = 0; g < ng; ++g)
    for (int c = 0; c < 3; ++c) parts.push_back(gx.reaction[g][c]);  // (sized when counting began)
  const std::vector<ExactSum> total = comm_.sum_exact(parts);
  Sums s;
  s.kinetic_energy = total[0].value();
  s.elastic_energy = total[1].value();
  s.contact_energy = total[2].value();
  s.plastic_work = total[kLine].value();
  s.viscous_work = total[kLine + 1].value();
  s.fracture_energy = total[kLine + 2].value();
  s.external_work = total[kLine + 3].value();
  s.contact_work = total[kLine + 4].value();
  s.heat_plastic = total[kLine + 5].value();
  s.heat_friction = total[kLine + 6].value();
  s.heat_to_tools = total[kLine + 7].value();
  s.heat_to_clamps = total[kLine + 8].value();
  ledger_digits_.clear();
  for (std::size_t k = 0; k < kLedgerLines; ++k) {
    const std::vector<std::int64_t> d = total[kLine + k].digits();
    ledger_digits_.insert(ledger_digits_.end(), d.begin(), d.end());
  }
  s.reactions.resize(ng);
  for (std::size_t g = 0; g < ng; ++g)
    for (int c = 0; c < 3; ++c) s.reactions[g][c] = total[kLine + kLedgerLines + 3 * g + c].value();
  s.mesh_forces = mesh_force_;  // (reduced after every step)
  s.broken_rods = comm_.sum_all(broken);
  return s;
}

World DomainRun::gather_world() {
  World out;
  copy_configuration(local_, out);
  out.particles = gather_owned();
  // Each rod once, from the owner of its first end, with its key and its ends' ids.
  Rods& r = local_.rods;
  const Particles& p = local_.particles;
  Bytes mine;
  for (std::size_t k = 0; k < r.size(); ++k)
    if (owned_[r.ends[k][0]]) pack_rod(mine, r, k, rod_key_[k], {p.id[r.ends[k][0]], p.id[r.ends[k][1]]});
  RodPool pool;
  for (const Bytes& b : comm_.all_gather(std::move(mine)))
    for (const std::byte* at = b.data(); at != b.data() + b.size();) at += unpack_rod(at, pool);
  const std::size_t m = pool.key.size();
  std::vector<std::size_t> order(m);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return pool.key[a] < pool.key[b]; });
  const std::vector<std::int64_t>& ids = out.particles.id;  // (ascending: gather_owned's order)
  const auto index = [&](std::int64_t id) {
    const auto it = std::lower_bound(ids.begin(), ids.end(), id);
    if (it == ids.end() || *it != id)
      throw std::logic_error(fmt::format("domains: a rod's end, particle id {}, is owned by no rank", id));
    return static_cast<std::int32_t>(it - ids.begin());
  };
  out.rods.ends.resize(m);
  for (std::size_t q = 0; q < m; ++q)
    out.rods.ends[q] = {index(pool.end_id[order[q]][0]), index(pool.end_id[order[q]][1])};
  out.rods.for_each_field_with(pool.rods, [&](auto& mine_field, auto& theirs) {
    mine_field.resize(m);
    for (std::size_t q = 0; q < m; ++q) mine_field[q] = theirs[order[q]];
  });
  out.rods.build_rows(out.particles.size());
  for (Group& g : out.groups) g.members.clear();
  for (std::size_t i = 0; i < out.particles.size(); ++i)
    if (const std::int32_t g = out.particles.group[i]; g >= 0)
      out.groups[g].members.push_back(static_cast<std::int32_t>(i));
  return out;
}

std::unique_ptr<Simulation> DomainRun::gather_simulation(World& storage) {
  storage = gather_world();
  World records = storage;  // (the Simulation's construction evaluates forces over 'storage')
  const ContactSystem::Records contacts = contacts_ ? gather_contacts(storage.particles.id, true)
                                                    : ContactSystem::Records{};
  auto out = std::make_unique<Simulation>(storage, settings_);
  out->replace_particles(std::move(records.particles), std::move(records.rods), contacts_ ? &contacts : nullptr);
  load_sums_into(*out);
  return out;
}

void DomainRun::gather_into(Simulation& mirror) {
  // Each rank's owned particles (each record after its id) and the rods whose first end it owns,
  // to rank 0, which writes them over the mirror's: the same particles, in id order, and the
  // same rods, in the global order (no particle or rod is made or removed over ranks yet).
  Particles& p = local_.particles;
  Rods& r = local_.rods;
  std::uint64_t np = 0, nr = 0;
  for (std::size_t i = 0; i < p.size(); ++i) np += owned_[i];
  for (std::size_t k = 0; k < r.size(); ++k) nr += owned_[r.ends[k][0]];
  // One buffer, kept from gather to gather, sized once and filled in place.
  const std::size_t pb = sizeof(std::int64_t) + particle_record_bytes(p), rb = rod_record_bytes(r);
  Bytes& mine = gather_out_;
  mine.resize(2 * sizeof(std::uint64_t) + np * pb + nr * rb);
  std::byte* at = mine.data();
  std::memcpy(at, &np, sizeof np);
  at += sizeof np;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (owned_[i]) {
      std::memcpy(at, &p.id[i], sizeof(std::int64_t));
      at += sizeof(std::int64_t);
      at += write_particle(at, p, i);
    }
  std::memcpy(at, &nr, sizeof nr);
  at += sizeof nr;
  for (std::size_t k = 0; k < r.size(); ++k)
    if (owned_[r.ends[k][0]]) at += write_rod(at, r, k, rod_key_[k], {p.id[r.ends[k][0]], p.id[r.ends[k][1]]});
  comm_.gather_to_root(mine, gather_in_);
  // The contacts: each pair from the owner of its first end, each triangle contact from its particle's.
  const ContactSystem::Records contacts = contacts_ ? gather_contacts(mirror.world().particles.id, false)
                                                    : ContactSystem::Records{};
  MemoryArchive state = sums_archive();
  if (comm_.rank() == 0) {
    // The step state first: the contacts are found again where the meshes are now.
    load_step_state(state, mirror);
    // Where each record lies: the particles' (after their ids) and the rods' (their heads).
    std::vector<std::pair<std::int64_t, const std::byte*>> precs;
    std::vector<std::pair<RodHead, const std::byte*>> rrecs;
    const std::size_t pbytes = particle_record_bytes(p);
    for (int rank = 0; rank < comm_.size(); ++rank) {
      const std::byte* at = rank == 0 ? mine.data() : gather_in_[rank].data();
      for (std::uint64_t n = get_count(at), q = 0; q < n; ++q) {
        const auto id = static_cast<std::int64_t>(get_count(at));
        precs.emplace_back(id, at);
        at += pbytes;
      }
      for (std::uint64_t m = get_count(at), q = 0; q < m; ++q) {
        rrecs.emplace_back(rod_head(at), at);
        at += rb;
      }
    }
    const Particles& current = mirror.world().particles;
    const auto index = [&](std::int64_t id) {
      const auto it = std::lower_bound(current.id.begin(), current.id.end(), id);
      if (it == current.id.end() || *it != id)
        throw std::logic_error(fmt::format("domains: particle id {} is not in the mirror", id));
      return static_cast<std::int32_t>(it - current.id.begin());
    };
    if (precs.size() != current.size() || static_cast<std::int64_t>(rrecs.size()) != global_rods_)
      throw std::logic_error(fmt::format("domains: {} particles and {} rods gathered, the run has {} and {}",
                                         precs.size(), rrecs.size(), current.size(), global_rods_));
    // The mirror's rods are the run's unless bond formation changed them since the last gather.
    const Rods& mirror_rods = mirror.world().rods;
    bool same_rods = mirror_rods.size() == rrecs.size();
    for (std::size_t q = 0; q < rrecs.size() && same_rods; ++q) {
      const RodHead& h = rrecs[q].first;
      const auto k = static_cast<std::size_t>(h.key);
      same_rods = h.key >= 0 && k < mirror_rods.size() && current.id[mirror_rods.ends[k][0]] == h.end_id[0] &&
                  current.id[mirror_rods.ends[k][1]] == h.end_id[1];
    }
    const auto write_particles = [&](Particles& mp) {
      for (const auto& [id, at] : precs) unpack_particle(at, mp, static_cast<std::size_t>(index(id)));
    };
    if (same_rods) {
      mirror.overwrite_records(
          [&](Particles& mp, Rods& mr) {
            write_particles(mp);
            for (const auto& [h, at] : rrecs) unpack_rod_over(at, mr, static_cast<std::size_t>(h.key));
          },
          contacts_ ? &contacts : nullptr);
    } else {
      // (the run's rods in their keys' order, ends as the mirror's indices)
      Particles mp = current;
      write_particles(mp);
      Rods mr;
      mr.ends.resize(rrecs.size());
      mr.for_each_field([&](const char*, auto& v) { v.resize(rrecs.size()); });
      for (const auto& [h, at] : rrecs) {
        const auto k = static_cast<std::size_t>(h.key);
        if (h.key < 0 || k >= rrecs.size())
          throw std::logic_error(fmt::format("domains: rod key {} of {} rods", h.key, rrecs.size()));
        mr.ends[k] = {index(h.end_id[0]), index(h.end_id[1])};
        unpack_rod_over(at, mr, k);
      }
      mirror.replace_particles(std::move(mp), std::move(mr), contacts_ ? &contacts : nullptr);
    }
  }
  state.set("broken_rods", static_cast<std::int64_t>(mirror.broken_rods()));  // (counted from its records)
  load_step_state(state, mirror);
}

void DomainRun::load_sums_into(Simulation& out) {
  MemoryArchive a = sums_archive();
  a.set("broken_rods", static_cast<std::int64_t>(out.broken_rods()));  // (counted from its records)
  load_step_state(a, out);
}

MemoryArchive DomainRun::sums_archive() {
  const Sums s = sums();
  MemoryArchive a = save_step_state(*sim_);
  // The run's sums where this rank's Simulation has its own share.
  a.set("ledger/plastic_work", s.plastic_work);
  a.set("ledger/viscous_work", s.viscous_work);
  a.set("ledger/fracture_energy", s.fracture_energy);
  a.set("ledger/external_work", s.external_work);
  a.set("ledger/contact_work", s.contact_work);
  if (local_.heat.enabled) {
    a.set("ledger/heat_plastic", s.heat_plastic);
    a.set("ledger/heat_friction", s.heat_friction);
    a.set("ledger/heat_to_tools", s.heat_to_tools);
    a.set("ledger/heat_to_clamps", s.heat_to_clamps);
  }
  a.set("groups/reaction", s.reactions);
  if (contacts_) {
    a.set("mesh_force", s.mesh_forces);
    a.set("contact_power_old", contact_power_);
  }
  return a;
}

std::vector<std::int64_t> DomainRun::weights() const {
  const Rods& r = local_.rods;
  std::vector<std::int64_t> w(local_.particles.size(), 1);
  for (std::size_t k = 0; k < r.size(); ++k)
    if (r.intact[k]) ++w[r.ends[k][0]], ++w[r.ends[k][1]];
  return w;
}

void DomainRun::step(double max_dt) {
  sim_->step(max_dt);
  const auto t0 = std::chrono::steady_clock::now();
  exchange_halo();
  if (contacts_) book_contacts(false);
  ++steps_;
  // Every rebalance_every steps new boxes (or slabs); in between, when a particle strayed beyond
  // its box and skin (looked for every check_every steps), every particle goes to the owner of
  // its box, the boxes kept. With contacts the ghosts are spatial: all particles move to their
  // boxes' owners and the ghost layers are made anew once any particle has moved half the
  // lists' skin since the last time (looked for after every step), so that a contact of an
  // owned particle never misses its other end.
  const bool recut = steps_ % ds_.rebalance_every == 0;
  bool stray = false;
  if (contacts_ && !recut) {
    // Where each particle will be after the next step's drift (x + h (v + h/2 a), as the
    // explicit step moves it; prescribed components move less than that bound allows for), so
    // that the layers are made anew before the step whose contacts would need more, as the
    // contact lists of one process are rebuilt before that step's evaluation (and as LAMMPS
    // checks its skin before the forces). Measured after the step, the check was one step late:
    // a default cut over 2 ranks parted from 1 rank's bits after 145 us.
    const Particles& p = local_.particles;
    const double h = sim_->dt();
    double moved2 = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (owned_[i]) {
        const Vec3 next = p.position[i] + h * (p.velocity[i] + (0.5 * h) * p.acceleration[i]);
        moved2 = std::max(moved2, (next - x_migrated_[i]).squaredNorm());
      }
    const double half = 0.5 * contact_skin_ * (1.0 - 1e-6);  // (a hair for the drift's own rounding)
    stray = !(comm_.max_all(moved2) <= half * half);         // (NaN: migrate; the next step fails)
  } else if (!recut && steps_ % ds_.check_every == 0) {
    const int rank = comm_.rank();
    const Particles& p = local_.particles;
    double left = 0.0;
    for (std::size_t i = 0; i < p.size() && left == 0.0; ++i)
      if (owned_[i] && !partition_.near(p.position[i], rank, ds_.skin)) left = 1.0;
    stray = comm_.max_all(left) > 0.0;
  }
  if (stray || recut) migrate(recut);
  exchange_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void DomainRun::repartition(const std::vector<Vec3>& x, const std::vector<std::int64_t>& w) {
  if (ds_.partitioner) {
    partition_ = Partition(ds_.partitioner->partition(x, w, !local_.periodic.on()));
    if (partition_.ranks() != comm_.size())
      throw std::logic_error(
          fmt::format("domains: the partitioner made {} boxes for {} ranks", partition_.ranks(), comm_.size()));
    // Every rank must own by the same boxes (a partitioner's collective gives them to all; a
    // rank with other boxes would own particles twice or not at all): one gather per rebalance.
    Bytes mine(partition_.boxes().size() * sizeof(DomainBox));
    std::memcpy(mine.data(), partition_.boxes().data(), mine.size());
    for (const Bytes& theirs : comm_.all_gather(mine))
      if (theirs != mine)
        throw std::logic_error("domains: the partitioner gave the ranks different boxes (" + ds_.partitioner->name() +
                               ")");
    return;
  }
  std::vector<double> xs(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) xs[i] = x[i][0];
  partition_ = Partition::balanced_slabs(comm_, xs, w);
}

void DomainRun::migrate(bool recut) {
  const int size = comm_.size(), rank = comm_.rank();
  Particles& p = local_.particles;
  Rods& r = local_.rods;
  ++migrations_;
  if (recut && ds_.fixed_cuts.empty()) {
    const std::vector<std::int64_t> w = weights();  // (owned particles have all their rods here)
    std::vector<Vec3> x;
    std::vector<std::int64_t> ow;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (owned_[i]) x.push_back(p.position[i]), ow.push_back(w[i]);
    repartition(x, ow);
  }
  // Each particle leaving this rank goes with its rods and their other ends (the new owner's
  // ghosts) and its contacts; with contacts, every owned particle within reach of another
  // rank's box goes there too (a spatial ghost).
  std::vector<std::vector<std::int64_t>> leaving(size);
  std::vector<std::vector<std::int32_t>> with_particle(size), with_rod(size);  // local indices, per rank
  std::vector<std::int64_t> staying;
  std::vector<int> leaves_to(p.size(), -1);
  std::vector<int> within;  // (the ranks whose boxes a particle is within reach of)
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!owned_[i]) continue;
    const int o = partition_.owner(p.position[i]);
    if (contacts_) {
      partition_.near_ranks(p.position[i], reach_, within);
      for (const int q : within)
        if (q != o && q != rank) with_particle[q].push_back(static_cast<std::int32_t>(i));
    }
    if (o == rank) {
      staying.push_back(p.id[i]);
      continue;
    }
    leaves_to[i] = o;
    leaving[o].push_back(p.id[i]);
    with_particle[o].push_back(static_cast<std::int32_t>(i));
    for (std::int32_t e = r.row_start[i]; e < r.row_start[i + 1]; ++e) {
      with_rod[o].push_back(r.entries[e].rod);
      with_particle[o].push_back(r.entries[e].other);
    }
  }
  // The contacts this rank computed exactly; those of a leaving particle go with it.
  const ContactPool own = own_contacts(true);
  std::vector<ContactPool> with_contacts(size);
  for (std::size_t k = 0; k < own.pairs.size(); ++k) {
    const int a = leaves_to[own.pairs[k].i], b = leaves_to[own.pairs[k].j];
    for (const int o : {a, b == a ? -1 : b})
      if (o >= 0) {
        with_contacts[o].pair_ids.push_back(own.pair_ids[k]);
        with_contacts[o].pairs.push_back(own.pairs[k]);
      }
  }
  for (std::size_t k = 0; k < own.tris.size(); ++k)
    if (const int o = leaves_to[own.tris[k].i]; o >= 0) {
      with_contacts[o].tri_ids.push_back(own.tri_ids[k]);
      with_contacts[o].tris.push_back(own.tris[k]);
    }
  std::vector<Bytes> out(size);
  for (int o = 0; o < size; ++o) {
    if (o == rank) continue;
    Bytes& b = out[o];
    put_count(b, leaving[o].size());
    const Bytes ids = Comm::to_bytes(leaving[o]);
    b.insert(b.end(), ids.begin(), ids.end());
    for (auto* list : {&with_particle[o], &with_rod[o]}) {
      std::sort(list->begin(), list->end());
      list->erase(std::unique(list->begin(), list->end()), list->end());
    }
    put_count(b, with_particle[o].size());
    for (const std::int32_t i : with_particle[o]) {
      b.push_back(static_cast<std::byte>(owned_[i]));  // exact: the sender owns it
      pack_particle(b, p, i);
    }
    put_count(b, with_rod[o].size());
    for (const std::int32_t k : with_rod[o]) pack_rod(b, r, k, rod_key_[k], {p.id[r.ends[k][0]], p.id[r.ends[k][1]]});
    with_contacts[o].put(b);
  }
  const std::vector<Bytes> in = comm_.all_to_all(std::move(out));
  // What this rank has and what it received; the owned ids: those staying and those arriving.
  Particles pool;
  pool.layout = p.layout;
  std::vector<std::uint8_t> exact;  // per pool entry: the copy of the particle's owner
  RodPool rods;
  Bytes buf;
  for (std::size_t i = 0; i < p.size(); ++i) {
    buf.clear();
    pack_particle(buf, p, i);
    unpack_new_particle(buf.data(), pool);
    exact.push_back(owned_[i]);
  }
  for (std::size_t k = 0; k < r.size(); ++k) {
    buf.clear();
    pack_rod(buf, r, k, rod_key_[k], {p.id[r.ends[k][0]], p.id[r.ends[k][1]]});
    unpack_rod(buf.data(), rods);
  }
  std::vector<std::int64_t> owned_ids = std::move(staying);
  ContactPool contacts = own;
  for (int s = 0; s < size; ++s) {
    if (in[s].empty()) continue;
    const std::byte* at = in[s].data();
    const std::uint64_t arriving = get_count(at);
    for (std::uint64_t q = 0; q < arriving; ++q) {
      std::int64_t id;
      std::memcpy(&id, at, sizeof id);
      at += sizeof id;
      owned_ids.push_back(id);
    }
    arrivals_ += static_cast<std::int64_t>(arriving);
    const std::uint64_t np = get_count(at);
    for (std::uint64_t q = 0; q < np; ++q) {
      exact.push_back(static_cast<std::uint8_t>(*at++));
      at += unpack_new_particle(at, pool);
    }
    const std::uint64_t nr = get_count(at);
    for (std::uint64_t q = 0; q < nr; ++q) at += unpack_rod(at, rods);
    contacts.get(at);
  }
  std::sort(owned_ids.begin(), owned_ids.end());
  adopt(assemble(pool, exact, rods, owned_ids, contacts));
}

}  // namespace swarf
