#include <gtest/gtest.h>

#include <cmath>

#include "element/quadrature.hpp"
#include "element_test_util.hpp"

namespace kontakt::element {
namespace {

// Exact integral of x^i y^j z^k over the reference domain of a topology.
Real factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }
Real interval(int i) { return i % 2 ? 0.0 : 2.0 / (i + 1); }
Real simplex2(int i, int j) { return factorial(i) * factorial(j) / factorial(i + j + 2); }
Real simplex3(int i, int j, int k) { return factorial(i) * factorial(j) * factorial(k) / factorial(i + j + k + 3); }

Real exact(Topology t, int i, int j, int k) {
  switch (t) {
    case Topology::Hex8: case Topology::Hex20: return interval(i) * interval(j) * interval(k);
    case Topology::Tet4: case Topology::Tet10: return simplex3(i, j, k);
    case Topology::Wedge6: case Topology::Wedge15: return simplex2(i, j) * interval(k);
    case Topology::Tri3: case Topology::Tri6: return k ? 0.0 : simplex2(i, j);
    default: return k ? 0.0 : interval(i) * interval(j);
  }
}

// Checks all monomials with in-plane degree <= dp and zeta/per-direction limits.
void check_rule(std::span<const QuadraturePoint> rule, Topology t, int deg_total, int deg_dir) {
  for (int i = 0; i <= deg_dir; ++i)
    for (int j = 0; j <= deg_dir; ++j)
      for (int k = 0; k <= (dimension(t) == 3 ? deg_dir : 0); ++k) {
        if (i + j + k > deg_total) continue;
        Real s = 0;
        for (const auto& q : rule) s += q.weight * std::pow(q.xi(0), i) * std::pow(q.xi(1), j) * std::pow(q.xi(2), k);
        EXPECT_NEAR(s, exact(t, i, j, k), 1e-14) << i << j << k;
      }
}

TEST(Quadrature, BrickRulesExactForTheirDegree) {
  check_rule(volume_rule(ElementType::C3D8R), Topology::Hex8, 1, 1);
  check_rule(volume_rule(ElementType::C3D8), Topology::Hex8, 9, 3);
  check_rule(volume_rule(ElementType::C3D20R), Topology::Hex20, 9, 3);
  check_rule(volume_rule(ElementType::C3D20), Topology::Hex20, 15, 5);
}

TEST(Quadrature, SimplexAndWedgeRulesExactForTheirDegree) {
  check_rule(volume_rule(ElementType::C3D4), Topology::Tet4, 1, 1);
  check_rule(volume_rule(ElementType::C3D10), Topology::Tet10, 2, 2);
  // Wedge: triangle degree (x,y) times Gauss degree in zeta.
  for (auto [type, dtri, dz] : {std::tuple{ElementType::C3D6, 1, 3}, std::tuple{ElementType::C3D15, 2, 5}})
    for (int i = 0; i <= dtri; ++i)
      for (int j = 0; i + j <= dtri; ++j)
        for (int k = 0; k <= dz; ++k) {
          Real s = 0;
          for (const auto& q : volume_rule(type)) s += q.weight * std::pow(q.xi(0), i) * std::pow(q.xi(1), j) * std::pow(q.xi(2), k);
          EXPECT_NEAR(s, exact(Topology::Wedge6, i, j, k), 1e-14);
        }
  check_rule(face_rule(Topology::Tri6), Topology::Tri6, 5, 5);
  check_rule(face_rule(Topology::Quad8), Topology::Quad8, 10, 5);
}

TEST(Quadrature, WeightsSumToReferenceMeasureAndCountsMatchTraits) {
  for (ElementType t : test::kAllTypes) {
    Real s = 0;
    for (const auto& q : volume_rule(t)) s += q.weight;
    EXPECT_NEAR(s, reference_measure(volume_topology(t)), 1e-14);
    EXPECT_EQ(static_cast<int>(volume_rule(t).size()), traits(t).n_ip);
  }
}

TEST(Quadrature, CcxPointOrder) {
  const Real g = 1 / std::sqrt(3.0);
  const auto hex = volume_rule(ElementType::C3D8);
  EXPECT_TRUE(hex[0].xi.isApprox(Vec3(-g, -g, -g)));
  EXPECT_TRUE(hex[1].xi.isApprox(Vec3(g, -g, -g)));
  EXPECT_TRUE(hex[2].xi.isApprox(Vec3(-g, g, -g)));
  EXPECT_TRUE(hex[4].xi.isApprox(Vec3(-g, -g, g)));
  const auto h27 = volume_rule(ElementType::C3D20);
  EXPECT_TRUE(h27[1].xi.isApprox(Vec3(0, -std::sqrt(0.6), -std::sqrt(0.6))));
  EXPECT_TRUE(h27[3].xi.isApprox(Vec3(-std::sqrt(0.6), 0, -std::sqrt(0.6))));
  const auto tet = volume_rule(ElementType::C3D10);
  EXPECT_NEAR(tet[1].xi(0), 0.585410196624968, 1e-14);
  EXPECT_NEAR(tet[3].xi(2), 0.585410196624968, 1e-14);
  const auto w15 = volume_rule(ElementType::C3D15);
  EXPECT_TRUE(w15[1].xi.isApprox(Vec3(2.0 / 3, 1.0 / 6, -std::sqrt(0.6))));
  EXPECT_TRUE(w15[3].xi.isApprox(Vec3(1.0 / 6, 1.0 / 6, 0.0)));
  EXPECT_LT(volume_rule(ElementType::C3D6)[0].xi(2), 0.0);
}

}  // namespace
}  // namespace kontakt::element
