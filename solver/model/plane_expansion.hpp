// Plane stress, plane strain and axisymmetric elements, solved as ccx 2.20 solves them: each
// 2D element becomes one layer of 3D elements (CPx4 -> C3D8, CPx4R -> C3D8R, CPx8 -> C3D20,
// CPx8R -> C3D20R, CPx6 -> C3D15, CPx3 -> C3D6) between a front and a back copy of its nodes
// (and a middle copy at the corners of quadratic elements), tied to the deck's 2D node by
// linear constraints:
//   plane strain    every copy moves in-plane with the 2D node, out of plane not at all;
//   plane stress    in-plane the same; the middle copy has no z motion, and at linear
//                   elements front and back move opposite in z (w_front + w_back = 0);
//   axisymmetric    a wedge from -1 to +1 degree about the y axis: the copies at +-1 degree
//                   move radially with the 2D node (u_x = cos u_r, u_z = -+sin u_r).
// Plane elements are `SolidSection::thickness` thick. A model with axisymmetric elements is
// given for 360 degrees: the wedge carries 1/180 of every *CLOAD, plane elements in such a
// model are 1/180 as thick, and reactions are the wedge's, as ccx prints them.
#pragma once

#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"
#include "model/model.hpp"

namespace kontakt::model {

/// Half the opening angle of the axisymmetric wedge (radians).
inline constexpr Real kWedgeHalfAngle = 3.14159265358979323846 / 180.0;
/// The part of a 360-degree load the wedge carries.
inline constexpr Real kWedgeLoadFactor = 1.0 / 180.0;
/// The keyword of the equations that tie the copies to their 2D node (Equation::keyword):
/// messages name the 2D element's card.
inline constexpr const char* kExpansionKeyword = "*ELEMENT";

/// Replaces the 2D elements of `model` by their 3D expansion in place: new nodes (labels after
/// the largest deck label), constraint equations, faces of surfaces and pressures renumbered
/// (edge k -> face k + 2), a node surface's 2D nodes replaced by their copies, *CLOAD of
/// axisymmetric models scaled, temperatures copied to the new nodes, and Model::planar_folds
/// filled. `element_where` is the *ELEMENT line of each element (for messages). Throws
/// InputError for what ccx refuses or Kontakt does not build: a 2D node off z = 0, a 2D node
/// shared with a solid or carrying a *TRANSFORM, a degenerate or (axisymmetric) clockwise
/// element, a node at negative radius.
void expand_planar_elements(Model& model, const std::vector<SourceLoc>& element_where);

/// The deck's 2D nodes' results from their expanded nodes: U the weighted mean (ccx: front and
/// back alike, the middle copy 4/6 at quadratic corners; the groups of a node shared by plane
/// and axisymmetric elements averaged), RF the sum of the internal forces of all copies.
void fold_to_planar_nodes(const std::vector<PlanarFold>& folds, MatX3& U, MatX3& RF);

}  // namespace kontakt::model
