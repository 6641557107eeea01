// The contact pairs of a model as one constraint of the Newton driver, which calls nothing but
// this lifecycle (thesis chapter 4, ccx-behaviour.md sections 1-3; FEBio's
// FESurfacePairConstraint is the model):
//   begin_increment(u)  broad phase (AABB tree over the master faces), integration points of
//                       every slave face (Gauss / Gauss-Cut) or the slave nodes (node-to-surface),
//                       pairing with master faces; the linear variants freeze projection, normal
//                       and area here. Fixes the contact groups (slave nodes + one master face)
//                       that the sparsity pattern takes for the whole increment.
//   update(u)           active set (linear variants: every evaluation; others: re-pairing in the
//                       first 8 evaluations of the increment unless SMALL SLIDING, then frozen),
//                       the trial state, force and tangent of every point.
//   add_to(system)      the groups' forces and tangents scattered into the reduced system.
//   accept(u)           the verdict on a converged increment: redo it smaller when a slave
//                       point penetrates a master face the increment's search did not offer it
//                       (the bodies slid farther than the search neighbourhood), or when the
//                       frozen geometry of a linear variant drifted (thesis section 7.1).
//   commit()            the trial point states become the committed ones (the output reads them).
//   roll_back()         the trial states are dropped (cutback).
// The driver also asks which convergence rules, solution controls and line search apply.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "assembly/assembler.hpp"
#include "contact/aabb_tree.hpp"
#include "contact/contact_surface.hpp"
#include "contact/coulomb_friction.hpp"
#include "contact/master_search.hpp"
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

/// The sum of |force component| over the active points and the number of those components:
/// contact's share of ccx's average force q_bar (contact springs count as elements there).
struct ForceMeasure {
  Real abs_sum = 0;
  Index components = 0;
};

/// Whether a converged increment stands, or is redone smaller by `redo_factor`.
struct Acceptance {
  bool accepted = true;
  Real redo_factor = 1;
  std::string reason;           ///< why it is redone, with the numbers
  bool required = false;        ///< wrong as it stands: redone or failed, never kept
  /// Within the tolerance a redo aims at, but a refreeze would sharpen it: may stand as it is.
  bool refreeze_only = false;
  /// A point penetrates a master face it was offered, with no contact element there (the
  /// pairing that decides them was fixed before it got there): pair again and iterate on.
  bool pair_again = false;
};

/// The deepest penetration of a slave point into a master face outside its increment's search
/// neighbourhood (depth 0: none).
struct MissedContact {
  Real depth = 0;
  Vec3 where = Vec3::Zero();    ///< the slave point, current configuration
};

/// What one point reports: its state after an evaluation (trial) or at the last converged
/// increment (committed).
struct PointState {
  bool active = false;
  Real gap = 0;                 ///< effective gap (negative: penetration)
  Real pressure = 0;
  Real area = 0;
  Real energy = 0;              ///< spring energy, pressure energy times area
  FrictionState friction;       ///< slip history (frictional pairs)
  Vec3 shear = Vec3::Zero();    ///< tangential traction F_T / A on the slave side
  bool slipping = false;
};

class ContactSystem {
 public:
  /// Builds the surfaces of every pair (each with the scheme its ContactPair names).
  explicit ContactSystem(const model::Model& model);

  bool empty() const { return pairs_.empty(); }

  // --- What the driver asks once per step -------------------------------------------------
  /// How the driver judges convergence with these pairs (ccx-behaviour.md section 3.5): ccx's
  /// face-to-face rules for the linear variants, node-to-face rules when any pair is nts or a
  /// nonlinear variant, None without pairs.
  nonlinear::ContactCriteria criteria() const;
  /// The step's controls with ccx's face-to-face changes under the face-to-face rules: the
  /// iteration cap is itf2f, the next increment is never shrunk for slow convergence (thesis
  /// 4.4.2) and grows after increments of up to I_G + 12 iterations.
  model::SolutionControls solution_controls(model::SolutionControls step_controls,
                                            const model::ContactControls& contact) const;
  /// ccx's line search (its face-to-face rules): from iteration 2, while some point is
  /// active; nts and the nonlinear variants only in the solves that pair once (stabilised
  /// levels, their release, a solve paired again), where a point contact's full steps
  /// overshoot.
  bool wants_line_search(int iteration) const;

