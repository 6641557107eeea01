#include "contact/master_search.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "contact/contact_surface.hpp"

namespace kontakt::contact {

namespace {

/// Distance from p to the box (0 inside).
Real box_distance(const Box& b, const Vec3& p) {
  return (b.lo - p).cwiseMax(p - b.hi).cwiseMax(Vec3::Zero()).norm();
}

}  // namespace

MasterFoot find_master(const Vec3& p, std::span<const FaceGeometry* const> candidates) {
  const std::size_t n = candidates.size();
  std::vector<std::pair<Real, std::size_t>> order(n);
  for (std::size_t k = 0; k < n; ++k) {
    // Inflated so that feet within the edge tolerance and bulging quadratic faces stay inside.
    const FaceGeometry& f = *candidates[k];
    order[k] = {box_distance(face_box(f).inflated(kEdgeTolerance * face_size(f)), p), k};
  }
  std::sort(order.begin(), order.end());
  std::vector<std::optional<ClosestPoint>> feet(n);  // projected on demand, kept for pass 2
  for (Real tol : {kInsideTolerance, kEdgeTolerance}) {
    MasterFoot best;
    Real best_distance = 1e300;
    for (const auto& [box_distance_k, k] : order) {
      // A foot lies in its (planar or curved) face's box: a farther box holds no nearer foot.
      if (box_distance_k > best_distance) break;
      if (!feet[k]) feet[k] = project_onto_face(*candidates[k], p, face_centre(candidates[k]->topo));
      const ClosestPoint& f = *feet[k];
      if (!f.converged || !inside_reference_face(candidates[k]->topo, f.xi, tol)) continue;
      const Real distance = (p - f.x).norm();
      if (distance < best_distance) {
        best_distance = distance;
        best = {static_cast<int>(k), f};
      }
    }
    if (best.candidate >= 0) return best;
  }
  return {};
}

}  // namespace kontakt::contact
