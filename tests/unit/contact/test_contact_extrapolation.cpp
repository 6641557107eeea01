// Extrapolation of contact values to the nodes (thesis §4.3.2-4.3.3, table 2): the method per
// point count, exactness of each fit for the fields it can represent, clamping, the midside
// rule, averaging over faces, the outside-master rule and the frame-level assembly.
#include <gtest/gtest.h>

#include <random>

#include "contact/contact_extrapolation.hpp"
#include "element/element_type.hpp"

using namespace kontakt;
using namespace kontakt::contact;
using element::Topology;
using Method = ExtrapolationMethod;

namespace {

/// Random points strictly inside the reference face (quad [-1,1]^2, triangle xi, eta > 0).
std::vector<Vec2> random_points(Topology face, int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(0.05, 0.95);
  std::vector<Vec2> xi;
  while (static_cast<int>(xi.size()) < n) {
    const Real a = u(rng), b = u(rng);
    if (face == Topology::Tri3 || face == Topology::Tri6) {
      if (a + b < 0.95) xi.emplace_back(a, b);
    } else {
      xi.emplace_back(2 * a - 1, 2 * b - 1);
    }
  }
  return xi;
}

template <class F>
MatX sample(const std::vector<Vec2>& xi, F field) {
  MatX v(static_cast<Index>(xi.size()), 1);
  for (std::size_t j = 0; j < xi.size(); ++j) v(static_cast<Index>(j), 0) = field(xi[j]);
  return v;
}

Vec2 corner(Topology face, int k) {
  const Vec3 c = element::reference_node(face, k);
  return {c(0), c(1)};
}

int corners(Topology face) { return face == Topology::Tri3 || face == Topology::Tri6 ? 3 : 4; }

}  // namespace

TEST(ContactExtrapolation, MethodFollowsTable2) {
  for (Topology quad : {Topology::Quad4, Topology::Quad8}) {
    EXPECT_EQ(extrapolation_method(quad, 1), Method::Constant);
    EXPECT_EQ(extrapolation_method(quad, 2), Method::Constant);
    EXPECT_EQ(extrapolation_method(quad, 3), Method::Plane);
    EXPECT_EQ(extrapolation_method(quad, 4), Method::ShapeFunctions);
    EXPECT_EQ(extrapolation_method(quad, 5), Method::LeastSquares);
    EXPECT_EQ(extrapolation_method(quad, 28), Method::LeastSquares);
  }
  for (Topology tri : {Topology::Tri3, Topology::Tri6}) {
    EXPECT_EQ(extrapolation_method(tri, 2), Method::Constant);
    EXPECT_EQ(extrapolation_method(tri, 3), Method::ShapeFunctions);
    EXPECT_EQ(extrapolation_method(tri, 4), Method::LeastSquares);
    EXPECT_EQ(extrapolation_method(tri, 7), Method::LeastSquares);
  }
}

TEST(ContactExtrapolation, EachFitReproducesTheFieldsItSpans) {
  const auto constant = [](const Vec2&) { return 2.5; };
  const auto linear = [](const Vec2& x) { return 1.0 - 2.0 * x(0) + 0.5 * x(1); };
  const auto bilinear = [](const Vec2& x) {
    return 1.0 - 2.0 * x(0) + 0.5 * x(1) + 3 * x(0) * x(1);
  };
  for (Topology face : {Topology::Tri3, Topology::Tri6, Topology::Quad4, Topology::Quad8}) {
    const bool quad = corners(face) == 4;
    for (int n : {1, 2, 3, 4, 5, 12, 28}) {
      const auto xi = random_points(face, n, 17u + static_cast<unsigned>(n));
      const Method method = extrapolation_method(face, n);
      auto check = [&](auto field, const char* what) {
        const MatX at_corners = fit_corner_values(face, method, xi, sample(xi, field));
        for (int k = 0; k < corners(face); ++k)
          EXPECT_NEAR(at_corners(k, 0), field(corner(face, k)), 1e-11)
              << what << " on " << static_cast<int>(face) << ", " << n << " points, corner " << k;
      };
      check(constant, "constant");
      if (n >= 3) check(linear, "linear");
      if (quad && n >= 4) check(bilinear, "bilinear");
    }
  }
}

TEST(ContactExtrapolation, LeastSquaresMinimisesTheResidual) {
  const auto xi = random_points(Topology::Quad4, 9, 5u);
  MatX v(9, 1);
  v << 1, 4, -2, 3, 0.5, 7, 2, -1, 5;
  const MatX fit = fit_corner_values(Topology::Quad4, Method::LeastSquares, xi, v);
  // The residual of the fitted corner values is orthogonal to every shape function.
  for (int k = 0; k < 4; ++k) {
    Real dot = 0;
    for (int j = 0; j < 9; ++j) {
      element::ShapeVec N;
      element::ShapeGrad dN;
      element::shape_functions(Topology::Quad4, Vec3(xi[j](0), xi[j](1), 0), N, dN);
      dot += N(k) * (v(j, 0) - N.dot(fit.col(0)));
    }
    EXPECT_NEAR(dot, 0.0, 1e-12) << k;
  }
}

