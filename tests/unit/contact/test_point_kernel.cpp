// Finite-difference and Taylor checks of the contact point kernels: frozen (linear variants)
// and sliding (nonlinear variants, node-to-surface), open, closed and near-edge, on every face
// topology, with curved and distorted master faces.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/point_kernel.hpp"
#include "contact_test_util.hpp"

using namespace kontakt;
using namespace kontakt::contact;
using element::Topology;

namespace {

struct PointCase {
  FaceCoords slave_x;
  FaceVec slave_w;
  FaceGeometry master;
};

/// A slave face (same topology as the master, shifted above it) and a point at `xi_s`; the
/// slave point is moved to overclosure `overclosure` along the master normal under it.
PointCase make_setup(Topology slave_topo, Topology master_topo, const Vec2& xi_s, const Vec2& xi_m,
                 Real overclosure, std::mt19937& rng) {
  PointCase s;
  s.master = fixtures::curved_face(master_topo, 1.0, 0.2, 0.05, rng);
  const FaceGeometry slave = fixtures::curved_face(slave_topo, 0.7, -0.1, 0.05, rng);
  FaceShape sh;
  face_shape(slave_topo, xi_s, sh);
  s.slave_w = sh.N;
  const SurfacePoint target = surface_point(s.master, xi_m);
  const Vec3 xs = slave.x.transpose() * sh.N;
  const Vec3 shift = target.x - overclosure * target.normal - xs;
  s.slave_x = slave.x;
  for (int i = 0; i < s.slave_x.rows(); ++i) s.slave_x.row(i) += shift.transpose();
  return s;
}

/// Displaces every node of `s` by `du` (slave dofs first).
PointCase displaced(const PointCase& s, const PointDofVec& du) {
  PointCase d = s;
  const int ns = static_cast<int>(s.slave_x.rows());
  for (int i = 0; i < ns; ++i) d.slave_x.row(i) += du.segment<3>(3 * i).transpose();
  for (int i = 0; i < d.master.x.rows(); ++i) d.master.x.row(i) += du.segment<3>(3 * (ns + i)).transpose();
  return d;
}

PointResponse sliding(const PointCase& s, const PressureLaw& law, Vec2 xi_m) {
  PointResponse r;
  EXPECT_TRUE(sliding_point_response(s.slave_x, s.slave_w, s.master, xi_m, 0.3, 0, law, 1e-3, r));
  return r;
}

PressureLaw quasi_bilinear() {
  model::SurfaceBehavior b;
  b.stiffness = 1e4;
  b.tension_limit = 2;
  return make_pressure_law(b, false);
}

/// Central differences of f_int against K, column by column.
template <class Eval>
void expect_tangent(const PointCase& s, Eval eval, Real tol) {
  const PointResponse r0 = eval(s);
  const int n = static_cast<int>(r0.f_int.size());
  const Real h = 1e-7;
  const Real scale = r0.K.cwiseAbs().maxCoeff() + 1e-30;
  for (int j = 0; j < n; ++j) {
    PointDofVec e = PointDofVec::Zero(n);
    e(j) = h;
    const PointResponse rp = eval(displaced(s, e)), rm = eval(displaced(s, -e));
    const PointDofVec fd = (rp.f_int - rm.f_int) / (2 * h);
    EXPECT_LT((fd - r0.K.col(j)).cwiseAbs().maxCoeff(), tol * scale) << "column " << j;
  }
  EXPECT_LT((r0.K - r0.K.transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale);
}

}  // namespace

TEST(PointKernel, SlidingTangentMatchesFiniteDifferencesOnEveryTopology) {
  std::mt19937 rng(7);
  const PressureLaw law = quasi_bilinear();
  for (Topology ms : fixtures::kFaceTopologies) {
    for (Topology ss : {Topology::Tri3, Topology::Quad8}) {
      const bool tri = is_triangle(ms);
      for (const Vec2& xi_m : {tri ? Vec2(0.3, 0.25) : Vec2(0.2, -0.35),
                              tri ? Vec2(0.02, 0.5) : Vec2(0.97, 0.1)}) {  // interior, near edge
        for (Real overclosure : {2e-3, -2e-4}) {  // closed, slightly open (quasi-bilinear)
          const PointCase s = make_setup(ss, ms, Vec2(0.3, 0.2), xi_m, overclosure, rng);
          SCOPED_TRACE(testing::Message() << "master " << int(ms) << " slave " << int(ss)
                                          << " overclosure " << overclosure);
          expect_tangent(s, [&](const PointCase& x) { return sliding(x, law, xi_m); }, 2e-5);
        }
      }
    }
  }
}

TEST(PointKernel, SlidingIsExactDerivativeTaylorRateTwo) {
  std::mt19937 rng(11);
  const PressureLaw law = quasi_bilinear();
  const PointCase s = make_setup(Topology::Quad8, Topology::Quad8, Vec2(0.1, 0.2), Vec2(0.3, -0.2),
                             3e-3, rng);
  const Vec2 xi0(0.3, -0.2);
  const PointResponse r0 = sliding(s, law, xi0);
  std::uniform_real_distribution<Real> u(-1, 1);
  PointDofVec dir(r0.f_int.size());
  for (int i = 0; i < dir.size(); ++i) dir(i) = u(rng);
  Real prev = 0;
  for (int k = 0; k < 4; ++k) {
    const Real h = 1e-5 * std::pow(0.5, k);
    const PointResponse r = sliding(displaced(s, h * dir), law, xi0);
    const Real err = (r.f_int - r0.f_int - h * r0.K * dir).norm();
    if (k > 0) {
      EXPECT_NEAR(std::log2(prev / err), 2.0, 0.15) << "h = " << h;
    }
    prev = err;
  }
}

TEST(PointKernel, FrozenIsLinearGapAndExactTangent) {
  std::mt19937 rng(3);
  model::SurfaceBehavior b;
  b.stiffness = 1e5;
  const PressureLaw law = make_pressure_law(b, true);
  for (Topology ms : fixtures::kFaceTopologies) {
    const PointCase s = make_setup(Topology::Quad4, ms, Vec2(0.1, -0.4), face_centre(ms), 1e-3, rng);
    FrozenPoint pt;
    pt.slave_weights = s.slave_w;
    FaceShape sh;
    face_shape(ms, face_centre(ms), sh);
    pt.master_weights = sh.N;
    pt.normal = surface_point(s.master, face_centre(ms)).normal;
    pt.area = 0.25;
    auto eval = [&](const PointCase& x) {
      PointResponse r;
      frozen_point_response(x.slave_x, x.master.x, pt, law, 0, r);
      return r;
    };
    const PointResponse r = eval(s);
    EXPECT_TRUE(r.active);
    EXPECT_NEAR(r.gap, -1e-3, 1e-12);
    EXPECT_NEAR(r.pressure.pressure, 100, 1e-6);
    // Force balance: slave and master forces cancel, slave force = A p n.
    const int ns = static_cast<int>(s.slave_w.size());
    Vec3 fs = Vec3::Zero(), fm = Vec3::Zero();
    for (int a = 0; a < ns; ++a) fs += r.f_int.segment<3>(3 * a);
    for (int b = 0; b < sh.N.size(); ++b) fm += r.f_int.segment<3>(3 * (ns + b));
    EXPECT_LT((fs + fm).norm(), 1e-10);
    EXPECT_LT((fs + 0.25 * 100 * pt.normal).norm(), 1e-9);
    expect_tangent(s, eval, 1e-6);
    // Open point: no force, no stiffness.
    pt.gap_offset = 2e-3;
    EXPECT_FALSE(eval(s).active);
    EXPECT_EQ(eval(s).K.cwiseAbs().maxCoeff(), 0);
  }
}

TEST(PointKernel, NodeToSurfaceSlaveIsOneNode) {
  std::mt19937 rng(5);
  const PressureLaw law = quasi_bilinear();
  PointCase s = make_setup(Topology::Tri3, Topology::Quad4, Vec2(0, 0), Vec2(0.1, 0.2), 1e-3, rng);
  s.slave_x = s.slave_x.topRows(1).eval();  // node 1 of the slave face at xi_s = (0,0)
  s.slave_w = FaceVec::Ones(1);
  const Vec2 xi(0.1, 0.2);
  const PointResponse r = sliding(s, law, xi);
  EXPECT_EQ(r.f_int.size(), 3 * (1 + 4));
  EXPECT_NEAR(r.gap, -1e-3, 1e-10);
  expect_tangent(s, [&](const PointCase& x) { return sliding(x, law, xi); }, 2e-5);
}
