#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <set>

#include "assembly/assembler.hpp"
#include "test_model_fixture.hpp"

using namespace kontakt;

namespace {

/// Deterministic symmetric "element stiffness" and load for element e.
void fake_kernel(int e, MatX& K, VecX& f) {
  std::srand(1000 + e);
  MatX R = MatX::Random(24, 24);
  K = R * R.transpose() + 24 * MatX::Identity(24, 24);
  f = VecX::Random(24);
}

/// Dense T (n_dofs x n_eq) and g of a DofMap, built independently from expand().
void dense_transform(const assembly::DofMap& dofs, const VecX& prescribed, MatX& T, VecX& g) {
  T = MatX::Zero(dofs.n_dofs(), dofs.n_equations());
  for (int j = 0; j < dofs.n_equations(); ++j) {
    VecX x = VecX::Zero(dofs.n_equations());
    x[j] = 1;
    T.col(j) = dofs.expand(x, VecX::Zero(prescribed.size()));
  }
  g = dofs.expand(VecX::Zero(dofs.n_equations()), prescribed);
}

}  // namespace

TEST(Assembler, ReducedSystemEqualsDenseTransformWithEquationsAndPrescribedValues) {
  model::Model m = fixtures::brick_row(3);
  model::Equation eq;
  eq.terms = {{5, 1, 2.0}, {14, 2, -1.0}, {9, 0, 0.5}};
  m.equations.push_back(eq);
  const std::vector<model::Boundary> bcs = {{0, 0, 0.01}, {1, 1, -0.02}, {2, 2, 0.0}};
  const assembly::DofMap dofs(m, bcs);
  VecX prescribed(3);
  prescribed << 0.01, -0.02, 0.0;

  MatX K_full = MatX::Zero(dofs.n_dofs(), dofs.n_dofs());
  VecX f_full = VecX::Zero(dofs.n_dofs());
  for (int e = 0; e < m.n_elements(); ++e) {
    MatX K;
    VecX f;
    fake_kernel(e, K, f);
    const auto& nodes = m.mesh.elements[e].nodes;
    for (int a = 0; a < 24; ++a) {
      f_full[3 * nodes[a / 3] + a % 3] += f[a];
      for (int b = 0; b < 24; ++b)
        K_full(3 * nodes[a / 3] + a % 3, 3 * nodes[b / 3] + b % 3) += K(a, b);
    }
  }
  MatX T;
  VecX g;
  dense_transform(dofs, prescribed, T, g);
  const MatX K_ref = T.transpose() * K_full * T;
  const VecX f_ref = T.transpose() * (f_full - K_full * g);

  for (bool symmetric : {true, false}) {
    const assembly::AssemblyPlan plan = assembly::make_plan(m, dofs, symmetric, 2);
    assembly::ReducedSystem sys;
    assembly::assemble(m, plan, prescribed, fake_kernel, 2, sys);
    MatX K_got = MatX::Zero(dofs.n_equations(), dofs.n_equations());
    for (int j = 0; j < plan.pattern.n; ++j)
      for (Index k = plan.pattern.col_start[j]; k < plan.pattern.col_start[j + 1]; ++k)
        K_got(plan.pattern.row_index[k], j) = sys.values[k];
    if (symmetric) K_got = K_got.selfadjointView<Eigen::Upper>();
    EXPECT_LT((K_got - K_ref).norm(), 1e-10 * K_ref.norm()) << "symmetric=" << symmetric;
    EXPECT_LT((sys.rhs - f_ref).norm(), 1e-10 * f_ref.norm());
  }
}

TEST(Assembler, ColoursNeverShareAnEquation) {
  model::Model m = fixtures::brick_row(10);
  const assembly::DofMap dofs(m, {});
  const auto eqs = assembly::element_equations(m, dofs);
  const auto colours = assembly::colour_elements(eqs, dofs.n_equations());
  std::size_t total = 0;
  for (const auto& colour : colours) {
    std::set<int> seen;
    for (int e : colour)
      for (Index k = eqs.start[e]; k < eqs.start[e + 1]; ++k)
        EXPECT_TRUE(seen.insert(eqs.eqs[k]).second) << "equation shared within a colour";
    total += colour.size();
  }
  EXPECT_EQ(total, 10u);
  EXPECT_EQ(colours.size(), 2u);  // a row of bricks alternates two colours
}

TEST(Assembler, NodalForcesReduceThroughEquations) {
  model::Model m = fixtures::brick_row(1);
  model::Equation eq;
  eq.terms = {{1, 0, 1.0}, {2, 0, -3.0}};
  m.equations.push_back(eq);
  const assembly::DofMap dofs(m, {});
  VecX f = VecX::Zero(dofs.n_dofs());
  f[3 * 1] = 2.0;  // force on the dependent dof is carried by its master with factor 3
  VecX rhs = VecX::Zero(dofs.n_equations());
  assembly::add_nodal_forces(dofs, f, rhs);
  const int master_eq = dofs.terms_begin(3 * 2)->index;
  EXPECT_DOUBLE_EQ(rhs[master_eq], 6.0);
  EXPECT_DOUBLE_EQ(rhs.sum(), 6.0);
}
