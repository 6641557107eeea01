// Shape functions N and their natural derivatives dN/dxi for every topology of the library.
#pragma once

#include "core/types.hpp"
#include "element/element_type.hpp"

namespace kontakt::element {

/// Interpolation topologies: 3-D volumes and the 2-D faces used for surface loads.
enum class Topology { Hex8, Hex20, Tet4, Tet10, Wedge6, Wedge15, Tri3, Tri6, Quad4, Quad8 };

inline constexpr int kMaxNodes = 20;

/// Heap-free vectors/matrices sized by the node count (at most kMaxNodes rows).
using ShapeVec = Eigen::Matrix<Real, Eigen::Dynamic, 1, 0, kMaxNodes, 1>;
using ShapeGrad = Eigen::Matrix<Real, Eigen::Dynamic, 3, Eigen::RowMajor, kMaxNodes, 3>;

int node_count(Topology topo);
/// 3 for volumes, 2 for faces (the third natural coordinate is then ignored).
int dimension(Topology topo);

/// Natural coordinates of node i (0-based) of the reference element. Hexes and quads span
/// [-1,1]; tets use (xi,eta,zeta) = (L2,L3,L4); wedges use triangle (xi,eta) x zeta in [-1,1].
Vec3 reference_node(Topology topo, int i);

/// N (n) and dN/dxi (n x 3; column 2 is zero for faces) at natural point xi.
void shape_functions(Topology topo, const Vec3& xi, ShapeVec& N, ShapeGrad& dN);

/// Topology of the element's volume interpolation (C3D8R/C3D8I: Hex8, C3D20R: Hex20).
Topology volume_topology(ElementType type);
/// Topology of face `face` (1-based) of the element.
Topology face_topology(ElementType type, int face);

}  // namespace kontakt::element
