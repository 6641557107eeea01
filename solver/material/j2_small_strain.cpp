#include "material/j2_small_strain.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "material/symmetric_voigt.hpp"

namespace kontakt::material {

namespace {

constexpr int kShear0 = 3;  // first shear slot in Voigt order

}  // namespace

void check_elastic_constants(Real young, Real poisson) {
  if (!(young > 0.0) || !std::isfinite(young))
    throw std::invalid_argument("J2 plasticity: Young's modulus must be positive and finite");
  if (!(poisson > -1.0 && poisson < 0.5))
    throw std::invalid_argument("J2 plasticity: Poisson's ratio must lie in (-1, 0.5)");
}

Mat6 isotropic_elastic_stiffness(Real young, Real poisson) {
  check_elastic_constants(young, poisson);
  const Real mu = young / (2.0 * (1.0 + poisson));
  const Real lambda = young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson));
  Mat6 c = Mat6::Zero();
  c.topLeftCorner<3, 3>().setConstant(lambda);
  for (int i = 0; i < 3; ++i) c(i, i) += 2.0 * mu;
  for (int i = kShear0; i < 6; ++i) c(i, i) = mu;
  return c;
}

J2Result j2_return_map(Real young, Real poisson, const HardeningTable& table,
                       const J2State& committed, const Vec6& strain, Real thermal_strain) {
  check_elastic_constants(young, poisson);
  table.validate();
  const Real mu = young / (2.0 * (1.0 + poisson));
  const Real bulk = young / (3.0 * (1.0 - 2.0 * poisson));

  // Elastic strain, tensor shear.
  Vec6 eps_e = strain;
  eps_e.tail<3>() *= 0.5;
  eps_e.head<3>().array() -= thermal_strain;
  eps_e -= committed.plastic_strain;

  const Real volumetric = eps_e(0) + eps_e(1) + eps_e(2);
  const Vec6 s_trial = 2.0 * mu * deviator(eps_e);
  const Real s_norm = tensor_norm(s_trial);
  const Real q_trial = std::sqrt(1.5) * s_norm;
  const Real alpha_n = committed.equivalent_plastic_strain;
  const Real yield_n = table.yield(alpha_n);

  J2Result out;
  out.state = committed;
  Vec6 pressure_part = Vec6::Zero();
  pressure_part.head<3>().setConstant(bulk * volumetric);

  // Relative tolerance: a point returned onto the surface and re-evaluated with the
  // same strain must stay elastic despite round-off.
  const Real f_trial = q_trial - yield_n;
  if (!(f_trial > 1e-12 * std::max(yield_n, q_trial))) {
    out.stress = s_trial + pressure_part;
    out.tangent = isotropic_elastic_stiffness(young, poisson);
    out.yielded = false;
    return out;
  }

  const RadialReturn ret = solve_radial_return(table, alpha_n, q_trial, mu);
  const Real dg = ret.delta_alpha, h = ret.slope;
  const Vec6 n = s_trial / s_norm;  // unit deviatoric flow direction, tensor shear
  const Real theta = 1.0 - 3.0 * mu * dg / q_trial;
  const Real theta_bar = 3.0 * mu / (3.0 * mu + h) - (1.0 - theta);

  out.stress = theta * s_trial + pressure_part;
  out.state.plastic_strain = committed.plastic_strain + std::sqrt(1.5) * dg * n;
  out.state.equivalent_plastic_strain = alpha_n + dg;
  out.yielded = true;
  out.delta_alpha = dg;

  // C = K 1(x)1 + 2 mu theta P_dev - 2 mu theta_bar n(x)n, written for engineering
  // shear input: P_dev has 1/2 on the shear diagonal, and n : d eps = n_voigt . d gamma
  // because the factor 2 of the tensor contraction cancels the 1/2 of gamma.
  Mat6 c = Mat6::Zero();
  c.topLeftCorner<3, 3>().setConstant(bulk - 2.0 * mu * theta / 3.0);
  for (int i = 0; i < 3; ++i) c(i, i) += 2.0 * mu * theta;
  for (int i = kShear0; i < 6; ++i) c(i, i) = mu * theta;
  c -= 2.0 * mu * theta_bar * (n * n.transpose());
  out.tangent = c;
  return out;
}

}  // namespace kontakt::material
