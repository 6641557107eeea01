// Internal building blocks shared by the solid kernels (B matrices, material, special elements).
#pragma once

#include <functional>
#include <vector>

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

/// Elasticity matrix for engineering shear strains (the anisotropic stiffness where set).
Mat6 elasticity_matrix(const PointElastic& point);

/// Geometry at natural point xi; throws SolverError for a non-positive Jacobian.
PointGeometry point_geometry(Topology topo, const MatX3& X, const Vec3& xi);

/// Geometry used at a rule point of `type`: point_geometry, except C3D8R, whose single point
/// carries the Flanagan-Belytschko mean gradients and the exact volume (uniform strain).
PointGeometry rule_point_geometry(ElementType type, const MatX3& X, const Vec3& xi);

/// Fills B (6 x 3n) from physical shape derivatives.
void b_matrix(const ShapeGrad& dNdx, BMatrix& B);

/// Engineering strain (gamma) -> tensor strain (eps_ij) in Voigt order.
Vec6 tensor_strain(const Vec6& engineering);

/// Isotropic thermal strain vector (engineering = tensor: no shear) of a point's material.
Vec6 thermal_strain(const PointElastic& mat);

/// Temperature change at natural point xi (shape values N there) in ccx's convention; 0 when
/// dT is empty (thermal_interpolation.cpp).
Real point_temperature(ElementType type, const Vec3& xi, const ShapeVec& N, const VecX& dT);

/// The material at natural point xi (shape values N) of `type`: initial temperature and change
/// (nodal dT, empty: none) interpolated by point_temperature (point_material.cpp).
PointElastic point_material(const ThermoElastic& mat, ElementType type, const Vec3& xi,
                            const ShapeVec& N, const VecX& dT);

/// An integration point as the nonlinear kernels see it: gradients, with respect to the
/// reference coordinates, of the functions interpolating the element's value rows (the nodes,
/// then any internal modes), the volume it carries and its material at its temperature.
struct KernelPoint {
  ShapeGrad dNdX;  ///< n_values x 3
  Real dv = 0;     ///< weight times Jacobian determinant
  PointElastic material;
};

/// The points of `type`'s rule (C3D8R: its mean-gradient point), the material evaluated at the
/// nodal temperature changes dT (empty: none). C3D8I gets the 8 nodal rows only
/// (incompatible_kernel_points adds its modes).
std::vector<KernelPoint> kernel_points(ElementType type, const MatX3& X, const ThermoElastic& mat,
                                       const VecX& dT);

/// The modulus of C3D8R's hourglass stiffness as a kernel reports it, with its derivative
/// with respect to the value rows (3n; empty: constant, or not needed by the tangent asked).
struct HourglassModulus {
  Real value = 0;
  VecX gradient;
};

/// A nonlinear kernel over prepared points: forces f (3 x value rows) and, when asked, the
/// tangent K of the value rows `values`; where `hourglass` is given (C3D8R) also the modulus
/// of the hourglass stiffness. Anything else it reports it records itself.
using PointKernel =
    std::function<void(const std::vector<KernelPoint>& points, const MatX3& values,
                       bool want_tangent, VecX& f, MatX& K, HourglassModulus* hourglass)>;

/// Runs `kernel` on an element of `type` at nodal displacements u (kernel_points.cpp): C3D8I
/// through the condensation of its incompatible modes (local solve from `modes_start`, 3 x 3
/// or empty for zero; the amplitudes reached go to `modes`; both in the element's frame,
/// incompatible_frame_rotation), C3D8R with its hourglass stiffness (reference
/// configuration, modulus from the kernel) added, all others directly (`modes` left empty).
void run_point_kernel(ElementType type, const MatX3& X, const ThermoElastic& mat, const MatX3& u,
                      const VecX& dT,
                      const MatX3& modes_start, bool want_tangent, const PointKernel& kernel,
                      VecX& f, MatX& K, MatX3& modes);

// --- Total Lagrangian building blocks (total_lagrangian_terms.cpp) ------------------------------

/// 6 x 3n nonlinear strain-displacement matrix at deformation gradient F:
/// dE (engineering shear) = B_NL du for dF = du^T dNdX.
void b_nonlinear(const ShapeGrad& dNdX, const Mat3& F, BMatrix& B);

/// Adds the initial-stress stiffness dv * (dNdX S dNdX^T)_ab delta_ik of the second
/// Piola-Kirchhoff stress S to K (3n x 3n).
void add_initial_stress_stiffness(const ShapeGrad& dNdX, const Mat3& S, Real dv, MatX& K);

/// Deformation gradient F = 1 + u^T dNdX of value rows u (n x 3).
Mat3 deformation_gradient(const ShapeGrad& dNdX, const MatX3& u);

/// ccx's mechanical deformation gradient under a thermal strain a = alpha dT: F - a 1, i.e.
/// the thermal strain is taken off the displacement gradient (free expansion by 1 + a is
/// stress free; measured against ccx 2.20, elastic and plastic). Not objective under large
/// rotations of heated material, which is what ccx does.
inline Mat3 mechanical_deformation_gradient(const Mat3& F, Real thermal) {
  return F - thermal * Mat3::Identity();
}

