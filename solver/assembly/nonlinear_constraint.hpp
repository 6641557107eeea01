// Nonlinear multiple point constraints (model::NonlinearConstraint): the scalar g(u) = 0 of
// each, its dofs and its gradient. DofMap solves g for the dependent dof and linearises it
// at the current displacements (assembly/README.md).
#pragma once

#include <vector>

#include "core/types.hpp"
#include "model/model.hpp"

namespace kontakt::assembly {

struct ConstraintDof {
  int node = 0;       ///< internal index
  int component = 0;  ///< 0, 1, 2 = x, y, z
};

/// The dofs g depends on, the dependent one first; no dof twice.
std::vector<ConstraintDof> constraint_dofs(const model::NonlinearConstraint& c);

/// g at global displacements `u` (3 per node) over the undeformed coordinates `coords` (a row
/// per node), and with `gradient` its derivative over constraint_dofs(c), in that order.
Real constraint_value(const model::NonlinearConstraint& c, const MatX3& coords, const VecX& u,
                      VecX* gradient = nullptr);

/// R(theta) v for the rotation vector theta (Rodrigues' formula; series near theta = 0).
Vec3 rotate(const Vec3& theta, const Vec3& v);

}  // namespace kontakt::assembly
