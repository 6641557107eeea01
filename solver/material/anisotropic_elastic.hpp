// Orthotropic and anisotropic linear elasticity (*ELASTIC, TYPE=ORTHO / ENGINEERING CONSTANTS /
// ANISO; ccx manual, *ELASTIC): S_IJ = D_IJKL E_KL in the material frame, the frame given by
// *ORIENTATION. At small strain S and E are the stress and strain; under NLGEOM the second
// Piola-Kirchhoff stress and the Green-Lagrange strain (St Venant-Kirchhoff, frame fixed in the
// reference configuration).
//
// Voigt order xx, yy, zz, xy, xz, yz with ENGINEERING shear strain, so the 6 x 6 matrix holds
// the D_IJKL themselves (S_12 = D_1212 * 2 E_12).
#pragma once

#include <array>

#include "core/types.hpp"

namespace kontakt::material {

/// The 21 constants of TYPE=ANISO in ccx's order: the upper triangle of the Voigt matrix
/// column by column, D1111, D1122, D2222, D1133, D2233, D3333, D1112, D2212, D3312, D1212,
/// D1113, ..., D2323.
using AnisotropicConstants = std::array<Real, 21>;

/// TYPE=ORTHO: D1111, D1122, D2222, D1133, D2233, D3333, D1212, D1313, D2323.
using OrthotropicConstants = std::array<Real, 9>;

/// TYPE=ENGINEERING CONSTANTS: E1, E2, E3, nu12, nu13, nu23, G12, G13, G23 (nu_ij: the
/// contraction in j under stress in i, so nu_ij / E_i = nu_ji / E_j).
using EngineeringConstants = std::array<Real, 9>;

/// The symmetric 6 x 6 stiffness of the 21 constants.
Mat6 anisotropic_stiffness(const AnisotropicConstants& d);

/// The 21 constants of an orthotropic material (the others zero).
AnisotropicConstants from_orthotropic(const OrthotropicConstants& d);

/// The 21 constants of the orthotropic material with these engineering constants: the
/// inverse of its compliance. Throws std::invalid_argument when a modulus is not positive or
/// the compliance is singular.
AnisotropicConstants from_engineering(const EngineeringConstants& c);

/// True when the stiffness is positive definite (a strain energy that is positive for every
/// strain: what a stable elastic material needs).
bool is_positive_definite(const Mat6& D);

/// The stiffness in global components of a material whose frame has the local axes as the
/// columns of the rotation R (u_global = R u_local): D_g = T^T D T, T mapping global to local
/// engineering strains.
Mat6 rotate_stiffness(const Mat6& D_local, const Mat3& R);

/// Stress (Voigt, tensor components) from global to the frame of R: sigma_l = R^T sigma R.
Vec6 stress_to_local(const Vec6& stress, const Mat3& R);

}  // namespace kontakt::material
