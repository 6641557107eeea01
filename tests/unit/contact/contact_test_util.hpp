// Shared fixtures of the contact unit tests: curved and distorted faces of every topology.
#pragma once

#include <Eigen/Geometry>
#include <random>

#include "contact/closest_point.hpp"

namespace kontakt::contact::fixtures {

inline const element::Topology kFaceTopologies[] = {element::Topology::Tri3, element::Topology::Tri6,
                                                     element::Topology::Quad4, element::Topology::Quad8};

/// Reference-face node coordinates (xi, eta) of a face topology.
inline Vec2 reference_face_node(element::Topology topo, int i) {
  const Vec3 r = element::reference_node(topo, i);
  return Vec2(r(0), r(1));
}

/// A face over the unit square / triangle, scaled by `size`, lifted into a dome of height
/// `bulge` (midside and corner nodes on z = bulge * (1 - |xy - c|^2)), with the nodes jittered
/// in-plane by `jitter` (fraction of size) and the whole face rotated and shifted.
inline FaceGeometry curved_face(element::Topology topo, Real size, Real bulge, Real jitter,
                                std::mt19937& rng) {
  std::uniform_real_distribution<Real> u(-1, 1);
  const int n = element::node_count(topo);
  FaceGeometry f{topo, FaceCoords(n, 3)};
  const bool tri = topo == element::Topology::Tri3 || topo == element::Topology::Tri6;
  for (int i = 0; i < n; ++i) {
    const Vec2 r = reference_face_node(topo, i);
    Vec2 q = tri ? r : Vec2(0.5 * (r + Vec2::Ones()));
    q += jitter * Vec2(u(rng), u(rng));
    const Real z = bulge * (1 - (q - Vec2(0.4, 0.4)).squaredNorm());
    f.x.row(i) << size * q(0), size * q(1), size * z;
  }
  const Mat3 rot = Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  for (int i = 0; i < n; ++i) f.x.row(i) = (rot * f.x.row(i).transpose() + Vec3(0.2, -0.1, 0.5)).transpose();
  return f;
}

}  // namespace kontakt::contact::fixtures
