#include "analysis/distance_links.hpp"

#include <sstream>

namespace kontakt::analysis {

namespace {

using model::NonlinearConstraint;

/// x_a - x_b of a DIST at displacements u.
Vec3 separation(const model::Model& model, const NonlinearConstraint& c, const VecX& u) {
  const int a = c.nodes[0], b = c.nodes[1];
  return (model.mesh.coords.row(a) - model.mesh.coords.row(b)).transpose() +
         u.segment<3>(3 * a) - u.segment<3>(3 * b);
}

}  // namespace

DistanceLinks::DistanceLinks(const model::Model& model) : model_(model) {
  const auto& constraints = model.nonlinear_constraints;
  in_force_.assign(constraints.size(), 1);
  const VecX rest = VecX::Zero(3 * model.n_nodes());
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    if (constraints[i].kind != NonlinearConstraint::Kind::Distance) continue;
    in_force_[i] = 0;
    Link link{.constraint = i, .linked = false, .switch_next = false};
    link.switch_next = calls_for_switch(link, rest, rest);
    links_.push_back(link);
  }
}

bool DistanceLinks::calls_for_switch(const Link& link, const VecX& u, const VecX& residual) const {
  const NonlinearConstraint& c = model_.nonlinear_constraints[link.constraint];
  const Vec3 s = separation(model_, c, u);
  if (!link.linked) return s.norm() >= c.distance;
  // The force on a is mu grad_a g = 2 mu (x_a - x_b): mu > 0 pushes a away from b.
  const Real mu = residual[3 * c.nodes[0] + c.component] / (2 * s[c.component]);
  return mu > 0;
}

std::vector<std::string> DistanceLinks::begin_increment() {
  std::vector<std::string> changes;
  for (const Link& link : links_) {
    const char in_force = link.linked != link.switch_next;
    if (in_force_[link.constraint] == in_force) continue;
    in_force_[link.constraint] = in_force;
    const NonlinearConstraint& c = model_.nonlinear_constraints[link.constraint];
    std::ostringstream line;
    line << c.where.file << ":" << c.where.line << ": *MPC DIST between nodes "
         << model_.mesh.node_ids[c.nodes[0]] << " and " << model_.mesh.node_ids[c.nodes[1]]
         << (in_force ? " linked from this increment on: their distance had reached "
                      : " let go from this increment on: at its distance of ")
         << c.distance << (in_force ? "" : " it had pushed them apart")
         << " in the state this increment starts from (judged there, as ccx does)";
    changes.push_back(line.str());
  }
  return changes;
}

void DistanceLinks::commit(const VecX& u, const VecX& residual) {
  for (Link& link : links_) {
    link.linked = in_force_[link.constraint] != 0;
    link.switch_next = calls_for_switch(link, u, residual);
  }
}

}  // namespace kontakt::analysis