  // --- Lifecycle --------------------------------------------------------------------------
  /// The surface behavior and friction in force from this step on (as *CHANGE SURFACE
  /// BEHAVIOR and *CHANGE FRICTION left them; TIED pairs stick with the *FRICTION card's
  /// slope); the slip history is kept.
  void begin_step(const model::Step& step);
  /// Rebuilds the points at the converged displacements `u`; their friction state is moved
  /// over from the committed state of the old ones (node-to-surface: per slave node; else per
  /// slave face, state_transfer). Also switches the stabilisation springs off. With
  /// `predicted` (where the static predictor expects the increment to end, when it differs
  /// from `u`) the linear variants freeze their geometry there as a refreeze does, relative
  /// motion and offsets counted from `u`: a sliding increment's frozen projections then drift
  /// by the prediction's error only, not by the whole slide.
  void begin_increment(const VecX& u, const IncrementContext& ctx, int threads,
                       const VecX* predicted = nullptr);
  /// Node lists of the contact groups of this increment (slave nodes first, then the master
  /// face's nodes); the same while begin_increment found the same candidates.
  const std::vector<std::vector<int>>& groups() const { return group_nodes_; }
  /// Freezes the linear variants' contact geometry again at `u` within the increment that
  /// started at `increment_start`: candidates, points and pairing as begin_increment finds them
  /// at `u`; each point's friction state, relative motion and initial-overlap offsets still
  /// from the increment's start. A converged increment whose frozen gaps drifted goes on from
  /// its solution with this instead of being redone smaller.
  void refreeze(const VecX& u, const VecX& increment_start, int threads);

  /// Evaluates every point at displacements `u` into the trial states and the group forces
  /// and tangents. Throws SolverError on non-finite values.
  void update(const VecX& u, int threads);
  /// Scatters the groups of the last update into `system` (tangent, and -f into the
  /// right-hand side, prescribed values moved by `prescribed_step` as for elements) and adds
  /// their forces to `internal_force` (full dof vector). Returns the force measure.
  ForceMeasure add_to(const assembly::AssemblyPlan& plan, const VecX& prescribed_step,
                      assembly::ReducedSystem& system, VecX& internal_force) const;
  /// Each group's force and tangent after the last update() (what add_to scatters).
  const std::vector<GroupContribution>& contributions() const { return contributions_; }
  /// Contact elements (points or nodes carrying force) after the last update().
  int n_active() const { return sums_.active; }
  /// Frictional pairs: active points sticking and slipping after the last update(); -1 when
  /// no pair has friction. While some point slips the tangent is unsymmetric.
  int n_sticking() const { return frictional_ ? sums_.sticking : -1; }
  int n_slipping() const { return frictional_ ? sums_.slipping : -1; }

  /// The verdict on an increment converged at `u`: a missed contact is always redone (its
  /// answer is wrong); with `check_drift`, so is a drifted frozen geometry (thesis section
  /// 7.1: frozen projections that no longer lie under their points give wrong gaps).
  Acceptance accept(const VecX& u, bool check_drift = true) const;
  /// The next update pairs every point of the nonlinear variants and nts again (as at the
  /// start of a stabilised solve), and keeps that pairing through the solve.
  void pair_again();
  void commit();
  void roll_back();

  // --- Contact stabilisation (README: a continuation in a normal spring) --------------------
  /// Normal springs of `factor` times the pair's penalty per unit area on every point paired
  /// at begin_increment, acting on the change of its gap since then (frozen normal and foot
  /// point); 0 switches them off. They hold a body that contact alone holds before it touches.
  /// A change of the springs starts a new Newton solve from the current iterate (a new level,
  /// a release, or a return to a saved level): the nonlinear variants re-pair once, at the
  /// next update's state, and keep that pairing through the solve, so each solve is smooth in
  /// the displacements (re-pairing within it is what makes point contacts chatter). Until the
  /// next begin_increment, also a change back to no springs (the release) keeps this rule.
  void set_stabilisation(Real factor);
  /// The largest fraction (at most 1) of the step `du` from `u` that carries no paired point of
  /// nts or a nonlinear variant without contact pressure deeper through the plane of its
  /// frozen master face (the springs' geometry) than the deepest pressing point goes: springs
  /// hold a rocking point contact only weakly, and a full Newton step would swing it far
  /// through the contact that stops it. (The linear variants evaluate every frozen point in
  /// every iteration: a point the step carries through is active in the next; cutting their
  /// steps cost iterations, 16.0-18.7 against 15.3-19.7 on the 8^3 punch.)
  Real step_fraction_to_contact(const VecX& u, const VecX& du) const;
  Real stabilisation() const { return stabilisation_; }
  /// The springs' energy at the last update, and the share of the normal force they carried
  /// there (springs over springs plus compressive contact forces: a law's tension tail holds
  /// nothing against a load that presses).
  Real stabilisation_energy() const { return sums_.stabilisation_energy; }
  Real stabilisation_share() const;
  /// True when, at the last update, no point pressed and the springs pulled the slave
  /// surfaces back towards their masters on balance: the loads move the bodies apart.
  bool separating() const { return sums_.pressing == 0 && sums_.stabilisation_pull > 0; }
  /// While no point presses and the springs are compressed (the bodies moved towards each
  /// other by their mean compression d): the ratio of spring factors d / (d + 1.2 g) that moves
  /// them about 1.2 times the smallest open gap g further under the same load. Else nullopt.
  std::optional<Real> approach_ratio() const;

