// Small-strain isotropic J2 (von Mises) plasticity with piecewise-linear isotropic
// hardening, integrated by the radial-return mapping with its consistent tangent.
//
// Conventions (see solver/core/types.hpp): Voigt order xx, yy, zz, xy, xz, yz.
//   * INPUT total strain: ENGINEERING shear components (gamma_xy = 2 eps_xy), i.e. the
//     strain B*u of a displacement element.
//   * Stress: ordinary Cauchy components (sigma_xy, ...).
//   * Stored plastic strain (J2State::plastic_strain): TENSOR shear components
//     (eps_p_xy, ...), the convention used for reported strains.
//   * Tangent: d(stress)/d(engineering strain), 6x6, symmetric.
#pragma once

#include "core/types.hpp"
#include "material/hardening_table.hpp"
#include "material/von_mises.hpp"

namespace kontakt::material {

/// Internal variables of one integration point.
struct J2State {
  Vec6 plastic_strain = Vec6::Zero();   ///< tensor shear components, trace 0
  Real equivalent_plastic_strain = 0;   ///< alpha = integral of sqrt(2/3 deps_p:deps_p)
  Vec6 back_stress = Vec6::Zero();      ///< kinematic and combined hardening; else zero
};

struct J2Result {
  Vec6 stress = Vec6::Zero();
  Mat6 tangent = Mat6::Zero();  ///< consistent (algorithmic) tangent, engineering shear
  J2State state;                ///< trial state at the end of the increment
  bool yielded = false;         ///< true when the return mapping was active
  Real delta_alpha = 0;         ///< increment of equivalent plastic strain
};

/// Throws std::invalid_argument unless 0 < E < inf and -1 < nu < 0.5.
void check_elastic_constants(Real young, Real poisson);

/// Isotropic linear-elastic stiffness (engineering shear strain -> stress).
Mat6 isotropic_elastic_stiffness(Real young, Real poisson);

/// Radial return from the committed state for the total strain `strain` (engineering
/// shear). `thermal_strain` is an isotropic thermal strain alpha_T*(T - T0) removed
/// from the normal components before the constitutive update. The committed state is
/// not modified; commit result.state once the global iteration has converged.
/// Throws std::invalid_argument on bad data (E <= 0, nu outside (-1, 0.5), invalid
/// table, softening slope <= -3G) and SolverError if the local iteration fails.
J2Result j2_return_map(Real young, Real poisson, const HardeningTable& table,
                       const J2State& committed, const Vec6& strain,
                       Real thermal_strain = 0);

}  // namespace kontakt::material
