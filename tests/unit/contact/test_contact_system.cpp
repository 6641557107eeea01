// The contact system on two stacked blocks: integration-point areas, the assembled contact
// force against finite differences of the assembled tangent for every scheme, and pairing.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <tuple>

#include "contact/adjust_nodes.hpp"
#include "contact/contact_system.hpp"
#include "contact/contact_surface.hpp"
#include "contact/pressure_overclosure.hpp"
#include "two_blocks.hpp"

using namespace kontakt;
using namespace kontakt::contact;

namespace {

model::ContactScheme scheme(const std::string& name) { return *model::contact_scheme_from_name(name); }

/// Contact force (full dof vector) and dense tangent at u from the system's groups.
void assembled(ContactSystem& sys, const VecX& u, VecX& f, MatX* K) {
  sys.update(u, 1);
  f = VecX::Zero(u.size());
  if (K) *K = MatX::Zero(u.size(), u.size());
  for (std::size_t g = 0; g < sys.groups().size(); ++g) {
    const auto& nodes = sys.groups()[g];
    const auto& c = sys.contributions()[g];
    for (std::size_t a = 0; a < nodes.size(); ++a) {
      f.segment<3>(3 * nodes[a]) += c.f_int.segment<3>(3 * a);
      if (!K) continue;
      for (std::size_t b = 0; b < nodes.size(); ++b)
        K->block<3, 3>(3 * nodes[a], 3 * nodes[b]) += c.K.block<3, 3>(3 * a, 3 * b);
    }
  }
}

/// A small random displacement field pushing the upper block into the lower one.
VecX pressed(const model::Model& m, Real depth, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> r(-1, 1);
  VecX u = VecX::Zero(3 * m.n_nodes());
  for (int n = 0; n < m.n_nodes(); ++n) {
    const Vec3 x = m.mesh.coords.row(n).transpose();
    if (x(2) > 1 - 1e-9 && m.mesh.node_ids[n] >= 100000) u(3 * n + 2) = -depth * (1 + 0.3 * x(0));
    for (int c = 0; c < 3; ++c) u(3 * n + c) += 0.1 * depth * r(rng);
  }
  return u;
}

/// The upper block moved down by `depth`.
VecX upper_lowered(const model::Model& m, Real depth) {
  VecX u = VecX::Zero(3 * m.n_nodes());
  for (int n = 0; n < m.n_nodes(); ++n)
    if (m.mesh.node_ids[n] >= 100000) u(3 * n + 2) = -depth;
  return u;
}

/// The points of the committed state, as the writers get them.
std::vector<output::ContactPointRecord> committed_points(const ContactSystem& sys, const VecX& u) {
  output::Frame frame;
  sys.write_output(u, frame);
  return frame.contact_points;
}

}  // namespace

class EveryScheme : public ::testing::TestWithParam<const char*> {};

/// Friction on the two blocks' pair from the first step on.
void add_friction(model::Model& m, Real mu, Real stick_slope) {
  model::Friction f;
  f.mu = mu;
  f.stick_slope = stick_slope;
  for (auto& step : m.steps) step.interaction_friction = {f};
}

void check_tangent_by_finite_differences(const char* scheme_name, Real stabilisation,
                                         Real mu = 0) {
  fixtures::TwoBlocks t;
  t.lower = {"C3D8", 3, 1};
  t.upper = {"C3D20", 2, 1};
  t.upper_size = 0.7;
  t.rotation_deg = 17;
  t.offset_x = 0.05;
  model::Model m = fixtures::two_blocks_model(t, 1e5, scheme(scheme_name));
  if (mu > 0) add_friction(m, mu, 3e4);
  ContactSystem sys(m);
  sys.begin_step(m.steps[0]);
  VecX u = pressed(m, 2e-3, 3);
  sys.begin_increment(0.5 * u, {.step = 2}, 1);
  if (mu > 0 && mu < 1)  // slipping: the upper block dragged well beyond the stick range
    for (int n = 0; n < m.n_nodes(); ++n)
      if (m.mesh.node_ids[n] >= 100000) u(3 * n) += 1e-3;
  sys.set_stabilisation(stabilisation);
  VecX f0;
  MatX K;
  // Evaluations past the re-pairing window (8): the pairing stays fixed, so the residual is a
  // smooth function of u and K must be its derivative.
  for (int k = 0; k < 8; ++k) sys.update(u, 1);
  assembled(sys, u, f0, &K);
  ASSERT_GT(sys.n_active(), 0);
  const Real h = 1e-7, scale = K.cwiseAbs().maxCoeff();
  VecX fp, fm;
  int checked = 0;
  for (int d = 0; d < u.size(); ++d) {
    if (K.col(d).cwiseAbs().maxCoeff() == 0) continue;
    VecX up = u, um = u;
    up(d) += h;
    um(d) -= h;
    assembled(sys, up, fp, nullptr);
    assembled(sys, um, fm, nullptr);
    const VecX fd = (fp - fm) / (2 * h);
    EXPECT_LT((fd - K.col(d)).cwiseAbs().maxCoeff(), 1e-4 * scale) << "dof " << d;
    ++checked;
  }
  EXPECT_GT(checked, 50);
  if (mu > 0) {  // the case is what its name says
    EXPECT_GT(sys.n_sticking() + sys.n_slipping(), 0);
    EXPECT_EQ(sys.n_slipping() > 0, mu < 1) << sys.n_sticking() << " stick, " << sys.n_slipping();
  }
  if (mu == 0 || sys.n_slipping() == 0) {
    EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-10 * scale);
  }
}