  // --- Output of the committed state --------------------------------------------------------
  /// The contact points, the nodal contact values and the active count of the committed
  /// state at the converged displacements `u`.
  void write_output(const VecX& u, output::Frame& frame) const;
  /// Total normal force (sum of pressure * area) and the largest pressure, committed state.
  Real total_normal_force() const;
  Real max_pressure() const;

  /// Largest difference between a frozen gap and the gap of a fresh projection, over the
  /// active points of the linear variants, relative to their largest overclosure (0 when
  /// nothing is active, or when the difference is round-off of the coordinates).
  Real frozen_drift(const VecX& u) const { return frozen_drift(u, master_trees(u)); }

  /// A fresh search at `u` over every master face: the deepest penetration of an inactive point
  /// into a face that was not among its candidates at begin_increment, beyond a tenth of the
  /// largest overclosure of the active points (the drift check's tolerance) and round-off.
  MissedContact missed_contact(const VecX& u) const { return missed_contact(u, master_trees(u)); }

  /// The deepest penetration, beyond the drift check's tolerance, of a point of the nonlinear
  /// variants or nts that carries no contact force into a master face its increment offered:
  /// their contact elements are decided at pairing, which the Newton solve stops doing after
  /// its first evaluations, so a point can pass through a face it was offered unseen.
  MissedContact unheld_penetration(const VecX& u) const;

