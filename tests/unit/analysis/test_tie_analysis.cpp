// *TIE through the linear driver: a tie model stays linear, is exact on matching meshes, and
// its tied slave nodes follow the master surface on non-matching ones.
#include <gtest/gtest.h>

#include "../contact/two_blocks.hpp"
#include "analysis/linear_static.hpp"
#include "analysis/nonlinear_static.hpp"
#include "collect_results.hpp"
#include "contact/tie_constraints.hpp"

using namespace kontakt;

namespace {

using testing_decks::Collect;

/// The two blocks bonded by a *TIE (upper bottom on lower top), set up as run_job does.
model::Model tied(const contact::fixtures::TwoBlocks& t) {
  std::string deck = contact::fixtures::two_blocks_deck(t);
  deck.insert(deck.find("*STEP"), "*TIE, NAME=BOND\nSLAVE, MASTER\n");
  model::Model m = inp::read_deck_text(deck, "tied.inp");
  contact::apply_ties(m);
  return m;
}

}  // namespace

TEST(TieAnalysis, MatchingMeshesGiveTheExactUniformStateInALinearSolve) {
  // nu = 0, unit pressure on top, bottom fixed, top held in x and y: sigma_zz = -1 everywhere.
  contact::fixtures::TwoBlocks t;
  t.lower = {"C3D20", 2, 1};
  t.upper = {"C3D20", 2, 2};
  model::Model m = tied(t);
  ASSERT_EQ(m.equations.size(), 3u * 21u);
  EXPECT_FALSE(analysis::needs_newton(m));
  Collect c;
  analysis::run_linear_static(m, {.threads = 1}, c, c);
  ASSERT_EQ(c.frames.size(), 1u);
  const auto& S = c.frames[0].S;
  for (Index k = 0; k < S.rows(); ++k) {
    EXPECT_NEAR(S(k, 2), -1.0, 1e-10) << k;
    for (int j : {0, 1, 3, 4, 5}) EXPECT_NEAR(S(k, j), 0.0, 1e-10) << k;
  }
}

TEST(TieAnalysis, TiedNodesFollowTheMasterOnNonMatchingMeshes) {
  contact::fixtures::TwoBlocks t;
  t.lower = {"C3D8", 3, 1};
  t.upper = {"C3D20", 2, 1};
  t.upper_size = 0.7;
  t.rotation_deg = 25;
  t.poisson = 0.3;
  model::Model m = tied(t);
  ASSERT_FALSE(m.equations.empty());
  Collect c;
  analysis::run_linear_static(m, {.threads = 1}, c, c);
  const MatX3& U = c.frames[0].U;
  const Real scale = U.rowwise().norm().maxCoeff();
  for (const model::Equation& eq : m.equations) {
    ASSERT_EQ(eq.keyword, "*TIE");
    Real residual = 0;
    for (const auto& term : eq.terms) residual += term.coef * U(term.node, term.dof);
    EXPECT_LT(std::abs(residual), 1e-13 * scale);
  }
}
