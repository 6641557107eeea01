// DofMap: how every nodal degree of freedom follows from the unknowns of the reduced system.
//
// Each global dof d = 3*node + component is one of
//   free        u_d = x[eq]                                 (an unknown of the reduced system)
//   prescribed  u_d = value of a *BOUNDARY                   (eliminated, reaction reported)
//   dependent   u_d = sum_k c_k * (free or prescribed dof)   (*EQUATION, first term dependent)
//               + h_d                                        (h_d, c_k of a nonlinear constraint
//                                                             are its linearisation: relinearise;
//                                                             so are an equation's whose terms
//                                                             follow one, e.g. a 2D node's copies
//                                                             on a rigid body)
//   inactive    u_d = 0                                      (node not attached to any element)
// so u = T x + g, with T and g stored row by row. Element matrices are reduced as T^T K T.
//
// The unknowns are nodal components in each node's own basis: the global axes, or the local
// axes R of a *TRANSFORM node (Model::local_frames), whose *BOUNDARY, *EQUATION and *CLOAD
// dofs are local components. A transformed node's global rows are u = R (its local
// unknowns), so a prescribed local component is an ordinary prescribed unknown (with its
// reaction) and a local roller leaves the other two local components free.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "core/types.hpp"
#include "model/model.hpp"

namespace kontakt::assembly {

struct DofTerm {
  int index;  ///< free equation (is_prescribed == false) or prescribed slot
  Real coef;
  bool is_prescribed;
};

class DofMap {
 public:
  /// Builds the map for one step's constraints. Throws InputError for contradictory
  /// constraints (a dof prescribed twice with different values is not an error: the last
  /// wins, as in ccx; a dependent dof that is also prescribed, or a cyclic equation chain, is).
  /// `active_elements` (Step::element_active; empty: all) leaves the dofs that only removed
  /// elements hold inactive. `in_force` (per Model::nonlinear_constraints; empty: all) leaves
  /// out the constraints not in force (a DIST whose nodes are not linked).
  DofMap(const model::Model& model, const std::vector<model::Boundary>& boundaries,
         const std::vector<char>& active_elements = {}, const std::vector<char>& in_force = {});

  int n_dofs() const { return static_cast<int>(start_.size()) - 1; }
  int n_equations() const { return n_equations_; }
  int n_prescribed() const { return static_cast<int>(prescribed_dof_.size()); }

  /// Terms of u_d: a free dof has one term with coefficient 1; inactive dofs have none.
  const DofTerm* terms_begin(int dof) const { return terms_.data() + start_[dof]; }
  const DofTerm* terms_end(int dof) const { return terms_.data() + start_[dof + 1]; }
  bool is_free(int dof) const;
  bool is_prescribed(int dof) const { return prescribed_slot_[dof] >= 0; }
  /// Unknown (3 * node + component in the node's basis: local for a transformed node) behind
  /// prescribed slot s, and the slot of an unknown (-1 if none).
  int prescribed_dof(int slot) const { return prescribed_dof_[slot]; }
  int prescribed_slot(int dof) const { return prescribed_slot_[dof]; }
  /// Unknown (as prescribed_dof) of free equation eq.
  int equation_dof(int eq) const { return equation_dof_[eq]; }
  /// The value of unknown `unknown` (as prescribed_dof) in global displacements `u`: R^T u
  /// at a transformed node, u itself elsewhere.
  Real unknown_value(const VecX& u, int unknown) const;
  /// The node's local axes (columns), or nullptr when its basis is the global one.
  const Mat3* local_frame(int node) const;

  /// Full displacement vector u = T x + g for reduced solution x and prescribed values.
  VecX expand(const VecX& x, const VecX& prescribed_values) const;

  /// Solves every nonlinear constraint (Model::nonlinear_constraints) for its dependent dof in
  /// `u`, the other dofs held, and linearises it there: afterwards expand() of the unknowns
  /// of `u` gives `u` back, and T holds the constraints' derivatives at it. Throws SolverError
  /// when a constraint cannot be solved for its dependent dof.
  void relinearise(VecX& u);
  bool has_nonlinear_constraints() const { return !nonlinear_rows_.empty(); }
  /// Adds the nodal force at each nonlinear constraint's dependent dof, through the
  /// constraint's current linearisation, to those of its other dofs whose node belongs to no
  /// element, as ccx reports them: the reference and rotation nodes of a rigid body carry the
  /// force and moment on the body, element nodes their element forces (measured: ccx 2.20's
  /// beamrb, beamrb2, beammrlin).
  void add_constraint_forces(MatX3& nodal_forces) const;

  /// Signature of the constraint structure: equal signatures give equal sparsity patterns.
  /// same_structure() compares the coefficients too, but not those of nonlinear constraints.
  const std::vector<int>& structure() const { return start_; }
  bool same_structure(const DofMap& other) const;

  /// "node 17 dof x" style description of a global dof for messages.
  std::string describe(const model::Model& model, int dof) const;
  /// The same for an unknown: "node 17 local dof 2" at a transformed node.
  std::string describe_unknown(const model::Model& model, int unknown) const;

 private:
  /// The row of a nonlinear constraint's dependent dof: its terms are the constraint's other
  /// dofs (constraint_dofs order), each a free or prescribed unknown of its own.
  struct NonlinearRow {
    int dof = 0;
    int constraint = 0;               ///< into Model::nonlinear_constraints
    std::vector<int> other_dofs;      ///< global dofs of the terms
    std::vector<char> elementless;    ///< per other dof: its node belongs to no element
  };
  /// The row of an equation's dependent dof whose terms include a moving row (a nonlinear
  /// constraint's dependent or another follower): u_d = sum c * u_source.
  struct FollowerRow {
    int dof = 0;
    std::vector<std::pair<int, Real>> sources;  ///< (global dof, coefficient)
  };
  const model::Model* model_ = nullptr;
  std::vector<NonlinearRow> nonlinear_rows_;
  std::vector<FollowerRow> follower_rows_;  ///< in the order their rows depend on each other
  std::vector<char> moving_dof_;      ///< per dof: a nonlinear or follower row
  std::vector<Real> row_constant_;    ///< per dof: h_d of its current linearisation
  std::vector<int> start_;
  std::vector<DofTerm> terms_;
  std::vector<int> prescribed_slot_;
  std::vector<int> prescribed_dof_;
  std::vector<int> equation_dof_;
  std::unordered_map<int, Mat3> frames_;
  int n_equations_ = 0;
};

}  // namespace kontakt::assembly
