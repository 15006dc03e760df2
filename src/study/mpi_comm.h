// mpi_comm.h: the domains' Comm (swarf/core/comm.h) over MPI_COMM_WORLD, for one run over MPI
// ranks (issue 38). MPI must be initialised (an MpiSession, sweep_mpi.h); built without MPI it is
// the group of one rank. All MPI calls of the domains live in mpi_comm.cpp.
#pragma once

#include "swarf/core/comm.h"

namespace swarf {

class MpiComm final : public Comm {
 public:
  MpiComm();
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  std::vector<Bytes> all_to_all(std::vector<Bytes> send) override;
  std::vector<Bytes> all_gather(Bytes mine) override;
  void gather_to_root(const Bytes& mine, std::vector<Bytes>& from) override;
  void barrier() override;
  std::vector<Bytes> exchange(std::vector<Bytes> send, const std::vector<std::size_t>& recv_bytes) override;

 private:
  int rank_ = 0, size_ = 1;
};

}  // namespace swarf