/// Symmetric tensor <-> Voigt vector (tensor components, xx yy zz xy xz yz).
Mat3 tensor_from_voigt(const Vec6& v);
Vec6 voigt_from_tensor(const Mat3& t);

/// What a material answers at a total Lagrangian point: second Piola-Kirchhoff S (Voigt,
/// tensor components) and dS/dE_m (engineering shear), E_m the Green-Lagrange strain of F_m.
struct TotalLagrangianResponse {
  Vec6 stress;
  Mat6 tangent;
};

/// The material law at point k for deformation gradient F and mechanical F_m; it records its
/// own point outputs (energy, plastic state).
using TotalLagrangianMaterial =
    std::function<TotalLagrangianResponse(Index k, const Mat3& F, const Mat3& Fm)>;

/// Total Lagrangian forces f = sum dv B_NL(F)^T S and tangent
/// K = sum dv (B_NL(F)^T D B_NL(F_m) + initial stress) over the points, with the Cauchy stress
/// and total Green-Lagrange strain of every point (n_ip x 6, resized here). F_m is ccx's
/// mechanical deformation gradient of the point's thermal strain. SolverError for an inverted
/// point.
void integrate_total_lagrangian(const std::vector<KernelPoint>& points, const MatX3& u,
                                bool want_tangent,
                                const TotalLagrangianMaterial& material, VecX& f, MatX& K,
                                MatX6& cauchy, MatX6& green_lagrange);

// --- C3D8I: Wilson-Taylor incompatible modes, condensed (incompatible_modes.cpp) ---------------

/// Condensed stiffness (24 x 24).
/// Condensed stiffness (24 x 24) at nodal temperature changes dT (8; empty: none).
void incompatible_stiffness(const MatX3& X, const ThermoElastic& mat, const VecX& dT, MatX& K);
/// Condensed thermal load (24).
void incompatible_thermal_load(const MatX3& X, const ThermoElastic& mat, const VecX& dT, VecX& f);
/// Total engineering strain at each of the 8 points, internal modes recovered from u and dT.
void incompatible_strains(const MatX3& X, const ThermoElastic& mat, const MatX3& u,
                          const VecX& dT, Eigen::Matrix<Real, 8, 6>& strains);

/// The 8 points of C3D8I with 11 value rows each: the 8 nodes, then the three modes, whose
/// gradients use the centroid Jacobian scaled by det(J0)/det(J) as in the linear element.
std::vector<KernelPoint> incompatible_kernel_points(const MatX3& X, const ThermoElastic& mat,
                                                   const VecX& dT);

/// Rotation of the polar decomposition of C3D8I's compatible deformation gradient at the
/// centroid, for nodal displacements u: the frame the mode amplitudes are kept in between
/// increments, so a rigid rotation of the element leaves the start of their local solve exact.
Mat3 incompatible_frame_rotation(const MatX3& X, const MatX3& u);

/// Forces (33) and tangent (33 x 33) of a C3D8I element at value rows (11 x 3): nodal
/// displacements, then the amplitudes of the three incompatible modes.
using IncompatibleEvaluation = std::function<void(const MatX3& values, VecX& f, MatX& K)>;

/// Static condensation of the incompatible modes of a nonlinear C3D8I: solves the modes'
/// equilibrium f_alpha(u, alpha) = 0 by Newton's method with backtracking, starting from the
/// amplitudes `start` (3 x 3; empty: zero; `size` the element's extent, the scale of what counts
/// as round-off), then returns the nodal forces (24), the condensed
/// tangent K_uu - K_ua K_aa^-1 K_au (24 x 24) and the amplitudes reached (incompatible_
/// condensation.cpp). The last call of `evaluate` is at the returned amplitudes, so whatever
/// it records (stresses, point states) belongs to them; f, K and alpha are written only after
/// the last call. SolverError when the local iteration fails.
void condense_incompatible_modes(const MatX3& u, const MatX3& start, Real size,
                                 const IncompatibleEvaluation& evaluate, bool want_tangent,
                                 VecX& f, MatX& K, MatX3& alpha);

// --- C3D8R: Flanagan-Belytschko hourglass control (hourglass.cpp) ------------------------------

/// Flanagan-Belytschko mean gradients b = (1/V) integral dN/dx dV (8 x 3) and the volume V.
void mean_gradients(const MatX3& X, ShapeGrad& b, Real& volume);

/// Hourglass stiffness (24 x 24) to be added to the one-point stiffness, for a material of
/// modulus `modulus`: Young's modulus for linear elasticity; ccx takes the current xx entry of
/// the material tangent, C_1111, for other materials (measured on *PLASTIC materials).
void hourglass_stiffness(const MatX3& X, Real modulus, MatX& Khg);

}  // namespace kontakt::element
