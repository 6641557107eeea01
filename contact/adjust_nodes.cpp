#include "contact/adjust_nodes.hpp"

#include <algorithm>
#include <string>

#include "contact/contact_surface.hpp"
#include "contact/master_search.hpp"

namespace kontakt::contact {

int adjust_slave_nodes(model::Model& model) {
  int moved = 0;
  const model::ContactPair* first = nullptr;
  const VecX zero = VecX::Zero(3 * model.n_nodes());
  for (const auto& pair : model.contact_pairs) {
    if (!pair.adjust_distance && pair.adjust_set.empty()) continue;
    if (!first) first = &pair;
    const ContactSurface slave = make_contact_surface(model, model.surfaces.at(pair.slave));
    const ContactSurface master = make_contact_surface(model, model.surfaces.at(pair.master));
    std::vector<FaceGeometry> faces;
    std::vector<Box> boxes;
    Real size = 0;
    for (const auto& f : master.faces) {
      faces.push_back(face_geometry(f, model.mesh.coords, zero));
      boxes.push_back(face_box(faces.back()));
      size = std::max(size, face_size(faces.back()));
    }
    const AabbTree tree(boxes);
    std::vector<char> in_set(model.n_nodes(), 0);
    if (!pair.adjust_set.empty())
      for (int n : model.node_sets.at(pair.adjust_set).nodes) in_set[n] = 1;
    const Real limit = pair.adjust_distance.value_or(0);
    // All feet are found on the unmoved mesh, then the nodes move.
    std::vector<std::pair<int, Vec3>> targets;
    for (int node : slave.nodes) {
      if (!pair.adjust_set.empty() && !in_set[node]) continue;
      const Vec3 x = model.mesh.coords.row(node).transpose();
      Box b;
      b.add(x);
      std::vector<const FaceGeometry*> candidates;
      for (int m : tree.overlapping(b.inflated(limit + size))) candidates.push_back(&faces[m]);
      const MasterFoot foot = find_master(x, candidates);
      if (foot.candidate < 0) continue;
      if (pair.adjust_set.empty() && foot.foot.gap > limit) continue;
      targets.push_back({node, foot.foot.x});
    }
    for (const auto& [node, x] : targets) {
      model.mesh.coords.row(node) = x.transpose();
      ++moved;
    }
  }
  if (moved > 0)
    model.warnings.push_back(first->where.file + ":" + std::to_string(first->where.line) +
                             ": *CONTACT PAIR: ADJUST moved " + std::to_string(moved) +
                             " slave nodes onto the master surface");
  return moved;
}

}  // namespace kontakt::contact
