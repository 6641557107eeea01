// Internal building blocks shared by the solid kernels (B matrices, material, special elements).
#pragma once

#include "core/types.hpp"
#include "element/shape_functions.hpp"
#include "element/solid_linear.hpp"

namespace kontakt::element {

/// 6 x 3n strain-displacement matrix (engineering shear strains), heap-free.
using BMatrix = Eigen::Matrix<Real, 6, Eigen::Dynamic, 0, 6, 3 * kMaxNodes>;

/// Shape data of one point mapped to physical space.
struct PointGeometry {
  ShapeVec N;
  ShapeGrad dNdx;  ///< n x 3 physical derivatives
  Mat3 J;          ///< J(i,j) = dx_j / dxi_i
  Real detJ = 0;
};

/// Isotropic elasticity matrix for engineering shear strains.
Mat6 elasticity_matrix(const LinearElastic& mat);

/// Geometry at natural point xi; throws SolverError for a non-positive Jacobian.
PointGeometry point_geometry(Topology topo, const MatX3& X, const Vec3& xi);

/// Geometry used at a rule point of `type`: point_geometry, except C3D8R, whose single point
/// carries the Flanagan-Belytschko mean gradients and the exact volume (uniform strain).
PointGeometry rule_point_geometry(ElementType type, const MatX3& X, const Vec3& xi);

/// Fills B (6 x 3n) from physical shape derivatives.
void b_matrix(const ShapeGrad& dNdx, BMatrix& B);

/// Engineering strain (gamma) -> tensor strain (eps_ij) in Voigt order.
Vec6 tensor_strain(const Vec6& engineering);

/// Isotropic thermal strain vector alpha*dT (engineering = tensor: no shear).
Vec6 thermal_strain(const LinearElastic& mat, Real dT);

/// Temperature change at natural point xi (shape values N there) in ccx's convention; 0 when
/// dT is empty (thermal_interpolation.cpp).
Real point_temperature(ElementType type, const Vec3& xi, const ShapeVec& N, const VecX& dT);

// --- C3D8I: Wilson-Taylor incompatible modes, condensed (incompatible_modes.cpp) ---------------

/// Condensed stiffness (24 x 24).
void incompatible_stiffness(const MatX3& X, const LinearElastic& mat, MatX& K);
/// Condensed thermal load (24).
void incompatible_thermal_load(const MatX3& X, const LinearElastic& mat, const VecX& dT, VecX& f);
/// Total engineering strain at each of the 8 points, internal modes recovered from u and dT.
void incompatible_strains(const MatX3& X, const LinearElastic& mat, const MatX3& u,
                          const VecX& dT, Eigen::Matrix<Real, 8, 6>& strains);

// --- C3D8R: Flanagan-Belytschko hourglass control (hourglass.cpp) ------------------------------

/// Flanagan-Belytschko mean gradients b = (1/V) integral dN/dx dV (8 x 3) and the volume V.
void mean_gradients(const MatX3& X, ShapeGrad& b, Real& volume);

/// Hourglass stiffness (24 x 24) to be added to the one-point stiffness.
void hourglass_stiffness(const MatX3& X, const LinearElastic& mat, MatX& Khg);

}  // namespace kontakt::element
