// Small-strain recovery of a displacement state: what the writers need from a linear solve.
#pragma once

#include "model/model.hpp"
#include "output/frame.hpp"

namespace kontakt::analysis {

/// Strains, stresses, energies, volumes and nodal forces (summed element internal forces) for
/// the full displacement vector u and nodal temperature changes dT in `step` (its sections),
/// plus nodal averages of the extrapolated stresses and strains. Elements run in parallel on
/// `threads`.
output::Frame small_strain_frame(const model::Model& model, const model::Step& step,
                                 const VecX& u, const VecX& dT, int threads);

/// A frame holding displacement u, with its point arrays sized for the model (values unset).
output::Frame sized_frame(const model::Model& model, const VecX& u);

/// Fills the nodal S and E (and PEEQ when the frame has it): every element's point values
/// extrapolated to its nodes, averaged over the elements at each node.
void average_to_nodes(const model::Model& model, output::Frame& frame);

}  // namespace kontakt::analysis
