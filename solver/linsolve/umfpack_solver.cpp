// UMFPACK (unsymmetric multifrontal LU) for general square systems, int64 interface.
#include <umfpack.h>

#include <new>
#include <sstream>

#include "linsolve/linear_solver.hpp"

namespace kontakt::linsolve {

namespace {

class UmfpackSolver final : public LinearSolver {
 public:
  UmfpackSolver() {
    umfpack_dl_defaults(control_);
    control_[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_SYMMETRIC;
    control_[UMFPACK_ORDERING] = UMFPACK_ORDERING_METIS;
  }
  ~UmfpackSolver() override { release(); }
  UmfpackSolver(const UmfpackSolver&) = delete;
  UmfpackSolver& operator=(const UmfpackSolver&) = delete;

  const char* name() const override { return "umfpack"; }

  void analyze(const assembly::SparsePattern& pattern) override {
    KONTAKT_REQUIRE(!pattern.upper, "UMFPACK needs the full pattern");
    release();
    n_ = pattern.n;
    col_start_.assign(pattern.col_start.begin(), pattern.col_start.end());
    row_index_.assign(pattern.row_index.begin(), pattern.row_index.end());
    const int status = umfpack_dl_symbolic(n_, n_, col_start_.data(), row_index_.data(),
                                           nullptr, &symbolic_, control_, info_);
    if (status == UMFPACK_ERROR_out_of_memory) throw std::bad_alloc();
    KONTAKT_REQUIRE(status == UMFPACK_OK, "UMFPACK symbolic analysis failed (status " +
                                              std::to_string(status) + ")");
  }

  void factorize(const std::vector<Real>& values) override {
    KONTAKT_REQUIRE(symbolic_ != nullptr, "UMFPACK: factorize before analyze");
    values_ = values;
    if (numeric_) umfpack_dl_free_numeric(&numeric_);
    const int status = umfpack_dl_numeric(col_start_.data(), row_index_.data(), values_.data(),
                                          symbolic_, &numeric_, control_, info_);
    if (status == UMFPACK_WARNING_singular_matrix)
      throw SingularMatrix("stiffness matrix is singular", -1);
    if (status == UMFPACK_ERROR_out_of_memory) throw std::bad_alloc();
    KONTAKT_REQUIRE(status == UMFPACK_OK, "UMFPACK numeric factorisation failed (status " +
                                              std::to_string(status) + ")");
    const double rcond = info_[UMFPACK_RCOND];
    if (!(rcond >= kSingularRcond)) {
      std::ostringstream msg;
      msg << "stiffness matrix is numerically singular (reciprocal condition estimate "
          << rcond << ")";
      throw SingularMatrix(msg.str(), -1);
    }
  }

  VecX solve(const VecX& rhs) override {
    VecX x(rhs.size());
    const int status = umfpack_dl_solve(UMFPACK_A, col_start_.data(), row_index_.data(),
                                        values_.data(), x.data(), rhs.data(), numeric_,
                                        control_, info_);
    if (status == UMFPACK_ERROR_out_of_memory) throw std::bad_alloc();
    KONTAKT_REQUIRE(status == UMFPACK_OK, "UMFPACK solve failed");
    return x;
  }

 private:
  void release() {
    if (numeric_) umfpack_dl_free_numeric(&numeric_);
    if (symbolic_) umfpack_dl_free_symbolic(&symbolic_);
  }

  double control_[UMFPACK_CONTROL]{};
  double info_[UMFPACK_INFO]{};
  SuiteSparse_long n_ = 0;
  std::vector<SuiteSparse_long> col_start_, row_index_;
  std::vector<double> values_;
  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
};

}  // namespace

std::unique_ptr<LinearSolver> make_umfpack_solver() {
  return std::make_unique<UmfpackSolver>();
}

}  // namespace kontakt::linsolve
