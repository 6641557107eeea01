// The Newton driver on small NLGEOM decks with closed-form answers.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/nonlinear_static.hpp"
#include "collect_results.hpp"
#include "cube_deck.hpp"
#include "inp/read_deck.hpp"

using namespace kontakt;

namespace {

using testing_decks::Collect;

/// The unit cube with E = 1000, nu = 0.25 on symmetry rollers; `rest` appended.
std::string cube(const std::string& rest) {
  return testing_decks::cube_model("*ELASTIC\n1000, 0.25\n") + testing_decks::kRollers + rest;
}

/// Controls tight enough that comparisons with closed forms see the model, not ccx's default
/// residual tolerance of 0.5 %.
analysis::NonlinearOptions tight_options() {
  analysis::NonlinearOptions o;
  model::SolutionControls c;
  c.residual_tolerance = 1e-10;
  c.correction_tolerance = 1e-10;
  o.controls = c;
  return o;
}

Collect solve(const std::string& deck, analysis::NonlinearOptions options = {}) {
  const model::Model m = inp::read_deck_text(deck, "cube.inp");
  Collect c;
  analysis::run_nonlinear_static(m, options, c, c);
  return c;
}

}  // namespace

TEST(NonlinearStatic, LargeUniaxialStretchMatchesStVenantKirchhoff) {
  // Stretch 1.5 with free lateral faces: S11 = E * E11, E22 = -nu E11, Cauchy = F S F^T / J.
  const auto c = solve(cube(R"(*STEP, NLGEOM
*STATIC
0.25, 1.0
*BOUNDARY
X1, 1, 1, 0.5
*END STEP
)"),
                       tight_options());
  ASSERT_FALSE(c.frames.empty());
  const auto& f = c.frames.back();
  const Real E11 = (1.5 * 1.5 - 1) / 2, S11 = 1000 * E11, E22 = -0.25 * E11;
  const Real lateral = std::sqrt(1 + 2 * E22), J = 1.5 * lateral * lateral;
  for (Index k = 0; k < f.S.rows(); ++k) {
    EXPECT_NEAR(f.S(k, 0), 1.5 * 1.5 * S11 / J, 1e-6 * S11);
    EXPECT_NEAR(f.S(k, 1), 0.0, 1e-6 * S11);
    EXPECT_NEAR(f.E(k, 0), E11, 1e-9);
    EXPECT_NEAR(f.E(k, 1), E22, 1e-9);
  }
  // node 7 contracts laterally; ccx's "linear" rule (r <= 1e-8 q~) may end the iteration
  // before the tight correction tolerance does, which leaves ~1e-9 here
  EXPECT_NEAR(f.U(6, 1), lateral - 1, 1e-8);
  // The reactions on x = 0 carry the first Piola-Kirchhoff force F11 * S11 * A0.
  Real reaction = 0;
  for (int n : {0, 3, 4, 7}) reaction += f.RF(n, 0);
  EXPECT_NEAR(reaction, -1.5 * S11, 1e-6 * S11);
  EXPECT_DOUBLE_EQ(f.total_time, 1.0);
  EXPECT_TRUE(f.is_step_end);
  EXPECT_GE(c.frames.size(), 2u);  // several increments
}

