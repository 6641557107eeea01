// Constant-strain patch test for every element type on distorted 2x2x2 patches.
#include <gtest/gtest.h>

#include <map>

#include "element/quadrature.hpp"
#include "element_test_util.hpp"

namespace kontakt::element {
namespace {

using Conn = std::vector<int>;

// Linear patch over [0,2]^3 made of hexes, wedges or tets.
test::Mesh linear_patch(Topology corner_topo) {
  test::Mesh m{ElementType::C3D8, MatX3(27, 3), {}};
  auto id = [](int i, int j, int k) { return i + 3 * j + 9 * k; };
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) m.nodes.row(id(i, j, k)) << i, j, k;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const Conn h = {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                        id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        if (corner_topo == Topology::Hex8) m.elements.push_back(h);
        if (corner_topo == Topology::Wedge6) {
          m.elements.push_back({h[0], h[1], h[2], h[4], h[5], h[6]});
          m.elements.push_back({h[0], h[2], h[3], h[4], h[6], h[7]});
        }
        if (corner_topo == Topology::Tet4) {
          const int ring[] = {1, 2, 3, 7, 4, 5, 1};
          for (int t = 0; t < 6; ++t) {
            Conn tet = {h[0], h[ring[t]], h[ring[t + 1]], h[6]};
            const Vec3 x0 = m.nodes.row(tet[0]);
            const Real vol = (m.nodes.row(tet[1]).transpose() - x0)
                                 .cross(m.nodes.row(tet[2]).transpose() - x0)
                                 .dot(m.nodes.row(tet[3]).transpose() - x0);
            if (vol < 0) std::swap(tet[1], tet[2]);
            m.elements.push_back(tet);
          }
        }
      }
  return m;
}

// Appends straight-edge midside nodes (quadratic types) using the type's corner edges.
void add_midsides(test::Mesh& m, Topology topo) {
  std::map<std::pair<int, int>, int> edge_node;
  std::vector<Vec3> extra;
  const int nc = topo == Topology::Hex20 ? 8 : (topo == Topology::Wedge15 ? 6 : 4);
  for (auto& conn : m.elements) {
    for (int e = nc; e < node_count(topo); ++e) {
      // Corners adjacent to midside e: the two corners whose natural midpoint is node e.
      const Vec3 p = reference_node(topo, e);
      int a = -1, b = -1;
      for (int i = 0; i < nc && b < 0; ++i)
        for (int j = i + 1; j < nc; ++j)
          if ((0.5 * (reference_node(topo, i) + reference_node(topo, j)) - p).norm() < 1e-12) { a = i; b = j; break; }
      const auto key = std::minmax(conn[a], conn[b]);
      auto [it, inserted] = edge_node.try_emplace({key.first, key.second}, static_cast<int>(m.nodes.rows() + extra.size()));
      if (inserted) extra.push_back(0.5 * (m.nodes.row(conn[a]) + m.nodes.row(conn[b])).transpose());
      conn.push_back(it->second);
    }
  }
  const Index n0 = m.nodes.rows();
  m.nodes.conservativeResize(n0 + static_cast<Index>(extra.size()), 3);
  for (std::size_t i = 0; i < extra.size(); ++i) m.nodes.row(n0 + static_cast<Index>(i)) = extra[i].transpose();
}

bool on_boundary(const Vec3& x) { return (x.array() < 1e-12).any() || (x.array() > 2 - 1e-12).any(); }

test::Mesh patch(ElementType type) {
  const Topology topo = volume_topology(type);
  const Topology corner = topo == Topology::Hex20 ? Topology::Hex8
                        : topo == Topology::Tet10 ? Topology::Tet4
                        : topo == Topology::Wedge15 ? Topology::Wedge6 : topo;
  test::Mesh m = linear_patch(corner);
  m.type = type;
  // Move the interior vertex; midside nodes then sit at edge midpoints (straight edges: the
  // reduced rules of C3D10/C3D15/C3D20R integrate the patch exactly only for straight edges).
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> U(-0.15, 0.15);
  for (Index a = 0; a < m.nodes.rows(); ++a)
    if (!on_boundary(m.nodes.row(a).transpose()))
      m.nodes.row(a) += Eigen::RowVector3d(U(rng), U(rng), U(rng));
  if (corner != topo) add_midsides(m, topo);
  return m;
}

class PatchTest : public ::testing::TestWithParam<ElementType> {};

TEST_P(PatchTest, ConstantStrainReproduced) {
  const test::Mesh m = patch(GetParam());
  const LinearElastic mat = test::test_material();
  Mat3 A;
  A << 1.0, 0.4, -0.3, 0.2, -0.7, 0.5, 0.6, -0.1, 0.9;
  A *= 1e-3;
  const Vec3 c(1e-3, -2e-3, 5e-4);
  const Index n = m.nodes.rows();
  VecX exact(3 * n), u = VecX::Zero(3 * n);
  std::vector<bool> fixed(3 * n, false);
  int interior = 0;
  for (Index a = 0; a < n; ++a) {
    exact.segment<3>(3 * a) = A * m.nodes.row(a).transpose() + c;
    if (on_boundary(m.nodes.row(a).transpose())) {
      for (int d = 0; d < 3; ++d) fixed[3 * a + d] = true;
      u.segment<3>(3 * a) = exact.segment<3>(3 * a);
    } else {
      ++interior;
    }
  }
  ASSERT_GT(interior, 0);
  test::solve_prescribed(test::assemble(m, mat), VecX::Zero(3 * n), fixed, u);
  EXPECT_LT((u - exact).cwiseAbs().maxCoeff(), 1e-10 * exact.cwiseAbs().maxCoeff());

  Vec6 eps;  // engineering
  eps << A(0, 0), A(1, 1), A(2, 2), A(0, 1) + A(1, 0), A(0, 2) + A(2, 0), A(1, 2) + A(2, 1);
  const Vec6 sigma = test::elasticity_matrix_for_test(mat) * eps;
  IpResults r;
  for (const auto& conn : m.elements) {
    MatX3 ue(static_cast<Index>(conn.size()), 3);
    for (std::size_t i = 0; i < conn.size(); ++i) ue.row(static_cast<Index>(i)) = u.segment<3>(3 * conn[i]).transpose();
    recover(m.type, test::element_coordinates(m, conn), mat, ue, VecX(), r);
    for (Index k = 0; k < r.stress.rows(); ++k)
      EXPECT_LT((r.stress.row(k).transpose() - sigma).norm(), 1e-10 * sigma.norm()) << "point " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(AllTypes, PatchTest, ::testing::ValuesIn(test::kAllTypes),
                         [](const auto& info) { return std::string(traits(info.param).name); });

}  // namespace
}  // namespace kontakt::element