TEST_P(EveryScheme, AssembledTangentMatchesFiniteDifferences) {
  check_tangent_by_finite_differences(GetParam(), 0);
}

TEST_P(EveryScheme, AssembledTangentWithStabilisationSpringsMatchesFiniteDifferences) {
  check_tangent_by_finite_differences(GetParam(), 0.3);
}

TEST_P(EveryScheme, AssembledTangentWithStickingFrictionMatchesFiniteDifferences) {
  check_tangent_by_finite_differences(GetParam(), 0, 100);
}

TEST_P(EveryScheme, AssembledTangentWithSlippingFrictionMatchesFiniteDifferences) {
  check_tangent_by_finite_differences(GetParam(), 0, 0.002);
}

INSTANTIATE_TEST_SUITE_P(ContactSystem, EveryScheme,
                         ::testing::Values("nts", "gauss", "lgauss", "gc1", "gc7", "lgc1", "lgc3",
                                           "lgc7", "lgc12"));

TEST_P(EveryScheme, SmallStrainPressesOnUndeformedAreasAndNlgeomOnDeformedOnes) {
  // Both blocks stretched 1 % in plane, the upper one lowered by a uniform depth: the slave
  // points carry the undeformed area in small strain (a pressure is then the stress under
  // it, as the Poisson patch test checks) and the deformed one under NLGEOM (Cauchy).
  for (const bool nlgeom : {false, true}) {
    fixtures::TwoBlocks t;
    t.lower = {"C3D8", 3, 1};
    t.upper = {"C3D8", 2, 1};
    t.upper_size = 0.6;
    const Real stretch = 0.01, depth = 1e-4, penalty = 1e5;
    model::Model m = fixtures::two_blocks_model(t, penalty, scheme(GetParam()));
    m.steps[0].nlgeom = nlgeom;
    ContactSystem sys(m);
    sys.begin_step(m.steps[0]);
    VecX u = upper_lowered(m, depth);
    for (int n = 0; n < m.n_nodes(); ++n)
      for (int c = 0; c < 2; ++c) u(3 * n + c) = stretch * (m.mesh.coords(n, c) - 0.5);
    sys.begin_increment(u, {.step = 2}, 1);
    for (int k = 0; k < 8; ++k) sys.update(u, 1);
    VecX f;
    assembled(sys, u, f, nullptr);
    sys.commit();
    Real area = 0, pressure = 0, push = 0;
    for (const auto& r : committed_points(sys, u)) {
      area += r.area;
      pressure = std::max(pressure, r.pressure);  // uniform: K depth (the law's, for nts)
    }
    for (int n = 0; n < m.n_nodes(); ++n)
      if (m.mesh.node_ids[n] >= 100000) push -= f(3 * n + 2);  // internal force: pushed up
    const Real expected = 0.36 * (nlgeom ? (1 + stretch) * (1 + stretch) : 1);
    EXPECT_NEAR(area, expected, 1e-10) << (nlgeom ? "NLGEOM" : "small strain");
    EXPECT_NEAR(pressure, penalty * depth, 0.01 * penalty * depth);
    EXPECT_NEAR(push, pressure * expected, 1e-10) << (nlgeom ? "NLGEOM" : "small strain");
  }
}

TEST(ContactSystem, GaussCutAreasSumToEachSlaveFaceArea) {
  // Upper faces fully inside the master surface: the overlap areas of each slave face add up
  // to its area, for linear and quadratic, quad and triangle faces, rotated and offset.
  for (const char* type : {"C3D8", "C3D20", "C3D6", "C3D15"}) {
    for (const char* lower : {"C3D8", "C3D20R"}) {
      fixtures::TwoBlocks t;
      t.lower = {lower, 3, 1};
      t.upper = {type, 2, 1};
      t.upper_size = 0.6;
      t.rotation_deg = 31;
      t.offset_x = 0.04;
      t.offset_y = -0.03;
      model::Model m = fixtures::two_blocks_model(t, 1e5, scheme("lgc7"));
      ContactSystem sys(m);
      const VecX u = VecX::Zero(3 * m.n_nodes());
      sys.begin_increment(u, {.step = 1}, 1);
      sys.update(u, 1);
      sys.commit();
      std::map<std::pair<int, int>, Real> area;
      for (const auto& r : committed_points(sys, u)) area[{r.slave_element, r.slave_face}] += r.area;
      const ContactSurface slave = make_contact_surface(m, m.surfaces.at("SLAVE"));
      ASSERT_EQ(area.size(), slave.faces.size()) << type;
      for (const auto& f : slave.faces) {
        const Real exact = face_area(face_geometry(f, m.mesh.coords, u));
        EXPECT_NEAR((area[{f.element, f.face}]), exact, 1e-12 * exact) << type << " on " << lower;
      }
      // Touching surfaces (gap 0 up to round-off, closed in step 1): every point is active.
      EXPECT_EQ(sys.n_active(), static_cast<int>(committed_points(sys, u).size()));
    }
  }
}