TEST(ContactExtrapolation, UndeterminedFitsFallBackToSimplerOnes) {
  // Points on the axes: xi * eta vanishes at all of them, so no bilinear fit; the plane is exact.
  const std::vector<Vec2> axes = {{0.5, 0}, {-0.5, 0}, {0, 0.5}, {0, -0.5}, {0.2, 0}};
  const auto linear = [](const Vec2& x) { return 3.0 + x(0) - 2 * x(1); };
  const MatX plane = fit_corner_values(Topology::Quad4, Method::LeastSquares, axes,
                                       sample(axes, linear));
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(plane(k, 0), linear(corner(Topology::Quad4, k)), 1e-12);
  // Points on one line determine no plane: the mean.
  const std::vector<Vec2> line = {{-0.5, 0.1}, {0, 0.1}, {0.5, 0.1}};
  MatX v(3, 1);
  v << 1, 2, 6;
  const MatX mean = fit_corner_values(Topology::Quad4, Method::Plane, line, v);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(mean(k, 0), 3.0, 1e-12);
  const MatX tri_mean = fit_corner_values(Topology::Tri3, Method::ShapeFunctions,
                                          {{0.1, 0.1}, {0.2, 0.2}, {0.3, 0.3}}, v);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(tri_mean(k, 0), 3.0, 1e-12);
}

TEST(ContactExtrapolation, CornersAreClampedToThePointsRange) {
  // Three points close to corner 1 with a steep gradient: the plane overshoots at corner 3.
  const std::vector<Vec2> xi = {{-0.9, -0.9}, {-0.7, -0.9}, {-0.9, -0.7}};
  const auto steep = [](const Vec2& x) { return 10 * (x(0) + x(1)); };
  const MatX values = sample(xi, steep);  // -18, -16, -16
  const MatX nodal = extrapolate_face(Topology::Quad4, xi, values);
  EXPECT_DOUBLE_EQ(nodal(0, 0), -18.0);  // -20 clamped to the minimum
  EXPECT_DOUBLE_EQ(nodal(1, 0), -16.0);  // 0 clamped to the maximum
  EXPECT_DOUBLE_EQ(nodal(2, 0), -16.0);
  EXPECT_DOUBLE_EQ(nodal(3, 0), -16.0);
  // Each field is clamped to its own range.
  MatX two(3, 2);
  two.col(0) = values.col(0);
  two.col(1) << 1, 1, 1;
  const MatX both = extrapolate_face(Topology::Quad4, xi, two);
  EXPECT_EQ(both.col(0), nodal.col(0));
  EXPECT_TRUE(both.col(1).isApproxToConstant(1.0));
}

TEST(ContactExtrapolation, MidsideNodesTakeTheMeanOfTheirCorners) {
  const auto linear = [](const Vec2& x) { return 1.0 + x(0) + 2 * x(1); };
  for (Topology face : {Topology::Tri6, Topology::Quad8}) {
    // Points on the corners themselves, so clamping leaves the corner values exact.
    std::vector<Vec2> xi;
    for (int k = 0; k < corners(face); ++k) xi.push_back(corner(face, k));
    xi.push_back(corner(face, 0) * 0.5 + corner(face, 1) * 0.5);
    const MatX nodal = extrapolate_face(face, xi, sample(xi, linear));
    ASSERT_EQ(nodal.rows(), element::node_count(face));
    const int c = corners(face);
    for (int k = 0; k < c; ++k) EXPECT_NEAR(nodal(k, 0), linear(corner(face, k)), 1e-12);
    for (int e = 0; e < c; ++e) {
      EXPECT_NEAR(nodal(c + e, 0), 0.5 * (nodal(e, 0) + nodal((e + 1) % c, 0)), 1e-15);
      // ... which for a linear field is its value at the midside node.
      EXPECT_NEAR(nodal(c + e, 0), linear(corner(face, c + e)), 1e-12);
    }
  }
}

