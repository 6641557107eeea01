#include "linsolve/spd_solve.hpp"

#include <algorithm>
#include <cmath>

namespace kontakt::linsolve {

namespace {

/// Largest absolute row sum of K stored as the upper triangle of a symmetric matrix (plus
/// its skew part, if any).
Real infinity_norm(const assembly::SparsePattern& pattern, const std::vector<Real>& values,
                   const std::vector<Real>& skew) {
  VecX row_sum = VecX::Zero(pattern.n);
  for (int j = 0; j < pattern.n; ++j)
    for (Index k = pattern.col_start[j]; k < pattern.col_start[j + 1]; ++k) {
      const int i = pattern.row_index[k];
      const Real s = skew.empty() || i == j ? 0 : skew[k];
      row_sum[i] += std::abs(values[k] + s);
      if (i != j) row_sum[j] += std::abs(values[k] - s);
    }
  return pattern.n ? row_sum.maxCoeff() : 0;
}

}  // namespace

VecX multiply_symmetric(const assembly::SparsePattern& pattern, const std::vector<Real>& values,
                        const VecX& x, const std::vector<Real>& skew) {
  VecX y = VecX::Zero(pattern.n);
  for (int j = 0; j < pattern.n; ++j)
    for (Index k = pattern.col_start[j]; k < pattern.col_start[j + 1]; ++k) {
      const int i = pattern.row_index[k];
      y[i] += values[k] * x[j];
      if (i != j) y[j] += values[k] * x[i];
      if (!skew.empty() && i != j) {
        y[i] += skew[k] * x[j];
        y[j] -= skew[k] * x[i];
      }
    }
  return y;
}

void SpdSolve::factorise(const assembly::SparsePattern& pattern, const std::vector<Real>& values,
                         SpdSolveReport& report, const std::vector<Real>& skew) {
  stabilised_ = indefinite_ = unsymmetric_ = false;
  if (pattern.n == 0) return;  // every dof prescribed: no equation left, nothing to factor
  if (std::any_of(skew.begin(), skew.end(), [](Real v) { return v != 0; })) {
    factorise_indefinite(pattern, values, skew);
    unsymmetric_ = indefinite_ = true;
    report.unsymmetric = true;
    return;
  }
  try {
    solver_.factorize(values);
    return;
  } catch (const SingularMatrix& e) {
    report.singular_equation = e.equation();
  }
  // Shift every diagonal by a tiny fraction of itself: the factorisation then exists, and the
  // refinement in solve() recovers the solution of K itself wherever one exists. A zero
  // diagonal is a dof nothing holds at all (a truss node across the plane of its bars; K is
  // positive semi-definite, so its whole row is zero): it gets a fraction of the largest.
  std::vector<Real> shifted = values;
  Real largest_diagonal = 0;
  for (int j = 0; j < pattern.n; ++j)
    largest_diagonal = std::max(largest_diagonal, std::abs(values[pattern.find(j, j)]));
  for (int j = 0; j < pattern.n; ++j) {
    const Index d = pattern.find(j, j);
    const Real own = std::abs(shifted[d]);
    shifted[d] += kStabilisation * (own > 0 ? own : std::max(largest_diagonal, 1e-300));
  }
  try {
    solver_.factorize(shifted);
    stabilised_ = true;
    report.stabilised = true;
    return;
  } catch (const SingularMatrix&) {
    if (!allow_indefinite_) throw;
  }
  // The shift does not help: K has negative pivots, not just a zero-energy mode.
  factorise_indefinite(pattern, values, {});
  indefinite_ = true;
  report.indefinite = true;
}

void SpdSolve::factorise_indefinite(const assembly::SparsePattern& upper,
                                    const std::vector<Real>& values,
                                    const std::vector<Real>& skew) {
  if (full_.of_col_start != upper.col_start || full_.of_row_index != upper.row_index) {
    // Column j of the full matrix: rows i <= j from upper column j, then rows i > j, which
    // are the entries (j, i) of the later upper columns.
    std::vector<Index> count(upper.n + 1, 0);
    for (int j = 0; j < upper.n; ++j)
      for (Index k = upper.col_start[j]; k < upper.col_start[j + 1]; ++k) {
        ++count[j + 1];
        if (upper.row_index[k] != j) ++count[upper.row_index[k] + 1];
      }
    full_.pattern.n = upper.n;
    full_.pattern.upper = false;
    full_.pattern.col_start.assign(count.begin(), count.end());
    for (int j = 0; j < upper.n; ++j) full_.pattern.col_start[j + 1] += full_.pattern.col_start[j];
    full_.pattern.row_index.assign(full_.pattern.nnz(), 0);
    full_.source.assign(full_.pattern.nnz(), 0);
    full_.lower.assign(full_.pattern.nnz(), 0);
    std::vector<Index> next(full_.pattern.col_start.begin(), full_.pattern.col_start.end() - 1);
    for (int j = 0; j < upper.n; ++j)  // rows ascending within each column: i <= j first
      for (Index k = upper.col_start[j]; k < upper.col_start[j + 1]; ++k) {
        full_.pattern.row_index[next[j]] = upper.row_index[k];
        full_.source[next[j]++] = k;
      }
    for (int j = 0; j < upper.n; ++j)
      for (Index k = upper.col_start[j]; k < upper.col_start[j + 1]; ++k) {
        const int i = upper.row_index[k];
        if (i == j) continue;
        full_.pattern.row_index[next[i]] = j;
        full_.lower[next[i]] = 1;
        full_.source[next[i]++] = k;
      }
    if (!lu_) lu_ = make_umfpack_solver();
    lu_->analyze(full_.pattern);
    full_.of_col_start = upper.col_start;
    full_.of_row_index = upper.row_index;
  }
  std::vector<Real> full_values(full_.source.size());
  for (std::size_t k = 0; k < full_values.size(); ++k) {
    full_values[k] = values[full_.source[k]];
    if (!skew.empty()) full_values[k] += full_.lower[k] ? -skew[full_.source[k]] : skew[full_.source[k]];
  }
  lu_->factorize(full_values);
}

VecX SpdSolve::solve(const assembly::SparsePattern& pattern, const std::vector<Real>& values,
                     const VecX& b, SpdSolveReport& report, const std::vector<Real>& skew) {
  report.stabilised = stabilised_;
  report.indefinite = indefinite_;
  report.unsymmetric = unsymmetric_;
  if (pattern.n == 0) return VecX();
  LinearSolver& factors = indefinite_ ? *lu_ : solver_;
  VecX x = factors.solve(b);
  const Real b_norm = std::max(b.norm(), 1e-300);
  // A stabilised solve must reach a small residual against b itself: a residual that will not
  // shrink means the loads drive the singular mode. Otherwise the test is the normwise
  // backward error |r| / (|K| |x| + |b|), which an ill-conditioned but regular system (a
  // thin plate in bending) meets although |r| / |b| cannot be brought down to round-off.
  static const std::vector<Real> kNoSkew;
  const std::vector<Real>& skew_part = unsymmetric_ ? skew : kNoSkew;
  const Real k_norm = infinity_norm(pattern, values, skew_part);
  auto backward_accurate = [&](const VecX& r) {
    const Real scale = k_norm * x.cwiseAbs().maxCoeff() + b.cwiseAbs().maxCoeff();
    return r.cwiseAbs().maxCoeff() <= kBackwardErrorTolerance * std::max(scale, 1e-300);
  };
  auto accurate = [&](const VecX& r) {
    return stabilised_ ? r.norm() <= kResidualTolerance * b_norm : backward_accurate(r);
  };
  VecX r = b - multiply_symmetric(pattern, values, x, skew_part);
  // Iterative refinement: one or two steps restore full accuracy after a stabilised
  // factorisation. A stabilised solution is refined to round-off while the residual still
  // falls, not just to the acceptance threshold: the shift would otherwise leave a stress
  // error of that threshold's order (a stress-free state computed as 1e-9 of its load).
  for (int step = 0; step < 10 && !backward_accurate(r); ++step) {
    const VecX dx = factors.solve(r);
    const VecX refined_r = b - multiply_symmetric(pattern, values, x + dx, skew_part);
    if (accurate(r) && refined_r.norm() > 0.5 * r.norm()) break;  // at its round-off floor
    x += dx;
    r = refined_r;
  }
  report.relative_residual = r.norm() / b_norm;
  if (!x.allFinite() || !accurate(r))
    throw SingularMatrix(stabilised_ ? "stiffness matrix is singular and the loads excite "
                                       "its zero-energy mode"
                                     : "the linear solve did not reach a small residual",
                         report.singular_equation);
  return x;
}

}  // namespace kontakt::linsolve
