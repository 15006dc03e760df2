// zoltan_rcb.h: the ranks' boxes of one run over MPI by Zoltan's recursive coordinate bisection
// (issue 38: a well-kept partitioner rather than one of our own). Behind the engine's
// Partitioner (swarf/domains/partition.h); Zoltan and MPI stay in zoltan_rcb.cpp. Built without
// Zoltan (or without MPI), available() is false and constructing one throws InputError.
#pragma once

#include <string>
#include <vector>

#include "swarf/domains/partition.h"

namespace swarf {

class ZoltanRcb final : public Partitioner {
 public:
  /// Over MPI_COMM_WORLD (MPI must be initialised: an MpiSession, sweep_mpi.h).
  ZoltanRcb();
  std::vector<DomainBox> partition(const std::vector<Vec3>& x, const std::vector<std::int64_t>& w, bool cut_y) override;
  std::string name() const override { return "Zoltan RCB"; }
  /// Whether this build has Zoltan.
  static bool available();
};

}  // namespace swarf