TEST(ContactSystem, FarApartSurfacesGetNoCandidates) {
  fixtures::TwoBlocks t;
  t.gap = 5.0;
  model::Model m = fixtures::two_blocks_model(t, 1e5, scheme("lgc7"));
  ContactSystem sys(m);
  const VecX u = VecX::Zero(3 * m.n_nodes());
  sys.begin_increment(u, {.step = 2}, 1);
  EXPECT_TRUE(sys.groups().empty());
  sys.update(u, 1);
  EXPECT_EQ(sys.n_active(), 0);
  EXPECT_TRUE(committed_points(sys, u).empty());
}

TEST(ContactSystem, InitialOverlapIsRampedOutOverStepOne) {
  // Overlap 1e-3 at the start of step 1: at the end of an increment reaching 40 % of the step,
  // 60 % of the overlap is still subtracted, so the effective overclosure is 0.4e-3.
  fixtures::TwoBlocks t;
  t.gap = -1e-3;
  model::Model m = fixtures::two_blocks_model(t, 1e5, scheme("lgc3"));
  ContactSystem sys(m);
  const VecX u = VecX::Zero(3 * m.n_nodes());
  sys.begin_increment(u, {.step = 1, .increment = 1, .fraction_start = 0, .fraction_end = 0.4}, 1);
  sys.update(u, 1);
  sys.commit();
  for (const auto& r : committed_points(sys, u)) EXPECT_NEAR(r.clearance, -0.4e-3, 1e-12);
  EXPECT_NEAR(sys.max_pressure(), 1e5 * 0.4e-3, 1e-6);
  // In a later step the overlap counts in full.
  sys.begin_increment(u, {.step = 2}, 1);
  sys.update(u, 1);
  sys.commit();
  for (const auto& r : committed_points(sys, u)) EXPECT_NEAR(r.clearance, -1e-3, 1e-12);
}

TEST(ContactSystem, APointThatArrivesAfterThePairingEvaluationsGetsItsElement) {
  // Upper block 0.01 above the lower one: paired with the faces under it at the increment's
  // start, but without contact elements (beyond the creation clearance c0 sqrt(A)). Moved
  // 0.011 down once the solve no longer pairs every point, its points are 1e-3 deep in faces
  // they were offered: as they stand (no evaluation there yet) they carry nothing, which the
  // acceptance refuses and pairs again; evaluated there, they get their elements and press.
  // The linear variant evaluates its frozen points in every update: nothing to pair again.
  for (const char* name : {"nts", "gc7", "lgc7"}) {
    SCOPED_TRACE(name);
    const bool linear = std::string(name) == "lgc7";
    fixtures::TwoBlocks t;
    t.gap = 0.01;
    model::Model m = fixtures::two_blocks_model(t, 1e5, scheme(name));
    ContactSystem sys(m);
    const VecX u0 = VecX::Zero(3 * m.n_nodes());
    const VecX u = upper_lowered(m, 0.011);
    sys.begin_increment(u0, {.step = 2}, 1);
    for (int evaluation = 0; evaluation < 12; ++evaluation) sys.update(u0, 1);
    EXPECT_EQ(sys.n_active(), 0);
    EXPECT_EQ(sys.missed_contact(u).depth, 0);  // every face under the points was offered
    if (linear) {
      sys.update(u, 1);
      EXPECT_GT(sys.n_active(), 0);
      EXPECT_EQ(sys.unheld_penetration(u).depth, 0);
      EXPECT_TRUE(sys.accept(u, /*check_drift=*/false).accepted);
      continue;
    }
    EXPECT_NEAR(sys.unheld_penetration(u).depth, 1e-3, 1e-9);
    const Acceptance again = sys.accept(u, /*check_drift=*/false);
    EXPECT_FALSE(again.accepted);
    EXPECT_TRUE(again.required);
    EXPECT_TRUE(again.pair_again);
    EXPECT_NE(again.reason.find("without contact element penetrates its master by 0.001"),
              std::string::npos);
    sys.update(u, 1);  // evaluation 14: past the pairing evaluations
    const int pressing = sys.n_active();
    EXPECT_GT(pressing, 0);
    EXPECT_EQ(sys.unheld_penetration(u).depth, 0);
    EXPECT_TRUE(sys.accept(u, /*check_drift=*/false).accepted);
    sys.pair_again();  // and paired again from scratch, they press alike
    for (int evaluation = 0; evaluation < 12; ++evaluation) sys.update(u, 1);
    EXPECT_EQ(sys.n_active(), pressing);
  }
}

TEST(ContactSystem, AStabilisedSolveCreatesContactElementsAndDeletesNone) {
  // Upper block 0.01 above the lower one, beyond the creation clearance: its points have no
  // contact elements at the solve's pairing. Pushed 1e-3 into the lower block later in a
  // stabilised solve, they get them (a rocking punch must meet the next ring of nodes there),
  // and keep them when lifted back (the tension tail of the quasi-bilinear law: no chatter).
  // An ordinary solve past its pairing evaluations creates and keeps them alike.
  for (const char* name : {"nts", "gc7"}) {
    SCOPED_TRACE(name);
    fixtures::TwoBlocks t;
    t.gap = 0.01;
    model::Model m = fixtures::two_blocks_model(t, 1e5, scheme(name));
    const VecX u0 = VecX::Zero(3 * m.n_nodes());
    const VecX u = upper_lowered(m, 0.011);
    ContactSystem stabilised(m);
    stabilised.begin_increment(u0, {.step = 2}, 1);
    stabilised.set_stabilisation(1e-2);
    stabilised.update(u0, 1);
    EXPECT_EQ(stabilised.n_active(), 0);
    stabilised.update(u, 1);
    const int created = stabilised.n_active();
    EXPECT_GT(created, 0);
    EXPECT_EQ(stabilised.unheld_penetration(u).depth, 0);
    stabilised.update(u0, 1);
    EXPECT_EQ(stabilised.n_active(), created);
    ContactSystem ordinary(m);
    ordinary.begin_increment(u0, {.step = 2}, 1);
    for (int evaluation = 0; evaluation < 12; ++evaluation) ordinary.update(u0, 1);
    EXPECT_EQ(ordinary.n_active(), 0);
    ordinary.update(u, 1);
    EXPECT_EQ(ordinary.n_active(), created);
    ordinary.update(u0, 1);
    EXPECT_EQ(ordinary.n_active(), created);
  }
}

