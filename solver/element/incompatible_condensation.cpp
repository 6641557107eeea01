// Nonlinear C3D8I: the incompatible modes are element-internal unknowns whose equilibrium is
// solved inside the element for the current nodal displacements, so the global Newton method
// sees a 24-dof element whose forces and condensed tangent are exact functions of u (and of
// the committed plastic state).
#include <Eigen/LU>
#include <algorithm>
#include <string>

#include "core/error.hpp"
#include "element/solid_kernels.hpp"

namespace kontakt::element {

namespace {

constexpr int kNodal = 24, kModes = 9;
// Started from the last converged amplitudes the local problem settles in a few steps; a
// failure within this many is numerical trouble the global driver answers by cutting back.
constexpr int kMaxIterations = 30;
constexpr int kMaxHalvings = 6;

Real max_abs(const VecX& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0; }

}  // namespace

void condense_incompatible_modes(const MatX3& u, const MatX3& start, Real size,
                                 const IncompatibleEvaluation& evaluate, bool want_tangent,
                                 VecX& f, MatX& K, MatX3& alpha) {
  KONTAKT_REQUIRE(u.rows() == 8, "C3D8I: needs 8 nodal displacements");
  KONTAKT_REQUIRE(start.size() == 0 || start.rows() == 3, "C3D8I: 3 mode amplitudes are needed");
  MatX3 values = MatX3::Zero(11, 3);
  values.topRows(8) = u;
  if (start.size()) values.bottomRows(3) = start;
  VecX f_all;
  MatX K_all;
  evaluate(values, f_all, K_all);
  // Length against which a mode correction counts as round-off: the larger of the amplitudes
  // and the spread of the nodal displacements (a translation deforms nothing), and at least a
  // strain of 1e-12 over the element: the stresses carry an absolute round-off of a few ulp
  // of the moduli, which no correction removes when the element is (nearly) undeformed.
  const Real spread = (u.colwise().maxCoeff() - u.colwise().minCoeff()).maxCoeff();
  const Real floor_length = 1e-2 * size;
  Eigen::PartialPivLU<MatX> lu;
  Real last_step = -1;  // size of the last correction applied, none yet
  for (int it = 0;; ++it) {
    const VecX r = f_all.tail(kModes);
    if (!r.allFinite() || !K_all.allFinite())
      throw SolverError("C3D8I: the incompatible modes diverged (NaN)");
    lu.compute(K_all.bottomRightCorner(kModes, kModes));
    // Converged once the mode forces are round-off against the nodal forces (both vanish in
    // the rest state), or the last correction was round-off against the element's deformation:
    // the mode forces then sit at their round-off floor, which cancellation in the stresses of
    // very small strains lifts above the first test.
    const Real length =
        std::max({spread, values.bottomRows(3).cwiseAbs().maxCoeff(), floor_length});
    if (max_abs(r) <= 1e-12 * max_abs(f_all.head(kNodal)) ||
        (last_step >= 0 && last_step <= 1e-10 * length))
      break;
    if (it == kMaxIterations)
      throw SolverError("C3D8I: the incompatible modes did not reach equilibrium in " +
                        std::to_string(kMaxIterations) + " local iterations");
    const VecX step = -lu.solve(r);
    // Backtracking: a plastic state change can make a full step overshoot; halve it until the
    // mode forces decrease (not needed, nor measurable, once they are nearly balanced).
    const MatX3 base = values.bottomRows(3);
    const bool near = max_abs(r) <= 1e-8 * max_abs(f_all.head(kNodal));
    Real lambda = 1;
    for (int halving = 0;; ++halving) {
      for (int m = 0; m < kModes; ++m)
        values(8 + m / 3, m % 3) = base(m / 3, m % 3) + lambda * step[m];
      try {
        evaluate(values, f_all, K_all);
      } catch (const SolverError&) {  // the trial amplitudes invert a point: shorter step
        if (halving == kMaxHalvings) throw;
        lambda /= 2;
        continue;
      }
      if (near || max_abs(f_all.tail(kModes)) < max_abs(r) || halving == kMaxHalvings) break;
      lambda /= 2;
    }
    last_step = lambda * max_abs(step);
  }
  // What is left of the mode forces is condensed with the converged tangent, as one more local
  // Newton step would leave it.
  const MatX Kua = K_all.topRightCorner(kNodal, kModes);
  f = f_all.head(kNodal) - Kua * lu.solve(f_all.tail(kModes));
  if (want_tangent)
    K = K_all.topLeftCorner(kNodal, kNodal) - Kua * lu.solve(K_all.bottomLeftCorner(kModes, kNodal));
  else
    K.resize(0, 0);
  alpha = values.bottomRows(3);
}

}  // namespace kontakt::element
