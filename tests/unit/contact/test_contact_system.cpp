// The contact system on two stacked blocks: integration-point areas, the assembled contact
// force against finite differences of the assembled tangent for every scheme, and pairing.
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <tuple>

#include "contact/adjust_nodes.hpp"
#include "contact/contact_system.hpp"
#include "contact/contact_surface.hpp"
#include "two_blocks.hpp"

using namespace kontakt;
using namespace kontakt::contact;

namespace {

model::ContactScheme scheme(const std::string& name) { return *model::contact_scheme_from_name(name); }

/// Contact force (full dof vector) and dense tangent at u from the system's groups.
void assembled(ContactSystem& sys, const VecX& u, int evaluation, VecX& f, MatX* K) {
  sys.evaluate(u, evaluation, 1);
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

}  // namespace

class EveryScheme : public ::testing::TestWithParam<const char*> {};

TEST_P(EveryScheme, AssembledTangentMatchesFiniteDifferences) {
  fixtures::TwoBlocks t;
  t.lower = {"C3D8", 3, 1};
  t.upper = {"C3D20", 2, 1};
  t.upper_size = 0.7;
  t.rotation_deg = 17;
  t.offset_x = 0.05;
  model::Model m = fixtures::two_blocks_model(t, 1e5, scheme(GetParam()));
  ContactSystem sys(m);
  const VecX u = pressed(m, 2e-3, 3);
  sys.begin_increment(u, {.step = 2}, 1);
  VecX f0;
  MatX K;
  // Evaluations past the re-pairing window: the pairing stays fixed, so the residual is a
  // smooth function of u and K must be its derivative.
  assembled(sys, u, 20, f0, &K);
  ASSERT_GT(sys.n_active(), 0);
  const Real h = 1e-7, scale = K.cwiseAbs().maxCoeff();
  VecX fp, fm;
  int checked = 0;
  for (int d = 0; d < u.size(); ++d) {
    if (K.col(d).cwiseAbs().maxCoeff() == 0) continue;
    VecX up = u, um = u;
    up(d) += h;
    um(d) -= h;
    assembled(sys, up, 20, fp, nullptr);
    assembled(sys, um, 20, fm, nullptr);
    const VecX fd = (fp - fm) / (2 * h);
    EXPECT_LT((fd - K.col(d)).cwiseAbs().maxCoeff(), 1e-4 * scale) << "dof " << d;
    ++checked;
  }
  EXPECT_GT(checked, 50);
  EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-10 * scale);
}

INSTANTIATE_TEST_SUITE_P(ContactSystem, EveryScheme,
                         ::testing::Values("nts", "gauss", "lgauss", "gc1", "gc7", "lgc1", "lgc3",
                                           "lgc7", "lgc12"));

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
      sys.evaluate(u, 1, 1);
      std::map<std::pair<int, int>, Real> area;
      for (const auto& r : sys.records(u)) area[{r.slave_element, r.slave_face}] += r.area;
      const ContactSurface slave = make_contact_surface(m, m.surfaces.at("SLAVE"));
      ASSERT_EQ(area.size(), slave.faces.size()) << type;
      for (const auto& f : slave.faces) {
        const Real exact = face_area(face_geometry(f, m.mesh.coords, u));
        EXPECT_NEAR((area[{f.element, f.face}]), exact, 1e-12 * exact) << type << " on " << lower;
      }
      // Touching surfaces (gap 0 up to round-off, closed in step 1): every point is active.
      EXPECT_EQ(sys.n_active(), static_cast<int>(sys.records(u).size()));
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
  sys.evaluate(u, 1, 1);
  EXPECT_EQ(sys.n_active(), 0);
  EXPECT_TRUE(sys.records(u).empty());
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
  sys.evaluate(u, 1, 1);
  for (const auto& r : sys.records(u)) EXPECT_NEAR(r.clearance, -0.4e-3, 1e-12);
  EXPECT_NEAR(sys.max_pressure(), 1e5 * 0.4e-3, 1e-6);
  // In a later step the overlap counts in full.
  sys.begin_increment(u, {.step = 2}, 1);
  sys.evaluate(u, 1, 1);
  for (const auto& r : sys.records(u)) EXPECT_NEAR(r.clearance, -1e-3, 1e-12);
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

TEST(ContactSystem, FrozenDriftSeesSlidingOverACurvedMaster) {
  // Lower block's top bent into a bowl z = 1 - 0.3 (x - 0.5)^2; a small flat block pressed on
  // its bottom. Without sliding the frozen gaps are exact; after sliding 0.2 along x the
  // frozen projections are far from the surface under the points.
  fixtures::TwoBlocks t;
  t.lower = {"C3D20", 6, 1};
  t.upper = {"C3D8", 2, 1};
  t.upper_size = 0.2;
  model::Model m = fixtures::two_blocks_model(t, 1e5, scheme("lgc7"));
  for (int n = 0; n < m.n_nodes(); ++n)
    if (m.mesh.node_ids[n] < 100000 && m.mesh.coords(n, 2) > 1 - 1e-9)
      m.mesh.coords(n, 2) -= 0.3 * std::pow(m.mesh.coords(n, 0) - 0.5, 2);
  ContactSystem sys(m);
  VecX u = VecX::Zero(3 * m.n_nodes());
  for (int n = 0; n < m.n_nodes(); ++n)
    if (m.mesh.node_ids[n] >= 100000) u(3 * n + 2) = -1e-3;
  sys.begin_increment(u, {.step = 2}, 1);
  sys.evaluate(u, 1, 1);
  ASSERT_GT(sys.n_active(), 0);
  EXPECT_LT(sys.frozen_drift(u), 1e-9);
  VecX slid = u;
  for (int n = 0; n < m.n_nodes(); ++n)
    if (m.mesh.node_ids[n] >= 100000) slid(3 * n) = 0.2;
  sys.evaluate(slid, 2, 1);
  EXPECT_GT(sys.frozen_drift(slid), 1.0);
}
