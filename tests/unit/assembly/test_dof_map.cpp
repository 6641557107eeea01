#include <gtest/gtest.h>

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
  EXPECT_NEAR(dofs.offset(3 * 1, g), 0.2, 1e-14);
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
