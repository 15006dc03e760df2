// sweep_mpi.h: the little MPI that 'swarf sweep' needs (rank, size, barrier, agreement on
// errors). MPI is initialised only when the process was started by mpirun, so a plain
// 'swarf sweep' needs no MPI launcher. All MPI calls live in sweep_mpi.cpp.
#pragma once

namespace swarf {

class MpiSession {
 public:
  /// Calls MPI_Init when launched() (else: one rank of one).
  MpiSession();
  /// Calls MPI_Finalize when this object called MPI_Init.
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  /// True when OMPI_COMM_WORLD_SIZE or PMI_SIZE is set (a process started by mpirun).
  static bool launched();

  int rank() const { return rank_; }
  int size() const { return size_; }
  /// Ranks on this machine (they share its cores), and this one's place among them.
  int local_size() const { return local_size_; }
  int local_rank() const { return local_rank_; }
  void barrier() const;
  /// The largest v over the ranks.
  int max_all(int v) const;
  /// Rank 0's v, on every rank.
  int from_root(int v) const;
  /// Ends every rank of the job with 'code' (MPI_Abort; mpirun exits non-zero): for an error on
  /// one rank of a run over ranks, whose others would wait for it forever in a collective.
  [[noreturn]] void abort(int code) const;

 private:
  bool active_ = false;
  int rank_ = 0, size_ = 1, local_size_ = 1, local_rank_ = 0;
};

}  // namespace swarf
