// What a hyperelastic potential returns at one point, in the conventions of the total-Lagrangian
// kernels: Voigt order xx, yy, zz, xy, xz, yz; S with tensor components; the tangent is dS/dE
// with E the Green-Lagrange strain in ENGINEERING shear.
#pragma once

#include "core/types.hpp"

namespace kontakt::material {

struct HyperelasticResponse {
  Real energy = 0;              ///< U per unit reference volume
  Vec6 stress = Vec6::Zero();   ///< second Piola-Kirchhoff S = dU/dE
  Mat6 tangent = Mat6::Zero();  ///< dS/dE (engineering shear), symmetric
};

}  // namespace kontakt::material
