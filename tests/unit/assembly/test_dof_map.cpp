#include <gtest/gtest.h>

#include <cmath>

#include "assembly/dof_map.hpp"
#include "test_model_fixture.hpp"

using namespace kontakt;

namespace {
model::Equation equation(std::vector<model::EquationTerm> terms) {
  model::Equation eq;
  eq.terms = std::move(terms);
  eq.where = {"deck.inp", 42};
  return eq;
}
}  // namespace

TEST(DofMap, ClassifiesFreePrescribedAndInactiveDofs) {
  model::Model m = fixtures::brick_row(1);
  // An extra node no element uses: its dofs are inactive, not unknowns.
  m.mesh.coords.conservativeResize(9, 3);
  m.mesh.coords.row(8) << 5, 5, 5;
  m.mesh.node_ids.push_back(99);
  const assembly::DofMap dofs(m, {{0, 0, 0.5}, {0, 1, 0}, {3, 2, 0}});
  EXPECT_EQ(dofs.n_dofs(), 27);
  EXPECT_EQ(dofs.n_prescribed(), 3);
  EXPECT_EQ(dofs.n_equations(), 24 - 3);
  EXPECT_TRUE(dofs.is_prescribed(0));
  EXPECT_FALSE(dofs.is_free(0));
  EXPECT_TRUE(dofs.is_free(2));
  EXPECT_EQ(dofs.terms_end(24) - dofs.terms_begin(24), 0);  // inactive
  VecX x = VecX::LinSpaced(dofs.n_equations(), 1, dofs.n_equations());
  VecX g(3);
  g << 0.5, 0, 0;
  const VecX u = dofs.expand(x, g);
  EXPECT_DOUBLE_EQ(u[0], 0.5);
  EXPECT_DOUBLE_EQ(u[2], x[0]);
  EXPECT_DOUBLE_EQ(u[26], 0);
  EXPECT_EQ(dofs.describe(m, 25), "node 99 dof y");
}

TEST(DofMap, ResolvesEquationChainsIntoFreeAndPrescribedTerms) {
  model::Model m = fixtures::brick_row(1);
  // u(node2,x) = 2 u(node3,x);  u(node3,x) = u(node1,x) [prescribed 0.1] + u(node4,y)
  m.equations.push_back(equation({{1, 0, 1.0}, {2, 0, -2.0}}));
  m.equations.push_back(equation({{2, 0, 1.0}, {0, 0, -1.0}, {3, 1, -1.0}}));
  const assembly::DofMap dofs(m, {{0, 0, 0.1}});
  VecX g(1);
  g << 0.1;
  VecX x = VecX::Random(dofs.n_equations());
  const VecX u = dofs.expand(x, g);
  EXPECT_NEAR(u[3 * 2], u[0] + u[3 * 3 + 1], 1e-14);
  EXPECT_NEAR(u[3 * 1], 2 * u[3 * 2], 1e-14);
  EXPECT_NEAR(dofs.expand(VecX::Zero(dofs.n_equations()), g)[3 * 1], 0.2, 1e-14);  // from g alone
  EXPECT_EQ(dofs.n_equations(), 24 - 1 - 2);
}

TEST(DofMap, RejectsCyclicEquations) {
  model::Model m = fixtures::brick_row(1);
  m.equations.push_back(equation({{1, 0, 1.0}, {2, 0, -1.0}}));
  m.equations.push_back(equation({{2, 0, 1.0}, {1, 0, -1.0}}));
  try {
    assembly::DofMap dofs(m, {});
    FAIL() << "cycle not detected";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("deck.inp:42"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("cycle"), std::string::npos);
  }
}

TEST(DofMap, RejectsDependentDofThatIsAlsoPrescribed) {
  model::Model m = fixtures::brick_row(1);
  m.equations.push_back(equation({{1, 0, 1.0}, {2, 0, -1.0}}));
  EXPECT_THROW(assembly::DofMap(m, {{1, 0, 0.0}}), InputError);
}

TEST(DofMap, SameStructureComparesConstraintLayoutNotValues) {
  model::Model m = fixtures::brick_row(2);
  const assembly::DofMap a(m, {{0, 0, 1.0}});
  const assembly::DofMap b(m, {{0, 0, 7.0}});
  const assembly::DofMap c(m, {{0, 1, 1.0}});
  EXPECT_TRUE(a.same_structure(b));
  EXPECT_FALSE(a.same_structure(c));
}

TEST(DofMap, TransformedNodeUnknownsAreLocalComponents) {
  model::Model m = fixtures::brick_row(1);
  // Node 0: local x' along (1, 1, 0)/sqrt2, y' along (-1, 1, 0)/sqrt2, z' = z.
  const Real s = 1 / std::sqrt(2.0);
  Mat3 r;
  r << s, -s, 0, s, s, 0, 0, 0, 1;
  m.local_frames[0] = r;
  // A roller in the rotated plane: local x' of node 0 prescribed to 0.3, y' and z' free.
  const assembly::DofMap dofs(m, {{0, 0, 0.3}});
  EXPECT_EQ(dofs.n_prescribed(), 1);
  EXPECT_EQ(dofs.n_equations(), 24 - 1);
  EXPECT_FALSE(dofs.is_free(1));  // its global rows mix local unknowns
  EXPECT_EQ(dofs.describe_unknown(m, 1), "node 1 local dof 2");
  EXPECT_EQ(dofs.describe_unknown(m, 4), "node 2 dof y");
  VecX x = VecX::Random(dofs.n_equations());
  VecX g(1);
  g << 0.3;
  const VecX u = dofs.expand(x, g);
  const Vec3 local = r.transpose() * u.segment<3>(0);
  EXPECT_NEAR(local[0], 0.3, 1e-15);  // the prescribed local component holds
  EXPECT_NEAR(dofs.unknown_value(u, 0), 0.3, 1e-15);
  ASSERT_EQ(dofs.equation_dof(0), 1);  // node 1's local y' is the first unknown
  EXPECT_NEAR(dofs.unknown_value(u, 1), x[0], 1e-15);
  EXPECT_NEAR(dofs.unknown_value(u, 4), u[4], 0);  // an untransformed node: itself
  // Global x and y of node 0 both carry the prescribed value: offsets 0.3 * (s, s, 0).
  const VecX offset = dofs.expand(VecX::Zero(dofs.n_equations()), g);
  EXPECT_NEAR(offset[0], 0.3 * s, 1e-15);
  EXPECT_NEAR(offset[1], 0.3 * s, 1e-15);
  EXPECT_NEAR(offset[2], 0.0, 0);
}

TEST(DofMap, EquationsOnTransformedNodesAreLocalTiesAreRefused) {
  model::Model m = fixtures::brick_row(1);
  Mat3 r;
  r << 0, -1, 0, 1, 0, 0, 0, 0, 1;  // x' = global y, y' = -global x
  m.local_frames[1] = r;
  // u'(node 2, x') = u(node 3, z): node 2's global y follows node 3's z.
  m.equations.push_back(equation({{1, 0, 1.0}, {2, 2, -1.0}}));
  const assembly::DofMap dofs(m, {});
  const VecX x = VecX::Random(dofs.n_equations());
  const VecX u = dofs.expand(x, VecX());
  EXPECT_NEAR(u[3 * 1 + 1], u[3 * 2 + 2], 1e-15);
  m.equations.back().keyword = "*TIE";
  EXPECT_THROW(assembly::DofMap(m, {}), InputError);
}
