#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "element/quadrature.hpp"
#include "element_test_util.hpp"

namespace kontakt::element {
namespace {

class SolidKernel : public ::testing::TestWithParam<ElementType> {
 protected:
  ElementType type() const { return GetParam(); }
  Topology topo() const { return volume_topology(type()); }
};

// Six rigid-body modes (3n x 6) for coordinates X.
MatX rigid_modes(const MatX3& X) {
  MatX R = MatX::Zero(3 * X.rows(), 6);
  for (Index a = 0; a < X.rows(); ++a) {
    for (int d = 0; d < 3; ++d) R(3 * a + d, d) = 1;
    const Vec3 x = X.row(a).transpose();
    for (int r = 0; r < 3; ++r) R.block<3, 1>(3 * a, 3 + r) = Vec3::Unit(r).cross(x);
  }
  return R;
}

TEST_P(SolidKernel, StiffnessSymmetricWithExactlySixZeroModes) {
  const MatX3 X = test::distorted_coordinates(topo());
  MatX K;
  linear_stiffness(type(), X, test::test_material(), VecX(), K);
  EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-10 * K.cwiseAbs().maxCoeff());
  EXPECT_LT((K * rigid_modes(X)).cwiseAbs().maxCoeff(), 1e-9 * K.cwiseAbs().maxCoeff());
  const VecX ev = Eigen::SelfAdjointEigenSolver<MatX>(K).eigenvalues();
  // Intrinsic to ccx's rules: C3D6 (2 points) has one, C3D20R (2x2x2) six spurious modes in
  // isolation (not communicable in meshes). C3D8R must have none thanks to hourglass control.
  const int expected = type() == ElementType::C3D6 ? 7 : type() == ElementType::C3D20R ? 12 : 6;
  EXPECT_LT(std::abs(ev(expected - 1)), 1e-10 * ev.maxCoeff());
  EXPECT_GT(ev(expected), 1e-6 * ev.maxCoeff()) << "spurious zero-energy mode";
}

TEST_P(SolidKernel, InternalForceAndEnergyConsistentWithStiffness) {
  const MatX3 X = test::distorted_coordinates(topo());
  const LinearElastic mat = test::test_material();
  MatX K;
  linear_stiffness(type(), X, mat, VecX(), K);
  std::mt19937 rng(5);
  std::uniform_real_distribution<Real> U(-1e-3, 1e-3);
  MatX3 u(X.rows(), 3);
  for (Index i = 0; i < u.size(); ++i) u.data()[i] = U(rng);
  IpResults r;
  recover(type(), X, mat, u, VecX(), r);
  const VecX ue = Eigen::Map<const VecX>(u.data(), u.size());
  EXPECT_LT((r.internal_force - K * ue).norm(), 1e-10 * (K * ue).norm());
  EXPECT_NEAR(r.volume, ip_volumes(type(), X).sum(), 1e-14);
  if (type() != ElementType::C3D8R) {  // hourglass energy is not a point quantity
    EXPECT_NEAR(r.energy_density.dot(ip_volumes(type(), X)), 0.5 * ue.dot(K * ue), 1e-10 * ue.dot(K * ue));
  }
}

TEST_P(SolidKernel, PressureOnEachFaceSumsToMinusPAn) {
  const MatX3 X = test::reference_coordinates(topo()) * 1.7;
  const Real p = 3.5;
  VecX total = VecX::Zero(3 * X.rows());
  for (int f = 1; f <= traits(type()).n_faces; ++f) {
    const auto nodes = face_nodes(type(), f);
    const int nc = node_count(face_topology(type(), f)) == 3 || node_count(face_topology(type(), f)) == 6 ? 3 : 4;
    Vec3 an = Vec3::Zero();  // area vector of the planar polygon
    for (int i = 0; i < nc; ++i)
      an += 0.5 * Vec3(X.row(nodes[i])).cross(Vec3(X.row(nodes[(i + 1) % nc])));
    VecX fe;
    pressure_load(type(), f, X, p, fe);
    Vec3 sum = Vec3::Zero();
    for (Index a = 0; a < X.rows(); ++a) sum += fe.segment<3>(3 * a);
    EXPECT_LT((sum + p * an).norm(), 1e-12 * p * an.norm()) << "S" << f;
    total += fe;
  }
  // A closed surface under uniform pressure carries no net force, even when distorted.
  const MatX3 Xd = test::distorted_coordinates(topo());
  Vec3 net = Vec3::Zero();
  for (int f = 1; f <= traits(type()).n_faces; ++f) {
    VecX fe;
    pressure_load(type(), f, Xd, p, fe);
    for (Index a = 0; a < Xd.rows(); ++a) net += fe.segment<3>(3 * a);
  }
  EXPECT_LT(net.norm(), 1e-12 * p);
}

TEST_P(SolidKernel, FreeThermalExpansionIsStressFree) {
  const MatX3 X = test::distorted_coordinates(topo());
  const LinearElastic mat = test::test_material();
  MatX K;
  linear_stiffness(type(), X, mat, VecX(), K);
  const VecX dT = VecX::Constant(X.rows(), 80.0);
  VecX f;
  thermal_load(type(), X, mat, dT, f);
  // Stiffness bordered with the 6 rigid-body constraints R^T u = 0.
  const MatX R = rigid_modes(X);
  const Index n = K.rows();
  MatX A = MatX::Zero(n + 6, n + 6);
  A.topLeftCorner(n, n) = K;
  A.topRightCorner(n, 6) = R;
  A.bottomLeftCorner(6, n) = R.transpose();
  VecX rhs = VecX::Zero(n + 6);
  rhs.head(n) = f;
  const VecX sol = A.fullPivLu().solve(rhs);
  const MatX3 u = Eigen::Map<const MatX3>(sol.data(), X.rows(), 3);
  IpResults r;
  recover(type(), X, mat, u, dT, r);
  const Real scale = mat.young * mat.expansion * 80.0;
  EXPECT_LT(r.stress.cwiseAbs().maxCoeff(), 1e-10 * scale);
  EXPECT_LT(r.energy_density.cwiseAbs().maxCoeff(), 1e-18 * scale);
  EXPECT_NEAR(r.strain(0, 0), mat.expansion * 80.0, 1e-10 * mat.expansion * 80.0);
}

TEST_P(SolidKernel, ConstrainedThermalEnergyIsHalfSigmaElasticStrain) {
  const MatX3 X = test::distorted_coordinates(topo());
  const LinearElastic mat = test::test_material();
  IpResults r;
  recover(type(), X, mat, MatX3::Zero(X.rows(), 3), VecX::Constant(X.rows(), 1.0), r);
  const Real s = -mat.young * mat.expansion / (1 - 2 * mat.poisson);
  for (Index k = 0; k < r.stress.rows(); ++k) {
    EXPECT_NEAR(r.stress(k, 0), s, 1e-10 * std::abs(s));
    EXPECT_NEAR(r.energy_density(k), 1.5 * s * -mat.expansion, 1e-10 * std::abs(s * mat.expansion));
  }
}

TEST_P(SolidKernel, ExtrapolationReproducesFieldsInThePointBasis) {
  const MatX& E = ip_to_node_extrapolation(type());
  const auto rule = volume_rule(type());
  ASSERT_EQ(E.rows(), traits(type()).n_nodes);
  ASSERT_EQ(E.cols(), traits(type()).n_ip);
  for (Index a = 0; a < E.rows(); ++a) EXPECT_NEAR(E.row(a).sum(), 1.0, 1e-12);
  if (rule.size() < 4) return;  // constant (or zeta-linear) extrapolation only
  const Vec3 c = type() == ElementType::C3D6 ? Vec3(0, 0, 0.7) : Vec3(0.3, -0.5, 0.7);
  VecX at_ip(static_cast<Index>(rule.size()));
  for (std::size_t k = 0; k < rule.size(); ++k) at_ip(static_cast<Index>(k)) = 2 + c.dot(rule[k].xi);
  const VecX nodal = E * at_ip;
  for (Index a = 0; a < E.rows(); ++a)
    EXPECT_NEAR(nodal(a), 2 + c.dot(reference_node(topo(), static_cast<int>(a))), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(AllTypes, SolidKernel, ::testing::ValuesIn(test::kAllTypes),
                         [](const auto& info) { return std::string(traits(info.param).name); });

// Frustum of square (hex) or triangular (wedge) section: V = h/3 (A1 + A2 + sqrt(A1 A2)).
TEST(SolidVolume, DistortedFrustumAndTetMatchClosedForm) {
  for (ElementType t : {ElementType::C3D8, ElementType::C3D20, ElementType::C3D6, ElementType::C3D15}) {
    const Topology topo = volume_topology(t);
    MatX3 X = test::reference_coordinates(topo);
    const bool hex = topo == Topology::Hex8 || topo == Topology::Hex20;
    for (Index a = 0; a < X.rows(); ++a) {
      const Real z = X(a, 2);  // -1..1 -> height 0..2, top scaled by 1/2
      const Real s = 1.0 - 0.25 * (z + 1);
      X.row(a) << s * X(a, 0), s * X(a, 1), z + 1;
    }
    const Real A1 = hex ? 4.0 : 0.5, A2 = A1 / 4;
    EXPECT_NEAR(ip_volumes(t, X).sum(), 2.0 / 3 * (A1 + A2 + std::sqrt(A1 * A2)), 1e-12) << traits(t).name;
  }
  MatX3 T(4, 3);
  T << 0.1, 0.2, 0.0, 2.0, 0.3, 0.1, 0.4, 1.5, -0.2, 0.3, 0.5, 1.8;
  const Real v = (T.row(1) - T.row(0)).cross(T.row(2) - T.row(0)).dot(T.row(3) - T.row(0)) / 6;
  EXPECT_NEAR(ip_volumes(ElementType::C3D4, T).sum(), v, 1e-14);
}

TEST(SolidPressure, QuadraticFaceHasNegativeCornerLoads) {
  const MatX3 X = test::reference_coordinates(Topology::Hex20);
  VecX f;
  pressure_load(ElementType::C3D20, 2, X, 1.0, f);  // top face, area 4, outward +z
  const auto nodes = face_nodes(ElementType::C3D20, 2);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(f(3 * nodes[i] + 2), 4.0 / 12, 1e-13);
  for (int i = 4; i < 8; ++i) EXPECT_NEAR(f(3 * nodes[i] + 2), -4.0 / 3, 1e-13);
}

// Cantilever 10 x 1 x 1 of 5 elements, tip shear: C3D8I near beam theory, C3D8 locks.
Real cantilever_tip(ElementType type) {
  test::Mesh m{type, MatX3(24, 3), {}};
  for (int i = 0; i <= 5; ++i)
    for (int c = 0; c < 4; ++c) m.nodes.row(4 * i + c) << 2.0 * i, (c == 1 || c == 2) ? 1 : 0, c >= 2 ? 1 : 0;
  for (int i = 0; i < 5; ++i) {
    const int b = 4 * i, e = 4 * (i + 1);
    m.elements.push_back({b, e, e + 1, b + 1, b + 3, e + 3, e + 2, b + 2});
  }
  const LinearElastic mat{1000.0, 0.0, 0.0};
  const MatX K = test::assemble(m, mat);
  VecX u = VecX::Zero(72), f = VecX::Zero(72);
  std::vector<bool> fixed(72, false);
  for (int d = 0; d < 12; ++d) fixed[d] = true;
  for (int c = 0; c < 4; ++c) f(3 * (20 + c) + 1) = 0.25;
  test::solve_prescribed(K, f, fixed, u);
  return u(3 * 20 + 1);
}

TEST(SolidBending, IncompatibleModesBeatPlainBrick) {
  const Real beam = 1.0 * 1000.0 / (3 * 1000.0 / 12.0);  // P L^3 / (3 E I) = 4
  const Real c3d8 = cantilever_tip(ElementType::C3D8), c3d8i = cantilever_tip(ElementType::C3D8I);
  EXPECT_GT(c3d8, 0.0);
  EXPECT_NEAR(c3d8i / beam, 1.0, 0.05);
  EXPECT_LT(c3d8 / beam, 0.9);
  EXPECT_LT(std::abs(c3d8i - beam), 0.25 * std::abs(c3d8 - beam));
}

TEST(SolidBending, IncompatibleModesAreExactInPureBendingOfAParallelogram) {
  // x = xi + 0.5 eta: the modes' gradients must map like the shape functions' (dphi J0^-T);
  // then C3D8I represents the pure bending field u_x = -k x y, u_y = k/2 (x^2 + nu (y^2 - z^2)),
  // u_z = nu k y z exactly: sigma_xx = -E k y, all else 0. (Mapping with J0^-1 instead
  // gave 68 % errors here, and 6 % differences from ccx on skewed meshes.)
  Mat3 M;
  M << 1.0, 0.5, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0;
  MatX3 X(8, 3);
  for (int a = 0; a < 8; ++a) X.row(a) = (M * reference_node(Topology::Hex8, a)).transpose();
  const Real k = 1e-3, nu = 0.3, E = 1000.0;
  MatX3 u(8, 3);
  for (int a = 0; a < 8; ++a) {
    const Real x = X(a, 0), y = X(a, 1), z = X(a, 2);
    u.row(a) << -k * x * y, 0.5 * k * (x * x + nu * (y * y - z * z)), nu * k * y * z;
  }
  IpResults r;
  recover(ElementType::C3D8I, X, LinearElastic{E, nu, 0.0}, u, VecX(), r);
  const auto rule = volume_rule(ElementType::C3D8I);
  for (int p = 0; p < 8; ++p) {
    const Vec3 x = M * rule[p].xi;
    EXPECT_NEAR(r.stress(p, 0), -E * k * x(1), 1e-12) << p;
    for (int c = 1; c < 6; ++c) EXPECT_NEAR(r.stress(p, c), 0.0, 1e-12) << p;
  }
}

TEST(Extrapolation, C3D20FitsItsOwnInterpolationOverAll27PointsLikeCcx) {
  // Point values sampled from any field of the 20-node interpolation return its nodal values.
  const MatX& E = ip_to_node_extrapolation(ElementType::C3D20);
  const auto rule = volume_rule(ElementType::C3D20);
  VecX nodal_field = VecX::LinSpaced(20, -1.0, 2.0).array().square();
  VecX at_ip(27);
  for (int k = 0; k < 27; ++k) {
    ShapeVec N;
    ShapeGrad dN;
    shape_functions(Topology::Hex20, rule[k].xi, N, dN);
    at_ip(k) = N.dot(nodal_field);
  }
  EXPECT_LT((E * at_ip - nodal_field).cwiseAbs().maxCoeff(), 1e-12);
  // ccx 2.20 tabulates this weight (corner node 1 from point 1) as 2.37499.
  EXPECT_NEAR(E(0, 0), 2.37499, 1e-5);
}

}  // namespace
}  // namespace kontakt::element
