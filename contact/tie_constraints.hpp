// *TIE as ccx does it (gentiedmpc.f): every slave node within the position tolerance of the
// master surface is bound to the master face it projects onto by one linear constraint per
// direction, u_slave = sum_a N_a(xi) u_a (N_a: the face's shape functions at the foot point),
// and moved onto that foot unless ADJUST=NO. The constraints join Model::equations, so the
// DofMap eliminates them like *EQUATION chains; a tie is no contact and keeps a linear model
// linear. A slave dof that already has a *BOUNDARY in the first step or is the dependent dof of
// an earlier equation or tie stays as it is (ccx: "DOF ... is not active; no tied constraint is
// generated"), and slave nodes without a master face within the tolerance stay free; both are
// reported as warnings naming the nodes (ccx writes them to a .nam file).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "contact/aabb_tree.hpp"
#include "contact/contact_surface.hpp"
#include "model/model.hpp"

namespace kontakt::contact {

/// ccx's default POSITION TOLERANCE: this fraction of the typical master element size.
inline constexpr Real kDefaultToleranceFraction = 0.025;

/// ccx's "typical element size" behind the default tolerance (tolloc in gentiedmpc.f): the
/// mean, over the triangles ccx splits the master faces into (tri3 1, quad4 2, tri6 4, quad8
/// 6; in ccx's face node order), of the distance from a triangle's centroid to the edge
/// opposite its first vertex. For a square face of side h: 0.285 h.
Real typical_master_size(std::span<const SurfaceFace> faces, const MatX3& coords);

/// The master side of one tie in the reference configuration, with its broad phase.
struct TieMaster {
  std::vector<SurfaceFace> faces;
  std::vector<int> nodes;               ///< every node of the faces, ascending
  std::vector<FaceGeometry> geometry;   ///< parallel to faces
  AabbTree tree;                        ///< over the faces' boxes
  Real largest_face = 0;                ///< longest face edge
};
TieMaster make_tie_master(const model::Model& model, const model::Surface& master);

/// Where a slave node attaches to the master surface.
struct TieFoot {
  int face = -1;                        ///< index into TieMaster::faces
  Vec2 xi = Vec2::Zero();               ///< natural coordinates, inside the face
  Vec3 x = Vec3::Zero();                ///< the foot point on the face
  Real distance = 0;                    ///< |p - x|
};

/// The foot of `p` on the nearest master face it projects into (the contact search's narrow
/// phase, with its edge tolerance), clamped into that face; nullopt when there is no such face
/// or the foot is farther than `tolerance`.
std::optional<TieFoot> find_tie_foot(const TieMaster& master, const Vec3& p, Real tolerance);

/// The constraint u[slave][dof] - sum_a N_a(xi) u[face node a][dof] = 0 (slave first: it is
/// the dependent dof), located at `where` and marked as coming from a *TIE.
model::Equation tie_equation(int slave, int dof, const SurfaceFace& face, const Vec2& xi,
                             const SourceLoc& where);

/// Deck labels of internal nodes, ascending, the first 20 and how many more: how a warning or an
/// error names nodes without growing with the model.
std::string named_nodes(const model::Model& model, const std::vector<int>& nodes);

/// Global dofs (3 node + component) that a tie may not make dependent: prescribed in the first
/// step (ccx generates the ties with the first step's constraints) or already the dependent
/// dof of an equation.
std::vector<char> constrained_dofs(const model::Model& model);

/// The model-setup step of every *TIE, in deck order (a later tie sees the nodes an earlier
/// one moved): appends the tie constraints to `model.equations` (a tie with SCHEME=: a
/// surface-to-surface pair with a TIED law, K = lambda = 50 E; a CYCLIC SYMMETRY tie: the
/// equations of its *CYCLIC SYMMETRY MODEL, cyclic_symmetry.hpp), moves the tied slave nodes
/// onto their feet unless ADJUST=NO, and reports free nodes, skipped dofs and moves in
/// `model.warnings`. Returns the number of slave nodes tied in at least one direction. Run
/// once, after reading, before any analysis.
int apply_ties(model::Model& model);

}  // namespace kontakt::contact
