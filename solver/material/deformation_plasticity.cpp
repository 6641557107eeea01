#include "material/deformation_plasticity.hpp"

#include <Eigen/LU>
#include <cmath>
#include <unsupported/Eigen/AutoDiff>

#include "core/error.hpp"
#include "material/symmetric_voigt.hpp"

namespace kontakt::material {

namespace {

using Dual = Eigen::AutoDiffScalar<Vec6>;  // derivatives with respect to E (engineering shear)
using DualMat3 = Eigen::Matrix<Dual, 3, 3>;

/// q g(q) = E ebar by Newton from the elastic guess (q g is increasing and convex for n >= 1).
Real von_mises_stress(const RambergOsgood& m, Real ebar) {
  const auto g = [&](Real q) { return 1 + m.poisson + 1.5 * m.alpha * std::pow(q / m.yield, m.exponent - 1); };
  const Real target = m.young * ebar;
  Real q = target / (1 + m.poisson);  // above the root: Newton from here decreases monotonically
  for (int it = 0; it < 100; ++it) {
    const Real slope = g(q) + 1.5 * m.alpha * (m.exponent - 1) * std::pow(q / m.yield, m.exponent - 1);
    const Real step = (q * g(q) - target) / slope;
    q -= step;
    if (std::abs(step) <= 1e-14 * q) return q;
  }
  throw SolverError("deformation plasticity: the von Mises stress did not converge");
}

}  // namespace

DeformationPlasticityResponse deformation_plasticity(const RambergOsgood& m, const Mat3& F) {
  if (!(m.young > 0) || !(m.poisson > -1 && m.poisson < 0.5) || !(m.yield > 0) ||
      !(m.exponent >= 1) || !(m.alpha >= 0))
    throw SolverError("deformation plasticity: invalid constants");
  const Real det = F.determinant();
  if (!(det > 0)) throw SolverError("deformation plasticity: det F <= 0 (inverted material)");

  // E as dual numbers, seeded on its six Voigt components (shear: the engineering value).
  const Mat3 C0 = F.transpose() * F;
  const Mat3 E0 = 0.5 * (C0 - Mat3::Identity());
  DualMat3 E;
  for (int a = 0; a < 6; ++a) {
    const int i = kVoigtI[a], j = kVoigtJ[a];
    E(i, j) = E(j, i) = Dual(E0(i, j), Vec6::Unit(a) * (a < 3 ? 1.0 : 0.5));
  }
  const DualMat3 C = DualMat3::Identity() + 2 * E;
  const DualMat3 Ci = C.inverse();
  const Dual J = sqrt(C.determinant());
  const DualMat3 CiECi = Ci * E * Ci;
  const Dual tr_e = (E * Ci).trace();
  const Dual ee = (E * Ci * E * Ci).trace();  // e : e
  const Dual dev2 = ee - tr_e * tr_e / 3;     // dev(e) : dev(e)

  // q from the scalar equation, its derivatives by one Newton step on the dual residual.
  const Real ebar0 = std::sqrt(std::max(0.0, 1.5 * dev2.value()));
  Dual g = 1 + m.poisson;
  if (ebar0 > 0) {
    const Real q0 = von_mises_stress(m, ebar0);
    const Dual ebar = sqrt(1.5 * dev2);
    const Real g0 = 1 + m.poisson + 1.5 * m.alpha * std::pow(q0 / m.yield, m.exponent - 1);
    const Real slope = g0 + 1.5 * m.alpha * (m.exponent - 1) * std::pow(q0 / m.yield, m.exponent - 1);
    const Dual q = q0 - (q0 * g0 - m.young * ebar) / slope;
    g = 1 + m.poisson + 1.5 * m.alpha * pow(q / m.yield, m.exponent - 1);
  }
  const Dual tr_sigma = m.young * tr_e / (1 - 2 * m.poisson);
  const DualMat3 S = J * (tr_sigma / 3 * Ci + m.young / g * (CiECi - tr_e / 3 * Ci));

  DeformationPlasticityResponse out;
  for (int a = 0; a < 6; ++a) {
    const Dual& s = S(kVoigtI[a], kVoigtJ[a]);
    out.stress[a] = s.value();
    out.tangent.row(a) = s.derivatives().transpose();
  }
  return out;
}

}  // namespace kontakt::material
