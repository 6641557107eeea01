// Sparse direct solvers behind one interface: analyze once per pattern, factorize per matrix,
// solve per right-hand side. CHOLMOD takes symmetric positive definite systems stored as the
// upper triangle; UMFPACK takes the full pattern of anything else.
#pragma once

#include <memory>
#include <vector>

#include "assembly/sparse_pattern.hpp"
#include "core/error.hpp"
#include "core/types.hpp"

namespace kontakt::linsolve {

/// The matrix is singular or not positive definite. `equation` is the reduced equation where
/// the factorisation broke down, or -1 when only a condition estimate showed it.
class SingularMatrix : public SolverError {
 public:
  SingularMatrix(const std::string& message, int equation)
      : SolverError(message), equation_(equation) {}
  int equation() const { return equation_; }

 private:
  int equation_;
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  /// Symbolic analysis (ordering); must be called again when the pattern changes.
  virtual void analyze(const assembly::SparsePattern& pattern) = 0;
  /// Numeric factorisation of values laid out in the analysed pattern.
  virtual void factorize(const std::vector<Real>& values) = 0;
  virtual VecX solve(const VecX& rhs) = 0;
  virtual const char* name() const = 0;
};

/// Reciprocal condition estimate below which a factorisation counts as singular.
inline constexpr Real kSingularRcond = 1e-14;

std::unique_ptr<LinearSolver> make_cholmod_solver();
/// UMFPACK with the symmetric strategy (diagonal pivots preferred, one METIS ordering of the
/// pattern) for every stiffness, indefinite or unsymmetric: its automatic choice on our
/// structurally symmetric patterns is the unsymmetric strategy with COLAMD, slower (a/h 6 Hertz
/// sphere with nts, 25 LU of 95 iterations: 54.2 -> 41.8 s, 535 -> 438 MB; frictional sliding
/// block --refine 4: factorisations 88.1 -> 60.8 s).
std::unique_ptr<LinearSolver> make_umfpack_solver();

}  // namespace kontakt::linsolve
