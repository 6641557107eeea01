// Force and tangent of one penalty contact point (thesis equations 35-42 for the sliding form,
// 58-60 for the frozen "linear" form). The point sits on the slave side at
//   x_s = sum_a Ns_a x_a        (slave face nodes and weights; node-to-surface: one node, 1)
// and acts against one master face. Its contact potential is A * Psi(g) with the gap
// g = (x_s - x_m) . n and Psi' = -p(-g), so the internal force is f = -A p dg/du and the
// tangent K = A (p' dg/du dg/du^T - p d2g/du2): symmetric for frictionless contact.
// Dof order: slave nodes (x, y, z each), then master nodes.
#pragma once

#include "contact/closest_point.hpp"
#include "contact/pressure_overclosure.hpp"

namespace kontakt::contact {

inline constexpr int kMaxPointDofs = 3 * 2 * kMaxFaceNodes;
using PointDofVec = Eigen::Matrix<Real, Eigen::Dynamic, 1, 0, kMaxPointDofs, 1>;
using PointDofMat = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxPointDofs,
                                  kMaxPointDofs>;

struct PointResponse {
  Real gap = 0;             ///< effective gap (after the overlap offset)
  bool active = false;
  PressureResponse pressure;
  PointDofVec f_int;        ///< internal force (slave dofs, then master dofs); zero if inactive
  PointDofMat K;            ///< tangent; zero if inactive
  PointDofVec gap_gradient;  ///< dg/du where active (the normal force's variation: friction)
};

/// What the linear variants freeze at the start of an increment (thesis section 4.4): the
/// master foot point's shape-function weights, the normal and the area.
struct FrozenPoint {
  FaceVec slave_weights;
  FaceVec master_weights;
  Vec3 normal = Vec3::UnitZ();
  Real area = 0;
  Real gap_offset = 0;      ///< added to the geometric gap (initial-overlap ramp)
};

/// The relative position of the slave point and its frozen foot, x_s - x_m, in the current
/// configuration (its change since the increment's start is friction's relative displacement).
Vec3 frozen_relative_position(const FaceCoords& slave_x, const FaceCoords& master_x,
                              const FrozenPoint& point);

/// Friction's part of a point on the frozen pairing: f_int += B^T F_T and
/// K += B^T (dF_T/ds B - dF_T/dF_N A p' dg^T) with B = [Ns I, -Nm I] (a = B u); `normal` is the
/// point's normal response on the same faces (its gap gradient couples the slip force).
void add_friction(const FrozenPoint& point, const Mat3& d_force_d_s, const Vec3& force,
                  const Vec3& d_force_d_normal, const PointResponse& normal, Real area,
                  PointDofVec& f_int, PointDofMat& K);

/// Frozen (linear) point: g is linear in the displacements, K = A p' dg dg^T.
void frozen_point_response(const FaceCoords& slave_x, const FaceCoords& master_x,
                           const FrozenPoint& point, const PressureLaw& law, Real clearance,
                           PointResponse& out);

/// Sliding (nonlinear) point: the foot point on `master` is re-projected from `xi_master`
/// (updated in place) and the tangent carries the variation of the projection and of the
/// normal, including the master face's curvature. Returns false when the projection failed.
bool sliding_point_response(const FaceCoords& slave_x, const FaceVec& slave_weights,
                            const FaceGeometry& master, Vec2& xi_master, Real area,
                            Real gap_offset, const PressureLaw& law, Real clearance,
                            PointResponse& out);

}  // namespace kontakt::contact