TEST(ContactSystem, AStepStopsWhereItWouldCarryAnOpenPointThroughItsMaster) {
  // Upper block 0.01 above the lower one. A step of 0.02 down would carry every point 0.01
  // through: half of it reaches contact. A step of 0.005 reaches nothing. Tilted so that only
  // the nodes at the far edge go 0.02 down (nts), half of it again. Once the block presses
  // 5e-4 deep, a further step down carries the pressing points along: nothing to stop. The
  // linear variant's steps are never cut (its frozen points are all evaluated in each update).
  for (const char* name : {"nts", "gc7", "lgc7"}) {
    SCOPED_TRACE(name);
    fixtures::TwoBlocks t;
    t.gap = 0.01;
    model::Model m = fixtures::two_blocks_model(t, 1e5, scheme(name));
    ContactSystem sys(m);
    const VecX u0 = VecX::Zero(3 * m.n_nodes());
    const auto down = [&](Real uniform, Real tilt) {
      VecX d = VecX::Zero(3 * m.n_nodes());
      for (int n = 0; n < m.n_nodes(); ++n)
        if (m.mesh.node_ids[n] >= 100000)
          d(3 * n + 2) = -uniform - tilt * (m.mesh.coords(n, 0) - t.offset_x);
      return d;
    };
    sys.begin_increment(u0, {.step = 2}, 1);
    sys.update(u0, 1);
    EXPECT_FALSE(sys.wants_line_search(2));  // nothing active
    const bool linear = std::string(name) == "lgc7";  // its steps are not cut
    EXPECT_NEAR(sys.step_fraction_to_contact(u0, down(0.02, 0)), linear ? 1 : 0.5, 1e-12);
    EXPECT_EQ(sys.step_fraction_to_contact(u0, down(0.005, 0)), 1);
    if (std::string(name) == "nts") {
      EXPECT_NEAR(sys.step_fraction_to_contact(u0, down(0, 0.02)), 0.5, 1e-12);
    }
    const VecX pressed = down(0.0105, 0);
    sys.update(pressed, 1);
    ASSERT_GT(sys.n_active(), 0);
    EXPECT_EQ(sys.step_fraction_to_contact(pressed, down(0.001, 0)), 1);
    // The line search from the second iteration on while contact is active: always for the
    // linear variant, for the others in the solves that pair once (a stabilised one here).
    EXPECT_EQ(sys.wants_line_search(2), linear);
    sys.set_stabilisation(1e-2);
    sys.update(pressed, 1);
    EXPECT_FALSE(sys.wants_line_search(1));
    EXPECT_TRUE(sys.wants_line_search(2));
  }
}

TEST(ContactSystem, StabilisationSpringsActOnTheChangeOfTheGapSinceTheIncrementStarted) {
  // Upper block 0.01 above the lower one: no contact. Moved down by 0.004 within the
  // increment, every paired point's spring (factor * K per unit area) is stretched by 0.004:
  // energy 1/2 f K A 0.004^2 over the slave area A, force f K A 0.004, all of it carried by
  // the springs. Moved back to where the increment started, the springs are slack.
  for (const char* name : {"lgc7", "gc7", "nts"}) {
    fixtures::TwoBlocks t;
    t.gap = 0.01;
    model::Model m = fixtures::two_blocks_model(t, 1e5, scheme(name));
    ContactSystem sys(m);
    const VecX u0 = VecX::Zero(3 * m.n_nodes());
    const VecX u = upper_lowered(m, 0.004);
    sys.begin_increment(u0, {.step = 2}, 1);
    sys.set_stabilisation(1e-2);
    sys.update(u, 1);
    EXPECT_EQ(sys.n_active(), 0) << name;
    const Real area = t.upper_size * t.upper_size, k = 1e-2 * 1e5;
    EXPECT_NEAR(sys.stabilisation_energy(), 0.5 * k * area * 0.004 * 0.004, 1e-9) << name;
    EXPECT_EQ(sys.stabilisation_share(), 1);
    VecX f;
    assembled(sys, u, f, nullptr);
    Real fz = 0;
    for (int n = 0; n < m.n_nodes(); ++n)
      if (m.mesh.node_ids[n] >= 100000) fz += f(3 * n + 2);
    EXPECT_NEAR(fz, -k * area * 0.004, 1e-9) << name;  // internal force: the springs pull back
    // 0.006 of the gap is left: the springs that move the block 1.2 * 0.006 further under the
    // same load are 0.004 / (0.004 + 0.0072) as stiff.
    ASSERT_TRUE(sys.approach_ratio().has_value()) << name;
    EXPECT_NEAR(*sys.approach_ratio(), 0.004 / (0.004 + 1.2 * 0.006), 1e-9) << name;
    EXPECT_FALSE(sys.separating()) << name;
    sys.update(-u, 1);  // moved up instead: the loads pull the bodies apart
    EXPECT_TRUE(sys.separating()) << name;
    EXPECT_FALSE(sys.approach_ratio().has_value()) << name;
    sys.update(u0, 1);
    EXPECT_NEAR(sys.stabilisation_energy(), 0, 1e-15) << name;
    sys.set_stabilisation(0);
    sys.update(u, 1);
    EXPECT_EQ(sys.stabilisation_energy(), 0) << name;
  }
}

