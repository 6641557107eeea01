#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <memory>

#include "linsolve/linear_solver.hpp"
#include "linsolve/blas_threads.hpp"
#include "linsolve/spd_solve.hpp"

using namespace kontakt;

namespace {

/// Pattern and values of a dense matrix (full or upper storage).
assembly::SparsePattern dense_pattern(const MatX& A, bool upper, std::vector<Real>& values) {
  assembly::SparsePattern p;
  p.n = static_cast<int>(A.rows());
  p.upper = upper;
  p.col_start.push_back(0);
  values.clear();
  for (int j = 0; j < p.n; ++j) {
    for (int i = 0; i < (upper ? j + 1 : p.n); ++i)
      if (A(i, j) != 0 || i == j) {
        p.row_index.push_back(i);
        values.push_back(A(i, j));
      }
    p.col_start.push_back(static_cast<Index>(p.row_index.size()));
  }
  return p;
}

/// CHOLMOD, analysed for a pattern.
std::unique_ptr<linsolve::LinearSolver> cholmod_for(const assembly::SparsePattern& p) {
  auto solver = linsolve::make_cholmod_solver();
  solver->analyze(p);
  return solver;
}

MatX spd_matrix(int n) {
  std::srand(7);
  MatX R = MatX::Random(n, n);
  return R * R.transpose() + n * MatX::Identity(n, n);
}

}  // namespace

TEST(LinearSolvers, CholmodAndUmfpackSolveSpdSystem) {
  const MatX A = spd_matrix(40);
  const VecX b = VecX::Random(40);
  const VecX x_ref = A.ldlt().solve(b);
  for (bool use_cholmod : {true, false}) {
    std::vector<Real> values;
    const auto p = dense_pattern(A, use_cholmod, values);
    auto solver = use_cholmod ? linsolve::make_cholmod_solver() : linsolve::make_umfpack_solver();
    solver->analyze(p);
    solver->factorize(values);
    EXPECT_LT((solver->solve(b) - x_ref).norm(), 1e-10 * x_ref.norm()) << solver->name();
    // Refactorise with new values in the same pattern: the symbolic analysis is reused.
    for (auto& v : values) v *= 2;
    solver->factorize(values);
    EXPECT_LT((solver->solve(b) - 0.5 * x_ref).norm(), 1e-10 * x_ref.norm()) << solver->name();
  }
}

TEST(LinearSolvers, UmfpackSolvesUnsymmetricSystem) {
  std::srand(3);
  MatX A = MatX::Random(30, 30) + 30 * MatX::Identity(30, 30);
  const VecX b = VecX::Random(30);
  std::vector<Real> values;
  const auto p = dense_pattern(A, false, values);
  auto solver = linsolve::make_umfpack_solver();
  solver->analyze(p);
  solver->factorize(values);
  EXPECT_LT((A * solver->solve(b) - b).norm(), 1e-10 * b.norm());
}

TEST(LinearSolvers, UmfpackSymmetricStrategySolvesIndefiniteAndUnsymmetricStiffnesses) {
  // A saddle point (a stiffness with two constraint rows: zeros on their diagonal), a
  // stiffness with a negative eigenvalue and one with a skew part as large as friction's: the
  // symmetric strategy's diagonal pivots must give way to off-diagonal ones where the
  // diagonal is zero, and it must take unsymmetric values on the symmetric pattern.
  const int n = 40;
  MatX K = spd_matrix(n);
  K(3, 3) = -5.0 * n;
  MatX saddle = MatX::Zero(n + 2, n + 2);
  saddle.topLeftCorner(n, n) = spd_matrix(n);
  for (int c = 0; c < 2; ++c)
    for (int j = 0; j < n; j += 3 + c) {
      saddle(n + c, j) = 1.0 + j;
      saddle(j, n + c) = 1.0 + j;
    }
  std::srand(5);
  MatX skew = MatX::Random(n, n);
  skew = (skew - skew.transpose()).eval() * (0.5 * n);
  MatX slipping = spd_matrix(n) + skew;
  for (const MatX* A : {&K, &saddle, &slipping}) {
    const VecX b = VecX::Random(A->rows());
    std::vector<Real> values;
    const auto p = dense_pattern(*A, false, values);
    auto solver = linsolve::make_umfpack_solver();
    solver->analyze(p);
    solver->factorize(values);
    EXPECT_LT((*A * solver->solve(b) - b).norm(), 1e-10 * b.norm()) << A->rows();
  }
}

