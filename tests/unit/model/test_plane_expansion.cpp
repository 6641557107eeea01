// The expansion of 2D elements into one layer of 3D elements (model/plane_expansion), on
// hand-built models: counts, geometry (thickness, offset, wedge), the constraint equations,
// renumbered faces, load scaling, temperatures, the folding of results and the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "model/plane_expansion.hpp"

using namespace kontakt;
using element::ElementType;
using model::Planar;

namespace {

const SourceLoc kWhere{"deck.inp", 7};

/// One 2D element on the unit square (x from x0), quadratic with midside nodes 5-8; one
/// section (thickness, offset), one step.
model::Model square(ElementType type, Planar planar, bool quadratic, Real x0 = 0,
                    Real thickness = 1, Real offset = 0) {
  model::Model m;
  std::vector<Vec2> xy{{x0, 0}, {x0 + 1, 0}, {x0 + 1, 1}, {x0, 1}};
  if (quadratic) xy.insert(xy.end(), {{x0 + 0.5, 0}, {x0 + 1, 0.5}, {x0 + 0.5, 1}, {x0, 0.5}});
  m.mesh.coords = MatX3::Zero(static_cast<Index>(xy.size()), 3);
  for (std::size_t k = 0; k < xy.size(); ++k) {
    m.mesh.node_ids.push_back(static_cast<int>(k) + 1);
    m.mesh.node_index.emplace(static_cast<int>(k) + 1, static_cast<int>(k));
    m.mesh.coords.row(static_cast<Index>(k)) << xy[k].x(), xy[k].y(), 0;
  }
  model::Element el{1, type, {}, 0, planar};
  for (std::size_t k = 0; k < xy.size(); ++k) el.nodes.push_back(static_cast<int>(k));
  m.mesh.elements.push_back(el);
  m.mesh.element_index.emplace(1, 0);
  m.materials.emplace_back();
  m.sections.push_back(model::SolidSection{"E", 0, kWhere, thickness, offset, std::nullopt});
  m.steps.emplace_back();
  return m;
}

void expand(model::Model& m) { model::expand_planar_elements(m, {kWhere}); }

Vec3 x_of(const model::Model& m, int node) { return m.mesh.coords.row(node).transpose(); }

std::string error_of(model::Model m) {
  try {
    expand(m);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(PlaneExpansion, PlaneStrainQuadBecomesAC3D8LayerOfTheSectionsThickness) {
  model::Model m = square(ElementType::C3D8, Planar::PlaneStrain, false, 0, 0.25);
  expand(m);
  ASSERT_EQ(m.n_nodes(), 4 + 8);
  const model::Element& el = m.mesh.elements[0];
  EXPECT_EQ(el.type, ElementType::C3D8);
  ASSERT_EQ(el.nodes.size(), 8u);
  for (int a = 0; a < 4; ++a) {  // front face first, then the back face, over the 2D nodes
    EXPECT_TRUE(x_of(m, el.nodes[a]).isApprox(x_of(m, a) - Vec3(0, 0, 0.125)));
    EXPECT_TRUE(x_of(m, el.nodes[a + 4]).isApprox(x_of(m, a) + Vec3(0, 0, 0.125)));
  }
  // New labels follow the deck's largest one.
  EXPECT_EQ(m.mesh.node_ids[4], 5);
  EXPECT_EQ(m.mesh.node_ids.back(), 12);
  // Per node: front and back follow the node in x and y and stay at z = 0.
  EXPECT_EQ(m.equations.size(), 4u * 6u);
  for (const model::Equation& eq : m.equations) {
    EXPECT_EQ(eq.where.line, 7);
    if (eq.terms.size() == 1) {
      EXPECT_EQ(eq.terms[0].dof, 2);
    } else {
      EXPECT_EQ(eq.terms[1].coef, -1.0);
    }
  }
  ASSERT_EQ(m.planar_folds.size(), 4u);
  EXPECT_EQ(m.planar_folds[0].weights, (std::vector<Real>{0.5, 0.5}));
}

TEST(PlaneExpansion, ClockwiseNodesPutTheFrontFaceOnTop) {
  model::Model m = square(ElementType::C3D8, Planar::PlaneStrain, false);
  std::swap(m.mesh.elements[0].nodes[1], m.mesh.elements[0].nodes[3]);
  expand(m);
  EXPECT_GT(x_of(m, m.mesh.elements[0].nodes[0]).z(), 0);  // the hexahedron is not inverted
}

TEST(PlaneExpansion, OffsetMovesTheLayer) {
  model::Model m = square(ElementType::C3D8, Planar::PlaneStress, false, 0, 2, 0.5);
  expand(m);
  EXPECT_NEAR(x_of(m, m.mesh.elements[0].nodes[0]).z(), -2.0, 1e-15);
  EXPECT_NEAR(x_of(m, m.mesh.elements[0].nodes[4]).z(), 0.0, 1e-15);
}

TEST(PlaneExpansion, QuadraticPlaneStressHasMiddleCopiesAtCornersAndFreeFaces) {
  model::Model m = square(ElementType::C3D20R, Planar::PlaneStress, true);
  expand(m);
  ASSERT_EQ(m.n_nodes(), 8 + 8 * 2 + 4);
  const model::Element& el = m.mesh.elements[0];
  ASSERT_EQ(el.nodes.size(), 20u);
  for (int a = 0; a < 4; ++a) {  // nodes 17-20: the middle copies of the corners
    EXPECT_TRUE(x_of(m, el.nodes[16 + a]).isApprox(x_of(m, a)));
    EXPECT_TRUE(x_of(m, el.nodes[8 + a]).isApprox(x_of(m, 4 + a) - Vec3(0, 0, 0.5)));
  }
  // Corners: 2 + 2 in-plane ties and the middle copy's 3; midside nodes 2 + 2. No z tie
  // between front and back faces: plane stress lets the layer thin.
  EXPECT_EQ(m.equations.size(), 4u * 7u + 4u * 4u);
  for (const model::Equation& eq : m.equations)
    EXPECT_TRUE(eq.terms[0].dof != 2 || eq.terms.size() == 1u);
  EXPECT_EQ(m.planar_folds[0].weights, (std::vector<Real>{1. / 6, 4. / 6, 1. / 6}));
  EXPECT_EQ(m.planar_folds[4].weights, (std::vector<Real>{0.5, 0.5}));
}

TEST(PlaneExpansion, LinearPlaneStressTiesFrontAndBackThickening) {
  model::Model m = square(ElementType::C3D8, Planar::PlaneStress, false);
  expand(m);
  int ties = 0;
  for (const model::Equation& eq : m.equations)
    if (eq.terms.size() == 2 && eq.terms[0].dof == 2 && eq.terms[1].dof == 2 &&
        eq.terms[0].coef == 1 && eq.terms[1].coef == 1)
      ++ties;
  EXPECT_EQ(ties, 4);  // w_front + w_back = 0 per node
  EXPECT_EQ(m.equations.size(), 4u * 5u);
}

TEST(PlaneExpansion, AxisymmetricWedgeSpansTwoDegreesAndScalesLoads) {
  model::Model m = square(ElementType::C3D20, Planar::Axisymmetric, true, 2.0);
  m.steps[0].cloads.push_back(model::ConcentratedLoad{2, 0, 360.0});
  m.steps[0].cloads.push_back(model::ConcentratedLoad{2, 2, 5.0});  // z on a 2D node: ignored
  m.steps[0].boundaries.push_back(model::Boundary{0, 2, 0});        // likewise
  m.steps[0].pressures.push_back(model::PressureLoad{{0, 2}, 10.0});
  m.surfaces["S"] = model::Surface{"S", model::Surface::Kind::ElementFaces, {{0, 4}}, {}, kWhere};
  m.initial_temperatures = VecX::LinSpaced(8, 1, 8);
  expand(m);
  const model::Element& el = m.mesh.elements[0];
  const Real a = M_PI / 180;
  for (int k : {0, 1}) {  // node 1 at r = 2, node 2 at r = 3
    const Real r = x_of(m, k).x();
    EXPECT_TRUE(x_of(m, el.nodes[k]).isApprox(Vec3(r * std::cos(a), 0, -r * std::sin(a))));
    EXPECT_TRUE(x_of(m, el.nodes[4 + k]).isApprox(Vec3(r * std::cos(a), 0, r * std::sin(a))));
    EXPECT_TRUE(x_of(m, el.nodes[16 + k]).isApprox(Vec3(r, 0, 0)));
  }
  // Front copy of node 1: u_x = cos u_r, u_y = v, u_z = -sin u_r.
  const model::Equation& z = m.equations[2];
  EXPECT_EQ(z.terms[0].node, el.nodes[0]);
  EXPECT_EQ(z.terms[0].dof, 2);
  EXPECT_EQ(z.terms[1].node, 0);
  EXPECT_EQ(z.terms[1].dof, 0);
  EXPECT_NEAR(z.terms[1].coef, std::sin(a), 1e-16);
  EXPECT_NEAR(m.equations[0].terms[1].coef, -std::cos(a), 1e-16);
  ASSERT_EQ(m.steps[0].cloads.size(), 1u);
  EXPECT_NEAR(m.steps[0].cloads[0].value, 2.0, 1e-14);
  EXPECT_TRUE(m.steps[0].boundaries.empty());
  EXPECT_EQ(m.steps[0].pressures[0].face.face, 4);  // edge 2 is the side face 4
  EXPECT_EQ(m.surfaces["S"].faces[0].face, 6);
  ASSERT_EQ(m.initial_temperatures.size(), m.n_nodes());
  for (Index n = 8; n < m.n_nodes(); ++n) {  // every copy has its 2D node's temperature
    const Vec3 x = x_of(m, static_cast<int>(n));
    const Real r = std::hypot(x.x(), x.z());
    Index source = -1;
    for (Index k = 0; k < 8; ++k)
      if (std::abs(m.mesh.coords(k, 1) - x.y()) < 1e-12 &&
          std::abs(m.mesh.coords(k, 0) - r) < 1e-12)
        source = k;
    ASSERT_GE(source, 0);
    EXPECT_EQ(m.initial_temperatures[n], m.initial_temperatures[source]);
  }
}

TEST(PlaneExpansion, PlaneElementsOfAnAxisymmetricModelAreThinnedLikeTheLoads) {
  model::Model m = square(ElementType::C3D8, Planar::PlaneStress, false, 2.0, 0.9);
  model::Element axi = m.mesh.elements[0];
  axi.id = 2;
  axi.planar = Planar::Axisymmetric;
  m.mesh.elements.push_back(axi);
  model::expand_planar_elements(m, {kWhere, kWhere});
  EXPECT_NEAR(x_of(m, m.mesh.elements[0].nodes[0]).z(), -0.9 / 2 / 180, 1e-16);
  // Shared 2D nodes get their own copies per kind of element, both tied to the node; the
  // node reports the mean of both groups and the forces of all four copies (ccx).
  EXPECT_EQ(m.n_nodes(), 4 + 8 + 8);
  ASSERT_EQ(m.planar_folds.size(), 4u);
  EXPECT_EQ(m.planar_folds[0].expanded.size(), 4u);
  EXPECT_EQ(m.planar_folds[0].weights, (std::vector<Real>{0.25, 0.25, 0.25, 0.25}));
}

TEST(PlaneExpansion, FoldReportsTheWeightedMeanAndTheSumOfForces) {
  MatX3 U = MatX3::Zero(4, 3), RF = MatX3::Zero(4, 3);
  U.row(1) << 1, 2, 3;
  U.row(2) << 4, 5, 6;
  U.row(3) << 7, 8, -9;
  RF.row(1) << 1, 1, 1;
  RF.row(2) << 2, 2, 2;
  RF.row(3) << 3, 3, -3;
  model::fold_to_planar_nodes({model::PlanarFold{0, {1, 2, 3}, {1. / 6, 4. / 6, 1. / 6}}}, U, RF);
  EXPECT_TRUE(U.row(0).isApprox(Vec3(4, 5, 3).transpose()));
  EXPECT_TRUE(RF.row(0).isApprox(Vec3(6, 6, 0).transpose()));
}

TEST(PlaneExpansion, RefusalsNameTheElementLine) {
  model::Model off_plane = square(ElementType::C3D8, Planar::PlaneStrain, false);
  off_plane.mesh.coords(2, 2) = 0.1;
  EXPECT_NE(error_of(off_plane).find("deck.inp:7"), std::string::npos);
  EXPECT_NE(error_of(off_plane).find("not in the z = 0 plane"), std::string::npos);

  model::Model clockwise = square(ElementType::C3D8, Planar::Axisymmetric, false, 1.0);
  std::swap(clockwise.mesh.elements[0].nodes[1], clockwise.mesh.elements[0].nodes[3]);
  EXPECT_NE(error_of(clockwise).find("clockwise"), std::string::npos);

  model::Model negative = square(ElementType::C3D8, Planar::Axisymmetric, false, -0.5);
  EXPECT_NE(error_of(negative).find("negative radius"), std::string::npos);

  model::Model flat = square(ElementType::C3D8, Planar::PlaneStrain, false);
  flat.mesh.coords.col(1).setZero();
  EXPECT_NE(error_of(flat).find("zero area"), std::string::npos);

  model::Model mixed = square(ElementType::C3D8, Planar::PlaneStrain, false);
  mixed.mesh.elements.push_back(model::Element{2, ElementType::C3D4, {0, 1, 2, 3}, 0});
  EXPECT_NE(error_of(mixed).find("also belongs to a solid element"), std::string::npos);

  model::Model transformed = square(ElementType::C3D8, Planar::PlaneStrain, false);
  transformed.local_frames.emplace(0, Mat3::Identity());
  EXPECT_NE(error_of(transformed).find("*TRANSFORM"), std::string::npos);
}

TEST(PlaneExpansion, SolidModelsAreUntouched) {
  model::Model m = square(ElementType::C3D8, Planar::None, false);
  m.mesh.elements[0].nodes = {0, 1, 2, 3, 0, 1, 2, 3};
  expand(m);
  EXPECT_EQ(m.n_nodes(), 4);
  EXPECT_TRUE(m.equations.empty());
  EXPECT_TRUE(m.planar_folds.empty());
}
