// Potentials in the principal stretches, N <= 3 terms (ccx manual, *HYPERELASTIC and
// *HYPERFOAM), l_k^2 being the eigenvalues of the right Cauchy-Green tensor C, J = l1 l2 l3:
//   Ogden (*HYPERELASTIC, OGDEN), with the isochoric stretches lb_k = J^-1/3 l_k:
//     U = sum_i 2 mu_i / alpha_i^2 (lb1^alpha_i + lb2^alpha_i + lb3^alpha_i - 3)
//         + sum_i (J - 1)^(2i) / D_i
//   hyperfoam (*HYPERFOAM):
//     U = sum_i 2 mu_i / alpha_i^2 [l1^alpha_i + l2^alpha_i + l3^alpha_i - 3
//                                   + (J^(-alpha_i beta_i) - 1) / beta_i]
//     (beta_i = 0: its limit, -alpha_i ln J).
// The shear modulus at rest is sum mu_i for both. Ogden with N = 1, alpha = 2 is Neo-Hooke with
// C10 = mu / 2. Conventions: hyperelastic_response.hpp.
#pragma once

#include <array>

#include "core/types.hpp"
#include "material/hyperelastic_response.hpp"

namespace kontakt::material {

/// Terms 0..n_terms-1 are used; every alpha of them is nonzero. d[k-1] = D_k (0: absent).
struct Ogden {
  int n_terms = 1;
  std::array<Real, 3> mu{}, alpha{}, d{};
};

/// Terms 0..n_terms-1 are used; every alpha of them is nonzero, beta_i = nu_i / (1 - 2 nu_i).
struct Hyperfoam {
  int n_terms = 1;
  std::array<Real, 3> mu{}, alpha{}, beta{};
};

/// The responses at the right Cauchy-Green tensor C (symmetric, positive definite; SolverError
/// otherwise). Exact for coincident principal stretches too (at rest, uniaxial states).
HyperelasticResponse ogden_hyperelastic(const Ogden& constants, const Mat3& C);
HyperelasticResponse hyperfoam(const Hyperfoam& constants, const Mat3& C);

}  // namespace kontakt::material
