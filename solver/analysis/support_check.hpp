// Detects bodies that no boundary condition holds, before a factorisation fails on them.
#pragma once

#include <string>
#include <vector>

#include "assembly/dof_map.hpp"
#include "model/model.hpp"

namespace kontakt::analysis {

/// A body (elements joined by shared nodes and *EQUATION terms) with directions in which no
/// prescribed dof holds it.
struct UnsupportedBody {
  int node = 0;          ///< the label of one of its nodes
  std::string free;      ///< "x", "x, z", ...
};
/// The bodies free to move in some direction; with `contact_holds`, the two sides of a contact
/// pair count as one body.
std::vector<UnsupportedBody> unsupported_bodies(const model::Model& model,
                                               const assembly::DofMap& dofs, bool contact_holds);

/// Throws SolverError naming a node of the first connected body (elements joined by shared
/// nodes, *EQUATION terms or a contact pair) that has no prescribed dof in x, y or z: such a body can translate
/// freely, and its stiffness matrix is singular.
void check_bodies_supported(const model::Model& model, const assembly::DofMap& dofs);

/// "the body containing node N is held in z only by contact; ..." for every body that only
/// contact holds in some direction (empty when there is none).
std::string bodies_held_only_by_contact(const model::Model& model, const assembly::DofMap& dofs);

}  // namespace kontakt::analysis
