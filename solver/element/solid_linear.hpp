// Small-strain, isotropic linear-elastic element kernels: pure functions of nodal data.
// DOF order everywhere is node-major: (u1x, u1y, u1z, u2x, ...). Tensors are in Voigt order
// xx, yy, zz, xy, xz, yz; strains are reported as tensor components (eps_xy, not gamma_xy).
#pragma once

#include <functional>
#include <optional>

#include "core/types.hpp"
#include "element/element_type.hpp"
#include "material/deformation_plasticity.hpp"
#include "material/hyperelastic_potential.hpp"
#include "material/temperature_table.hpp"

namespace kontakt::element {

/// Isotropic elastic constants at one temperature.
struct LinearElastic {
  Real young = 0;
  Real poisson = 0;
  Real expansion = 0;  ///< secant thermal expansion coefficient; strain = expansion * dT
};

/// What an integration point's material is: the constants at its temperature and its free
/// thermal strain (isotropic) since the initial state.
struct PointElastic {
  LinearElastic constants;
  Real thermal_strain = 0;
  Real temperature = 0;  ///< initial + change (what temperature-dependent hardening is read at)
  /// Set for an orthotropic / anisotropic material: its stiffness in global components
  /// (engineering shear); constants.young and poisson are then unused.
  std::optional<Mat6> stiffness;
};

/// An element's isotropic thermo-elastic material: *ELASTIC and *EXPANSION tables evaluated at
/// each integration point's temperature, as ccx 2.20 does (measured on one-element decks): the
/// constants interpolated at T = T0 + dT, and the thermal strain
/// alpha(T) (T - Z) - alpha(T0) (T0 - Z) with Z the ZERO= reference temperature and alpha the
/// secant coefficient (a constant alpha gives alpha dT whatever Z).
struct ThermoElastic {
  material::TemperatureTable<2> elastic;    ///< (E, nu) rows
  /// Orthotropic / anisotropic instead (elastic empty): the 21 constants in the material frame
  /// (material/anisotropic_elastic), rotated to global components at each point.
  material::TemperatureTable<21> anisotropic;
  /// The material frame at a point x (columns: local axes); empty: the global axes.
  std::function<Mat3(const Vec3& x)> frame;
  /// Hyperelastic instead (elastic and anisotropic empty): total Lagrangian kernels only.
  std::optional<material::HyperelasticPotential> hyperelastic;
  /// Deformation plasticity instead (elastic and anisotropic empty): total Lagrangian only.
  std::optional<material::RambergOsgood> deformation_plasticity;
  MatX3 coords;  ///< the element's nodes, where `frame` is evaluated from (with frame only)
  material::TemperatureTable<1> expansion;  ///< secant alpha rows; empty: no thermal strain
  Real expansion_zero = 0;
  VecX initial_temperature;  ///< the element's nodal initial temperatures (empty: 0)

  ThermoElastic() = default;
  /// A constant material (what a deck without temperature columns gives).
  ThermoElastic(const LinearElastic& constant);  // NOLINT(google-explicit-constructor)
  /// The material of a point at x (read by a varying frame only), initial temperature T0,
  /// heated by dT.
  PointElastic at(Real T0, Real dT, const Vec3& x = Vec3::Zero()) const;
};

/// Element stiffness K (3n x 3n) for nodal coordinates X (n x 3, ccx local node order) at the
/// nodal temperature changes dT (n; empty: none), which choose the constants of a
/// temperature-dependent material. C3D8I condenses its incompatible modes; C3D8R adds
/// hourglass stiffness.
void linear_stiffness(ElementType type, const MatX3& X, const ThermoElastic& mat, const VecX& dT,
                      MatX& K);

/// Equivalent nodal forces (3n) of the free thermal strain, with the temperature change dT
/// given at the nodes (n) and interpolated to the integration points.
void thermal_load(ElementType type, const MatX3& X, const ThermoElastic& mat, const VecX& dT,
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
void recover(ElementType type, const MatX3& X, const ThermoElastic& mat, const MatX3& u,
             const VecX& dT, IpResults& out);

/// Integration-point weights times Jacobian determinants (n_ip): the volume each point carries.
VecX ip_volumes(ElementType type, const MatX3& X);

/// Matrix E (n_nodes x n_ip) that extrapolates integration point values to the nodes:
/// nodal = E * ip. Midside nodes of quadratic elements get the average of their edge corners
/// where the rule cannot reach them otherwise.
const MatX& ip_to_node_extrapolation(ElementType type);

}  // namespace kontakt::element
