#include "contact/cyclic_symmetry.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "contact/contact_surface.hpp"
#include "contact/tie_constraints.hpp"

namespace kontakt::contact {

namespace {

/// The nearest of `candidates` to p, and its distance.
std::pair<int, Real> nearest(const MatX3& coords, const std::vector<int>& candidates,
                             const Vec3& p) {
  std::pair<int, Real> best{-1, std::numeric_limits<Real>::infinity()};
  for (int n : candidates) {
    const Real d = (coords.row(n).transpose() - p).norm();
    if (d < best.second) best = {n, d};
  }
  return best;
}

Real distance_to_axis(const Vec3& p, const Vec3& from, const Vec3& to) {
  const Vec3 axis = (to - from).normalized();
  const Vec3 r = p - from;
  return (r - r.dot(axis) * axis).norm();
}

}  // namespace

Mat3 axis_rotation(const Vec3& from, const Vec3& to, Real angle) {
  return Eigen::AngleAxis<Real>(angle, (to - from).normalized()).toRotationMatrix();
}

SectorPairs pair_sectors(const MatX3& coords, const std::vector<int>& dependent,
                         const std::vector<int>& independent,
                         const model::CyclicSymmetry& cyclic, Real tolerance) {
  const Real sector = 2 * std::numbers::pi / cyclic.sectors;
  SectorPairs best;
  bool first = true;
  for (const Real sign : {1.0, -1.0}) {
    SectorPairs found;
    found.rotation = axis_rotation(cyclic.axis_from, cyclic.axis_to, sign * sector);
    for (int dep : dependent) {
      const Vec3 x = coords.row(dep).transpose();
      if (distance_to_axis(x, cyclic.axis_from, cyclic.axis_to) <= tolerance) {
        found.on_axis.push_back(dep);
        continue;
      }
      // x_dep = R x_ind about the axis: the partner sits at R^T (x_dep - from) + from.
      const Vec3 back =
          found.rotation.transpose() * (x - cyclic.axis_from) + cyclic.axis_from;
      const auto [ind, distance] = nearest(coords, independent, back);
      if (ind >= 0 && distance <= tolerance)
        found.pairs.emplace_back(dep, ind);
      else
        found.unmatched.push_back(dep);
    }
    if (first || found.pairs.size() > best.pairs.size()) best = std::move(found);
    first = false;
  }
  return best;
}

int apply_cyclic_symmetry(model::Model& model, const model::Tie& tie,
                          const model::CyclicSymmetry& cyclic, std::vector<char>& constrained) {
  const std::vector<int> dependent =
      make_contact_surface(model, model.surfaces.at(tie.slave)).nodes;
  std::vector<int> independent = make_contact_surface(model, model.surfaces.at(tie.master)).nodes;
  Real tolerance = tie.position_tolerance.value_or(0);
  if (!tie.position_tolerance) {
    Real spacing = std::numeric_limits<Real>::infinity();
    for (std::size_t a = 0; a < independent.size(); ++a)
      for (std::size_t b = a + 1; b < independent.size(); ++b)
        spacing = std::min(spacing, (model.mesh.coords.row(independent[a]) -
                                     model.mesh.coords.row(independent[b])).norm());
    tolerance = kDefaultCyclicToleranceFraction * (std::isfinite(spacing) ? spacing : 0);
  }
  const SectorPairs found = pair_sectors(model.mesh.coords, dependent, independent, cyclic,
                                         tolerance);
  const std::string at = "tie " + tie.name + " (*CYCLIC SYMMETRY MODEL, N=" +
                         std::to_string(cyclic.sectors) + "): ";
  if (!found.on_axis.empty())
    throw InputError(cyclic.where, "*CYCLIC SYMMETRY MODEL",
                     at + "node(s) on the axis are not supported: " +
                         named_nodes(model, found.on_axis));
  if (!found.unmatched.empty())
    throw InputError(cyclic.where, "*CYCLIC SYMMETRY MODEL",
                     at + std::to_string(found.unmatched.size()) + " dependent node(s) of " +
                         tie.slave + " have no node of " + tie.master +
                         " one sector away within the position tolerance " +
                         std::to_string(tolerance) + ": " + named_nodes(model, found.unmatched));
  std::vector<int> skipped;
  int tied = 0;
  for (const auto& [dep, ind] : found.pairs) {
    if (dep == ind) continue;
    bool any = false;
    for (int i = 0; i < 3; ++i) {
      char& taken = constrained[3 * static_cast<std::size_t>(dep) + static_cast<std::size_t>(i)];
      if (taken) {
        if (skipped.empty() || skipped.back() != dep) skipped.push_back(dep);
        continue;
      }
      model::Equation eq;
      eq.where = tie.where;
      eq.keyword = "*TIE";
      eq.terms.push_back({dep, i, 1.0});
      for (int j = 0; j < 3; ++j)
        if (std::abs(found.rotation(i, j)) > 1e-14)
          eq.terms.push_back({ind, j, -found.rotation(i, j)});
      model.equations.push_back(std::move(eq));
      taken = 1;
      any = true;
    }
    tied += any;
  }
  if (!skipped.empty())
    model.warnings.push_back(tie.where.file + ":" + std::to_string(tie.where.line) + ": *TIE: " +
                             at + std::to_string(skipped.size()) +
                             " dependent node(s) keep directions already constrained (by "
                             "*BOUNDARY in the first step, or an earlier equation): " +
                             named_nodes(model, skipped));
  return tied;
}

}  // namespace kontakt::contact