 private:
  /// Where a point is paired: fixed at begin_increment, except for the re-pairing of the
  /// nonlinear variants within their first evaluations.
  struct Pairing {
    int master = -1;            ///< index into the unit's candidates; -1: no master under it
    Vec2 xi_m = Vec2::Zero();
    Real gap = 0;               ///< geometric gap at pairing
    bool exists = false;        ///< nonlinear variants: contact element created at pairing
    Real area = 0;              ///< nonlinear variants: area at pairing
  };
  struct Point {
    Vec2 xi_s = Vec2::Zero();
    Real ref_weight = 0;        ///< area = ref_weight * |J_slave(xi_s)|; NTS: share of the nodal area
    Pairing pairing{};
    /// The pairing at begin_increment, frozen (foot weights, normal, area): what the linear
    /// variants evaluate, and where every scheme's stabilisation spring and friction act.
    FrozenPoint frozen{};
    int frozen_master = -1;
    Real frozen_gap = 0;        ///< geometric gap at begin_increment
    Vec3 frozen_relative = Vec3::Zero();  ///< x_s - x_m at begin_increment
    Real overlap0 = 0;          ///< initial overlap being ramped out (<= 0)
    Real closure = 0;           ///< tiny initial gap counted as closed (>= 0)
    PointState trial{}, committed{};
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
    Real penalty = 0;           ///< reference_stiffness(law): scales the stabilisation
    std::optional<CoulombLaw> friction;  ///< in force for the current step
    bool active = true;         ///< *MODEL CHANGE: a removed pair offers its points no master
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
  FaceGeometry slave_geometry(const Unit& unit, const VecX& u) const;
  /// The broad phase: one tree over each pair's master faces at `u`.
  std::vector<AabbTree> master_trees(const VecX& u) const;
  // accept() builds the trees once for both checks.
  Real frozen_drift(const VecX& u, const std::vector<AabbTree>& trees) const;
  MissedContact missed_contact(const VecX& u, const std::vector<AabbTree>& trees) const;
  /// How deep a missed or unheld point may be: the drift check's share of the largest
  /// overclosure of the active points, or round-off of slave coordinates up to `coordinates`.
  Real penetration_tolerance(Real coordinates) const;
  /// Where a unit looks for master faces: its slave face's (node's) box, its size (the largest
  /// of the node's faces) and the slave face's normal (zero for a node).
  struct SearchRegion {
    Box box;
    Real size = 0;
    Vec3 slave_normal = Vec3::Zero();
  };
  SearchRegion search_region(const Unit& unit, const FaceGeometry& slave, const VecX& u) const;
  /// Surface-to-surface pairs only see master faces that face the slave face.
  static bool faces_slave(const FaceGeometry& master, const SearchRegion& region);
  /// A fresh search around a unit at `u` (not limited to its candidates): the master faces
  /// within `reach` of its sizes, to project its points on as they are now.
  struct FreshMasters {
    std::vector<int> faces;               ///< master face indices of the pair
    std::vector<FaceGeometry> geometry;
    MasterFoot find(const Vec3& x) const;  ///< candidate indexes `faces`
  };
  FreshMasters fresh_masters(const Unit& unit, const FaceGeometry& slave, const AabbTree& tree,
                             const VecX& u, Real reach = 1) const;
  FaceVec slave_weights(const Unit& unit, const Point& pt) const;
  /// Slave area a point represents in configuration `g` (NTS: the nodal area).
  Real point_area(const Unit& unit, const Point& pt, const UnitGeometry& g, const VecX& u) const;
  Real nodal_area(const Pair& pair, int node, const VecX& u) const;
  Real gap_offset(const Point& pt) const {
    return -pt.overlap0 * (1 - ctx_.fraction_end) - pt.closure;
  }
  void find_candidates(Unit& unit, const VecX& u, const std::vector<AabbTree>& trees) const;
  /// Points, pairing and frozen geometry of one unit at `u`; the friction state moves over from
  /// `old` (the unit's committed points before, with the corners' states for faces).
  struct OldStates {
    std::vector<Vec2> xi;
    MatX states;                ///< one packed FrictionState per row
    MatX corners;               ///< faces: per corner, averaged over the faces at its node
  };
  /// With `increment_start` (a refreeze): the relative motion friction sees and the offsets
  /// measured from the increment's start.
  void build_points(Unit& unit, const VecX& u, const OldStates& old,
                    const VecX* increment_start) const;
  /// The committed friction states of every unit's points, with averaged face corners.
  std::vector<OldStates> committed_states() const;
  Pairing pair_point(const Unit& unit, const UnitGeometry& g, const Point& pt,
                     const VecX& u) const;
  void freeze(const Unit& unit, const UnitGeometry& g, Point& pt, const VecX& u) const;
  void build_groups();
  /// What the evaluation of a unit adds up.
  struct Sums {
    ForceMeasure force;         ///< of the active points and the stabilisation springs
    int active = 0;
    int pressing = 0;           ///< active points in compression
    int sticking = 0, slipping = 0;
    Real contact_force = 0;     ///< sum of the compressive normal forces
    Real stabilisation_force = 0, stabilisation_energy = 0;
    Real stabilisation_pull = 0;  ///< sum of the springs' tensions (minus their compressions)
    Real spring_stiffness = 0;    ///< sum of the springs' k A
    Real min_open_gap = std::numeric_limits<Real>::infinity();  ///< over paired open points
    void add(const Sums& o);
  };
  /// Which points of the nonlinear variants an evaluation pairs again.
  enum class Repairing {
    None,             ///< the pairing stays (linear variants, SMALL SLIDING, the first
                      ///< evaluation of an increment)
    All,              ///< every point (the first evaluations of an increment or solve)
    WithoutElement,   ///< the points without contact element: elements are created, never
                      ///< deleted (the later evaluations)
  };
  /// Evaluates one unit into its points' trial states and its groups.
  Sums evaluate_unit(Unit& unit, const VecX& u, Repairing repairing);
  /// Friction of one point (frictional pairs), into its trial state and its frozen group;
  /// `normal` is its normal response when active.
  void add_point_friction(Unit& unit, const UnitGeometry& g, Point& pt,
                          const PointResponse* normal, Sums& sums);

  const model::Model& model_;
  std::vector<Pair> pairs_;
  std::vector<Unit> units_;
  std::vector<std::vector<int>> group_nodes_;
  std::vector<GroupContribution> contributions_;
  IncrementContext ctx_;
  int evaluations_ = 0;         ///< update() calls in this solve (they decide re-pairing)
  /// Stabilised solves, their release, a solve paired again: all points are paired at the
  /// first update only (then those without element), and the line search is on.
  bool repair_once_ = false;
  Real stabilisation_ = 0;
  bool reference_areas_ = true;  ///< small strain: point areas of the undeformed surfaces
  VecX no_displacement_;         ///< the reference configuration's displacements
  bool frictional_ = false;     ///< some pair has friction (or is TIED) in the current step
  Sums sums_;                   ///< of the last update
};

}  // namespace kontakt::contact
