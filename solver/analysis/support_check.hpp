// Detects bodies that no boundary condition holds, before a factorisation fails on them.
#pragma once

#include "assembly/dof_map.hpp"
#include "model/model.hpp"

namespace kontakt::analysis {

/// Throws SolverError naming a node of the first connected body (elements joined by shared
/// nodes, *EQUATION terms or a contact pair) that has no prescribed dof in x, y or z: such a body can translate
/// freely, and its stiffness matrix is singular.
void check_bodies_supported(const model::Model& model, const assembly::DofMap& dofs);

}  // namespace kontakt::analysis