TEST(ContactSystem, OutputShowsTheCommittedStateAndRollBackDropsTheTrial) {
  // Pressed 1e-3 into the lower block and committed; then an evaluation pressed twice as deep
  // is rolled back: the output and the summary still show the committed state, and a commit
  // after the roll-back keeps it.
  fixtures::TwoBlocks t;
  model::Model m = fixtures::two_blocks_model(t, 1e5, scheme("lgc7"));
  ContactSystem sys(m);
  VecX u = VecX::Zero(3 * m.n_nodes());
  for (int n = 0; n < m.n_nodes(); ++n)
    if (m.mesh.node_ids[n] >= 100000) u(3 * n + 2) = -1e-3;
  sys.begin_increment(VecX::Zero(u.size()), {.step = 2}, 1);
  sys.update(u, 1);
  sys.commit();
  const Real committed_force = sys.total_normal_force();
  EXPECT_NEAR(sys.max_pressure(), 1e5 * 1e-3, 1e-6);
  sys.update(2 * u, 1);
  EXPECT_NEAR(sys.max_pressure(), 1e5 * 1e-3, 1e-6);  // the trial state is not reported
  sys.roll_back();
  sys.commit();
  EXPECT_NEAR(sys.total_normal_force(), committed_force, 1e-12 * committed_force);
  for (const auto& r : committed_points(sys, u)) {
    EXPECT_TRUE(r.active);
    EXPECT_NEAR(r.pressure, 1e5 * 1e-3, 1e-6);
  }
}

TEST(ContactSystem, ANodeOnARidgeOfTheMasterPressesOnBothFacesAlike) {
  // Two blocks meshed alike on a roof (ridge x = 0, slope 0.2 either side), node to surface;
  // the upper one pushed down by d. The ridge's slave nodes lie on the bisector of the two
  // master faces: they press on each with half their area (gap d cos a, force along the
  // faces' normals), so their force is vertical, A K d cos^2 a. Either face alone would tilt
  // it by a. Each slave node is one output record and one active contact.
  const Real slope = 0.2, d = 1e-3, stiffness = 1e5;
  std::ostringstream deck;
  deck << "*NODE\n";
  const Real xs[3] = {-1, 0, 1};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      const int n = 1 + i + 3 * j;
      const Real z = -slope * std::abs(xs[i]);
      deck << n << ", " << xs[i] << ", " << j << ", " << z << "\n"            // roof, lower
           << 10 + n << ", " << xs[i] << ", " << j << ", -1.5\n"             // lower bottom
           << 20 + n << ", " << xs[i] << ", " << j << ", " << z << "\n"      // roof, upper
           << 30 + n << ", " << xs[i] << ", " << j << ", 1.0\n";             // upper top
    }
  deck << "*ELEMENT, TYPE=C3D8, ELSET=LOWER\n1, 11, 12, 15, 14, 1, 2, 5, 4\n"
          "2, 12, 13, 16, 15, 2, 3, 6, 5\n"
          "*ELEMENT, TYPE=C3D8, ELSET=UPPER\n3, 21, 22, 25, 24, 31, 32, 35, 34\n"
          "4, 22, 23, 26, 25, 32, 33, 36, 35\n"
          "*SURFACE, NAME=SLAVE\nUPPER, S1\n*SURFACE, NAME=MASTER\nLOWER, S2\n"
          "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.\n"
          "*SOLID SECTION, ELSET=LOWER, MATERIAL=M\n*SOLID SECTION, ELSET=UPPER, MATERIAL=M\n"
          "*SURFACE INTERACTION, NAME=SI\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n"
       << stiffness << "\n*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO SURFACE\nSLAVE, MASTER\n"
          "*STEP\n*STATIC\n*END STEP\n";
  const model::Model m = inp::read_deck_text(deck.str(), "roof.inp");
  ContactSystem sys(m);
  sys.begin_step(m.steps[0]);
  VecX u = VecX::Zero(3 * m.n_nodes());
  for (int n = 0; n < m.n_nodes(); ++n)
    if (m.mesh.node_ids[n] > 20) u(3 * n + 2) = -d;
  sys.begin_increment(u, {.step = 2}, 1);
  VecX f;
  assembled(sys, u, f, nullptr);
  const Real cos_a = 1 / std::hypot(1.0, slope);
  const Real pressure = pressure_overclosure(
      make_pressure_law(m.interactions[0].behavior, false), d * cos_a).pressure;
  const Real ridge_area = 0.5 / cos_a;  // a quarter of each of the two slave faces at the node
  for (int n = 0; n < m.n_nodes(); ++n) {
    if (m.mesh.node_ids[n] != 22 && m.mesh.node_ids[n] != 25) continue;
    EXPECT_NEAR(std::abs(f(3 * n + 2)), ridge_area * pressure * cos_a, 1e-9);
    EXPECT_LT(std::abs(f(3 * n)), 1e-12 * std::abs(f(3 * n + 2))) << m.mesh.node_ids[n];
    EXPECT_LT(std::abs(f(3 * n + 1)), 1e-12 * std::abs(f(3 * n + 2)));
  }
  Vec3 resultant = Vec3::Zero();
  for (int n = 0; n < m.n_nodes(); ++n)
    if (m.mesh.node_ids[n] > 20) resultant += f.segment<3>(3 * n);
  EXPECT_LT(std::abs(resultant.x()), 1e-12 * std::abs(resultant.z()));
  sys.commit();
  const auto records = committed_points(sys, u);
  EXPECT_EQ(records.size(), 6u);
  EXPECT_EQ(sys.n_active(), 6);
  for (const auto& r : records) {
    EXPECT_TRUE(r.active);
    EXPECT_NEAR(r.clearance, -d * cos_a, 1e-12);
    EXPECT_NEAR(r.pressure, pressure, 1e-9);
  }
}

