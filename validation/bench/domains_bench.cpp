// domains_bench.cpp: W1 (or another rods-only case) stepped over MPI ranks by the domain
// decomposition (swarf/domains/domain_run.h, issue 38 item 5), timed beside the serial run.
//
//   swarf_domains_bench CASE STEPS [--set key=value ...]            one process: the serial run
//   mpirun -n N swarf_domains_bench CASE STEPS [--set ...] [--rebalance-every K] [--check-every S]   N domains
//   ... [--partition rcb|slabs]    the ranks' regions: Zoltan's RCB boxes or slabs along x (the default here)
//   ... [--checkpoint-at K FILE]   after step K the gathered state as a checkpoint (HDF5, rank 0 writes)
//   ... [--restart FILE]           go on from a checkpoint to step STEPS, on any rank count (serially: a plain run)
//
// Prints, per rank, the owned and ghost particles and the halo's bytes per step, and on rank 0
// the wall time per particle-step of the stepping (the setup excluded) and the time in the
// halo exchange and migrations (the part of a step that waits on the other ranks). Not a test:
// validation/bench/README.md ("Domains") keeps what it measured. Then a hash of every
// particle's position in id order, the same for any rank count (the serial bits), the energies
// (exact sums: the same bits serial and over ranks) and the ledger: over ranks its exact sums
// (DomainRun::sums, the same bits for any rank count), serial its plain sums (equal to those to
// round-off).
#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "io/checkpoint.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "study/mpi_comm.h"
#include "study/sweep_mpi.h"
#include "study/zoltan_rcb.h"
#include "swarf/core/errors.h"
#include "swarf/core/state_archive.h"
#include "swarf/domains/domain_run.h"
#include "swarf/simulation.h"

namespace {

using Clock = std::chrono::steady_clock;

// The state archive's hash (core/state_archive.h) of the positions, in id order.
std::uint64_t position_hash(const swarf::Particles& p) {
  std::vector<std::size_t> order(p.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p.id[a] < p.id[b]; });
  std::vector<swarf::Vec3> x;
  for (std::size_t i : order) x.push_back(p.position[i]);
  swarf::HashArchive h;
  h.array("position", x, x.size());
  return h.value();
}

}  // namespace

