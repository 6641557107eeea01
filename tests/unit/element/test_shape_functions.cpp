#include <gtest/gtest.h>

#include "element_test_util.hpp"

namespace kontakt::element {
namespace {

constexpr Topology kTopologies[] = {Topology::Hex8,    Topology::Hex20, Topology::Tet4,  Topology::Tet10,
                                    Topology::Wedge6,  Topology::Wedge15, Topology::Tri3, Topology::Tri6,
                                    Topology::Quad4,   Topology::Quad8};

class ShapeFunctions : public ::testing::TestWithParam<Topology> {};

TEST_P(ShapeFunctions, PartitionOfUnityAndZeroDerivativeSum) {
  std::mt19937 rng(42);
  ShapeVec N;
  ShapeGrad dN;
  for (int trial = 0; trial < 20; ++trial) {
    shape_functions(GetParam(), test::random_point(GetParam(), rng), N, dN);
    EXPECT_NEAR(N.sum(), 1.0, 1e-14);
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(dN.col(d).sum(), 0.0, 1e-13);
  }
}

TEST_P(ShapeFunctions, DerivativesMatchFiniteDifferences) {
  std::mt19937 rng(7);
  const Topology topo = GetParam();
  ShapeVec N, Np, Nm;
  ShapeGrad dN, tmp;
  const Real h = 1e-6;
  for (int trial = 0; trial < 10; ++trial) {
    const Vec3 x = test::random_point(topo, rng);
    shape_functions(topo, x, N, dN);
    for (int d = 0; d < dimension(topo); ++d) {
      Vec3 xp = x, xm = x;
      xp(d) += h;
      xm(d) -= h;
      shape_functions(topo, xp, Np, tmp);
      shape_functions(topo, xm, Nm, tmp);
      for (int a = 0; a < N.size(); ++a) EXPECT_NEAR(dN(a, d), (Np(a) - Nm(a)) / (2 * h), 1e-8);
    }
  }
}

TEST_P(ShapeFunctions, KroneckerPropertyAtNodes) {
  const Topology topo = GetParam();
  ShapeVec N;
  ShapeGrad dN;
  for (int j = 0; j < node_count(topo); ++j) {
    shape_functions(topo, reference_node(topo, j), N, dN);
    for (int i = 0; i < node_count(topo); ++i) EXPECT_NEAR(N(i), i == j ? 1.0 : 0.0, 1e-14);
  }
}

TEST_P(ShapeFunctions, ReproduceLinearFieldsExactly) {
  std::mt19937 rng(3);
  const Topology topo = GetParam();
  ShapeVec N;
  ShapeGrad dN;
  const Vec3 c(0.3, -1.7, 2.2);
  for (int trial = 0; trial < 10; ++trial) {
    const Vec3 x = test::random_point(topo, rng);
    shape_functions(topo, x, N, dN);
    Real value = 0;
    Vec3 grad = Vec3::Zero();
    for (int a = 0; a < N.size(); ++a) {
      const Real na = 1.0 + c.dot(reference_node(topo, a));
      value += N(a) * na;
      grad += na * dN.row(a).transpose();
    }
    EXPECT_NEAR(value, 1.0 + c.dot(x), 1e-13);
    for (int d = 0; d < dimension(topo); ++d) EXPECT_NEAR(grad(d), c(d), 1e-12);
  }
}

INSTANTIATE_TEST_SUITE_P(AllTopologies, ShapeFunctions, ::testing::ValuesIn(kTopologies));

}  // namespace
}  // namespace kontakt::element
