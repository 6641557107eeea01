// T3D2 truss kernel (analysis/truss through analysis/connector): the axial force against the
// closed forms of ccx's expanded brick (linear, St. Venant-Kirchhoff under NLGEOM), tangents
// against central differences of the force, the force against differences of the energy, and
// the printed point values against the force; the Newton driver on ccx's truss.inp and on a
// mechanism.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <Eigen/Geometry>

#include "analysis/connector.hpp"
#include "analysis/nonlinear_static.hpp"
#include "analysis/truss.hpp"
#include "collect_results.hpp"
#include "inp/read_deck.hpp"

using namespace kontakt;
using analysis::connector_response;

namespace {

using testing_decks::Collect;

model::Connector truss() {
  model::Connector c;
  c.kind = model::Connector::Kind::Truss;
  c.area = 0.04;
  c.young = 2000.0;
  c.poisson = 0.3;
  return c;
}

const Vec3 X1(0.1, -0.2, 0.3), X2(1.3, 0.4, -0.5);

analysis::ConnectorResponse at(const model::Connector& c, const Vec6& u, bool nlgeom) {
  return connector_response(c, X1, X2, u.head<3>(), u.tail<3>(), nlgeom);
}

/// Largest relative error of the tangent's columns against central differences of the force,
/// and of the force against central differences of the energy.
std::pair<Real, Real> consistency_errors(const model::Connector& c, const Vec6& u, bool nlgeom) {
  const auto r = at(c, u, nlgeom);
  const Real h = 1e-6;
  Real tangent_error = 0, force_error = 0;
  for (int j = 0; j < 6; ++j) {
    Vec6 up = u, um = u;
    up[j] += h;
    um[j] -= h;
    const auto rp = at(c, up, nlgeom), rm = at(c, um, nlgeom);
    const Vec6 column = (rp.force - rm.force) / (2 * h);
    tangent_error = std::max(tangent_error, (r.stiffness.col(j) - column).norm() /
                                                 (r.stiffness.norm()));
    force_error = std::max(force_error, std::abs(r.force[j] - (rp.energy - rm.energy) / (2 * h)) /
                                            (r.force.norm() + 1e-30));
  }
  return {tangent_error, force_error};
}

Vec6 displacement() {
  Vec6 u;
  u << 0.01, 0.05, -0.03, 0.08, -0.06, 0.04;  // a stretch of a few per cent and a rotation
  return u;
}

}  // namespace

TEST(Truss, LinearForceIsEAOverLTimesTheAxialElongation) {
  const model::Connector c = truss();
  const Vec6 u = displacement();
  const Vec3 A = (X2 - X1).normalized();
  const Real L = (X2 - X1).norm();
  const auto r = at(c, u, false);
  const Real N = c.young * c.area / L * A.dot(u.tail<3>() - u.head<3>());
  EXPECT_NEAR((r.force.tail<3>() - N * A).norm(), 0, 1e-13);
  EXPECT_NEAR((r.force.head<3>() + r.force.tail<3>()).norm(), 0, 1e-13);
  const auto [tangent_error, force_error] = consistency_errors(c, u, false);
  std::printf("linear: tangent vs FD %.1e, force vs FD of energy %.1e\n", tangent_error,
              force_error);
  EXPECT_LT(tangent_error, 1e-8);
  EXPECT_LT(force_error, 1e-8);
}

TEST(Truss, NlgeomForceIsTheStVenantKirchhoffBarsAlongTheCurrentAxis) {
  const model::Connector c = truss();
  const Vec6 u = displacement();
  const Vec3 d = X2 + u.tail<3>() - X1 - u.head<3>();
  const Real L = (X2 - X1).norm(), stretch = d.norm() / L;
  const Real green = 0.5 * (stretch * stretch - 1);
  const auto r = at(c, u, true);
  EXPECT_NEAR((r.force.tail<3>() - c.young * c.area * stretch * green * d.normalized()).norm(), 0,
              1e-12);
  EXPECT_NEAR(r.energy, 0.5 * c.young * c.area * L * green * green, 1e-15);
  const auto [tangent_error, force_error] = consistency_errors(c, u, true);
  std::printf("NLGEOM: tangent vs FD %.1e, force vs FD of energy %.1e\n", tangent_error,
              force_error);
  EXPECT_LT(tangent_error, 1e-7);
  EXPECT_LT(force_error, 1e-7);
  // stiffness symmetric
  EXPECT_NEAR((r.stiffness - r.stiffness.transpose()).norm(), 0, 1e-12 * r.stiffness.norm());
}

TEST(Truss, NlgeomRigidRotationCarriesNoForce) {
  const model::Connector c = truss();
  const Vec3 L0 = X2 - X1;
  const Mat3 R = Eigen::AngleAxis<Real>(0.7, Vec3(1, 2, -1).normalized()).toRotationMatrix();
  Vec6 u = Vec6::Zero();
  u.tail<3>() = R * L0 - L0;
  EXPECT_NEAR(at(c, u, true).force.norm(), 0, 1e-12);
  const auto p = analysis::truss_point_output(c, X1, X2, u.head<3>(), u.tail<3>(), true);
  EXPECT_NEAR(p.stress.norm(), 0, 1e-10);
}

