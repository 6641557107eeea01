// The contact pairs of a model as one "extra constraint" of the Newton driver. Lifecycle per
// increment (thesis chapter 4, ccx-behaviour.md sections 1-2):
//   begin_increment(u)  broad phase (AABB tree over the master faces), integration points of
//                       every slave face (Gauss / Gauss-Cut) or the slave nodes (node-to-surface),
//                       pairing with master faces; the linear variants freeze projection, normal
//                       and area here. Fixes the contact groups (slave nodes + one master face)
//                       that the sparsity pattern takes for the whole increment.
//   evaluate(u, it)     active set (linear variants: every iteration; others: re-pairing in the
//                       first 8 evaluations unless SMALL SLIDING, then frozen), force and tangent
//                       of every group.
//   records(u)          per-point output of a converged state.
// Cutbacks need no rollback: the next begin_increment rebuilds everything from the converged
// displacements; the only state carried between increments is the initial-overlap ramp.
#pragma once

#include <vector>

#include "contact/aabb_tree.hpp"
#include "contact/contact_surface.hpp"
#include "contact/point_kernel.hpp"
#include "model/model.hpp"
#include "nonlinear/convergence.hpp"
#include "output/frame.hpp"

namespace kontakt::contact {

struct IncrementContext {
  int step = 1;                 ///< 1-based
  int increment = 1;            ///< 1-based within the step
  Real fraction_start = 0;      ///< step fraction reached when the increment starts
  Real fraction_end = 1;        ///< step fraction at its end
};

/// One group's share of the tangent and internal force, over its nodes (x, y, z each).
struct GroupContribution {
  MatX K;
  VecX f_int;
};

class ContactSystem {
 public:
  /// Builds the surfaces of every pair (each with the scheme its ContactPair names).
  explicit ContactSystem(const model::Model& model);

  bool empty() const { return pairs_.empty(); }
  /// How the driver judges convergence with these pairs (ccx-behaviour.md section 3.5): ccx's
  /// face-to-face rules for the linear variants, node-to-face rules when any pair is nts or a
  /// nonlinear variant, None without pairs.
  nonlinear::ContactCriteria criteria() const;

  void begin_increment(const VecX& u, const IncrementContext& ctx, int threads);
  /// Node lists of the contact groups of this increment (slave nodes first, then the master
  /// face's nodes); the same while begin_increment found the same candidates.
  const std::vector<std::vector<int>>& groups() const { return group_nodes_; }

  /// Evaluates every point at displacements `u`; `evaluation` counts the evaluations of this
  /// increment from 1 (it decides re-pairing). Fills contributions(). Throws SolverError on
  /// non-finite values.
  void evaluate(const VecX& u, int evaluation, int threads);
  const std::vector<GroupContribution>& contributions() const { return contributions_; }
  /// Contact elements (points or nodes carrying force) after the last evaluate().
  int n_active() const { return n_active_; }
  /// Sum of |force component| over the active points and the number of those components:
  /// their share of ccx's average force q_bar (contact springs included).
  Real force_abs_sum() const { return force_abs_sum_; }
  Index force_components() const { return force_components_; }
  /// Total normal contact force (sum of pressure * area) and the largest pressure.
  Real total_normal_force() const;
  Real max_pressure() const;

  /// Largest difference between a frozen gap and the gap of a fresh projection, over the
  /// active points of the linear variants, relative to their largest overclosure (0 when
  /// nothing is active). Thesis section 7.1: a large value means the frozen geometry drifted.
  Real frozen_drift(const VecX& u) const;

  /// Per model node: a slave node that projects onto no master face (thesis §4.3.2: such
  /// nodes get no extrapolated contact values).
  std::vector<bool> nodes_outside_master(const VecX& u) const;

  /// One record per integration point / slave node at the last evaluated state.
  std::vector<output::ContactPointRecord> records(const VecX& u) const;

 private:
  struct Point {
    Vec2 xi_s = Vec2::Zero();
    Real ref_weight = 0;        ///< area = ref_weight * |J_slave(xi_s)|; NTS: the nodal area
    int master = -1;            ///< index into the unit's candidates; -1: no master under it
    Vec2 xi_m = Vec2::Zero();
    bool exists = false;        ///< nonlinear variants: contact element created at pairing
    FrozenPoint frozen{};       ///< linear variants
    Real overlap0 = 0;          ///< initial overlap being ramped out (<= 0)
    Real closure = 0;           ///< tiny initial gap counted as closed (>= 0)
    // last evaluation
    Real gap = 0, pressure = 0, area = 0, energy = 0;
    bool active = false;
  };
  /// A slave face (surface-to-surface) or slave node (node-to-surface) with its candidates.
  struct Unit {
    int pair = 0;
    int face = -1;              ///< index into the pair's slave faces
    int node = -1;              ///< node-to-surface: internal node index
    std::vector<int> candidates{};  ///< master face indices
    std::vector<int> groups{};    ///< global group index per candidate
    std::vector<Point> points{};
  };
  struct Pair {
    const model::ContactPair* def = nullptr;
    model::ContactScheme scheme;
    model::SurfaceBehavior behavior;
    PressureLaw law;            ///< the scheme's law for this behaviour
    ContactSurface slave, master;
    /// node-to-surface: the faces nodal areas come from (the slave faces, or for a node-based
    /// slave surface the exterior faces at its nodes) and, per node, (face, local node)
    std::vector<SurfaceFace> area_faces;
    std::vector<std::vector<std::pair<int, int>>> node_faces;
  };

  /// A unit's geometry in one configuration.
  struct UnitGeometry {
    FaceGeometry slave;         ///< the slave face, or the slave node as a one-node "face"
    std::vector<FaceGeometry> masters;  ///< the candidates
  };
  UnitGeometry geometry(const Unit& unit, const VecX& u) const;
  FaceVec slave_weights(const Unit& unit, const Point& pt) const;
  /// Slave area a point represents in configuration `g` (NTS: the nodal area).
  Real point_area(const Unit& unit, const Point& pt, const UnitGeometry& g, const VecX& u) const;
  Real nodal_area(const Pair& pair, int node, const VecX& u) const;
  Real gap_offset(const Point& pt) const {
    return -pt.overlap0 * (1 - ctx_.fraction_end) - pt.closure;
  }
  void find_candidates(Unit& unit, const VecX& u, const std::vector<AabbTree>& trees,
                       const std::vector<Real>& margins) const;
  void build_points(Unit& unit, const VecX& u) const;
  void pair_point(const Unit& unit, const UnitGeometry& g, Point& pt, const VecX& u) const;
  void freeze(const Unit& unit, const UnitGeometry& g, Point& pt, const VecX& u) const;
  /// Evaluates one unit; returns (sum |f|, components) of its active points.
  std::pair<Real, Index> evaluate_unit(Unit& unit, const VecX& u, bool repair);

  const model::Model& model_;
  std::vector<Pair> pairs_;
  std::vector<Unit> units_;
  std::vector<std::vector<int>> group_nodes_;
  std::vector<GroupContribution> contributions_;
  IncrementContext ctx_;
  int n_active_ = 0;
  Real force_abs_sum_ = 0;
  Index force_components_ = 0;
};

}  // namespace kontakt::contact
