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

/// Normals closer than this (1 - cos) are one plane: a point over the edge between two
/// coplanar faces gets the same force from either.
constexpr Real kSameNormal = 1e-10;

/// One search: the candidates in the order of their (inflated) boxes' distance from the point,
/// each projected at most once.
class Search {
 public:
  Search(const Vec3& p, std::span<const FaceGeometry* const> candidates)
      : p_(p), candidates_(candidates), order_(candidates.size()), feet_(candidates.size()) {
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      // Inflated so that feet within the edge tolerance and bulging quadratic faces stay inside.
      const FaceGeometry& f = *candidates[k];
      order_[k] = {box_distance(face_box(f).inflated(kEdgeTolerance * face_size(f)), p), k};
    }
    std::sort(order_.begin(), order_.end());
  }

  /// The nearest candidate `p` projects into at tolerance `tol`, and that tolerance.
  std::pair<MasterFoot, Real> nearest() {
    for (Real tol : {kInsideTolerance, kEdgeTolerance}) {
      MasterFoot best;
      Real best_distance = 1e300;
      for (const auto& [box_distance_k, k] : order_) {
        // A foot lies in its (planar or curved) face's box: a farther box holds no nearer foot.
        if (box_distance_k > best_distance) break;
        const std::optional<Real> d = distance_inside(k, tol);
        if (d && *d < best_distance) {
          best_distance = *d;
          best = {static_cast<int>(k), *feet_[k]};
        }
      }
      if (best.candidate >= 0) return {best, tol};
    }
    return {MasterFoot{}, 0};
  }

  /// `best` and every other candidate `p` projects into (at `tol`) within `tie` of its
  /// distance, one per plane.
  std::vector<MasterFoot> tied(const MasterFoot& best, Real tol, Real tie) {
    std::vector<MasterFoot> found{best};
    const Real limit = (p_ - best.foot.x).norm() + tie;
    for (const auto& [box_distance_k, k] : order_) {
      if (box_distance_k > limit) break;
      if (static_cast<int>(k) == best.candidate) continue;
      const std::optional<Real> d = distance_inside(k, tol);
      if (!d || *d > limit) continue;
      const Vec3& n = feet_[k]->normal;
      const auto same_plane = [&n](const MasterFoot& m) { return 1 - m.foot.normal.dot(n) < kSameNormal; };
      if (std::none_of(found.begin(), found.end(), same_plane))
        found.push_back({static_cast<int>(k), *feet_[k]});
    }
    return found;
  }

 private:
  /// Distance from p to its foot on candidate k when the foot lies inside the face.
  std::optional<Real> distance_inside(std::size_t k, Real tol) {
    const FaceGeometry& face = *candidates_[k];
    if (!feet_[k]) feet_[k] = project_onto_face(face, p_, face_centre(face.topo));
    const ClosestPoint& f = *feet_[k];
    if (!f.converged || !inside_reference_face(face.topo, f.xi, tol)) return std::nullopt;
    return (p_ - f.x).norm();
  }

  const Vec3& p_;
  std::span<const FaceGeometry* const> candidates_;
  std::vector<std::pair<Real, std::size_t>> order_;
  std::vector<std::optional<ClosestPoint>> feet_;
};

}  // namespace

std::vector<const FaceGeometry*> as_candidates(const std::vector<FaceGeometry>& faces) {
  std::vector<const FaceGeometry*> c;
  for (const FaceGeometry& f : faces) c.push_back(&f);
  return c;
}

MasterFoot find_master(const Vec3& p, std::span<const FaceGeometry* const> candidates) {
  return Search(p, candidates).nearest().first;
}

std::vector<MasterFoot> find_tied_masters(const Vec3& p,
                                          std::span<const FaceGeometry* const> candidates) {
  Search search(p, candidates);
  const auto [best, tol] = search.nearest();
  if (best.candidate < 0) return {};
  return search.tied(best, tol, kTieTolerance * face_size(*candidates[best.candidate]));
}

}  // namespace kontakt::contact
