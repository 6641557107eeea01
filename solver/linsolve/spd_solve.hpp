// Solving a symmetric stiffness system robustly: Cholesky, a residual check, and a stabilised
// retry for singular-but-consistent systems (zero-energy modes the loads do not excite, such
// as hourglass modes of one-element-thick C3D20R meshes, which ccx and Abaqus also solve).
#pragma once

#include <vector>

#include "assembly/sparse_pattern.hpp"
#include "linsolve/linear_solver.hpp"

namespace kontakt::linsolve {

/// y = K x for K stored as the upper triangle of a symmetric matrix.
VecX multiply_symmetric(const assembly::SparsePattern& pattern, const std::vector<Real>& values,
                        const VecX& x);

/// What happened during one solve; the caller turns a stabilised solve into a warning.
struct SpdSolveReport {
  bool stabilised = false;   ///< K had a zero-energy mode; solved with K + delta*diag(K)
  int singular_equation = -1;
  Real relative_residual = 0;  ///< |b - K x| / |b| of the returned solution
};

/// Solves K x = b with a Cholesky factorisation held by `solver` (analysed for `pattern`).
/// When `refactorise` is false the existing factorisation is reused (K unchanged).
/// Throws SingularMatrix when K is singular and the loads excite the singular mode.
class SpdSolve {
 public:
  explicit SpdSolve(LinearSolver& solver) : solver_(solver) {}
  void factorise(const assembly::SparsePattern& pattern, const std::vector<Real>& values,
                 SpdSolveReport& report);
  VecX solve(const assembly::SparsePattern& pattern, const std::vector<Real>& values,
             const VecX& b, SpdSolveReport& report);

  /// Relative stabilisation of the diagonal, and the residual a solution must reach.
  static constexpr Real kStabilisation = 1e-9;
  static constexpr Real kResidualTolerance = 1e-8;

 private:
  LinearSolver& solver_;
  bool stabilised_ = false;
};

}  // namespace kontakt::linsolve
