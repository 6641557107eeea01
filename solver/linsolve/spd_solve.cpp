#include "linsolve/spd_solve.hpp"

#include <algorithm>
#include <cmath>

namespace kontakt::linsolve {

VecX multiply_symmetric(const assembly::SparsePattern& pattern, const std::vector<Real>& values,
                        const VecX& x) {
  VecX y = VecX::Zero(pattern.n);
  for (int j = 0; j < pattern.n; ++j)
    for (Index k = pattern.col_start[j]; k < pattern.col_start[j + 1]; ++k) {
      const int i = pattern.row_index[k];
      y[i] += values[k] * x[j];
      if (i != j) y[j] += values[k] * x[i];
    }
  return y;
}

void SpdSolve::factorise(const assembly::SparsePattern& pattern, const std::vector<Real>& values,
                         SpdSolveReport& report) {
  stabilised_ = false;
  try {
    solver_.factorize(values);
    return;
  } catch (const SingularMatrix& e) {
    report.singular_equation = e.equation();
  }
  // Shift every diagonal by a tiny fraction of itself: the factorisation then exists, and the
  // refinement in solve() recovers the solution of K itself wherever one exists.
  std::vector<Real> shifted = values;
  for (int j = 0; j < pattern.n; ++j) {
    const Index d = pattern.find(j, j);
    shifted[d] += kStabilisation * std::max(std::abs(shifted[d]), 1e-300);
  }
  solver_.factorize(shifted);
  stabilised_ = true;
  report.stabilised = true;
}

VecX SpdSolve::solve(const assembly::SparsePattern& pattern, const std::vector<Real>& values,
                     const VecX& b, SpdSolveReport& report) {
  report.stabilised = stabilised_;
  VecX x = solver_.solve(b);
  const Real b_norm = std::max(b.norm(), 1e-300);
  VecX r = b - multiply_symmetric(pattern, values, x);
  // Iterative refinement: one or two steps restore full accuracy after a stabilised
  // factorisation; a residual that will not shrink means the loads drive a singular mode.
  for (int step = 0; step < 10 && r.norm() > kResidualTolerance * b_norm; ++step) {
    x += solver_.solve(r);
    r = b - multiply_symmetric(pattern, values, x);
  }
  report.relative_residual = r.norm() / b_norm;
  if (!x.allFinite() || report.relative_residual > kResidualTolerance)
    throw SingularMatrix(stabilised_ ? "stiffness matrix is singular and the loads excite "
                                       "its zero-energy mode"
                                     : "the linear solve did not reach a small residual",
                         report.singular_equation);
  return x;
}

}  // namespace kontakt::linsolve