TEST(LinearSolvers, CholmodNamesTheEquationOfAZeroPivot) {
  MatX A = spd_matrix(10);
  A.row(6).setZero();
  A.col(6).setZero();
  std::vector<Real> values;
  const auto p = dense_pattern(A, true, values);
  auto solver = linsolve::make_cholmod_solver();
  solver->analyze(p);
  try {
    solver->factorize(values);
    FAIL() << "singular matrix accepted";
  } catch (const linsolve::SingularMatrix& e) {
    EXPECT_EQ(e.equation(), 6);
  }
}

TEST(LinearSolvers, BothDetectARigidBodyModeNumerically) {
  // Two springs in series with no support: K has the constant vector in its null space, but
  // round-off may leave a tiny positive pivot instead of an exact zero.
  MatX A(3, 3);
  A << 1e6, -1e6, 0, -1e6, 1e6 + 3e5, -3e5, 0, -3e5, 3e5;
  for (bool use_cholmod : {true, false}) {
    std::vector<Real> values;
    const auto p = dense_pattern(A, use_cholmod, values);
    auto solver = use_cholmod ? linsolve::make_cholmod_solver() : linsolve::make_umfpack_solver();
    solver->analyze(p);
    EXPECT_THROW(solver->factorize(values), linsolve::SingularMatrix) << solver->name();
  }
}

TEST(SpdSolve, SolvesSingularSystemWhenTheLoadLeavesTheZeroModeAlone) {
  // A free-free chain of three springs: null space = rigid translation (1, 1, 1, 1).
  MatX A(4, 4);
  A << 2, -2, 0, 0, -2, 5, -3, 0, 0, -3, 4, -1, 0, 0, -1, 1;
  std::vector<Real> values;
  const auto p = dense_pattern(A, true, values);
  auto cholmod = linsolve::make_cholmod_solver();
  cholmod->analyze(p);
  linsolve::SpdSolve spd(*cholmod);
  linsolve::SpdSolveReport report;
  spd.factorise(p, values, report);
  EXPECT_TRUE(report.stabilised);
  VecX self_equilibrated(4);
  self_equilibrated << 1, -2, 0.5, 0.5;  // sums to zero: orthogonal to the null space
  const VecX x = spd.solve(p, values, self_equilibrated, report);
  // Refined to round-off, not just below the acceptance threshold: the shift must leave no
  // trace in the solution (a stress-free state would otherwise carry 1e-9 of its load).
  EXPECT_LT((A * x - self_equilibrated).norm(), 1e-14 * self_equilibrated.norm() * A.norm());
  EXPECT_LT(report.relative_residual, 1e-13);
  // A net force drives the rigid mode: no solution exists and none may be returned.
  VecX net(4);
  net << 1, 0, 0, 0;
  EXPECT_THROW(spd.solve(p, values, net, report), linsolve::SingularMatrix);
}

TEST(SpdSolve, ADofWithoutAnyStiffnessIsSolvedWhenUnloadedAndReportedWhenLoaded) {
  // A truss joint across the plane of its bars: its row and column are exactly zero, so its
  // own diagonal gives no scale for the shift.
  MatX A(3, 3);
  A << 4e6, 0, -1e6, 0, 0, 0, -1e6, 0, 3e6;
  std::vector<Real> values;
  const auto p = dense_pattern(A, true, values);
  auto cholmod = linsolve::make_cholmod_solver();
  cholmod->analyze(p);
  linsolve::SpdSolve spd(*cholmod);
  linsolve::SpdSolveReport report;
  spd.factorise(p, values, report);
  EXPECT_TRUE(report.stabilised);
  EXPECT_EQ(report.singular_equation, 1);
  VecX unloaded(3);
  unloaded << 1, 0, 2;
  const VecX x = spd.solve(p, values, unloaded, report);
  EXPECT_LT((A * x - unloaded).norm(), 1e-8 * unloaded.norm());
  EXPECT_EQ(x[1], 0.0);
  VecX loaded(3);
  loaded << 1, 1, 2;
  EXPECT_THROW(spd.solve(p, values, loaded, report), linsolve::SingularMatrix);
}

