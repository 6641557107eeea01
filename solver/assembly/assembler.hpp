// Scatter of element contributions into the reduced system T^T K T x = T^T (f - K g).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "assembly/dof_map.hpp"
#include "assembly/sparse_pattern.hpp"
#include "model/model.hpp"

namespace kontakt::assembly {

/// The reduced linear system in a pattern's storage. In an upper-triangular pattern an
/// unsymmetric system (friction slip) keeps its symmetric part in `values` and its
/// skew-symmetric part in `skew`: K(r, c) = values + skew and K(c, r) = values - skew for the
/// entry (r < c). `skew` is empty while the system is symmetric.
struct ReducedSystem {
  std::vector<Real> values;  ///< one per pattern entry
  std::vector<Real> skew;    ///< one per pattern entry, or empty
  VecX rhs;
};

/// Fills the element's stiffness K (3n x 3n) and load vector f (3n) for element e; called
/// concurrently from several threads with distinct elements.
using ElementKernel = std::function<void(int e, MatX& K, VecX& f)>;
/// The same for the load vector alone.
using ElementLoadKernel = std::function<void(int e, VecX& f)>;

/// Everything assembly needs that stays fixed while the constraint structure holds.
struct AssemblyPlan {
  const DofMap* dofs = nullptr;
  SparsePattern pattern;
  std::vector<std::vector<int>> colours;  ///< elements sharing no equation
  /// Kept to extend the pattern by node groups: the elements', then the connectors' node
  /// pairs (Model::connectors order).
  ElementEquations element_eqs;
  /// Node groups beyond the elements (contact: slave nodes with one master face) that the
  /// pattern includes; scattered by scatter_groups().
  std::vector<std::vector<int>> groups;
  /// Changes whenever the pattern does: values assembled for one generation fit only it.
  std::uint64_t generation = 0;
};
AssemblyPlan make_plan(const model::Model& model, const DofMap& dofs, bool symmetric,
                       int threads);
/// Replaces the plan's node groups and rebuilds its pattern (elements + groups).
void set_groups(AssemblyPlan& plan, std::vector<std::vector<int>> groups, int threads);

/// Assembles stiffness and loads of every element; prescribed values enter the right-hand
/// side as -K g. `out` is overwritten.
void assemble(const model::Model& model, const AssemblyPlan& plan,
              const VecX& prescribed_values, const ElementKernel& kernel, int threads,
              ReducedSystem& out);

/// Assembles only the element load vectors into `rhs` (overwritten): for residuals whose
/// stiffness is known already.
void assemble_loads(const model::Model& model, const AssemblyPlan& plan,
                    const ElementLoadKernel& kernel, int threads, VecX& rhs);

/// Adds the stiffness K[g] and load f[g] of every node group g of the plan (dof order: the
/// group's nodes, x, y, z each) into `out`, after assemble(). With `out.skew` sized to the
/// pattern (upper storage), K[g] may be unsymmetric: its skew part goes there.
void scatter_groups(const AssemblyPlan& plan, const VecX& prescribed_values,
                    const std::vector<const MatX*>& K, const std::vector<const VecX*>& f,
                    ReducedSystem& out);

/// Adds the stiffness K and load f of one node group the pattern holds (a connector's node
/// pair; dof order: the nodes', x, y, z each) into `out` (symmetric K).
void scatter_nodes(const AssemblyPlan& plan, const std::vector<int>& nodes,
                   const VecX& prescribed_values, const MatX& K, const VecX& f,
                   ReducedSystem& out);

/// rhs += T^T f for a nodal force vector f over all 3 * n_nodes dofs.
void add_nodal_forces(const DofMap& dofs, const VecX& f, VecX& rhs);

}  // namespace kontakt::assembly