int main(int argc, char** argv) {
  using namespace swarf;
  if (argc < 3) {
    fmt::print(stderr,
               "usage: [mpirun -n N] swarf_domains_bench CASE STEPS [--set key=value ...] [--rebalance-every K] "
               "[--check-every S] [--partition rcb|slabs] [--checkpoint-at K FILE] [--restart FILE]\n");
    return 2;
  }
  MpiSession session;
  try {
    std::vector<std::string> overrides;
    DomainSettings ds;
    int checkpoint_at = -1;
    bool rcb = false;
    std::string checkpoint, restart;
    for (int a = 3; a + 1 < argc; a += 2) {
      const std::string opt = argv[a];
      if (opt == "--checkpoint-at" && a + 2 < argc) {
        checkpoint_at = std::stoi(argv[a + 1]);
        checkpoint = argv[a + 2];
        ++a;
      } else if (opt == "--restart")
        restart = argv[a + 1];
      else if (opt == "--set")
        overrides.push_back(argv[a + 1]);
      else if (opt == "--rebalance-every")
        ds.rebalance_every = std::stoi(argv[a + 1]);
      else if (opt == "--check-every")
        ds.check_every = std::stoi(argv[a + 1]);
      else if (opt == "--partition" && (std::strcmp(argv[a + 1], "rcb") == 0 || std::strcmp(argv[a + 1], "slabs") == 0))
        rcb = std::strcmp(argv[a + 1], "rcb") == 0;
      else
        throw InputError("unknown option '" + opt + "'");
    }
    const int steps = std::stoi(argv[2]);
    CaseSettings cs = load_case(argv[1], overrides);
    Model model = build_model(cs);
    const std::size_t n = model.particles.size();
    // A checkpoint written from any rank count (the gathered state), read by any rank count.
    std::unique_ptr<Simulation> start;
    if (!restart.empty()) {
      start = std::make_unique<Simulation>(model, model.step);
      RunRecord rec;
      read_checkpoint(restart, *start, rec, [](StateArchive&) {});
      fmt::print("rank {}: restarted from {} at step {}\n", session.rank(), restart, start->steps());
    }
    if (session.size() == 1 && start) {  // (serially from a checkpoint: the plain run goes on)
      while (start->steps() < steps) start->step();
      fmt::print("positions hash {:016x}\n", position_hash(model.particles));
      return 0;
    }
    if (session.size() == 1 && checkpoint.empty()) {
      Simulation sim(model, model.step);
      const auto t0 = Clock::now();
      for (int k = 0; k < steps; ++k) sim.step();
      const double s = std::chrono::duration<double>(Clock::now() - t0).count();
      fmt::print("serial: {} particles, {} rods, {} threads: {:.1f} ns per particle-step ({:.3f} s for {} steps)\n", n,
                 model.rods.size(), omp_get_max_threads(), 1e9 * s / (double(n) * steps), s, steps);
      fmt::print("positions hash {:016x}\n", position_hash(model.particles));
      const EnergyLedger& l = sim.ledger();
      fmt::print("energies: kinetic {:.17g} J, elastic {:.17g} J (exact sums)\n", sim.kinetic_energy(),
                 sim.elastic_energy());
      fmt::print("ledger (plain sums): plastic {:.17g} J, viscous {:.17g} J, fracture {:.17g} J, external {:.17g} J\n",
                 l.plastic_work, l.viscous_work, l.fracture_energy, l.external_work);
      return 0;
    }
    MpiComm comm;
    if (rcb) ds.partitioner = std::make_shared<ZoltanRcb>();
    DomainRun d = start ? DomainRun(comm, *start, ds) : DomainRun(comm, model, model.step, ds);
    comm.barrier();
    const auto t0 = Clock::now();
    while (d.simulation().steps() < steps) {
      d.step();
      if (d.simulation().steps() == checkpoint_at) {
        World storage;
        const std::unique_ptr<Simulation> g = d.gather_simulation(storage);
        if (comm.rank() == 0) {
          CheckpointCase c{cs.text, cs.source, cs.directory, cs.overrides, g->time(), double(g->steps())};
          RunRecord rec;
          rec.columns = 1;  // (no series here: a record of no rows)
          write_checkpoint(checkpoint, *g, rec, c, [](StateArchive&) {});
          fmt::print("checkpoint {} written at step {}\n", checkpoint, g->steps());
        }
      }
    }
    comm.barrier();
    const double s = std::chrono::duration<double>(Clock::now() - t0).count();
    const double in_halo = d.exchange_seconds();
    const std::size_t owned = d.owned_count(), local = d.world().particles.size();
    const std::size_t ghosts = local - owned;
    for (int r = 0; r < comm.size(); ++r) {
      comm.barrier();
      if (r == comm.rank())
        fmt::print(
            "rank {} of {}: {} owned, {} ghosts ({:.1f} % of owned), halo {:.0f} kB sent in the last step, {} "
            "migrations; "
            "{:.3f} s of {:.3f} in the halo exchange and migrations; box x [{:.4g}, {:.4g}) y [{:.4g}, {:.4g}) z "
            "[{:.4g}, {:.4g}) m\n",
            r, comm.size(), owned, ghosts, 100.0 * double(ghosts) / double(owned), 1e-3 * double(d.halo_bytes()),
            d.migrations(), in_halo, s, d.partition().boxes()[r].lo[0], d.partition().boxes()[r].hi[0],
            d.partition().boxes()[r].lo[1], d.partition().boxes()[r].hi[1], d.partition().boxes()[r].lo[2],
            d.partition().boxes()[r].hi[2]);
      std::fflush(stdout);
    }
    Particles all = d.gather_owned();
    const DomainRun::Sums sums = d.sums();
    if (comm.rank() == 0) {
      fmt::print("energies: kinetic {:.17g} J, elastic {:.17g} J (exact sums)\n", sums.kinetic_energy,
                 sums.elastic_energy);
      fmt::print("ledger (exact sums): plastic {:.17g} J, viscous {:.17g} J, fracture {:.17g} J, external {:.17g} J\n",
                 sums.plastic_work, sums.viscous_work, sums.fracture_energy, sums.external_work);
      fmt::print("{} ranks x {} threads: {:.1f} ns per particle-step ({:.3f} s for {} steps)\n", comm.size(),
                 omp_get_max_threads(), 1e9 * s / (double(n) * steps), s, steps);
      fmt::print("positions hash {:016x}\n", position_hash(all));
    }
    return 0;
  } catch (const std::exception& e) {
    fmt::print(stderr, "swarf_domains_bench: {}\n", e.what());
    return 1;
  }
}