TEST(AdjustSlaveNodes, MovesNodesWithinTheDistanceOntoTheMaster) {
  for (const auto& [gap, distance, moves] : {std::tuple{1e-3, 1e-2, true}, {1e-3, 1e-4, false},
                                             {-1e-3, 0.0, true}}) {
    fixtures::TwoBlocks t;
    t.upper = {"C3D20", 2, 1};
    t.gap = gap;
    model::Model m = fixtures::two_blocks_model(t, 1e5, scheme("lgc7"));
    m.contact_pairs[0].adjust_distance = distance;
    const ContactSurface slave = make_contact_surface(m, m.surfaces.at("SLAVE"));
    EXPECT_EQ(adjust_slave_nodes(m), moves ? static_cast<int>(slave.nodes.size()) : 0);
    for (int n : slave.nodes) EXPECT_NEAR(m.mesh.coords(n, 2), moves ? 1.0 : 1 + gap, 1e-12);
  }
  // ADJUST=nset moves exactly the set's nodes, whatever their distance.
  fixtures::TwoBlocks t;
  t.gap = 0.05;
  model::Model m = fixtures::two_blocks_model(t, 1e5, scheme("lgc7"));
  const ContactSurface slave = make_contact_surface(m, m.surfaces.at("SLAVE"));
  m.node_sets["ADJ"] = {"ADJ", {slave.nodes[0], slave.nodes[1]}};
  m.contact_pairs[0].adjust_set = "ADJ";
  EXPECT_EQ(adjust_slave_nodes(m), 2);
  EXPECT_NEAR(m.mesh.coords(slave.nodes[0], 2), 1.0, 1e-12);
  EXPECT_NEAR(m.mesh.coords(slave.nodes[2], 2), 1.05, 1e-12);
}

TEST(ContactSystem, FrozenDriftIgnoresRoundOffWithoutOverclosure) {
  // Flat blocks touching with an overclosure of one ulp (a tied interface in pure shear): the
  // gaps of fresh projections after a slide differ from the frozen ones by round-off only,
  // which is no drift, however small the overclosure.
  fixtures::TwoBlocks t;
  t.lower = {"C3D8", 3, 1};
  t.upper = {"C3D8", 2, 1};
  model::Model m = fixtures::two_blocks_model(t, 1e5, scheme("lgc7"));
  ContactSystem sys(m);
  VecX u = VecX::Zero(3 * m.n_nodes());
  for (int n = 0; n < m.n_nodes(); ++n)
    if (m.mesh.node_ids[n] >= 100000) u(3 * n + 2) = -std::numeric_limits<Real>::epsilon();
  sys.begin_increment(u, {.step = 1}, 1);
  for (int n = 0; n < m.n_nodes(); ++n)
    if (m.mesh.node_ids[n] >= 100000) u(3 * n) = 0.0123;
  sys.update(u, 1);
  ASSERT_GT(sys.n_active(), 0);
  EXPECT_EQ(sys.frozen_drift(u), 0);
  EXPECT_TRUE(sys.accept(u).accepted);
}

/// The lower block's top bent into a bowl z = 1 - 0.3 (x - 0.5)^2 (C3D20, 6 x 6) under a small
/// flat block (0.2 wide), lgc7.
model::Model bowl_under_small_block() {
  fixtures::TwoBlocks t;
  t.lower = {"C3D20", 6, 1};
  t.upper = {"C3D8", 2, 1};
  t.upper_size = 0.2;
  model::Model m = fixtures::two_blocks_model(t, 1e5, scheme("lgc7"));
  for (int n = 0; n < m.n_nodes(); ++n)
    if (m.mesh.node_ids[n] < 100000 && m.mesh.coords(n, 2) > 1 - 1e-9)
      m.mesh.coords(n, 2) -= 0.3 * std::pow(m.mesh.coords(n, 0) - 0.5, 2);
  return m;
}

