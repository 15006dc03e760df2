// hypre_amg.h: BoomerAMG (hypre's algebraic multigrid, Debian's libhypre-dev) as the Newton
// step's CG preconditioner, behind the engine's LinearPreconditioner
// (swarf/integrate/tangent_matrix.h; issue 35 item 4: a well-kept solver library measured
// against the matrix-free block-Jacobi). One V-cycle per application, on one process
// (MPI_COMM_SELF; hypre and MPI stay in hypre_amg.cpp). Debian's hypre is built without
// OpenMP, so the cycle runs on one thread and gives the same bits for any thread count.
// Used by 'swarf bench --preconditioner amg'; built without hypre (or MPI), available() is
// false and constructing one throws InputError.
#pragma once

#include <memory>
#include <string>

#include "swarf/integrate/tangent_matrix.h"

namespace swarf {

struct HypreAmgSettings {
  /// Set the hierarchy up again at every refresh-th tangent (1: every Newton iteration); in
  /// between, the cycle of the older J preconditions (still symmetric positive definite).
  int refresh = 1;
  double strong_threshold = 0.5;  ///< BoomerAMG's strength of connection, 1 (0.5 for 3D elasticity)
  bool nodal = false;             ///< coarsen by particles (the 3x3 blocks' norms) instead of by unknowns
};

class HypreAmg final : public LinearPreconditioner {
 public:
  explicit HypreAmg(const HypreAmgSettings& s = {});
  ~HypreAmg() override;
  std::string name() const override { return "BoomerAMG"; }
  bool wants_tangent(std::size_t rows) override;
  void setup(const TangentMatrix& J) override;
  void apply(const double* r, double* z) override;
  static bool available();

  int setups() const;            ///< hierarchies built
  double setup_seconds() const;  ///< wall time in them (the assembly into hypre's matrix included), s
  double apply_seconds() const;  ///< wall time in the cycles, s

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace swarf
