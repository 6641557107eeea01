#include "contact/tie_constraints.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cstdio>
#include <map>
#include <set>
#include <string>

#include "contact/cyclic_symmetry.hpp"
#include "contact/master_search.hpp"
#include "model/plane_expansion.hpp"

namespace kontakt::contact {

namespace {

using Triangle = std::array<int, 3>;  ///< 1-based positions in ccx's face node order

/// ccx's split of a face into triangles (triangucont.f).
std::span<const Triangle> ccx_triangles(element::Topology topo) {
  static constexpr Triangle tri3[] = {{1, 2, 3}};
  static constexpr Triangle quad4[] = {{1, 2, 4}, {2, 3, 4}};
  static constexpr Triangle tri6[] = {{1, 4, 6}, {4, 2, 5}, {6, 5, 3}, {4, 5, 6}};
  static constexpr Triangle quad8[] = {{1, 5, 8}, {5, 2, 6}, {7, 6, 3},
                                       {8, 7, 4}, {8, 5, 7}, {5, 6, 7}};
  switch (topo) {
    case element::Topology::Tri3: return tri3;
    case element::Topology::Quad4: return quad4;
    case element::Topology::Tri6: return tri6;
    case element::Topology::Quad8: return quad8;
    default: return {};
  }
}

/// How many corners later than ours ccx starts a face: its hexahedron face S1 and tetrahedron
/// face S4 begin one corner further round (same orientation).
int ccx_corner_shift(element::ElementType type, int face) {
  using element::ElementType;
  switch (type) {
    case ElementType::C3D8:
    case ElementType::C3D8R:
    case ElementType::C3D8I:
    case ElementType::C3D20:
    case ElementType::C3D20R: return face == 1 ? 1 : 0;
    case ElementType::C3D4:
    case ElementType::C3D10: return face == 4 ? 1 : 0;
    default: return 0;
  }
}

/// Coordinates of the face node at 1-based position `k` of ccx's order.
Vec3 ccx_face_node(const SurfaceFace& face, const MatX3& coords, int k) {
  const int n_corners = is_triangle(face.topo) ? 3 : 4;
  const int shift = ccx_corner_shift(face.element_type, face.face);
  const int i = k - 1;
  const int ours = i < n_corners ? (i + shift) % n_corners
                                 : n_corners + (i - n_corners + shift) % n_corners;
  return coords.row(face.nodes[static_cast<std::size_t>(ours)]).transpose();
}

std::string number(Real value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

/// The first 20 items, comma-separated, and how many more there are: a warning names the
/// nodes without growing with the model.
std::string first_items(const std::vector<std::string>& items) {
  constexpr std::size_t kShown = 20;
  std::string out;
  for (std::size_t i = 0; i < std::min(kShown, items.size()); ++i)
    out += (i ? ", " : "") + items[i];
  if (items.size() > kShown) out += " and " + std::to_string(items.size() - kShown) + " more";
  return out;
}

/// Deck labels of internal nodes, ascending.
std::vector<std::string> node_labels(const model::Model& model, const std::vector<int>& nodes) {
  std::vector<int> labels;
  for (int n : nodes) labels.push_back(model.mesh.node_ids[static_cast<std::size_t>(n)]);
  std::sort(labels.begin(), labels.end());
  std::vector<std::string> out;
  for (int label : labels) out.push_back(std::to_string(label));
  return out;
}

const char* direction(int dof) { return dof == 0 ? "x" : dof == 1 ? "y" : "z"; }

/// ccx's default tolerance: one value from the master faces of every tie, also those with a
/// tolerance of their own (0 when no tie needs it).
Real default_tolerance(const model::Model& model) {
  if (std::all_of(model.ties.begin(), model.ties.end(), [](const model::Tie& tie) {
        return tie.position_tolerance.has_value() || tie.cyclic;
      }))
    return 0;
  std::vector<SurfaceFace> faces;
  for (const model::Tie& tie : model.ties) {
    if (tie.cyclic) continue;
    const ContactSurface master = make_contact_surface(model, model.surfaces.at(tie.master));
    faces.insert(faces.end(), master.faces.begin(), master.faces.end());
  }
  return kDefaultToleranceFraction * typical_master_size(faces, model.mesh.coords);
}

struct Move {
  int node;
  Vec3 to;
  Real distance;
};

/// The warnings of one tie: free nodes, dofs left alone, nodes moved.
void report(model::Model& model, const model::Tie& tie, Real tolerance,
            const std::vector<int>& missed, const std::map<int, std::string>& skipped,
            const std::vector<Move>& moves, Real visible_move) {
  const std::string at = tie.where.file + ":" + std::to_string(tie.where.line) + ": *TIE: tie " +
                         tie.name + ": ";
  if (!missed.empty())
    model.warnings.push_back(
        at + std::to_string(missed.size()) + " slave node(s) of " + tie.slave +
        " have no master face of " + tie.master + " within the position tolerance " +
        number(tolerance) +
        (tie.position_tolerance ? "" : " (the default: 2.5 % of a typical master element size)") +
        " and stay free, not tied: " + named_nodes(model, missed));
  if (!skipped.empty()) {
    std::vector<std::string> dofs;
    for (const auto& [label, directions] : skipped)
      dofs.push_back(std::to_string(label) + " (" + directions + ")");
    model.warnings.push_back(at + std::to_string(skipped.size()) +
                             " slave node(s) are not tied in directions already constrained (by "
                             "*BOUNDARY in the first step, or as the dependent dof of an "
                             "*EQUATION or an earlier tie), as in ccx: " + first_items(dofs));
  }
  const Move* farthest = nullptr;
  int n_moved = 0;
  for (const Move& m : moves) {
    if (m.distance <= visible_move) continue;
    ++n_moved;
    if (!farthest || m.distance > farthest->distance) farthest = &m;
  }
  if (farthest)
    model.warnings.push_back(
        at + std::to_string(n_moved) + " slave node(s) moved onto the master surface " +
        tie.master + ", the farthest by " + number(farthest->distance) + " (node " +
        std::to_string(model.mesh.node_ids[static_cast<std::size_t>(farthest->node)]) + ")");
}

/// A tie with SCHEME= as a surface-to-surface pair with a TIED law of its own in every step:
/// K = lambda = 50 E (ccx's default penalty, E of the first material), mu unused.
void add_tied_contact(model::Model& model, const model::Tie& tie) {
  const Real young = model.materials.empty() || model.materials.front().elastic.empty()
                         ? 0
                         : model.materials.front().elastic.rows.front()[0];  // its first row
  if (!(young > 0))
    throw InputError(tie.where, "*TIE",
                     "tie " + tie.name + ": SCHEME= takes its stiffness from Young's modulus of "
                     "the first material, which has none");
  model::SurfaceInteraction interaction;
  interaction.name = "*TIE " + tie.name;
  interaction.behavior.law = model::SurfaceBehavior::Law::Tied;
  interaction.behavior.stiffness = 50 * young;
  interaction.friction = model::Friction{.mu = 1, .stick_slope = 50 * young, .where = tie.where};
  interaction.where = tie.where;
  for (model::Step& step : model.steps) {
    step.interaction_friction.push_back(interaction.friction);
    step.interaction_behavior.push_back(interaction.behavior);
  }
  model::ContactPair pair;
  pair.interaction = static_cast<int>(model.interactions.size());
  pair.slave = tie.slave;
  pair.master = tie.master;
  pair.scheme = *tie.scheme;
  pair.scheme_given = true;
  pair.where = tie.where;
  model.interactions.push_back(std::move(interaction));
  model.contact_pairs.push_back(std::move(pair));
  model.warnings.push_back(tie.where.file + ":" + std::to_string(tie.where.line) +
                           ": *TIE: tie " + tie.name + " through TIED contact (" +
                           model::contact_scheme_name(*tie.scheme) + "), K = lambda = 50 E = " +
                           number(50 * young));
}

}  // namespace

std::string named_nodes(const model::Model& model, const std::vector<int>& nodes) {
  return first_items(node_labels(model, nodes));
}

std::vector<char> constrained_dofs(const model::Model& model) {
  std::vector<char> taken(3 * static_cast<std::size_t>(model.n_nodes()), 0);
  if (!model.steps.empty())
    for (const auto& bc : model.steps.front().boundaries) taken[3 * bc.node + bc.dof] = 1;
  for (const auto& eq : model.equations)
    taken[3 * eq.terms.front().node + eq.terms.front().dof] = 1;
  return taken;
}

Real typical_master_size(std::span<const SurfaceFace> faces, const MatX3& coords) {
  Real sum = 0;
  int count = 0;
  for (const SurfaceFace& face : faces)
    for (const Triangle& t : ccx_triangles(face.topo)) {
      const Vec3 a = ccx_face_node(face, coords, t[0]), b = ccx_face_node(face, coords, t[1]),
                 c = ccx_face_node(face, coords, t[2]);
      const Vec3 centroid = (a + b + c) / 3, edge = c - b;
      sum += (centroid - b).cross(edge).norm() / edge.norm();
      ++count;
    }
  return count ? sum / count : 0;
}

TieMaster make_tie_master(const model::Model& model, const model::Surface& master) {
  TieMaster out;
  ContactSurface surface = make_contact_surface(model, master);
  out.faces = std::move(surface.faces);
  out.nodes = std::move(surface.nodes);
  const VecX zero = VecX::Zero(3 * model.n_nodes());
  std::vector<Box> boxes;
  for (const SurfaceFace& face : out.faces) {
    out.geometry.push_back(face_geometry(face, model.mesh.coords, zero));
    boxes.push_back(face_box(out.geometry.back()));
    out.largest_face = std::max(out.largest_face, face_size(out.geometry.back()));
  }
  out.tree = AabbTree(boxes);
  return out;
}

std::optional<TieFoot> find_tie_foot(const TieMaster& master, const Vec3& p, Real tolerance) {
  Box near_p;
  near_p.add(p);
  const std::vector<int> near =
      master.tree.overlapping(near_p.inflated(tolerance + kEdgeTolerance * master.largest_face));
  std::vector<const FaceGeometry*> candidates;
  for (int m : near) candidates.push_back(&master.geometry[static_cast<std::size_t>(m)]);
  const MasterFoot found = find_master(p, candidates);
  if (found.candidate < 0) return std::nullopt;
  TieFoot foot;
  foot.face = near[static_cast<std::size_t>(found.candidate)];
  const FaceGeometry& face = master.geometry[static_cast<std::size_t>(foot.face)];
  // A foot within the edge tolerance comes back into the face, as ccx's attach_2d keeps it.
  foot.xi = clamp_to_reference_face(face.topo, found.foot.xi);
  foot.x = surface_point(face, foot.xi).x;
  foot.distance = (p - foot.x).norm();
  if (foot.distance > tolerance) return std::nullopt;
  return foot;
}

model::Equation tie_equation(int slave, int dof, const SurfaceFace& face, const Vec2& xi,
                             const SourceLoc& where) {
  FaceShape shape;
  face_shape(face.topo, xi, shape);
  model::Equation eq;
  eq.where = where;
  eq.keyword = "*TIE";
  eq.terms.push_back({slave, dof, 1.0});
  for (std::size_t a = 0; a < face.nodes.size(); ++a)
    eq.terms.push_back({face.nodes[a], dof, -shape.N(static_cast<Eigen::Index>(a))});
  return eq;
}

/// The dofs of plane and axisymmetric elements' expanded copies (equations from *ELEMENT)
/// that follow another dof, u = c u_2D, keyed by global dof; the dofs those equations hold
/// outright (u_z = 0 of plane strain) map to nothing.
std::map<int, std::optional<model::EquationTerm>> expansion_followers(const model::Model& model) {
  std::map<int, std::optional<model::EquationTerm>> out;
  for (const model::Equation& eq : model.equations) {
    if (eq.keyword != model::kExpansionKeyword) continue;
    const model::EquationTerm& lead = eq.terms.front();
    std::optional<model::EquationTerm> followed;
    if (eq.terms.size() == 2)
      followed = model::EquationTerm{eq.terms[1].node, eq.terms[1].dof,
                                     -eq.terms[1].coef / lead.coef};
    out[3 * lead.node + lead.dof] = followed;
  }
  return out;
}

int apply_ties(model::Model& model) {
  if (model.ties.empty()) return 0;
  const Real default_tol = default_tolerance(model);
  std::vector<char> constrained = constrained_dofs(model);
  // A slave copy of a 2D node is tied through the dof it follows (its 2D node's, once for all
  // its copies, which the expansion keeps moving alike); so ccx ties 2D parts (thread).
  const std::map<int, std::optional<model::EquationTerm>> followers = expansion_followers(model);
  int n_tied = 0;
  for (const model::Tie& tie : model.ties) {
    if (tie.cyclic) {
      const auto cyclic = std::find_if(
          model.cyclic_symmetry.begin(), model.cyclic_symmetry.end(),
          [&](const model::CyclicSymmetry& c) { return c.tie == tie.name; });
      n_tied += apply_cyclic_symmetry(model, tie, *cyclic, constrained);
      continue;
    }
    const TieMaster master = make_tie_master(model, model.surfaces.at(tie.master));
    const Real tolerance = tie.position_tolerance.value_or(default_tol);
    std::vector<int> missed;
    std::map<int, std::string> skipped;  // deck label -> directions left alone
    std::vector<Move> moves;
    std::set<int> tied_dofs;  // by this tie, directly or through a copy
    // Every foot is found on the mesh as this tie found it; its slave nodes move afterwards.
    for (int node : make_contact_surface(model, model.surfaces.at(tie.slave)).nodes) {
      const Vec3 p = model.mesh.coords.row(node).transpose();
      // A node the two surfaces share moves with the master already: nothing to tie.
      if (std::binary_search(master.nodes.begin(), master.nodes.end(), node)) continue;
      const std::optional<TieFoot> foot = find_tie_foot(master, p, tolerance);
      if (!foot) {
        missed.push_back(node);
        continue;
      }
      const SurfaceFace& face = master.faces[static_cast<std::size_t>(foot->face)];
      if (tie.adjust) moves.push_back({node, foot->x, foot->distance});
      if (tie.scheme) {  // bound by the contact pair below, not by equations
        ++n_tied;
        continue;
      }
      bool tied = false;
      for (int dof = 0; dof < 3; ++dof) {
        char& taken = constrained[3 * static_cast<std::size_t>(node) + dof];
        if (const auto copy = followers.find(3 * node + dof); copy != followers.end()) {
          const std::optional<model::EquationTerm>& followed = copy->second;
          if (!followed) continue;  // held by the expansion itself
          const int followed_dof = 3 * followed->node + followed->dof;
          if (tied_dofs.contains(followed_dof)) continue;  // through another copy
          if (!constrained[static_cast<std::size_t>(followed_dof)]) {
            model::Equation eq = tie_equation(node, dof, face, foot->xi, tie.where);
            eq.terms.front() = *followed;
            model.equations.push_back(std::move(eq));
            constrained[static_cast<std::size_t>(followed_dof)] = 1;
            tied_dofs.insert(followed_dof);
            tied = true;
            continue;
          }
        }
        if (taken && tied_dofs.contains(3 * node + dof)) continue;  // through a copy
        if (taken) {
          std::string& directions = skipped[model.mesh.node_ids[static_cast<std::size_t>(node)]];
          directions += (directions.empty() ? "" : ", ") + std::string(direction(dof));
          continue;
        }
        model.equations.push_back(tie_equation(node, dof, face, foot->xi, tie.where));
        taken = 1;
        tied_dofs.insert(3 * node + dof);
        tied = true;
      }
      n_tied += tied;
    }
    for (const Move& m : moves) model.mesh.coords.row(m.node) = m.to.transpose();
    if (tie.scheme) add_tied_contact(model, tie);
    // Moves below this are round-off of the projection, not worth a word.
    report(model, tie, tolerance, missed, skipped, moves, 1e-9 * master.largest_face);
  }
  return n_tied;
}

}  // namespace kontakt::contact
