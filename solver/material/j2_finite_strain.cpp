#include "material/j2_finite_strain.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "material/symmetric_voigt.hpp"

namespace kontakt::material {

namespace {

Mat3 tensor(const Vec6& v) {
  Mat3 t;
  t << v[0], v[3], v[4], v[3], v[1], v[5], v[4], v[5], v[2];
  return t;
}

/// Gradient of a scalar f with respect to the engineering Green-Lagrange strain, given the
/// symmetric tensor g with df = g : dC (dC = 2 dE, shear entries counted twice).
Vec6 strain_gradient(const Mat3& g) { return 2.0 * voigt(g); }

}  // namespace

J2FiniteResult j2_finite_strain(Real young, Real poisson, const HardeningTable& table,
                                const J2State& committed, const Mat3& C) {
  check_elastic_constants(young, poisson);
  table.validate();
  const Real mu = young / (2.0 * (1.0 + poisson));
  const Real bulk = young / (3.0 * (1.0 - 2.0 * poisson));
  const Real det_c = C.determinant();
  if (!(det_c > 0.0)) throw SolverError("finite-strain J2: det C <= 0 (inverted material)");

  const Real J = std::sqrt(det_c);
  const Mat3 Ci = C.inverse();
  const Mat3 P = Mat3::Identity() - 2.0 * tensor(committed.plastic_strain);  // Cp^-1
  const Real j23 = std::pow(J, -2.0 / 3.0);
  const Mat3 PC = P * C;
  const Real ie = j23 * PC.trace() / 3.0;                     // tr(b_e)/3
  const Real tr_b2 = j23 * j23 * (PC * PC).trace();          // tr(b_e b_e)
  const Real s_norm = std::sqrt(std::max(0.0, mu * mu * (tr_b2 - 3.0 * ie * ie)));
  const Real q = std::sqrt(1.5) * s_norm / J;
  const Real alpha_n = committed.equivalent_plastic_strain;
  const Real yield_n = table.yield(alpha_n);
  const Real pressure = 0.5 * bulk * (J * J - 1.0);  // Kirchhoff pressure

  // Gradients (with respect to engineering E) shared by both branches.
  const Vec6 Ci_v = voigt(Ci), P_v = voigt(P);
  const Vec6 dJ = J * Ci_v;
  const Vec6 d_j23 = (-2.0 / 3.0) * j23 * Ci_v;
  const Vec6 d_ie = strain_gradient((-ie / 3.0) * Ci + (j23 / 3.0) * P);
  const Mat6 d_Ci = 2.0 * inverse_derivative(Ci);  // with respect to E (dC = 2 dE)
  const Vec6 dev_pull = j23 * P_v - ie * Ci_v;  // F^-1 (b_e - I_e 1) F^-T

  J2FiniteResult out;
  out.state = committed;
  Real beta = 1.0;
  Vec6 d_beta = Vec6::Zero(), d_beta_kirchhoff = Vec6::Zero();
  // Relative tolerance: a point returned onto the surface and re-evaluated with the same C
  // must stay elastic despite round-off, which the rebuilt elastic deviator (small against
  // mu) amplifies to about 1e-12.
  if (q - yield_n > 1e-10 * std::max(yield_n, q)) {
    const Real G = mu * ie / J;  // effective shear modulus of the return
    const RadialReturn ret = solve_radial_return(table, alpha_n, q, G);
    const Real da = ret.delta_alpha;
    beta = 1.0 - 3.0 * G * da / q;
    // Consistent linearisation of q, G, d_alpha and beta. q and G carry 1/J (the yield test
    // is on the Cauchy deviator); without those dJ terms it is the linearisation with the
    // yield stress J sigma_y held fixed, the Kirchhoff form of Simo's return.
    const Vec6 d_tr_b2 = strain_gradient((-2.0 / 3.0) * tr_b2 * Ci + 2.0 * j23 * j23 * (P * C * P));
    const Vec6 d_s_norm = (mu * mu * (d_tr_b2 - 6.0 * ie * d_ie)) / (2.0 * s_norm);
    auto beta_gradient = [&](Real volume_terms) {
      const Vec6 dq = q * (d_s_norm / s_norm - volume_terms * dJ / J);
      const Vec6 dG = G * (d_ie / ie - volume_terms * dJ / J);
      const Vec6 d_da = (dq - 3.0 * da * dG) / (3.0 * G + ret.slope);
      return Vec6(-3.0 * (da * dG + G * d_da) / q + (3.0 * G * da / (q * q)) * dq);
    };
    d_beta = beta_gradient(1.0);
    d_beta_kirchhoff = beta_gradient(0.0);
    const Mat3 P_new = beta * P + (1.0 - beta) * (ie / j23) * Ci;
    out.state.plastic_strain = voigt(0.5 * (Mat3::Identity() - P_new));
    out.state.equivalent_plastic_strain = alpha_n + da;
    out.yielded = true;
    out.delta_alpha = da;
  }
  out.stress = pressure * Ci_v + beta * mu * dev_pull;
  const Mat6 at_fixed_beta = Ci_v * (bulk * J * dJ.transpose()) + pressure * d_Ci +
                             beta * mu * (P_v * d_j23.transpose() - Ci_v * d_ie.transpose() - ie * d_Ci);
  out.tangent = at_fixed_beta + mu * dev_pull * d_beta.transpose();
  out.kirchhoff_tangent = at_fixed_beta + mu * dev_pull * d_beta_kirchhoff.transpose();
  return out;
}

}  // namespace kontakt::material