/// The upper block of the bowl slid 0.2 along x and lowered with the bowl's surface.
VecX slid_along_the_bowl(const model::Model& m, const VecX& u) {
  VecX slid = u;
  for (int n = 0; n < m.n_nodes(); ++n)
    if (m.mesh.node_ids[n] >= 100000) {
      slid(3 * n) = 0.2;
      slid(3 * n + 2) -= 0.3 * 0.2 * 0.2;
    }
  return slid;
}

TEST(ContactSystem, FrozenDriftSeesSlidingOverACurvedMaster) {
  // Lower block's top bent into a bowl z = 1 - 0.3 (x - 0.5)^2; a small flat block pressed on
  // its bottom. Without sliding the frozen gaps are exact; after sliding 0.2 along x the
  // frozen projections are far from the surface under the points.
  const model::Model m = bowl_under_small_block();
  ContactSystem sys(m);
  const VecX u = upper_lowered(m, 1e-3);
  sys.begin_increment(u, {.step = 2}, 1);
  sys.update(u, 1);
  ASSERT_GT(sys.n_active(), 0);
  EXPECT_LT(sys.frozen_drift(u), 1e-9);
  EXPECT_TRUE(sys.accept(u).accepted);
  VecX slid = u;
  for (int n = 0; n < m.n_nodes(); ++n)
    if (m.mesh.node_ids[n] >= 100000) slid(3 * n) = 0.2;
  sys.update(slid, 1);
  EXPECT_GT(sys.frozen_drift(slid), 1.0);
  const Acceptance redo = sys.accept(slid);
  EXPECT_FALSE(redo.accepted);
  // The drift grows with the square of the increment: the redo aims at 80 % of the tolerance.
  EXPECT_NEAR(redo.redo_factor, std::sqrt(0.8 * 0.1 / sys.frozen_drift(slid)), 1e-12);
}

TEST(ContactSystem, ARefreezeAtTheSolutionRemovesTheDrift) {
  // The bowl of the test above, slid 0.2 within the increment and lowered with the bowl's
  // surface: frozen again there, the gaps are those of fresh projections, and it stands.
  const model::Model m = bowl_under_small_block();
  ContactSystem sys(m);
  const VecX u = upper_lowered(m, 1e-3);
  sys.begin_increment(u, {.step = 2}, 1);
  const VecX slid = slid_along_the_bowl(m, u);
  sys.update(slid, 1);
  ASSERT_GT(sys.frozen_drift(slid), 0.1);  // redone smaller without the refreeze
  sys.refreeze(slid, u, 1);
  sys.update(slid, 1);
  ASSERT_GT(sys.n_active(), 0);
  EXPECT_LT(sys.frozen_drift(slid), 1e-9);
  EXPECT_TRUE(sys.accept(slid).accepted);
}

TEST(ContactSystem, TheLinearVariantsFreezeWhereTheIncrementIsPredictedToEnd) {
  // The slide of the refreeze test above, predicted at the increment's start: lgc7 freezes
  // there, so the solution at the prediction has no drift to refreeze; a nonlinear variant
  // pairs at the converged state whatever the prediction.
  model::Model m = bowl_under_small_block();
  const VecX u = upper_lowered(m, 1e-3);
  const VecX slid = slid_along_the_bowl(m, u);
  ContactSystem predicted(m), plain(m);
  predicted.begin_increment(u, {.step = 2}, 1, &slid);
  plain.begin_increment(u, {.step = 2}, 1);
  predicted.update(slid, 1);
  plain.update(slid, 1);
  ASSERT_GT(predicted.n_active(), 0);
  EXPECT_LT(predicted.frozen_drift(slid), 1e-9);
  EXPECT_TRUE(predicted.accept(slid).accepted);
  EXPECT_GT(plain.frozen_drift(slid), 0.1);
  // Not ahead: the prediction equal to the converged state changes nothing.
  ContactSystem still(m);
  still.begin_increment(u, {.step = 2}, 1, &u);
  still.update(slid, 1);
  EXPECT_EQ(still.frozen_drift(slid), plain.frozen_drift(slid));

  for (auto& pair : m.contact_pairs) pair.scheme = scheme("gc7");
  ContactSystem nonlinear_predicted(m), nonlinear_plain(m);
  nonlinear_predicted.begin_increment(u, {.step = 2}, 1, &slid);
  nonlinear_plain.begin_increment(u, {.step = 2}, 1);
  EXPECT_EQ(nonlinear_predicted.groups(), nonlinear_plain.groups());
}

