// *PRE-TENSION SECTION with SURFACE= (bolt pretension), as ccx 2.20 builds it: the nodes of the
// section's element faces are copied, the elements owning those faces take the copies, and each
// copy is tied to its original by three linear constraints
//     u_copy = u_original + u_ref n,
// with u_ref the reference node's first dof and n the section normal (pointing away from the
// owning elements). So the two sides stay glued in the section plane and the owning side moves
// by u_ref along n against the other everywhere: a positive u_ref overlaps the cut, i.e.
// shortens the bolt (tension, as the ccx manual says). *BOUNDARY on u_ref prescribes that
// shortening, *CLOAD on it is the bolt force. Measured against ccx 2.20 (pret1 and its own
// *EQUATION version of it agree to 2e-13, also under an unsymmetric load); ccx 2.11 instead
// constrained only the mean opening, weighted by the faces' nodal areas.
#pragma once

#include "model/model.hpp"

namespace kontakt::model {

/// Cuts `model` along every Model::pretension_sections entry in place: copies (labels after the
/// largest), connectivity of the owning elements, the equations (keyword *PRE-TENSION SECTION),
/// and the initial and step temperatures of the copies. Run after the 2D expansion, so the faces
/// of 2D elements are faces of their 3D layer. Throws InputError at the section's card for a
/// missing or node surface, a reference node that belongs to an element, and
/// a node in two sections.
void split_pretension_sections(Model& model);

}  // namespace kontakt::model
