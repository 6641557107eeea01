// Compressible polynomial hyperelasticity (*HYPERELASTIC, NEO HOOKE / MOONEY-RIVLIN /
// POLYNOMIAL N <= 3; ccx manual, *HYPERELASTIC):
//   U = sum_{i+j=1..N} C_ij (I1b - 3)^i (I2b - 3)^j + sum_{k=1..N} (J - 1)^(2k) / D_k
// with J = sqrt(det C), I1b = J^-2/3 tr C, I2b = J^-4/3 (tr(C)^2 - tr(C^2)) / 2 (the isochoric
// invariants of the right Cauchy-Green tensor C = 1 + 2E). Neo-Hooke is C10 and D1 only,
// Mooney-Rivlin C10, C01, D1.
// Conventions: hyperelastic_response.hpp.
#pragma once

#include <array>

#include "core/types.hpp"
#include "material/hyperelastic_response.hpp"

namespace kontakt::material {

/// The constants of the potential: c[i][j] = C_ij (i + j between 1 and 3), d[k-1] = D_k
/// (0: the term is absent).
struct HyperelasticPolynomial {
  std::array<std::array<Real, 4>, 4> c{};
  std::array<Real, 3> d{};
};

/// The response at the right Cauchy-Green tensor C (symmetric, det C > 0; SolverError
/// otherwise).
HyperelasticResponse polynomial_hyperelastic(const HyperelasticPolynomial& constants,
                                             const Mat3& C);

}  // namespace kontakt::material
