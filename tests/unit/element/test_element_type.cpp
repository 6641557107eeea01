#include <gtest/gtest.h>

#include <set>

#include "core/error.hpp"

#include "element_test_util.hpp"

namespace kontakt::element {
namespace {

TEST(ElementType, TraitsAndNames) {
  for (ElementType t : test::kAllTypes) {
    const auto& tr = traits(t);
    EXPECT_EQ(tr.type, t);
    EXPECT_EQ(element_type_from_name(tr.name), t);
    EXPECT_EQ(tr.n_nodes, node_count(volume_topology(t)));
  }
  EXPECT_EQ(element_type_from_name("c3d20r"), ElementType::C3D20R);
  EXPECT_FALSE(element_type_from_name("C3D8X").has_value());
  EXPECT_FALSE(element_type_from_name("S4").has_value());
  EXPECT_EQ(traits(ElementType::C3D20).n_ip, 27);
  EXPECT_EQ(traits(ElementType::C3D15).n_faces, 5);
}

TEST(ElementType, CcxFaceNodeSets) {
  // ccx manual: hex S1 = 1-2-3-4, S3 = 1-5-6-2; tet S2 = 1-4-2; wedge S5 = 3-1-4-6.
  auto set_of = [](ElementType t, int f) {
    const auto s = face_nodes(t, f);
    return std::set<int>(s.begin(), s.end());
  };
  EXPECT_EQ(set_of(ElementType::C3D8, 1), (std::set<int>{0, 1, 2, 3}));
  EXPECT_EQ(set_of(ElementType::C3D8, 3), (std::set<int>{0, 4, 5, 1}));
  EXPECT_EQ(set_of(ElementType::C3D8, 6), (std::set<int>{3, 7, 4, 0}));
  EXPECT_EQ(set_of(ElementType::C3D4, 2), (std::set<int>{0, 3, 1}));
  EXPECT_EQ(set_of(ElementType::C3D6, 5), (std::set<int>{2, 0, 3, 5}));
  EXPECT_EQ(set_of(ElementType::C3D20, 1), (std::set<int>{0, 1, 2, 3, 8, 9, 10, 11}));
  EXPECT_EQ(set_of(ElementType::C3D10, 3), (std::set<int>{1, 3, 2, 8, 9, 5}));
  EXPECT_THROW(face_nodes(ElementType::C3D4, 5), SolverError);
}

TEST(ElementType, FacesLieOnTheirPlaneWithOutwardNormal) {
  for (ElementType t : test::kAllTypes) {
    const Topology topo = volume_topology(t);
    const MatX3 X = test::reference_coordinates(topo);
    const Vec3 centroid = X.colwise().mean().transpose();
    for (int f = 1; f <= traits(t).n_faces; ++f) {
      const auto nodes = face_nodes(t, f);
      const Topology ft = face_topology(t, f);
      ASSERT_EQ(static_cast<int>(nodes.size()), node_count(ft));
      const int nc = (ft == Topology::Tri3 || ft == Topology::Tri6) ? 3 : 4;
      const Vec3 x0 = X.row(nodes[0]), x1 = X.row(nodes[1]), x2 = X.row(nodes[nc - 1]);
      const Vec3 n = (x1 - x0).cross(x2 - x0).normalized();
      for (int a : nodes) EXPECT_NEAR(n.dot(X.row(a).transpose() - x0), 0.0, 1e-14);
      for (int a = 0; a < X.rows(); ++a) EXPECT_LE(n.dot(X.row(a).transpose() - x0), 1e-14);
      EXPECT_GT(n.dot(x0 - centroid), 0.0) << traits(t).name << " S" << f;
      for (int e = 0; e < static_cast<int>(nodes.size()) - nc; ++e) {  // midside of corner pair
        const Vec3 mid = 0.5 * (X.row(nodes[e]) + X.row(nodes[(e + 1) % nc])).transpose();
        EXPECT_TRUE(mid.isApprox(X.row(nodes[nc + e]).transpose()));
      }
    }
  }
}

}  // namespace
}  // namespace kontakt::element
