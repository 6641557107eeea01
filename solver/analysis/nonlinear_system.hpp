// The system one Newton iteration solves: element tangents and internal forces at a
// displacement state (total Lagrangian under NLGEOM, J2 return mapping for plastic materials,
// linear elasticity otherwise), reduced by the constraints, with the point states it reached.
#pragma once

#include <cstdint>
#include <vector>

#include "assembly/assembler.hpp"
#include "element/element_state.hpp"
#include "model/model.hpp"
#include "output/frame.hpp"

namespace kontakt::analysis {

/// Element point states (plastic points, C3D8I modes): the trial states an evaluation reaches
/// become the committed ones when the increment converges, and are dropped on a cutback.
struct ElementStates {
  std::vector<element::ElementState> committed, trial;  ///< per element
  /// The step's Step::element_active (empty: all), and per element the nodal displacements it
  /// was added back at (*MODEL CHANGE, TYPE=ELEMENT, ADD), its strain-free configuration; empty
  /// for the others. Both set at the start of each step.
  std::vector<char> active;
  std::vector<MatX3> added_at;

  /// Plastic points virgin, C3D8I mode amplitudes zero.
  explicit ElementStates(const model::Model& model);
  void commit();
  void roll_back() { trial = committed; }
};

/// What an element reports at its points in the state last evaluated.
struct ElementOutput {
  MatX6 stress, strain;  ///< Cauchy stress and strain (Green-Lagrange under NLGEOM)
  VecX energy_density, peeq;
};

/// Tangent and T^T (f_ext - f_int) at a displacement state, with what the output needs.
struct Evaluation {
  assembly::ReducedSystem system;
  VecX internal_force;             ///< full dof vector (reaction forces at constrained dofs)
  Real force_abs_sum = 0;          ///< sum of |element nodal force component| (ccx's q_bar)
  Index force_components = 0;      ///< ... and their number
  Real connector_energy = 0;       ///< stored in springs, gaps and trusses
  std::vector<ElementOutput> outputs;
};

/// The assembled stiffness of linear elements (small strain, elastic), which stays the same
/// through a step: assembled once per pattern generation and reused, so iterations (contact)
/// only recompute element forces.
struct LinearElementCache {
  bool usable = false;          ///< every element of the step is linear
  std::uint64_t generation = 0;  ///< pattern the values belong to (0: none yet)
  std::vector<Real> values;
};

/// Assembles the element tangents and residual T^T(-f_int) at `u` (full dof vector) with
/// temperatures `dT`, from the committed point states into `states.trial`. A nonzero
/// `prescribed_step` (per prescribed slot) moves the constrained dofs within the linearised
/// system (-K g on the right-hand side), so the free dofs follow them at once.
Evaluation evaluate_elements(const model::Model& model, const assembly::AssemblyPlan& plan,
                             bool nlgeom, ElementStates& states, const VecX& u, const VecX& dT,
                             const VecX& prescribed_step, LinearElementCache& cache, int threads);

/// The output frame of a converged state from its last evaluation (stresses, strains,
/// energies, PEEQ, volumes, reactions, nodal averages, truss points).
output::Frame converged_frame(const model::Model& model, const VecX& u, const Evaluation& ev,
                              bool nlgeom);

}  // namespace kontakt::analysis
