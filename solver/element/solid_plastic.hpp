// Small-strain solid kernels with J2 plasticity (isotropic hardening): the element-level
// wrapper around material::j2_return_map. Pure functions; the caller owns the point states
// (committed on convergence, discarded on cutback).
#pragma once

#include <vector>

#include "core/types.hpp"
#include "element/element_state.hpp"
#include "element/element_type.hpp"
#include "element/solid_linear.hpp"
#include "material/hardening_curves.hpp"
#include "material/j2_small_strain.hpp"

namespace kontakt::element {

struct PlasticResult {
  VecX internal_force;   ///< 3n
  MatX tangent;          ///< 3n x 3n consistent tangent (when requested)
  MatX6 stress;          ///< n_ip x 6
  MatX6 strain;          ///< n_ip x 6 total strain, tensor shear components
  VecX peeq;             ///< n_ip equivalent plastic strain
  VecX energy_density;   ///< n_ip elastic strain energy density
  ElementState state;    ///< trial state: point states, C3D8I's mode amplitudes
};

/// One element for nodal displacements u (n x 3), from the committed state (n_ip point states;
/// C3D8I: the mode amplitudes its local solve starts from, empty for zero). C3D8R adds its
/// elastic hourglass stiffness; C3D8I condenses its incompatible modes by a local Newton
/// iteration (SolverError if it fails). Each point reads the hardening at its temperature.
void plastic_element(ElementType type, const MatX3& X, const ThermoElastic& mat,
                     const material::HardeningCurves& hardening, const MatX3& u, const VecX& dT,
                     const ElementState& committed, bool want_tangent, PlasticResult& out);

}  // namespace kontakt::element
