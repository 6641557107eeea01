// The Newton driver with penalty contact on two stacked blocks: the contact patch test
// (thesis section 5.4) per scheme, and the driver's contact bookkeeping.
#include <gtest/gtest.h>

#include <cmath>

#include "../contact/two_blocks.hpp"
#include "analysis/nonlinear_static.hpp"
#include "collect_results.hpp"

using namespace kontakt;

namespace {

using testing_decks::Collect;

struct PatchResult {
  Real szz_min = 1e300, szz_max = -1e300, cpress_min = 1e300, cpress_max = -1e300;
  int iterations = 0;
};

/// Upper block coarse (2 x 2 C3D15 wedges: 6-node triangle faces), lower fine (3 x 3 C3D20),
/// nu = 0, unit pressure, K = 1e7: the exact state is sigma_zz = -1 and p = 1 everywhere.
PatchResult patch_test(const std::string& scheme) {
  contact::fixtures::TwoBlocks t;
  t.upper = {"C3D15", 2, 1};
  t.lower = {"C3D20", 3, 2};
  const model::Model m =
      contact::fixtures::two_blocks_model(t, 1e7, *model::contact_scheme_from_name(scheme));
  Collect c;
  analysis::run_nonlinear_static(m, {}, c, c);
  PatchResult r;
  const output::Frame& f = c.frames.back();
  for (Index k = 0; k < f.S.rows(); ++k) {
    r.szz_min = std::min(r.szz_min, f.S(k, 2));
    r.szz_max = std::max(r.szz_max, f.S(k, 2));
  }
  for (const auto& p : f.contact_points) {
    if (!p.active) continue;
    r.cpress_min = std::min(r.cpress_min, p.pressure);
    r.cpress_max = std::max(r.cpress_max, p.pressure);
  }
  r.iterations = c.events.back().iterations;
  return r;
}

}  // namespace

TEST(ContactPatchTest, GaussCutSchemesTransmitTheUniformState) {
  // The 3-point rule integrates the face-pair products (degree 4) inexactly, so the point
  // pressures scatter a little more; the stresses are uniform to 1e-3 for all.
  for (const auto& [scheme, p_tol] : {std::pair{"lgc3", 5e-3}, {"lgc7", 1e-3}, {"lgc12", 1e-3}, {"gc7", 1e-3}}) {
    const PatchResult r = patch_test(scheme);
    std::printf("%-6s szz %.6f .. %.6f  point pressure %.6f .. %.6f  iterations %d\n", scheme,
                r.szz_min, r.szz_max, r.cpress_min, r.cpress_max, r.iterations);
    SCOPED_TRACE(scheme);
    EXPECT_NEAR(r.szz_min, -1, 1e-3);
    EXPECT_NEAR(r.szz_max, -1, 1e-3);
    EXPECT_NEAR(r.cpress_min, 1, p_tol);
    EXPECT_NEAR(r.cpress_max, 1, p_tol);
  }
}

TEST(ContactPatchTest, NodeToSurfaceAndGaussFailItAsInTheThesis) {
  for (const char* scheme : {"nts", "lgauss", "gauss"}) {
    const PatchResult r = patch_test(scheme);
    std::printf("%-6s szz %.6f .. %.6f  point pressure %.6f .. %.6f  iterations %d\n", scheme,
                r.szz_min, r.szz_max, r.cpress_min, r.cpress_max, r.iterations);
    SCOPED_TRACE(scheme);
    EXPECT_GT(std::max(std::abs(r.szz_min + 1), std::abs(r.szz_max + 1)), 1e-2);
  }
}

namespace {

/// The patch test's blocks with the upper one `gap` above the lower one and pressure
/// `pressure` on its top (negative: pulling up), solved in `mode`.
Collect solve_blocks(const std::string& scheme, Real gap, Real pressure,
                     analysis::ContactStabilisation mode = analysis::ContactStabilisation::Auto) {
  contact::fixtures::TwoBlocks t;
  t.upper = {"C3D8", 2, 1};
  t.lower = {"C3D8", 3, 1};
  t.gap = gap;
  t.pressure = pressure;
  const model::Model m =
      contact::fixtures::two_blocks_model(t, 1e7, *model::contact_scheme_from_name(scheme));
  Collect c;
  analysis::NonlinearOptions options;
  options.contact_stabilisation = mode;
  analysis::run_nonlinear_static(m, options, c, c);
  return c;
}

}  // namespace

