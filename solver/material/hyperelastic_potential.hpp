// Which *HYPERELASTIC / *HYPERFOAM potential a material has, as plain data, and its response.
#pragma once

#include <variant>

#include "material/hyperelastic.hpp"
#include "material/hyperelastic_response.hpp"
#include "material/ogden.hpp"

namespace kontakt::material {

using HyperelasticPotential = std::variant<HyperelasticPolynomial, Ogden, Hyperfoam>;

/// The response of the potential at the right Cauchy-Green tensor C (SolverError where C is not
/// positive definite).
HyperelasticResponse hyperelastic_response(const HyperelasticPotential& potential, const Mat3& C);

}  // namespace kontakt::material
