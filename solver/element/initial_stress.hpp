// Nodal forces of a prescribed initial (residual) stress, *INITIAL CONDITIONS, TYPE=STRESS.
#pragma once

#include "core/types.hpp"
#include "element/element_type.hpp"

namespace kontakt::element {

/// Internal force f (3n) of the stress sigma0 (n_ip x 6, rows in `type`'s integration point
/// order, Voigt xx yy zz xy xz yz) held at the points of a small-strain element with reference
/// coordinates X: f = sum_q w_q detJ_q B_q^T sigma0_q. It does not depend on the displacements
/// (small strain), so it adds nothing to the tangent. C3D8I is not supported (its incompatible
/// modes would take a share of the load): SolverError.
void initial_stress_force(ElementType type, const MatX3& X, const MatX& sigma0, VecX& f);

}  // namespace kontakt::element