TEST(NonlinearStatic, NewtonConvergesQuadratically) {
  const auto c = solve(cube(R"(*STEP, NLGEOM
*STATIC
1.0, 1.0
*CLOAD
X1, 1, 100.
*END STEP
)"));
  std::vector<Real> residuals;
  for (const auto& e : c.events)
    if (e.kind == analysis::Event::Kind::Iteration && e.increment == 1 && e.attempt == 1)
      residuals.push_back(e.residual);
  ASSERT_GE(residuals.size(), 3u);
  // Each residual is at most a constant times the square of the previous (relative to q~).
  for (std::size_t k = 1; k + 1 < residuals.size(); ++k)
    if (residuals[k] > 1e-8) {
      EXPECT_LT(residuals[k + 1] / 100, 10 * std::pow(residuals[k] / 100, 2)) << k;
    }
}

TEST(NonlinearStatic, SmallLoadReproducesTheLinearSolution) {
  const auto c = solve(cube(R"(*STEP, NLGEOM
*STATIC
*CLOAD
X1, 1, 1e-4
*END STEP
)"));
  // Linear: sigma_xx = 4e-4 on the unit face, eps_xx = 4e-7, u_x = 4e-7.
  EXPECT_NEAR(c.frames.back().U(1, 0), 4e-7, 1e-12);
}

TEST(NonlinearStatic, ElasticAnswerDoesNotDependOnTheIncrements) {
  const std::string tail = R"(
*CLOAD
X1, 1, 150.
*END STEP
)";
  const analysis::NonlinearOptions tight = tight_options();  // what remains is the path
  const auto one = solve(cube("*STEP, NLGEOM\n*STATIC, DIRECT\n1.0, 1.0" + tail), tight);
  const auto many = solve(cube("*STEP, NLGEOM\n*STATIC, DIRECT\n0.1, 1.0" + tail), tight);
  EXPECT_EQ(many.frames.size(), 10u);
  EXPECT_NEAR(one.frames.back().U(1, 0), many.frames.back().U(1, 0), 1e-9);
}

TEST(NonlinearStatic, CancellationStopsWithinAnIteration) {
  std::atomic<bool> cancel{true};
  analysis::NonlinearOptions options;
  options.cancel = &cancel;
  EXPECT_THROW(solve(cube("*STEP, NLGEOM\n*STATIC\n*CLOAD\nX1, 1, 10.\n*END STEP\n"), options),
               analysis::Cancelled);
}

TEST(NonlinearStatic, UnreachableLoadLevelEndsAsNonConvergence) {
  // Compressing a cube to zero volume under a dead load cannot converge; the run must stop
  // with NonConvergence after the cutbacks (two allowed by the deck's *CONTROLS), never with
  // NaN results.
  Collect c;
  const model::Model m = inp::read_deck_text(cube(R"(*STEP, NLGEOM
*STATIC
1.0, 1.0
*CONTROLS, PARAMETERS=TIME INCREMENTATION
, , , , , , , 2
*CLOAD
X1, 1, -1e6
*END STEP
)"), "cube.inp");
  EXPECT_EQ(m.steps[0].controls.max_cutbacks, 2);
  try {
    analysis::run_nonlinear_static(m, {}, c, c);
    FAIL() << "an unreachable load level converged";
  } catch (const NonConvergence& e) {
    EXPECT_NE(std::string(e.what()).find("more than 2 cutbacks"), std::string::npos) << e.what();
  }
  int cutbacks = 0;
  for (const auto& e : c.events) cutbacks += e.kind == analysis::Event::Kind::Cutback;
  EXPECT_EQ(cutbacks, 3);
}

TEST(NonlinearStatic, PressureFollowsTheDeformedFaceUnderNlgeom) {
  // Pressure on the x = 1 face (S4) of a cube free to expand sideways: a true traction, so the
  // Cauchy stress is exactly -p however much the face area grows (a dead load would give
  // -p / (lateral stretch)^2).
  const Real p = 150;
  const auto c = solve(cube(R"(*STEP, NLGEOM
*STATIC
0.5, 1.0
*DLOAD
1, P4, 150.
*END STEP
)"),
                       tight_options());
  const auto& f = c.frames.back();
  for (Index k = 0; k < f.S.rows(); ++k) {
    EXPECT_NEAR(f.S(k, 0), -p, 1e-6 * p);
    EXPECT_NEAR(f.S(k, 1), 0.0, 1e-6 * p);
  }
  EXPECT_GT(f.U(6, 1), 0.01);  // the face really grew
}

TEST(NonlinearStatic, UniaxialElasticPlasticBarFollowsTheHardeningCurve) {
  // Small strain, E = 200000, yield 200, linear hardening H = 1000 from the *PLASTIC table:
  // sigma = 200 + E H / (E + H) (eps - 200 / E) once yielded; PEEQ = (sigma - 200) / H.
  std::string deck = cube(R"(*STEP
*STATIC, DIRECT
0.1, 1.0
*BOUNDARY
X1, 1, 1, 0.01
*EL PRINT, ELSET=EALL
S, PEEQ
*END STEP
)");
  deck.replace(deck.find("1000, 0.25"), 10, "200000, 0.3\n*PLASTIC\n200., 0.\n300., 0.1");
  const auto c = solve(deck, tight_options());
  ASSERT_EQ(c.frames.size(), 10u);
  const Real E = 200000, H = 1000, sy = 200;
  for (const auto& f : c.frames) {
    const Real eps = 0.01 * f.step_time;
    const Real expected = eps * E <= sy ? eps * E : sy + E * H / (E + H) * (eps - sy / E);
    ASSERT_EQ(f.PEEQ.size(), 8);
    for (Index k = 0; k < f.S.rows(); ++k) {
      EXPECT_NEAR(f.S(k, 0), expected, 1e-6 * expected) << "eps " << eps;
      EXPECT_NEAR(f.S(k, 1), 0.0, 1e-6 * expected);
      EXPECT_NEAR(f.PEEQ(k), std::max(0.0, (expected - sy) / H), 1e-9);
    }
  }
}

/// The cube deck with an elastic-plastic material: E, nu, then the *PLASTIC rows.
std::string plastic_cube(const std::string& rest, const std::string& plastic_rows,
                         const std::string& element = "C3D8") {
  std::string deck = cube(rest);
  deck.replace(deck.find("1000, 0.25"), 10, "200000, 0.3\n*PLASTIC\n" + plastic_rows);
  deck.replace(deck.find("TYPE=C3D8,"), 10, "TYPE=" + element + ",");
  return deck;
}

TEST(NonlinearStatic, FiniteStrainBarFollowsTheTrueStressCurveExactly) {
  // Stretch 1.3 with free lateral faces under NLGEOM. Exact for any increment size: the Cauchy
  // (true) stress of a yielding point is the *PLASTIC curve at its PEEQ (ccx's yield test is
  // on the Cauchy stress), and the volume follows the Kirchhoff pressure, K/2 (J^2 - 1) =
  // J sigma / 3, so the lateral stretch is sqrt(J / 1.3) whatever the plastic flow did.
  const auto c = solve(plastic_cube(R"(*STEP, NLGEOM
*STATIC, DIRECT
0.1, 1.0
*BOUNDARY
X1, 1, 1, 0.3
*EL PRINT, ELSET=EALL
S, PEEQ
*END STEP
)",
                                    "200., 0.\n300., 0.1\n320., 0.3"),
                       tight_options());
  ASSERT_EQ(c.frames.size(), 10u);
  const Real K = 200000 / (3 * (1 - 2 * 0.3));
  auto curve = [](Real a) { return a < 0.1 ? 200 + 1000 * a : 300 + 100 * (a - 0.1); };
  for (const auto& f : c.frames) {
    const Real stretch = 1 + 0.3 * f.step_time, sigma = f.S(0, 0);
    ASSERT_GT(f.PEEQ(0), 0.0) << "yielded from the first increment on";
    for (Index k = 0; k < f.S.rows(); ++k) {
      EXPECT_NEAR(f.S(k, 0), curve(f.PEEQ(k)), 1e-7 * sigma) << "stretch " << stretch;
      EXPECT_NEAR(f.S(k, 1), 0.0, 1e-7 * sigma);
    }
    // J from the pressure: a quadratic K/2 J^2 - sigma/3 J - K/2 = 0.
    const Real b = sigma / 3, J = (b + std::sqrt(b * b + K * K)) / K;
    EXPECT_NEAR(f.U(6, 1), std::sqrt(J / stretch) - 1, 1e-9) << "stretch " << stretch;
  }
}

TEST(NonlinearStatic, PlasticEnergyIsTheWorkSummedOverTheIncrementsAsCcx) {
  // ccx 2.20 prints ENER 66.84480, 89.05290, 105.0671 for the cube stretched by 10 % in 1, 2 and
  // 10 increments (E = 210000, nu = 0.3, *PLASTIC 800 / 1600 at 0.1): the trapezoidal sum of
  // S : dE over the increments, not a stored energy.
  const Real ccx[3][2] = {{1.0, 66.84480}, {0.5, 89.05290}, {0.1, 105.0671}};
  for (const auto& [increment, ener] : ccx) {
    std::string deck = cube("*STEP, NLGEOM\n*STATIC, DIRECT\n" + std::to_string(increment) +
                            ", 1.0\n*BOUNDARY\nX1, 1, 1, 0.1\n*EL PRINT, ELSET=EALL\nS, ENER\n"
                            "*END STEP\n");
    deck.replace(deck.find("1000, 0.25"), 10, "210000, 0.3\n*PLASTIC\n800., 0.\n1600., 0.1");
    const auto c = solve(deck);
    for (Index k = 0; k < 8; ++k)
      EXPECT_NEAR(c.frames.back().ENER(k), ener, 1e-4 * ener) << increment;
  }
  // Held at its length and heated by alpha dT = 0.018 (4 increments): the total strain along
  // the bar does no work, the mechanical one does; ccx prints 13.51453.
  std::string held = cube(R"(*INITIAL CONDITIONS, TYPE=TEMPERATURE
NALL, 0.
*STEP, NLGEOM
*STATIC, DIRECT
0.25, 1.0
*BOUNDARY
X1, 1, 1, 0.
*TEMPERATURE
NALL, 1500.
*EL PRINT, ELSET=EALL
S, ENER
*END STEP
)");
  held.replace(held.find("1000, 0.25"), 10,
               "210000, 0.3\n*PLASTIC\n800., 0.\n1600., 0.1\n*EXPANSION, ZERO=0.\n12.E-6");
  const auto c = solve(held);
  for (Index k = 0; k < 8; ++k) EXPECT_NEAR(c.frames.back().ENER(k), 13.51453, 2e-4);
}

TEST(NonlinearStatic, IncompatibleModesStayIdleInAHomogeneousPlasticStretch) {
  // C3D8I's modes carry no strain in a homogeneous deformation: under NLGEOM and plasticity
  // it answers exactly as C3D8.
  const std::string step = R"(*STEP, NLGEOM
*STATIC, DIRECT
0.25, 1.0
*BOUNDARY
X1, 1, 1, 0.2
*EL PRINT, ELSET=EALL
S, PEEQ
*END STEP
)";
  const auto brick = solve(plastic_cube(step, "200., 0.\n300., 0.1"), tight_options());
  const auto incompatible = solve(plastic_cube(step, "200., 0.\n300., 0.1", "C3D8I"), tight_options());
  ASSERT_EQ(brick.frames.size(), incompatible.frames.size());
  const auto& a = brick.frames.back();
  const auto& b = incompatible.frames.back();
  EXPECT_LT((a.U - b.U).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_LT((a.S - b.S).cwiseAbs().maxCoeff(), 1e-7 * a.S.cwiseAbs().maxCoeff());
  EXPECT_LT((a.PEEQ - b.PEEQ).cwiseAbs().maxCoeff(), 1e-10);
}

TEST(NonlinearStatic, FailedAttemptLeavesNoPlasticStrainBehind) {
  // The first attempt (the whole load, past yield) needs a third iteration, which *CONTROLS
  // forbids (I_C = 3): it is cut back to half the load, which is elastic. The plastic state
  // that attempt reached must be gone: no PEEQ at half load, and the run finishes.
  const auto c = solve(plastic_cube(R"(*STEP, NLGEOM
*STATIC
1.0, 1.0
*CONTROLS, PARAMETERS=TIME INCREMENTATION
4, 3, 9, 3, 10, 4, , 5
*CLOAD
X1, 1, 62.
*EL PRINT, ELSET=EALL
S, PEEQ
*END STEP
)",
                                    "200., 0.\n300., 0.1"));
  int cutbacks = 0;
  for (const auto& e : c.events) cutbacks += e.kind == analysis::Event::Kind::Cutback;
  ASSERT_GE(cutbacks, 1);
  ASSERT_GE(c.frames.size(), 2u);
  EXPECT_DOUBLE_EQ(c.frames.front().step_time, 0.5);
  EXPECT_EQ(c.frames.front().PEEQ.maxCoeff(), 0.0);
  EXPECT_GT(c.frames.back().PEEQ.minCoeff(), 0.0);  // 248 > 200 at full load
  EXPECT_DOUBLE_EQ(c.frames.back().step_time, 1.0);
}
