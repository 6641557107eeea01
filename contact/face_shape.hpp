// Shape functions of contact faces (tri3, tri6, quad4, quad8) with first and second derivatives
// in the face's natural coordinates. The second derivatives give the curvature terms of the
// closest-point projection and of the sliding contact tangent. Node order as element faces:
// corners first, then midside nodes (tri6: 1-2, 2-3, 3-1; quad8: 1-2, 2-3, 3-4, 4-1).
#pragma once

#include "core/types.hpp"
#include "element/shape_functions.hpp"

namespace kontakt::contact {

inline constexpr int kMaxFaceNodes = 8;

using FaceVec = Eigen::Matrix<Real, Eigen::Dynamic, 1, 0, kMaxFaceNodes, 1>;
/// One row per node: d/dxi, d/deta.
using FaceGrad = Eigen::Matrix<Real, Eigen::Dynamic, 2, Eigen::RowMajor, kMaxFaceNodes, 2>;
/// One row per node: d2/dxi2, d2/deta2, d2/dxi deta.
using FaceHess = Eigen::Matrix<Real, Eigen::Dynamic, 3, Eigen::RowMajor, kMaxFaceNodes, 3>;
/// Nodal coordinates of a face, one row per node.
using FaceCoords = Eigen::Matrix<Real, Eigen::Dynamic, 3, Eigen::RowMajor, kMaxFaceNodes, 3>;

struct FaceShape {
  FaceVec N;
  FaceGrad dN;
  FaceHess d2N;
};

bool is_face_topology(element::Topology topo);
bool is_triangle(element::Topology topo);

/// N, dN and d2N of a face topology at natural point xi (quads: [-1,1]^2; triangles: area
/// coordinates xi = L2, eta = L3).
void face_shape(element::Topology topo, const Vec2& xi, FaceShape& out);

/// The face's centroid in natural coordinates.
Vec2 face_centre(element::Topology topo);

/// True when xi lies in the reference face, widened by `tol` (in natural coordinates).
bool inside_reference_face(element::Topology topo, const Vec2& xi, Real tol);

/// The nearest point of the reference face to xi (xi itself when inside).
Vec2 clamp_to_reference_face(element::Topology topo, const Vec2& xi);

}  // namespace kontakt::contact
