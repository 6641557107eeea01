// *RIGID BODY and *MPC (PLANE, STRAIGHT, MEANROT, DIST): nonlinear constraints
// (model::NonlinearConstraint).
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "inp/keyword_handlers.hpp"
#include "inp/model_builder.hpp"
#include "inp/record_access.hpp"

namespace kontakt::inp {

namespace {

using model::NonlinearConstraint;

/// The node REF NODE= or ROT NODE= names, defined before the card.
int parameter_node(const Record& record, DeckState& state, std::string_view name) {
  const std::string value = required_value(record, name);
  const std::optional<int> label = parse_int(value);
  if (!label) fail(record, std::string(name) + "=" + value + " is not a node label");
  const auto found = state.model.mesh.node_index.find(*label);
  if (found == state.model.mesh.node_index.end())
    fail(record, "node " + value + " (" + std::string(name) +
                     "=) is not defined; define it with *NODE before this card");
  return found->second;
}

/// The nodes an *MPC line lists, labels or node sets (a set in its definition order), zero
/// entries skipped (ccx).
std::vector<int> listed_nodes(const Record& record, const DeckState& state, std::size_t first) {
  std::vector<int> nodes;
  for (const DataLine& line : record.lines)
    for (std::size_t f = &line == &record.lines.front() ? first : 0; f < line.fields.size(); ++f) {
      const std::string& field = line.fields[f];
      if (field.empty()) continue;
      if (const std::optional<int> label = parse_int(field)) {
        if (*label != 0) nodes.push_back(node_index_of(state, record, line, *label));
        continue;
      }
      const std::string name = remove_blanks(to_upper(field));
      const auto set = state.node_sets.find(name);
      if (set == state.node_sets.end()) fail(record, line, "node set " + name + " is not defined");
      for (const model::LabelRange& range : set->second.sequence)
        for (long long label = range.first; label <= range.last; label += range.step)
          if (const auto found = state.model.mesh.node_index.find(static_cast<int>(label));
              found != state.model.mesh.node_index.end())
            nodes.push_back(found->second);
    }
  return nodes;
}

/// The component of `v` largest in magnitude.
int largest_component(const Vec3& v) {
  int k = 0;
  for (int c = 1; c < 3; ++c)
    if (std::abs(v[c]) > std::abs(v[k])) k = c;
  return k;
}

/// MEANROT: each node three times (once per dof), then the axis node. The dependent dof is the
/// first listed, as in ccx, or, where the rotation hardly depends on it, the one it depends
/// on most (the solution does not depend on the choice).
void add_mean_rotation(const Record& record, DeckState& state, const std::vector<int>& listed) {
  const DataLine& head = record.lines.front();
  if (listed.size() < 4 || (listed.size() - 1) % 3 != 0)
    fail(record, head,
         "MEANROT lists each node three times (once per dof), then the node whose "
         "coordinates give the rotation axis");
  std::vector<int> nodes;
  for (std::size_t i = 0; i + 1 < listed.size(); i += 3) {
    if (listed[i + 1] != listed[i] || listed[i + 2] != listed[i])
      fail(record, head,
           "node " + std::to_string(state.model.mesh.node_ids[listed[i]]) +
               " is not listed three times in a row (once per dof)");
    if (std::find(nodes.begin(), nodes.end(), listed[i]) != nodes.end())
      fail(record, head,
           "node " + std::to_string(state.model.mesh.node_ids[listed[i]]) + " is listed twice");
    nodes.push_back(listed[i]);
  }
  const int axis_node = listed.back();
  const Vec3 axis = state.coords[static_cast<std::size_t>(axis_node)];
  if (axis.norm() == 0)
    fail(record, head,
         "the coordinates of node " + std::to_string(state.model.mesh.node_ids[axis_node]) +
             " (the rotation axis) are zero");
  const Vec3 a = axis.normalized();
  const Real n = static_cast<Real>(nodes.size());
  Vec3 centre = Vec3::Zero();
  for (int node : nodes) centre += state.coords[static_cast<std::size_t>(node)] / n;
  // At rest, d(mean rotation)/du_p = sum_i (delta_ip - 1/N) (a x b_i) / |b_i|^2 / N.
  std::vector<Vec3> turn;  // (a x b_i) / |b_i|^2
  Real reach = 0;
  for (int node : nodes) {
    const Vec3 r = state.coords[static_cast<std::size_t>(node)] - centre;
    reach = std::max(reach, r.norm());
    const Vec3 b = r - r.dot(a) * a;
    turn.push_back(b.squaredNorm() > 0 ? Vec3(a.cross(b) / b.squaredNorm()) : Vec3::Zero());
    if (b.norm() <= 1e-9 * reach)
      fail(record, head,
           "node " + std::to_string(state.model.mesh.node_ids[node]) +
               " lies on the rotation axis through the nodes' centre: its rotation "
               "is undefined");
  }
  Vec3 mean_turn = Vec3::Zero();
  for (const Vec3& t : turn) mean_turn += t / n;
  // ccx's dependent dof, the first listed, unless the rotation hardly depends on it: its force
  // gives the axis node's torque (RF), which agrees between dofs only at full convergence.
  auto weight = [&](std::size_t i, int c) { return std::abs(turn[i][c] - mean_turn[c]); };
  std::size_t dependent = 0, largest = 0;
  int component = 0, largest_c = 0;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (int c = 0; c < 3; ++c)
      if (weight(i, c) > weight(largest, largest_c)) {
        largest = i;
        largest_c = c;
      }
  if (weight(0, 0) < 1e-3 * weight(largest, largest_c)) {
    dependent = largest;
    component = largest_c;
  }
  NonlinearConstraint c{.kind = NonlinearConstraint::Kind::MeanRotation,
                        .nodes = {nodes[dependent]},
                        .component = component,
                        .pivot = 0,
                        .where = record.where,
                        .keyword = "*MPC"};
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (i != dependent) c.nodes.push_back(nodes[i]);
  c.nodes.push_back(axis_node);
  state.model.nonlinear_constraints.push_back(std::move(c));
}

/// DIST: a, a, a, b, b, b, c (each of a and b once per dof): the distance from a to b may not
/// exceed c's first coordinate. Solved, when linked, for the component of a along which the
/// two lie farthest apart at rest.
void add_distance(const Record& record, DeckState& state, const std::vector<int>& listed) {
  const DataLine& head = record.lines.front();
  const auto label = [&](int node) { return std::to_string(state.model.mesh.node_ids[node]); };
  if (listed.size() != 7 || listed[1] != listed[0] || listed[2] != listed[0] ||
      listed[4] != listed[3] || listed[5] != listed[3])
    fail(record, head,
         "DIST lists node a three times, node b three times (once per dof), then the node whose "
         "first coordinate is the largest distance");
  const int a = listed[0], b = listed[3], c = listed[6];
  if (a == b) fail(record, head, "DIST: node " + label(a) + " is both ends");
  const Real distance = state.coords[static_cast<std::size_t>(c)].x();
  if (!(distance > 0))
    fail(record, head,
         "DIST: the first coordinate of node " + label(c) + " (the largest distance) must be positive");
  const Vec3 rest = state.coords[static_cast<std::size_t>(a)] - state.coords[static_cast<std::size_t>(b)];
  if (rest.norm() == 0) fail(record, head, "DIST: nodes " + label(a) + " and " + label(b) + " coincide");
  state.model.nonlinear_constraints.push_back({.kind = NonlinearConstraint::Kind::Distance,
                                               .nodes = {a, b},
                                               .component = largest_component(rest),
                                               .pivot = 0,
                                               .distance = distance,
                                               .where = record.where,
                                               .keyword = "*MPC"});
}

}  // namespace

void handle_rigid_body(const Record& record, DeckState& state) {
  check_params(record, {"NSET", "ELSET", "REFNODE", "ROTNODE"});
  if (!has_param(record, "REFNODE") || !has_param(record, "ROTNODE"))
    fail(record,
         "REF NODE= and ROT NODE= are required here (ccx would generate them; give "
         "them as nodes of their own to print and load the rigid body's motion)");
  if (!record.lines.empty()) fail(record, record.lines.front(), "this card has no data lines");
  RawRigidBody body{.nset = name_value(record, "NSET"),
                    .elset = name_value(record, "ELSET"),
                    .ref = parameter_node(record, state, "REFNODE"),
                    .rot = parameter_node(record, state, "ROTNODE"),
                    .where = record.where};
  if (body.nset.has_value() == body.elset.has_value())
    fail(record, "give exactly one of NSET= and ELSET=");
  if (body.nset && !state.node_sets.contains(*body.nset))
    fail(record, "node set " + *body.nset + " is not defined");
  if (body.elset && !state.element_sets.contains(*body.elset))
    fail(record, "element set " + *body.elset + " is not defined");
  if (body.ref == body.rot) fail(record, "REF NODE and ROT NODE must be different nodes");
  state.rigid_bodies.push_back(std::move(body));
}

void resolve_rigid_bodies(DeckState& state) {
  const model::Mesh& mesh = state.model.mesh;
  std::vector<char> in_element(mesh.node_ids.size(), 0);
  for (const auto& el : mesh.elements)
    for (int n : el.nodes) in_element[static_cast<std::size_t>(n)] = 1;
  const auto label = [&](int node) {
    return std::to_string(mesh.node_ids[static_cast<std::size_t>(node)]);
  };
  for (const RawRigidBody& body : state.rigid_bodies) {
    std::vector<int> nodes;
    if (body.nset) {
      nodes = node_set_members(state, state.node_sets.at(*body.nset), *body.nset);
    } else {
      for (int e : element_set_members(state, state.element_sets.at(*body.elset), *body.elset))
        for (int n : mesh.elements[static_cast<std::size_t>(e)].nodes) nodes.push_back(n);
    }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    if (std::binary_search(nodes.begin(), nodes.end(), body.rot))
      throw InputError(body.where, "*RIGID BODY",
                       "ROT NODE " + label(body.rot) +
                           " belongs to the rigid body; it must be a node of its own");
    if (in_element[static_cast<std::size_t>(body.rot)])
      throw InputError(body.where, "*RIGID BODY",
                       "ROT NODE " + label(body.rot) +
                           " belongs to an element; its dofs are the body's rotation");
    for (int node : nodes) {
      if (node == body.ref) continue;  // moves with itself
      for (int c = 0; c < 3; ++c)
        state.model.nonlinear_constraints.push_back({.kind = NonlinearConstraint::Kind::Rigid,
                                                     .nodes = {node, body.ref, body.rot},
                                                     .component = c,
                                                     .pivot = 0,
                                                     .where = body.where,
                                                     .keyword = "*RIGID BODY"});
    }
  }
}

void handle_mpc(const Record& record, DeckState& state) {
  check_params(record, {});
  require_line_count(record, 1, record.lines.size() + 1);
  const DataLine& head = record.lines.front();
  const std::string type = remove_blanks(to_upper(head.fields.empty() ? "" : head.fields[0]));
  const bool plane = type == "PLANE", straight = type == "STRAIGHT";
  if (type == "MEANROT") return add_mean_rotation(record, state, listed_nodes(record, state, 1));
  if (type == "DIST") {
    add_distance(record, state, listed_nodes(record, state, 1));
    state.nonlinear_mpc = true;
    return;
  }
  if (!plane && !straight)
    fail(record, head,
         "MPC type " + type + " is not supported (PLANE, STRAIGHT, MEANROT and DIST are)");
  const std::vector<int> nodes = listed_nodes(record, state, 1);
  const std::size_t n_defining = plane ? 3 : 2;
  std::vector<int> seen = nodes;
  std::sort(seen.begin(), seen.end());
  if (std::adjacent_find(seen.begin(), seen.end()) != seen.end())
    fail(record, head, "a node is listed twice");
  if (nodes.size() <= n_defining)
    fail(record, head,
         type + " needs " + std::to_string(n_defining) +
             " defining nodes and at least one more node");
  auto x = [&](std::size_t i) -> Vec3 { return state.coords[static_cast<std::size_t>(nodes[i])]; };
  const Vec3 direction = plane ? Vec3((x(1) - x(0)).cross(x(2) - x(0))) : Vec3(x(1) - x(0));
  if (direction.norm() <= 1e-12 * (x(1) - x(0)).norm() || direction.norm() == 0)
    fail(record, head,
         plane ? "the three defining nodes lie on one line" : "the two defining nodes coincide");
  const int pivot = largest_component(direction);
  for (std::size_t i = n_defining; i < nodes.size(); ++i) {
    NonlinearConstraint c{
        .kind = plane ? NonlinearConstraint::Kind::Plane : NonlinearConstraint::Kind::Straight,
        .nodes = {nodes[i]},
        .component = pivot,
        .pivot = pivot,
        .where = record.where,
        .keyword = "*MPC"};
    for (std::size_t k = 0; k < n_defining; ++k) c.nodes.push_back(nodes[k]);
    if (plane) {  // solved for the component along the plane's normal
      state.model.nonlinear_constraints.push_back(c);
      continue;
    }
    for (int j = 0; j < 3; ++j) {  // the two components across the line
      if (j == pivot) continue;
      c.component = j;
      state.model.nonlinear_constraints.push_back(c);
    }
  }
  state.nonlinear_mpc = true;
}

}  // namespace kontakt::inp
