#include "analysis/support_check.hpp"

#include <array>
#include <cmath>
#include <numeric>
#include <string>

namespace kontakt::analysis {

namespace {

struct DisjointSets {
  std::vector<int> parent;
  explicit DisjointSets(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(int a, int b) { parent[find(a)] = find(b); }
};

}  // namespace

std::vector<UnsupportedBody> unsupported_bodies(const model::Model& model,
                                               const assembly::DofMap& dofs,
                                               bool contact_holds) {
  const int n_nodes = model.n_nodes();
  DisjointSets bodies(n_nodes);
  std::vector<char> in_element(n_nodes, 0);
  for (const auto& el : model.mesh.elements)
    for (int node : el.nodes) {
      bodies.join(el.nodes.front(), node);
      in_element[node] = 1;
    }
  for (const auto& eq : model.equations)
    for (const auto& term : eq.terms) bodies.join(eq.terms.front().node, term.node);
  for (const auto& c : model.nonlinear_constraints)
    for (int node : c.nodes) bodies.join(c.nodes.front(), node);
  // A spring or truss joins its nodes into one body; a gap, like contact, only when contact
  // holds.
  for (const auto& c : model.connectors) {
    for (int node : c.nodes) in_element[node] = 1;
    if (c.kind != model::Connector::Kind::Gap || contact_holds) bodies.join(c.nodes[0], c.nodes[1]);
  }
  // Contact can hold a body against another: the two sides of a pair count as one body.
  if (contact_holds)
    for (const auto& pair : model.contact_pairs) {
      std::vector<int> nodes;
      for (const auto* name : {&pair.slave, &pair.master}) {
        const auto& surface = model.surfaces.at(*name);
        for (int n : surface.nodes) nodes.push_back(n);
        for (const auto& f : surface.faces) nodes.push_back(model.mesh.elements[f.element].nodes.front());
      }
      for (int n : nodes) bodies.join(nodes.front(), n);
    }

  // A body is held in a direction when some dof in it is prescribed in that direction; a
  // prescribed local component (*TRANSFORM) counts for every global direction it has a part
  // in (a coarse check: the factorisation reports what it lets through).
  std::vector<std::array<char, 3>> held(n_nodes, {0, 0, 0});
  for (int slot = 0; slot < dofs.n_prescribed(); ++slot) {
    const int d = dofs.prescribed_dof(slot);
    const Mat3* frame = dofs.local_frame(d / 3);
    for (int c = 0; c < 3; ++c) {
      const bool part = frame ? std::abs((*frame)(c, d % 3)) > 1e-8 : c == d % 3;
      if (part) held[bodies.find(d / 3)][c] = 1;
    }
  }
  std::vector<UnsupportedBody> out;
  for (int node = 0; node < n_nodes; ++node) {
    if (!in_element[node] || bodies.find(node) != node) continue;
    const auto& h = held[node];
    if (h[0] && h[1] && h[2]) continue;
    UnsupportedBody b{.node = model.mesh.node_ids[node], .free = ""};
    for (int c = 0; c < 3; ++c)
      if (!h[c]) b.free += std::string(b.free.empty() ? "" : ", ") + "xyz"[c];
    out.push_back(b);
  }
  return out;
}

void check_bodies_supported(const model::Model& model, const assembly::DofMap& dofs) {
  const auto free = unsupported_bodies(model, dofs, true);
  if (free.empty()) return;
  throw SolverError("the body containing node " + std::to_string(free.front().node) +
                    " has no displacement boundary condition in " + free.front().free +
                    ": it can move as a rigid body (add *BOUNDARY constraints)");
}

std::string bodies_held_only_by_contact(const model::Model& model, const assembly::DofMap& dofs) {
  std::string out;
  for (const auto& b : unsupported_bodies(model, dofs, false))
    out += std::string(out.empty() ? "" : "; ") + "the body containing node " +
           std::to_string(b.node) + " is held in " + b.free + " only by contact";
  return out;
}

}  // namespace kontakt::analysis