TEST(ContactStabilisation, ABodyOnlyContactHoldsClosesAGapAndEndsUnstabilised) {
  // Upper block 1e-3 above the lower one, pushed down: singular without contact, so the
  // springs engage, land it on contact and are released. The end state is that of the
  // touching blocks (the patch test's uniform sigma_zz = -1 for the segment schemes), and the
  // iterations show the springs' levels.
  for (const char* scheme : {"lgc7", "lgc3", "gc7", "nts"}) {
    SCOPED_TRACE(scheme);
    const Collect c = solve_blocks(scheme, 1e-3, 1);
    const MatX6& S = c.frames.back().S;
    const Collect touching = solve_blocks(scheme, 0, 1);
    EXPECT_LT((S - touching.frames.back().S).cwiseAbs().maxCoeff(), 1e-6);
    if (std::string(scheme) != "nts") {
      for (Index k = 0; k < S.rows(); ++k) EXPECT_NEAR(S(k, 2), -1, 1e-3);
    }
    bool stabilised = false, engaged = false;
    for (const auto& e : c.events) {
      stabilised |= e.kind == analysis::Event::Kind::Iteration && e.stabilisation > 0;
      engaged |= e.kind == analysis::Event::Kind::Warning &&
                 e.message.find("contact stabilisation engaged") != std::string::npos;
      if (e.kind == analysis::Event::Kind::Increment) {
        EXPECT_GE(e.stabilisation_energy, 0);
        EXPECT_GT(e.strain_energy, 0);
      }
    }
    EXPECT_TRUE(stabilised);
    EXPECT_TRUE(engaged);
    // The last iteration runs without springs: what is committed is unstabilised.
    for (auto e = c.events.rbegin(); e != c.events.rend(); ++e)
      if (e->kind == analysis::Event::Kind::Iteration) {
        EXPECT_EQ(e->stabilisation, 0);
        break;
      }
  }
}

TEST(ContactStabilisation, ForcedStabilisationLeavesTheUnstabilisedAnswer) {
  // Touching blocks converge without springs; with springs forced into every increment the
  // displacements agree to far below 1e-6 of their largest value.
  for (const char* scheme : {"lgc7", "gc7", "nts"}) {
    SCOPED_TRACE(scheme);
    const Collect plain = solve_blocks(scheme, 0, 1, analysis::ContactStabilisation::Never);
    const Collect forced = solve_blocks(scheme, 0, 1, analysis::ContactStabilisation::Always);
    const MatX3& u0 = plain.frames.back().U;
    const MatX3& u1 = forced.frames.back().U;
    EXPECT_LT((u1 - u0).cwiseAbs().maxCoeff(), 1e-6 * u0.cwiseAbs().maxCoeff());
  }
}

TEST(ContactStabilisation, LoadsThatPullABodyOffItsContactAreReported) {
  // Upper block above the lower one, its top pulled up: no equilibrium exists; the run says
  // which body moves away instead of returning springs' answer.
  for (const char* scheme : {"lgc7", "nts"}) {
    SCOPED_TRACE(scheme);
    try {
      solve_blocks(scheme, 1e-3, -1);
      ADD_FAILURE() << "a body pulled off its contact converged";
    } catch (const NonConvergence& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("away from its contact"), std::string::npos) << what;
      EXPECT_NE(what.find("the body containing node 100"), std::string::npos) << what;
      EXPECT_NE(what.find("is held in z only by contact"), std::string::npos) << what;
    }
  }
}

TEST(ContactStabilisation, AnUnloadedBodyOverAGapIsSolvedWithAWarningNamingTheDof) {
  // No load on the upper block: the stiffness is singular, but the loads leave the free
  // motion alone; it is solved with a warning that names where, and nothing moves.
  const Collect c = solve_blocks("lgc7", 1e-3, 0);
  bool warned = false;
  for (const auto& e : c.events)
    warned |= e.kind == analysis::Event::Kind::Warning &&
              e.message.find("zero-energy mode") != std::string::npos &&
              e.message.find("is held in z only by contact, and nothing touches") !=
                  std::string::npos;
  EXPECT_TRUE(warned);
  EXPECT_LT(c.frames.back().U.cwiseAbs().maxCoeff(), 1e-12);
}

TEST(ContactStabilisation, TheReportedStrainEnergyCountsTheSprings) {
  // The increment's strain energy (beside the stabilisation's) is the elements' and the
  // connectors': a spring from the lower block's first node to the upper block's last.
  contact::fixtures::TwoBlocks t;
  t.upper = {"C3D8", 2, 1};
  t.lower = {"C3D8", 3, 1};
  t.pressure = 1;
  model::Model m =
      contact::fixtures::two_blocks_model(t, 1e7, *model::contact_scheme_from_name("lgc7"));
  model::Connector spring;
  spring.id = 9999;
  spring.nodes = {0, m.n_nodes() - 1};
  spring.stiffness = 50;
  m.connectors.push_back(spring);
  Collect c;
  analysis::run_nonlinear_static(m, {}, c, c);
  const output::Frame& f = c.frames.back();
  const auto& [a, b] = spring.nodes;
  const Vec3 X = m.mesh.coords.row(b) - m.mesh.coords.row(a);
  const Vec3 du = f.U.row(b) - f.U.row(a);
  const Real elongation =
      m.steps[0].nlgeom ? (X + du).norm() - X.norm() : X.normalized().dot(du);
  const Real spring_energy = 0.5 * spring.stiffness * elongation * elongation;
  ASSERT_GT(spring_energy, 0);
  const analysis::Event* last = nullptr;
  for (const auto& e : c.events)
    if (e.kind == analysis::Event::Kind::Increment) last = &e;
  ASSERT_NE(last, nullptr);
  EXPECT_NEAR(last->strain_energy - f.ENER.dot(f.ip_volume), spring_energy,
              1e-9 * last->strain_energy);
}
