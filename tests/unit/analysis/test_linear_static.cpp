// End-to-end checks of the linear static driver on small hand-written decks.
#include <gtest/gtest.h>

#include <string>

#include "analysis/linear_static.hpp"
#include "collect_results.hpp"
#include "cube_deck.hpp"
#include "inp/read_deck.hpp"

using namespace kontakt;

namespace {

using testing_decks::Collect;

/// The unit cube with E = 1000, nu = 0.25, alpha = 1e-5; `rest` is appended.
std::string cube_deck(const std::string& rest) {
  return testing_decks::cube_model("*ELASTIC\n1000, 0.25\n*EXPANSION\n1e-5\n") + rest;
}

using testing_decks::kRollers;

Collect solve_linear(const std::string& deck, int threads = 1) {
  const model::Model m = inp::read_deck_text(deck, "cube.inp");
  Collect c;
  analysis::run_linear_static(m, {.threads = threads}, c, c);
  return c;
}

}  // namespace

TEST(LinearStatic, UniaxialTensionGivesExactStressStrainAndReactions) {
  // Total force 10 on the x = 1 face of a unit cube: sigma_xx = 10, eps_xx = 0.01.
  const auto c = solve_linear(cube_deck(std::string(kRollers) + R"(*STEP
*STATIC
*CLOAD
X1, 1, 2.5
*END STEP
)"));
  ASSERT_EQ(c.frames.size(), 1u);
  const auto& f = c.frames[0];
  for (Index k = 0; k < f.S.rows(); ++k) {
    EXPECT_NEAR(f.S(k, 0), 10.0, 1e-10);
    for (int j = 1; j < 6; ++j) EXPECT_NEAR(f.S(k, j), 0.0, 1e-10);
    EXPECT_NEAR(f.E(k, 0), 0.01, 1e-14);
    EXPECT_NEAR(f.E(k, 1), -0.0025, 1e-14);
  }
  EXPECT_NEAR(f.U(1, 0), 0.01, 1e-14);   // node 2
  EXPECT_NEAR(f.U(6, 2), -0.0025, 1e-14);  // node 7
  EXPECT_NEAR(f.RF.col(0).segment(0, 1).sum(), -2.5, 1e-10);  // node 1 reaction in x
  EXPECT_NEAR(f.RF(1, 0), 2.5, 1e-10);  // loaded node: internal force balances the load
  EXPECT_NEAR(f.EVOL[0], 1.0, 1e-14);
  EXPECT_EQ(c.events.back().status, "converged");
}

TEST(LinearStatic, FreeThermalExpansionIsStressFree) {
  const auto c = solve_linear(cube_deck(std::string(kRollers) + R"(*INITIAL CONDITIONS, TYPE=TEMPERATURE
NALL, 20
*STEP
*STATIC
*TEMPERATURE
NALL, 120
*END STEP
)"));
  const auto& f = c.frames[0];
  EXPECT_LT(f.S.cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_NEAR(f.U(6, 0), 1e-3, 1e-15);
  EXPECT_NEAR(f.U(6, 1), 1e-3, 1e-15);
  EXPECT_NEAR(f.U(6, 2), 1e-3, 1e-15);
}

TEST(LinearStatic, PrescribedDisplacementAndEquationTie) {
  // Pull the x = 1 face by 0.02 through node 2 alone; nodes 3, 6, 7 follow by *EQUATION.
  const auto c = solve_linear(cube_deck(std::string(kRollers) + R"(*EQUATION
2
3, 1, 1.0, 2, 1, -1.0
2
6, 1, 1.0, 2, 1, -1.0
2
7, 1, 1.0, 2, 1, -1.0
*STEP
*STATIC
*BOUNDARY
2, 1, 1, 0.02
*END STEP
)"));
  const auto& f = c.frames[0];
  for (int node : {1, 2, 5, 6}) EXPECT_NEAR(f.U(node, 0), 0.02, 1e-14);
  for (Index k = 0; k < f.S.rows(); ++k) EXPECT_NEAR(f.S(k, 0), 20.0, 1e-9);
}

TEST(LinearStatic, LaterStepsReuseTheFactorisationAndScaleLinearly) {
  const auto c = solve_linear(cube_deck(std::string(kRollers) + R"(*STEP
*STATIC
*CLOAD
X1, 1, 1.0
*END STEP
*STEP
*STATIC
*CLOAD
X1, 1, 3.0
*END STEP
)"));
  ASSERT_EQ(c.frames.size(), 2u);
  EXPECT_NEAR(c.frames[1].U(1, 0), 3 * c.frames[0].U(1, 0), 1e-15);
  EXPECT_DOUBLE_EQ(c.frames[1].total_time, 2.0);
}

TEST(LinearStatic, UnsupportedBodyIsReportedWithANode) {
  try {
    solve_linear(cube_deck(R"(*STEP
*STATIC
*CLOAD
2, 1, 1.0
*END STEP
)"));
    FAIL() << "a free-floating body was solved";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("rigid body"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("node"), std::string::npos) << e.what();
  }
}

TEST(LinearStatic, MechanismIsReportedNotSolved) {
  // Every body is held in x, y and z somewhere, but rotation about x is free.
  try {
    solve_linear(cube_deck(R"(*BOUNDARY
1, 1, 3
2, 1
*STEP
*STATIC
*CLOAD
7, 2, 1.0
*END STEP
)"));
    FAIL() << "a mechanism was solved";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("singular"), std::string::npos) << e.what();
  }
}

TEST(LinearStatic, ResultsDoNotDependOnThreadCount) {
  std::string mesh = "*NODE, NSET=NALL\n";
  const int n = 12;  // a 12-element bar of unit cubes
  for (int i = 0; i <= n; ++i)
    for (int k = 0; k < 4; ++k)
      mesh += std::to_string(4 * i + k + 1) + ", " + std::to_string(i) + ", " +
              std::to_string(k == 1 || k == 2) + ", " + std::to_string(k >= 2) + "\n";
  mesh += "*ELEMENT, TYPE=C3D8, ELSET=EALL\n";
  for (int i = 0; i < n; ++i) {
    const int a = 4 * i + 1, b = 4 * (i + 1) + 1;
    mesh += std::to_string(i + 1) + ", " + std::to_string(a) + ", " + std::to_string(b) + ", " +
            std::to_string(b + 1) + ", " + std::to_string(a + 1) + ", " + std::to_string(a + 3) +
            ", " + std::to_string(b + 3) + ", " + std::to_string(b + 2) + ", " +
            std::to_string(a + 2) + "\n";
  }
  mesh += R"(*MATERIAL, NAME=M
*ELASTIC
1000, 0.3
*SOLID SECTION, ELSET=EALL, MATERIAL=M
*BOUNDARY
1, 1, 3
2, 1, 3
3, 1, 3
4, 1, 3
*STEP
*STATIC
*CLOAD
52, 3, -1.0
*END STEP
)";
  const auto one = solve_linear(mesh, 1), two = solve_linear(mesh, 2);
  EXPECT_EQ((one.frames[0].U - two.frames[0].U).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ((one.frames[0].S - two.frames[0].S).cwiseAbs().maxCoeff(), 0.0);
}

TEST(LinearStatic, BoundaryFixedHoldsThePreviousStepsDisplacement) {
  // Step 1 pulls the x = 1 face; step 2 removes the load but FIXED holds node 2 where it was.
  const auto c = solve_linear(cube_deck(std::string(kRollers) + R"(*STEP
*STATIC
*CLOAD
X1, 1, 2.5
*END STEP
*STEP
*STATIC
*CLOAD, OP=NEW
*BOUNDARY, FIXED
2, 1, 1
*END STEP
)"));
  ASSERT_EQ(c.frames.size(), 2u);
  EXPECT_NEAR(c.frames[0].U(1, 0), 0.01, 1e-14);
  EXPECT_NEAR(c.frames[1].U(1, 0), 0.01, 1e-14);
}

TEST(LinearStatic, EveryDofPrescribedIsSolvedWithoutEquations) {
  // Issue 10: no free equation left (ccx solves this and prints the reactions); this crashed.
  // Uniaxial strain 0.01: sigma_xx = (lambda + 2 mu) eps = 12, sigma_yy = sigma_zz = 4.
  const auto c = solve_linear(cube_deck(R"(*BOUNDARY
X0, 1, 3
X1, 2, 3
X1, 1, 1, 0.01
*STEP
*STATIC
*END STEP
)"));
  ASSERT_EQ(c.frames.size(), 1u);
  const auto& f = c.frames[0];
  EXPECT_EQ(c.events.back().status, "converged");
  EXPECT_NEAR(f.S(0, 0), 12.0, 1e-10);
  EXPECT_NEAR(f.S(0, 1), 4.0, 1e-10);
  EXPECT_NEAR(f.RF(1, 0), 3.0, 1e-10);   // node 2 on x = 1: sigma_xx / 4
  EXPECT_NEAR(f.RF(0, 0), -3.0, 1e-10);  // node 1 on x = 0
  EXPECT_NEAR(f.RF(2, 1), 1.0, 1e-10);   // node 3 on y = 1: sigma_yy / 4
  EXPECT_NEAR(f.RF(1, 1), -1.0, 1e-10);  // node 2 on y = 0
  EXPECT_NEAR(f.U(6, 0), 0.01, 1e-15);
}
