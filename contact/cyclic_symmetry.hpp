// *CYCLIC SYMMETRY MODEL in a static analysis, as ccx applies it under a load that is the same
// on every sector (nodal diameter 0): each dependent node of the cyclic *TIE moves as its
// independent partner turned by one sector, u_dep = R u_ind, where the rotation R by 2 pi / N
// about the axis maps the independent side onto the dependent one. The partners are found
// node to node within the tie's position tolerance; three linear equations per dependent node
// join Model::equations (the dependent dof first), so the DofMap eliminates them like *TIE's.
// The rotation maps positions, so the equations hold exactly under NLGEOM too.
#pragma once

#include <utility>
#include <vector>

#include "model/model.hpp"

namespace kontakt::contact {

/// The right-handed rotation by `angle` about the axis from `from` to `to`.
Mat3 axis_rotation(const Vec3& from, const Vec3& to, Real angle);

/// Dependent nodes and their independent partners, and the rotation that maps the independent
/// side onto the dependent one (by +2 pi / N or -2 pi / N about the axis: the one that pairs
/// more nodes). `unmatched`: dependent nodes without a partner within `tolerance`; `on_axis`:
/// nodes within `tolerance` of the axis (they map onto themselves).
struct SectorPairs {
  Mat3 rotation = Mat3::Identity();
  std::vector<std::pair<int, int>> pairs;  ///< (dependent, independent), internal indices
  std::vector<int> unmatched, on_axis;
};
SectorPairs pair_sectors(const MatX3& coords, const std::vector<int>& dependent,
                         const std::vector<int>& independent,
                         const model::CyclicSymmetry& cyclic, Real tolerance);

/// The tolerance of a cyclic tie without POSITION TOLERANCE: this fraction of the smallest
/// distance between two of its independent nodes.
inline constexpr Real kDefaultCyclicToleranceFraction = 0.025;

/// Appends the equations of one *CYCLIC SYMMETRY MODEL (its tie: `tie`). Dependent dofs marked
/// in `constrained` (prescribed in the first step, or dependent in an earlier equation) are left
/// alone with a warning, as *TIE does; the others are marked. Throws InputError when a
/// dependent node has no partner or a node lies on the axis. Returns the dependent nodes tied.
int apply_cyclic_symmetry(model::Model& model, const model::Tie& tie,
                          const model::CyclicSymmetry& cyclic, std::vector<char>& constrained);

}  // namespace kontakt::contact