TEST(ContactSystem, ARefreezeKeepsTheFrictionOfTheWholeIncrement) {
  // Flat blocks pressed and dragged 0.01 along x within one sticking increment: frozen again at
  // the dragged state, the points still see the drag since the increment's start, so the
  // friction force is the same (measured from the refreeze it would vanish).
  fixtures::TwoBlocks t;
  t.lower = {"C3D8", 3, 1};
  t.upper = {"C3D8", 2, 1};
  t.upper_size = 0.5;
  t.offset_x = 0.1;
  model::Model m = fixtures::two_blocks_model(t, 1e5, scheme("lgc7"));
  add_friction(m, 100, 3e4);
  ContactSystem sys(m);
  sys.begin_step(m.steps[0]);
  const VecX u = upper_lowered(m, 1e-3);
  sys.begin_increment(u, {.step = 2}, 1);
  VecX dragged = u;
  for (int n = 0; n < m.n_nodes(); ++n)
    if (m.mesh.node_ids[n] >= 100000) dragged(3 * n) = 0.01;
  const auto upper_shear = [&](const VecX& f) {
    Real sum = 0;
    for (int n = 0; n < m.n_nodes(); ++n)
      if (m.mesh.node_ids[n] >= 100000) sum += f(3 * n);
    return sum;
  };
  VecX before, after;
  assembled(sys, dragged, before, nullptr);
  ASSERT_GT(sys.n_sticking(), 0);
  ASSERT_GT(std::abs(upper_shear(before)), 0);
  sys.refreeze(dragged, u, 1);
  assembled(sys, dragged, after, nullptr);
  EXPECT_NEAR(upper_shear(after), upper_shear(before), 1e-9 * std::abs(upper_shear(before)));
  // So does a geometry frozen at the predicted end of the increment.
  ContactSystem predicted(m);
  predicted.begin_step(m.steps[0]);
  predicted.begin_increment(u, {.step = 2}, 1, &dragged);
  assembled(predicted, dragged, after, nullptr);
  EXPECT_NEAR(upper_shear(after), upper_shear(before), 1e-9 * std::abs(upper_shear(before)));
}

TEST(ContactSystem, AMissedContactIsRedoneWhateverTheScheme) {
  // A small block pressed on a 6 x 6 block, then slid 0.5 along x within one increment: far
  // beyond the faces the increment's search offered it (two face sizes, 0.2): the fresh search
  // sees its points inside the lower block, 1e-3 deep, on faces that were no candidates.
  for (const char* name : {"nts", "gc7", "lgc7"}) {
    SCOPED_TRACE(name);
    fixtures::TwoBlocks t;
    t.lower = {"C3D8", 6, 1};
    t.upper = {"C3D8", 2, 1};
    t.upper_size = 0.2;
    t.offset_x = -0.25;
    model::Model m = fixtures::two_blocks_model(t, 1e5, scheme(name));
    ContactSystem sys(m);
    VecX u = VecX::Zero(3 * m.n_nodes());
    for (int n = 0; n < m.n_nodes(); ++n)
      if (m.mesh.node_ids[n] >= 100000) u(3 * n + 2) = -1e-3;
    sys.begin_increment(u, {.step = 2}, 1);
    sys.update(u, 1);
    ASSERT_GT(sys.n_active(), 0);
    EXPECT_EQ(sys.missed_contact(u).depth, 0);
    EXPECT_TRUE(sys.accept(u).accepted);
    VecX slid = u;
    for (int n = 0; n < m.n_nodes(); ++n)
      if (m.mesh.node_ids[n] >= 100000) slid(3 * n) = 0.5;
    for (int evaluation = 0; evaluation < 3; ++evaluation) sys.update(slid, 1);  // re-pairing
    // Every scheme: the nonlinear ones lost their faces, the linear one pushes on faces that
    // are no longer under its points (exact gaps on the flat extended faces, wrong master nodes).
    EXPECT_NEAR(sys.missed_contact(slid).depth, 1e-3, 1e-9);
    const Acceptance redo = sys.accept(slid, /*check_drift=*/false);
    EXPECT_FALSE(redo.accepted);
    EXPECT_TRUE(redo.required);
    EXPECT_EQ(redo.redo_factor, 0.5);
    EXPECT_NE(redo.reason.find("contact search missed a penetration of 0.001"), std::string::npos);
  }
}

TEST(ContactSystem, FrozenDriftSeesAPointItsFrozenGeometryHoldsFarFromTheMaster) {
  // A steep bowl z = 1 - (x - 0.5)^2 under a finely meshed small block. Slid by 0.2 along x and
  // lifted by 0.03, the points frozen on the left slope still overclose their (tilted, extended)
  // faces, while the bowl under them is now about 0.04 away: beyond the slave faces' own size,
  // where the near fresh search looks. The far search finds it: a drift, not "no master".
  fixtures::TwoBlocks t;
  t.lower = {"C3D20", 6, 1};
  t.upper = {"C3D8", 20, 1};
  t.upper_size = 0.2;
  model::Model m = fixtures::two_blocks_model(t, 1e5, scheme("lgc7"));
  for (int n = 0; n < m.n_nodes(); ++n)
    if (m.mesh.node_ids[n] < 100000 && m.mesh.coords(n, 2) > 1 - 1e-9)
      m.mesh.coords(n, 2) -= std::pow(m.mesh.coords(n, 0) - 0.5, 2);
  ContactSystem sys(m);
  VecX u = VecX::Zero(3 * m.n_nodes());
  for (int n = 0; n < m.n_nodes(); ++n)
    if (m.mesh.node_ids[n] >= 100000) u(3 * n + 2) = -1e-3;
  sys.begin_increment(u, {.step = 2}, 1);
  sys.update(u, 1);
  EXPECT_TRUE(sys.accept(u).accepted);
  VecX slid = u;
  for (int n = 0; n < m.n_nodes(); ++n)
    if (m.mesh.node_ids[n] >= 100000) {
      slid(3 * n) = 0.2;
      slid(3 * n + 2) += 0.03;
    }
  sys.update(slid, 1);
  ASSERT_GT(sys.n_active(), 0);
  EXPECT_GT(sys.frozen_drift(slid), 1.0);
  EXPECT_FALSE(sys.accept(slid).accepted);
}
