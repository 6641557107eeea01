// Small-strain, isotropic linear-elastic element kernels: pure functions of nodal data.
// DOF order everywhere is node-major: (u1x, u1y, u1z, u2x, ...). Tensors are in Voigt order
// xx, yy, zz, xy, xz, yz; strains are reported as tensor components (eps_xy, not gamma_xy).
#pragma once

#include "core/types.hpp"
#include "element/element_type.hpp"

namespace kontakt::element {

struct LinearElastic {
  Real young = 0;
  Real poisson = 0;
  Real expansion = 0;  ///< secant thermal expansion coefficient; strain = expansion * dT
};

/// Element stiffness K (3n x 3n) for nodal coordinates X (n x 3, ccx local node order).
/// C3D8I condenses its incompatible modes; C3D8R adds hourglass stiffness.
void linear_stiffness(ElementType type, const MatX3& X, const LinearElastic& mat, MatX& K);

/// Equivalent nodal forces (3n) of the free thermal strain expansion * dT, with the temperature
/// change dT given at the nodes (n) and interpolated to the integration points.
void thermal_load(ElementType type, const MatX3& X, const LinearElastic& mat, const VecX& dT,
                  VecX& f);

/// Consistent nodal forces (3n, over all element nodes) of a uniform pressure p on face
/// `face` (1-based): f = -integral(N * p * n_out dA); positive p pushes into the element.
void pressure_load(ElementType type, int face, const MatX3& X, Real p, VecX& f);

/// What an element reports at its integration points for nodal displacements u (n x 3).
struct IpResults {
  MatX6 stress;          ///< n_ip x 6, ccx integration point order
  MatX6 strain;          ///< n_ip x 6, total strain (tensor shear components)
  VecX energy_density;   ///< n_ip, elastic strain energy per unit volume
  VecX internal_force;   ///< 3n, integral of B^T sigma: the element's nodal forces
  Real volume = 0;
};
void recover(ElementType type, const MatX3& X, const LinearElastic& mat, const MatX3& u,
             const VecX& dT, IpResults& out);

/// Integration-point weights times Jacobian determinants (n_ip): the volume each point carries.
VecX ip_volumes(ElementType type, const MatX3& X);

/// Matrix E (n_nodes x n_ip) that extrapolates integration point values to the nodes:
/// nodal = E * ip. Midside nodes of quadratic elements get the average of their edge corners
/// where the rule cannot reach them otherwise.
const MatX& ip_to_node_extrapolation(ElementType type);

}  // namespace kontakt::element
