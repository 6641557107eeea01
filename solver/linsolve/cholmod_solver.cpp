// CHOLMOD (supernodal Cholesky) for symmetric positive definite systems, int64 interface.
#include <cholmod.h>
#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <new>
#include <sstream>

#include "linsolve/blas_threads.hpp"
#include "linsolve/linear_solver.hpp"

namespace kontakt::linsolve {

namespace {

/// CHOLMOD reports exhausted memory (a job's memory limit) through its status; the caller
/// sees it as every other allocation failure.
void throw_if_out_of_memory(const cholmod_common& common) {
  if (common.status == CHOLMOD_OUT_OF_MEMORY) throw std::bad_alloc();
}

/// CHOLMOD's supernodal numeric factorisation opens an OpenMP region with a compile-time 4
/// threads for every supernode's scatter; on small machines that is oversubscription and a
/// futex round trip per supernode, which dominated factorisations in Newton loops. The
/// regions are serialised (OpenMP's max-active-levels 0); the dense work of each supernode
/// still runs in the threaded BLAS.
void serialise_cholmod_openmp() {
  using SetLevels = void (*)(int);
  if (auto fn = reinterpret_cast<SetLevels>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels")))
    fn(0);
}

class CholmodSolver final : public LinearSolver {
 public:
  CholmodSolver() {
    serialise_cholmod_openmp();
    cholmod_l_start(&common_);
    common_.print = 0;  // failures are reported through exceptions, not stderr
  }
  ~CholmodSolver() override {
    release();
    cholmod_l_finish(&common_);
  }
  CholmodSolver(const CholmodSolver&) = delete;
  CholmodSolver& operator=(const CholmodSolver&) = delete;

  const char* name() const override { return "cholmod"; }

  void analyze(const assembly::SparsePattern& pattern) override {
    KONTAKT_REQUIRE(pattern.upper, "CHOLMOD needs the upper-triangular pattern");
    release();
    A_ = cholmod_l_allocate_sparse(pattern.n, pattern.n, pattern.nnz(), 1, 1, 1, CHOLMOD_REAL,
                                   &common_);
    throw_if_out_of_memory(common_);
    KONTAKT_REQUIRE(A_ != nullptr, "CHOLMOD could not allocate the matrix");
    auto* p = static_cast<SuiteSparse_long*>(A_->p);
    auto* i = static_cast<SuiteSparse_long*>(A_->i);
    std::copy(pattern.col_start.begin(), pattern.col_start.end(), p);
    std::copy(pattern.row_index.begin(), pattern.row_index.end(), i);
    L_ = cholmod_l_analyze(A_, &common_);
    throw_if_out_of_memory(common_);
    KONTAKT_REQUIRE(L_ != nullptr && common_.status >= CHOLMOD_OK,
                    "CHOLMOD symbolic analysis failed");
    flops_ = common_.fl;
  }

  void factorize(const std::vector<Real>& values) override {
    KONTAKT_REQUIRE(A_ != nullptr && L_ != nullptr, "CHOLMOD: factorize before analyze");
    std::copy(values.begin(), values.end(), static_cast<double*>(A_->x));
    use_blas_threads_for(flops_);
    cholmod_l_factorize(A_, L_, &common_);
    throw_if_out_of_memory(common_);
    if (common_.status == CHOLMOD_NOT_POSDEF) {
      const auto* perm = static_cast<const SuiteSparse_long*>(L_->Perm);
      const int eq = static_cast<int>(perm ? perm[L_->minor] : L_->minor);
      throw SingularMatrix("stiffness matrix is singular or not positive definite", eq);
    }
    KONTAKT_REQUIRE(common_.status >= CHOLMOD_OK, "CHOLMOD numeric factorisation failed");
    const double rcond = cholmod_l_rcond(L_, &common_);
    if (!(rcond >= kSingularRcond)) {
      std::ostringstream msg;
      msg << "stiffness matrix is numerically singular (reciprocal condition estimate "
          << rcond << ")";
      throw SingularMatrix(msg.str(), -1);
    }
  }

  VecX solve(const VecX& rhs) override {
    cholmod_dense* b = cholmod_l_allocate_dense(rhs.size(), 1, rhs.size(), CHOLMOD_REAL,
                                                &common_);
    if (b == nullptr) throw std::bad_alloc();
    std::copy(rhs.data(), rhs.data() + rhs.size(), static_cast<double*>(b->x));
    cholmod_dense* x = cholmod_l_solve(CHOLMOD_A, L_, b, &common_);
    cholmod_l_free_dense(&b, &common_);
    throw_if_out_of_memory(common_);
    KONTAKT_REQUIRE(x != nullptr, "CHOLMOD solve failed");
    VecX out = Eigen::Map<const VecX>(static_cast<const double*>(x->x), rhs.size());
    cholmod_l_free_dense(&x, &common_);
    return out;
  }

 private:
  void release() {
    if (L_) cholmod_l_free_factor(&L_, &common_);
    if (A_) cholmod_l_free_sparse(&A_, &common_);
  }

  cholmod_common common_{};
  cholmod_sparse* A_ = nullptr;
  cholmod_factor* L_ = nullptr;
  double flops_ = 0;  ///< of one numeric factorisation, from the analysis
};

}  // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver() { return std::make_unique<CholmodSolver>(); }

}  // namespace kontakt::linsolve