TEST(Truss, PointsPrintTheAxialStressInGlobalComponents) {
  // truss.inp of the ccx suite: a 45 degree bar in the x-z plane prints sigma / 2 in xx, zz, xz.
  model::Connector c = truss();
  const Vec3 a(0, 0, 0), b(5, 0, 5);
  const Vec3 axis = (b - a).normalized();
  const Real eps = 1e-3;
  const Vec3 u2 = eps * (b - a).norm() * axis;
  const auto p = analysis::truss_point_output(c, a, b, Vec3::Zero(), u2, false);
  const Real sigma = c.young * eps;
  EXPECT_NEAR(p.stress[0], sigma / 2, 1e-12);
  EXPECT_NEAR(p.stress[2], sigma / 2, 1e-12);
  EXPECT_NEAR(p.stress[4], sigma / 2, 1e-12);
  EXPECT_NEAR(p.stress[1] * p.stress[1] + p.stress[3] * p.stress[3] + p.stress[5] * p.stress[5], 0,
              1e-24);
  // lateral contraction nu eps; energy E eps^2 / 2 per volume, A L of it the bar's energy
  EXPECT_NEAR(p.strain[1], -c.poisson * eps, 1e-15);
  EXPECT_NEAR(p.strain[0] + p.strain[1] + p.strain[2], (1 - 2 * c.poisson) * eps, 1e-15);
  EXPECT_NEAR(p.energy_density, 0.5 * c.young * eps * eps, 1e-15);
  const auto r = connector_response(c, a, b, Vec3::Zero(), u2, false);
  EXPECT_NEAR(r.energy, p.energy_density * c.area * (b - a).norm(), 1e-15);
}

TEST(Truss, NlgeomPointsPrintCauchyStressOverTheShrunkSection) {
  const model::Connector c = truss();
  const Vec6 u = displacement();
  const auto r = at(c, u, true);
  const auto p = analysis::truss_point_output(c, X1, X2, u.head<3>(), u.tail<3>(), true);
  const Vec3 d = X2 + u.tail<3>() - X1 - u.head<3>();
  const Vec3 a = d.normalized();
  const Real L = (X2 - X1).norm(), green = 0.5 * (d.squaredNorm() / (L * L) - 1);
  Mat3 S;
  S << p.stress[0], p.stress[3], p.stress[4], p.stress[3], p.stress[1], p.stress[5], p.stress[4],
      p.stress[5], p.stress[2];
  // sigma times the current section A (1 - 2 nu E_11) is the axial force (here compressive)
  EXPECT_NEAR(a.dot(S * a) * c.area * (1 - 2 * c.poisson * green), r.force.tail<3>().dot(a),
              1e-12);
  EXPECT_NEAR((S - a.dot(S * a) * a * a.transpose()).norm(), 0, 1e-12);
  EXPECT_NEAR(p.energy_density * c.area * L, r.energy, 1e-15);
}

namespace {

/// ccx's truss.inp: two bars at 45 degrees in the x-z plane pinned at their far ends, pulled
/// at their joint along x; `load` replaces that *CLOAD line.
std::string two_bars(const std::string& load = "2, 1, 1.") {
  return "*NODE, NSET=NALL\n1, 0, 0, 0\n2, 5, 0, 5\n3, 0, 0, 10\n"
         "*ELEMENT, TYPE=T3D2, ELSET=EALL\n1, 1, 2\n2, 2, 3\n*BOUNDARY\n1, 1, 3\n3, 1, 3\n"
         "*MATERIAL, NAME=ALUM\n*ELASTIC\n1E7, .3\n*SOLID SECTION, ELSET=EALL, MATERIAL=ALUM\n"
         ".0625\n*STEP\n*STATIC\n*CLOAD\n" + load + "\n*END STEP\n";
}

}  // namespace

TEST(TrussAnalysis, AJointFreeAcrossItsUnloadedBarsIsSolvedWithAWarning) {
  Collect c;
  analysis::run_nonlinear_static(inp::read_deck_text(two_bars()), {}, c, c);
  const output::Frame& f = c.frames.back();
  // ccx's truss.dat.ref: 11.3137 / 2 in xx, zz and +-xz
  ASSERT_EQ(f.truss_S.rows(), 2);
  for (int bar = 0; bar < 2; ++bar) {
    EXPECT_NEAR(f.truss_S(bar, 0), 5.656854, 1e-6);
    EXPECT_NEAR(f.truss_S(bar, 2), 5.656854, 1e-6);
    EXPECT_NEAR(f.truss_S(bar, 4), bar == 0 ? 5.656854 : -5.656854, 1e-6);
  }
  // the reactions carry the load (to the stabilised solve's residual)
  EXPECT_NEAR(f.RF.row(0).sum() + f.RF.row(2).sum(), -1.0, 1e-8);
  bool warned = false;
  for (const auto& e : c.events)
    warned |= e.kind == analysis::Event::Kind::Warning &&
              e.message.find("zero-energy mode at node 2 dof y") != std::string::npos;
  EXPECT_TRUE(warned);
  EXPECT_EQ(f.U(1, 1), 0.0);
}

TEST(TrussAnalysis, ABarLoadedAcrossItsFreeJointIsASingularSystem) {
  for (const bool nlgeom : {false, true}) {
    std::string deck = two_bars("2, 2, 1.");
    if (nlgeom) deck.replace(deck.find("*STEP\n"), 6, "*STEP, NLGEOM\n");
    Collect c;
    try {
      analysis::run_nonlinear_static(inp::read_deck_text(deck), {}, c, c);
      ADD_FAILURE() << "a mechanism loaded in its free direction converged";
    } catch (const NonConvergence& e) {  // every cutback meets the same singular system
      EXPECT_NE(std::string(e.what()).find("loads excite its zero-energy mode at node 2 dof y"),
                std::string::npos)
          << e.what();
    }
  }
}