TEST(SpdSolve, RegularSystemIsSolvedWithoutStabilisation) {
  const MatX A = spd_matrix(12);
  std::vector<Real> values;
  const auto p = dense_pattern(A, true, values);
  auto cholmod = linsolve::make_cholmod_solver();
  cholmod->analyze(p);
  linsolve::SpdSolve spd(*cholmod);
  linsolve::SpdSolveReport report;
  spd.factorise(p, values, report);
  const VecX b = VecX::Random(12);
  const VecX x = spd.solve(p, values, b, report);
  EXPECT_FALSE(report.stabilised);
  EXPECT_LT((A * x - b).norm(), 1e-12 * b.norm());
  EXPECT_LT((linsolve::multiply_symmetric(p, values, x) - A * x).norm(), 1e-12 * b.norm());
}

TEST(SpdSolve, IndefiniteSystemIsSolvedByLuOnlyWhenAllowed) {
  // A symmetric stiffness with a negative eigenvalue (a tangent past a limit point), dense
  // enough for CHOLMOD's supernodal LL^T (small sparse systems get its LDL^T, which takes
  // indefinite matrices anyway).
  const int n = 200;
  MatX A = spd_matrix(n);
  A(4, 4) = -30.0 * n;
  const VecX b = VecX::Random(n);
  std::vector<Real> values;
  const auto p = dense_pattern(A, true, values);
  const auto cholmod = cholmod_for(p);
  linsolve::SpdSolveReport refused;
  linsolve::SpdSolve strict(*cholmod);
  EXPECT_THROW(strict.factorise(p, values, refused), linsolve::SingularMatrix);
  linsolve::SpdSolve nonlinear(*cholmod, /*allow_indefinite=*/true);
  linsolve::SpdSolveReport report;
  nonlinear.factorise(p, values, report);
  EXPECT_TRUE(report.indefinite);
  const VecX x = nonlinear.solve(p, values, b, report);
  EXPECT_LT((A * x - b).norm(), 1e-10 * b.norm());
  // Back to a positive definite matrix in the same pattern: Cholesky again.
  const MatX B = spd_matrix(n);
  const auto q = dense_pattern(B, true, values);
  nonlinear.factorise(q, values, report = {});
  EXPECT_FALSE(report.indefinite);
  EXPECT_LT((B * nonlinear.solve(q, values, b, report) - b).norm(), 1e-10 * b.norm());
}

TEST(SpdSolve, IllConditionedRegularSystemPassesOnItsBackwardError) {
  // Condition 1e13: |r|/|b| stays far above round-off although the solve is as good as
  // floating point allows; the normwise backward error is what is tested.
  const int n = 20;
  std::srand(11);
  const MatX Q = MatX::Random(n, n).householderQr().householderQ();
  VecX eigen(n);
  for (int k = 0; k < n; ++k) eigen[k] = std::pow(10.0, 13.0 * k / (n - 1));
  const MatX A = Q * eigen.asDiagonal() * Q.transpose();
  const MatX As = 0.5 * (A + A.transpose());
  std::vector<Real> values;
  const auto p = dense_pattern(As, true, values);
  const auto cholmod = cholmod_for(p);
  linsolve::SpdSolve spd(*cholmod);
  linsolve::SpdSolveReport report;
  spd.factorise(p, values, report);
  const VecX b = As * VecX::Ones(n);
  const VecX x = spd.solve(p, values, b, report);
  const VecX r = b - As * x;
  EXPECT_LT(r.cwiseAbs().maxCoeff(),
            1e-12 * (As.cwiseAbs().rowwise().sum().maxCoeff() * x.cwiseAbs().maxCoeff()));
  EXPECT_FALSE(report.stabilised);
}

TEST(BlasThreads, TheInstalledBlasAcceptsAThreadCount) {
  // deploy/install-deps.sh installs OpenBLAS; `kontakt --threads N` relies on reaching it.
  EXPECT_TRUE(linsolve::set_blas_threads(1));
}
