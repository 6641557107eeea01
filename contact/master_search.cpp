#include "contact/master_search.hpp"

#include <cmath>

namespace kontakt::contact {

MasterFoot find_master(const Vec3& p, std::span<const FaceGeometry* const> candidates) {
  std::vector<ClosestPoint> feet(candidates.size());
  for (std::size_t k = 0; k < candidates.size(); ++k)
    feet[k] = project_onto_face(*candidates[k], p, face_centre(candidates[k]->topo));
  for (Real tol : {kInsideTolerance, kEdgeTolerance}) {
    MasterFoot best;
    Real best_distance = 1e300;
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      const ClosestPoint& f = feet[k];
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