TEST(ContactExtrapolation, NodesAverageOverFacesAndOutsideNodesAreSkipped) {
  // Two quads sharing nodes 1 and 2; node 5 belongs to no face.
  std::vector<FaceNodeValues> faces(2);
  faces[0].nodes = {0, 1, 2, 3};
  faces[0].values = (MatX(4, 2) << 1, 10, 2, 20, 3, 30, 4, 40).finished();
  faces[1].nodes = {1, 4, 6, 2};
  faces[1].values = (MatX(4, 2) << 4, 40, 5, 50, 6, 60, 7, 70).finished();
  const NodalAverage all = average_over_faces(7, 2, faces, {});
  EXPECT_EQ(all.n_faces, (std::vector<int>{1, 2, 2, 1, 1, 0, 1}));
  EXPECT_DOUBLE_EQ(all.values(1, 0), 3.0);   // (2 + 4) / 2
  EXPECT_DOUBLE_EQ(all.values(2, 1), 50.0);  // (30 + 70) / 2
  EXPECT_DOUBLE_EQ(all.values(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(all.values(5, 0), 0.0);
  std::vector<bool> outside(7, false);
  outside[1] = outside[4] = true;
  const NodalAverage skipped = average_over_faces(7, 2, faces, outside);
  EXPECT_EQ(skipped.n_faces[1], 0);
  EXPECT_EQ(skipped.n_faces[4], 0);
  EXPECT_DOUBLE_EQ(skipped.values(1, 0), 0.0);
  EXPECT_DOUBLE_EQ(skipped.values(2, 0), 5.0);  // unaffected
}

namespace {

/// One C3D8 unit cube, node labels 1..8.
model::Model unit_cube() {
  model::Model m;
  const Real x[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                        {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  m.mesh.coords.resize(8, 3);
  for (int i = 0; i < 8; ++i) {
    m.mesh.node_ids.push_back(i + 1);
    m.mesh.node_index[i + 1] = i;
    m.mesh.coords.row(i) << x[i][0], x[i][1], x[i][2];
  }
  m.mesh.elements.push_back({1, element::ElementType::C3D8, {0, 1, 2, 3, 4, 5, 6, 7}, 0});
  m.mesh.element_index[1] = 0;
  return m;
}

output::ContactPointRecord face_point(Vec2 xi, Real pressure, bool active, bool sticking) {
  output::ContactPointRecord p;
  p.slave_element = 0;
  p.slave_face = 2;
  p.xi = xi;
  p.active = active;
  p.sticking = sticking;
  p.pressure = pressure;
  p.clearance = -pressure * 1e-7;
  p.shear = Vec2(0.1 * pressure, -0.1 * pressure);
  p.slip = Vec2(1e-6, 2e-6);
  return p;
}

}  // namespace

TEST(ContactExtrapolation, FrameValuesFromFacePointsAndSlaveNodes) {
  const model::Model m = unit_cube();
  // Face S2 of a C3D8: four active points, a constant state, and one inactive point whose
  // values must not enter.
  std::vector<output::ContactPointRecord> points;
  for (Vec2 xi : {Vec2(-0.5, -0.5), Vec2(0.5, -0.5), Vec2(0.5, 0.5), Vec2(-0.5, 0.5)})
    points.push_back(face_point(xi, 100, true, true));
  points.push_back(face_point(Vec2(0, 0), 1e9, false, false));
  const auto nodal = contact_nodal_values(m, points, {});
  const auto face = element::face_nodes(element::ElementType::C3D8, 2);
  for (int n = 0; n < 8; ++n) {
    const bool on_face = std::find(face.begin(), face.end(), n) != face.end();
    EXPECT_DOUBLE_EQ(nodal.CPRESS(n), on_face ? 100 : 0) << n;
    EXPECT_DOUBLE_EQ(nodal.COPEN(n), on_face ? -1e-5 : 0) << n;
    EXPECT_DOUBLE_EQ(nodal.CSHEAR(n, 1), on_face ? -10 : 0) << n;
    EXPECT_DOUBLE_EQ(nodal.CSLIP(n, 0), on_face ? 1e-6 : 0) << n;
    EXPECT_EQ(nodal.status(n), on_face ? 1 : 0) << n;  // all sticking
  }
  // Sliding points give status 2; a node flagged outside the master surface gets nothing.
  for (auto& p : points) p.sticking = false;
  std::vector<bool> outside(8, false);
  outside[static_cast<std::size_t>(face[0])] = true;
  const auto sliding = contact_nodal_values(m, points, outside);
  EXPECT_EQ(sliding.status(face[1]), 2);
  EXPECT_EQ(sliding.status(face[0]), 0);
  EXPECT_DOUBLE_EQ(sliding.CPRESS(face[0]), 0);
  // Node-to-surface: the slave node's own values.
  output::ContactPointRecord node;
  node.slave_node = 6;
  node.active = true;
  node.pressure = 42;
  node.clearance = 1e-6;  // slightly open, still a contact element (ccx node-to-face)
  const auto nts = contact_nodal_values(m, {node}, {});
  EXPECT_DOUBLE_EQ(nts.CPRESS(6), 42);
  EXPECT_DOUBLE_EQ(nts.COPEN(6), 1e-6);
  EXPECT_EQ(nts.status(6), 2);
  EXPECT_DOUBLE_EQ(nts.CPRESS.sum(), 42);
}
