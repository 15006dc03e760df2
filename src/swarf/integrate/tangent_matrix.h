// tangent_matrix.h: the Newton step's tangent J assembled as a sparse matrix, and the interface
// of a preconditioner that needs it (issue 35 item 4: an algebraic multigrid measured against
// the matrix-free solve's block-Jacobi).
//
// The Newton solve (newton.cpp) applies J = M + beta h^2 K + gamma h C matrix-free and
// preconditions CG with the inverse of each particle's 3x3 diagonal block. A preconditioner
// that coarsens the matrix (BoomerAMG, study/hypre_amg.h) needs J's entries: assemble_tangent
// writes them from the same per-rod and per-contact blocks S = lateral I + axial n n^T the
// product uses, in scalar compressed rows (row 3 i + c is particle i's component c), so that
// J x equals the matrix-free product to round-off (tests/test_newton.cpp checks it through a
// preconditioner that solves exactly). Prescribed components keep only their unit diagonal
// (their row and column of J are dropped, as in the product). The engine knows no solver
// library: a LinearPreconditioner is handed in (Simulation::set_newton_preconditioner).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "swarf/core/vec3.h"

namespace swarf {

struct Integration;

/// J in compressed sparse rows: 3 n rows, each row's columns ascending, values in kg.
struct TangentMatrix {
  std::vector<std::int64_t> row_start;  ///< 3 n + 1 offsets into column and value
  std::vector<std::int32_t> column;     ///< scalar column 3 j + c
  std::vector<double> value;            ///< kg
  std::size_t rows() const { return row_start.empty() ? 0 : row_start.size() - 1; }
  /// y = J x over the scalar components (x, y of 3 n values), in each row's order.
  void times(const double* x, double* y) const;
};

/// A preconditioner of the Newton step's CG that reads the assembled tangent.
class LinearPreconditioner {
 public:
  virtual ~LinearPreconditioner() = default;
  virtual std::string name() const = 0;
  /// Asked at each Newton iteration: whether it will read this iteration's J (false: it keeps
  /// the older one, and J is not assembled; CG only needs a symmetric positive definite
  /// approximation of J^-1). 'rows': J's size now, 3 n.
  virtual bool wants_tangent(std::size_t rows) = 0;
  /// Called with the new J when wants_tangent said so.
  virtual void setup(const TangentMatrix& J) = 0;
  /// z ~ J^-1 r (r in N, z in m/s^2), both 3 n values in the matrix's row order. For the
  /// engine's guarantee it must give the same bits for any number of OpenMP threads.
  virtual void apply(const double* r, double* z) = 0;
};

/// J of the latest Newton tangent (after newton.cpp's tangent stage: the rods' and contacts'
/// blocks of the current iteration), particle i's rows from its diagonal block, its rods and
/// its sphere-sphere contacts.
void assemble_tangent(const Integration& it, TangentMatrix& J);

}  // namespace swarf
