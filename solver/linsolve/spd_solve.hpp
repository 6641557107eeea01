// Solving a symmetric stiffness system robustly: Cholesky, a residual check, and a stabilised
// retry for singular-but-consistent systems (zero-energy modes the loads do not excite, such
// as hourglass modes of one-element-thick C3D20R meshes, which ccx and Abaqus also solve).
// Nonlinear analyses may also allow indefinite systems (a tangent past a limit point, plastic
// zones under compression), which are then solved by LU with pivoting, as ccx's LDL^T solver
// solves them.
#pragma once

#include <memory>
#include <vector>

#include "assembly/sparse_pattern.hpp"
#include "linsolve/linear_solver.hpp"

namespace kontakt::linsolve {

/// y = K x for K stored as the upper triangle of a symmetric matrix, plus the skew-symmetric
/// part `skew` (same storage; empty: none) of an unsymmetric one.
VecX multiply_symmetric(const assembly::SparsePattern& pattern, const std::vector<Real>& values,
                        const VecX& x, const std::vector<Real>& skew = {});

/// What happened during one solve; the caller turns a stabilised solve into a warning.
struct SpdSolveReport {
  bool stabilised = false;   ///< K had a zero-energy mode; solved with K + delta*diag(K)
  bool indefinite = false;   ///< K was indefinite; solved by LU (allow_indefinite only)
  bool unsymmetric = false;  ///< K had a skew part (friction slip); solved by LU
  int singular_equation = -1;
  Real relative_residual = 0;  ///< |b - K x| / |b| of the returned solution
};

/// Solves K x = b with a Cholesky factorisation held by `solver` (analysed for `pattern`). A
/// system without equations (every dof prescribed, as ccx allows) has the empty solution.
/// When `refactorise` is false the existing factorisation is reused (K unchanged).
/// Throws SingularMatrix when K is singular and the loads excite the singular mode, and when K
/// is indefinite unless `allow_indefinite` is set (then LU with pivoting on the full matrix,
/// built from the upper triangle; its symbolic analysis is kept while the pattern holds).
class SpdSolve {
 public:
  explicit SpdSolve(LinearSolver& solver, bool allow_indefinite = false)
      : solver_(solver), allow_indefinite_(allow_indefinite) {}
  /// `skew`: the skew-symmetric part of an unsymmetric K in the same storage (empty: K is
  /// symmetric); a nonzero one goes to the LU path at once.
  void factorise(const assembly::SparsePattern& pattern, const std::vector<Real>& values,
                 SpdSolveReport& report, const std::vector<Real>& skew = {});
  VecX solve(const assembly::SparsePattern& pattern, const std::vector<Real>& values,
             const VecX& b, SpdSolveReport& report, const std::vector<Real>& skew = {});

  /// Relative stabilisation of the diagonal; the residual |r| / |b| a stabilised solution must
  /// reach, and the normwise backward error every other solution must reach.
  static constexpr Real kStabilisation = 1e-9;
  static constexpr Real kResidualTolerance = 1e-8;
  static constexpr Real kBackwardErrorTolerance = 1e-12;

 private:
  /// The full matrix of an upper-triangular pattern for the LU fallback: its pattern and, per
  /// full entry, the position of its value in the upper storage.
  struct FullMatrix {
    assembly::SparsePattern pattern;
    std::vector<Index> source;
    std::vector<char> lower;  ///< per full entry: it mirrors its source (K(c, r), r < c)
    std::vector<Index> of_col_start;  ///< the upper pattern it was built from
    std::vector<int> of_row_index;
  };
  void factorise_indefinite(const assembly::SparsePattern& pattern,
                            const std::vector<Real>& values, const std::vector<Real>& skew);

  LinearSolver& solver_;
  bool allow_indefinite_;
  bool stabilised_ = false;
  bool indefinite_ = false;
  bool unsymmetric_ = false;
  std::unique_ptr<LinearSolver> lu_;  ///< UMFPACK, its symmetric strategy
  FullMatrix full_;
};

}  // namespace kontakt::linsolve
