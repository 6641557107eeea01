#include "contact/point_kernel.hpp"

#include <Eigen/Geometry>

namespace kontakt::contact {

namespace {

Mat3 skew(const Vec3& v) {
  Mat3 s;
  s << 0, -v(2), v(1), v(2), 0, -v(0), -v(1), v(0), 0;
  return s;
}

/// dg/du for a foot point with master weights Nm and normal n.
PointDofVec gap_gradient(const FaceVec& Ns, const FaceVec& Nm, const Vec3& n) {
  const int ns = static_cast<int>(Ns.size()), nm = static_cast<int>(Nm.size());
  PointDofVec g(3 * (ns + nm));
  for (int a = 0; a < ns; ++a) g.segment<3>(3 * a) = Ns(a) * n;
  for (int b = 0; b < nm; ++b) g.segment<3>(3 * (ns + b)) = -Nm(b) * n;
  return g;
}

void set_inactive(int n_dofs, PointResponse& out) {
  out.active = false;
  out.pressure = {};
  out.f_int.setZero(n_dofs);
  out.K.setZero(n_dofs, n_dofs);
  out.gap_gradient.setZero(n_dofs);
}

}  // namespace

void frozen_point_response(const FaceCoords& slave_x, const FaceCoords& master_x,
                           const FrozenPoint& pt, const PressureLaw& law, Real clearance,
                           PointResponse& out) {
  const Vec3 xs = slave_x.transpose() * pt.slave_weights;
  const Vec3 xm = master_x.transpose() * pt.master_weights;
  out.gap = (xs - xm).dot(pt.normal) + pt.gap_offset;
  const int n_dofs = 3 * static_cast<int>(pt.slave_weights.size() + pt.master_weights.size());
  if (!is_active(law, -out.gap, clearance)) return set_inactive(n_dofs, out);
  out.active = true;
  out.pressure = pressure_overclosure(law, -out.gap);
  const PointDofVec dg = gap_gradient(pt.slave_weights, pt.master_weights, pt.normal);
  out.gap_gradient = dg;
  out.f_int = -pt.area * out.pressure.pressure * dg;
  out.K = pt.area * out.pressure.slope * dg * dg.transpose();
}

bool sliding_point_response(const FaceCoords& slave_x, const FaceVec& Ns,
                            const FaceGeometry& master, Vec2& xi, Real area, Real gap_offset,
                            const PressureLaw& law, Real clearance, PointResponse& out) {
  const int ns = static_cast<int>(Ns.size()), nm = static_cast<int>(master.x.rows());
  const int n_dofs = 3 * (ns + nm);
  const Vec3 xs = slave_x.transpose() * Ns;
  const ClosestPoint cp = project_onto_face(master, xs, xi);
  if (!cp.converged) {
    set_inactive(n_dofs, out);
    return false;
  }
  xi = cp.xi;
  out.gap = cp.gap + gap_offset;
  if (!is_active(law, -out.gap, clearance)) {
    set_inactive(n_dofs, out);
    return true;
  }
  out.active = true;
  out.pressure = pressure_overclosure(law, -out.gap);

  FaceShape s;
  face_shape(master.topo, xi, s);
  const Vec3 a[2] = {master.x.transpose() * s.dN.col(0), master.x.transpose() * s.dN.col(1)};
  const Vec3 x11 = master.x.transpose() * s.d2N.col(0), x22 = master.x.transpose() * s.d2N.col(1),
             x12 = master.x.transpose() * s.d2N.col(2);
  const Vec3 xab[2][2] = {{x11, x12}, {x12, x22}};
  const Vec3 r = xs - cp.x, n = cp.normal;
  const Vec3 m = a[0].cross(a[1]);
  const Real m_norm = m.norm();

  // Variation of the foot point from the orthogonality conditions r . a_alpha = 0:
  // H dxi = R du with H_ab = a_a . a_b - r . x,ab.
  Eigen::Matrix2d H;
  for (int p = 0; p < 2; ++p)
    for (int q = 0; q < 2; ++q) H(p, q) = a[p].dot(a[q]) - r.dot(xab[p][q]);
  Eigen::Matrix<Real, 2, Eigen::Dynamic, 0, 2, kMaxPointDofs> R(2, n_dofs);
  for (int p = 0; p < 2; ++p) {
    for (int c = 0; c < ns; ++c) R.block<1, 3>(p, 3 * c) = Ns(c) * a[p].transpose();
    for (int b = 0; b < nm; ++b)
      R.block<1, 3>(p, 3 * (ns + b)) = -s.N(b) * a[p].transpose() + s.dN(b, p) * r.transpose();
  }
  const Eigen::Matrix<Real, 2, Eigen::Dynamic, 0, 2, kMaxPointDofs> Dxi = H.inverse() * R;

  // Variation of the tangents, the (unnormalised) normal m = a1 x a2, and n = m / |m|.
  Eigen::Matrix<Real, 3, Eigen::Dynamic, 0, 3, kMaxPointDofs> Da[2];
  for (int p = 0; p < 2; ++p) {
    Da[p] = xab[p][0] * Dxi.row(0) + xab[p][1] * Dxi.row(1);
    for (int b = 0; b < nm; ++b) Da[p].block<3, 3>(0, 3 * (ns + b)) += s.dN(b, p) * Mat3::Identity();
  }
  const Eigen::Matrix<Real, 3, Eigen::Dynamic, 0, 3, kMaxPointDofs> Dn =
      (Mat3::Identity() - n * n.transpose()) * (skew(a[0]) * Da[1] - skew(a[1]) * Da[0]) / m_norm;

  // d2g/du2: derivative of dg/du = [Ns_a n ; -N_b(xi) n].
  PointDofMat D2g(n_dofs, n_dofs);
  for (int c = 0; c < ns; ++c) D2g.middleRows<3>(3 * c) = Ns(c) * Dn;
  for (int b = 0; b < nm; ++b)
    D2g.middleRows<3>(3 * (ns + b)) =
        -s.N(b) * Dn - n * (s.dN(b, 0) * Dxi.row(0) + s.dN(b, 1) * Dxi.row(1));

  const PointDofVec dg = gap_gradient(Ns, s.N, n);
  out.gap_gradient = dg;
  const Real p = out.pressure.pressure;
  out.f_int = -area * p * dg;
  out.K = area * (out.pressure.slope * dg * dg.transpose() - p * D2g);
  // d2g/du2 is symmetric in exact arithmetic; remove the round-off asymmetry.
  out.K = 0.5 * (out.K + out.K.transpose()).eval();
  return true;
}

Vec3 frozen_relative_position(const FaceCoords& slave_x, const FaceCoords& master_x,
                              const FrozenPoint& point) {
  return slave_x.transpose() * point.slave_weights - master_x.transpose() * point.master_weights;
}

void add_friction(const FrozenPoint& point, const Mat3& d_force_d_s, const Vec3& force,
                  const Vec3& d_force_d_normal, const PointResponse& normal, Real area,
                  PointDofVec& f_int, PointDofMat& K) {
  const int ns = static_cast<int>(point.slave_weights.size());
  const int n_dofs = 3 * (ns + static_cast<int>(point.master_weights.size()));
  auto weight = [&](int node) {
    return node < ns ? point.slave_weights(node) : -point.master_weights(node - ns);
  };
  // dF_N/du = A p' dd/du = -A p' dg/du (zero for an inactive normal response).
  const PointDofVec d_normal = -area * normal.pressure.slope * normal.gap_gradient;
  for (int a = 0; a < n_dofs / 3; ++a) {
    f_int.segment<3>(3 * a) += weight(a) * force;
    for (int b = 0; b < n_dofs / 3; ++b)
      K.block<3, 3>(3 * a, 3 * b) += weight(a) * weight(b) * d_force_d_s;
    if (normal.active) K.middleRows<3>(3 * a) += weight(a) * d_force_d_normal * d_normal.transpose();
  }
}

}  // namespace kontakt::contact
