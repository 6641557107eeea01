// *CYCLIC SYMMETRY MODEL: the sector rotation, the pairing of dependent and independent nodes,
// and the equations it adds to a model read from a deck.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "contact/cyclic_symmetry.hpp"
#include "contact/tie_constraints.hpp"
#include "core/error.hpp"
#include "inp/read_deck.hpp"

namespace kontakt::contact {
namespace {

constexpr Real kDeg = std::numbers::pi / 180;

/// An annular sector r in [r0, r0 + 1], theta in [0, 30 deg], z in [0, 0.5], 2 x 2 x 1 C3D8,
/// node label 100 i + 10 j + k (radial i, angular j, axial k); node sets THETA0 and THETA30;
/// a tie DEP (the set `dependent`) to IND (the other) with its cyclic model of 12 sectors about
/// the axis through (0, 0, 0) and (0, 0, 1); `moved` shifts node 121 by that much in z.
std::string sector_deck(Real r0, const std::string& dependent, Real moved = 0) {
  std::ostringstream d;
  d << "*NODE\n";
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j)
      for (int k = 0; k <= 1; ++k) {
        const Real r = r0 + 0.5 * i, t = 15.0 * j * kDeg;
        const Real z = 0.5 * k + (100 * i + 10 * j + k == 121 ? moved : 0);
        d << 100 * i + 10 * j + k << ", " << r * std::cos(t) << ", " << r * std::sin(t) << ", "
          << z << "\n";
      }
  d << "*ELEMENT, TYPE=C3D8, ELSET=EALL\n";
  int e = 1;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const int n = 100 * i + 10 * j;
      d << e++ << ", " << n << ", " << n + 100 << ", " << n + 110 << ", " << n + 10 << ", "
        << n + 1 << ", " << n + 101 << ", " << n + 111 << ", " << n + 11 << "\n";
    }
  d << "*NSET, NSET=THETA0\n0, 1, 100, 101, 200, 201\n"
       "*NSET, NSET=THETA30\n20, 21, 120, 121, 220, 221\n";
  const std::string independent = dependent == "THETA30" ? "THETA0" : "THETA30";
  d << "*SURFACE, NAME=DEP, TYPE=NODE\n" << dependent << "\n"
    << "*SURFACE, NAME=IND, TYPE=NODE\n" << independent << "\n"
    << "*TIE, NAME=CS, CYCLIC SYMMETRY, POSITION TOLERANCE=0.001\nDEP, IND\n"
    << "*CYCLIC SYMMETRY MODEL, N=12, TIE=CS, ELSET=EALL\n0., 0., 0., 0., 0., 1.\n"
    << "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*SOLID SECTION, ELSET=EALL, MATERIAL=M\n"
    << "*STEP\n*STATIC\n*BOUNDARY\n1, 3, 3\n*END STEP\n";
  return d.str();
}

int node(const model::Model& m, int label) {
  for (std::size_t k = 0; k < m.mesh.node_ids.size(); ++k)
    if (m.mesh.node_ids[k] == label) return static_cast<int>(k);
  return -1;
}

TEST(CyclicSymmetry, AxisRotationIsRightHandedAboutATiltedAxis) {
  const Mat3 about_z = axis_rotation(Vec3(0, 0, 5), Vec3(0, 0, 7), 90 * kDeg);
  EXPECT_LT((about_z * Vec3(1, 0, 0) - Vec3(0, 1, 0)).norm(), 1e-15);
  const Vec3 from(1, -2, 0.5), to(3, 1, 2);
  const Mat3 r = axis_rotation(from, to, 37 * kDeg);
  EXPECT_LT((r * r.transpose() - Mat3::Identity()).norm(), 1e-15);
  EXPECT_NEAR(r.determinant(), 1, 1e-15);
  EXPECT_LT((r * (to - from) - (to - from)).norm(), 1e-14);  // the axis stays
  EXPECT_NEAR(std::acos((r.trace() - 1) / 2), 37 * kDeg, 1e-14);
}

TEST(CyclicSymmetry, EachDependentNodeMovesAsItsPartnerTurnedBySector) {
  model::Model m = inp::read_deck_text(sector_deck(1.0, "THETA30"), "sector.inp");
  apply_ties(m);
  ASSERT_EQ(m.equations.size(), 18u);  // 6 dependent nodes, 3 directions
  const Mat3 r = axis_rotation(Vec3::Zero(), Vec3::UnitZ(), 30 * kDeg);
  for (const model::Equation& eq : m.equations) {
    const model::EquationTerm& dep = eq.terms.front();
    EXPECT_EQ(dep.coef, 1.0);
    const int label = m.mesh.node_ids[static_cast<std::size_t>(dep.node)];
    const int partner = node(m, label - 20);  // theta 30 -> theta 0
    for (std::size_t t = 1; t < eq.terms.size(); ++t) {
      EXPECT_EQ(eq.terms[t].node, partner);
      EXPECT_NEAR(eq.terms[t].coef, -r(dep.dof, eq.terms[t].dof), 1e-15);
    }
    EXPECT_EQ(eq.terms.size(), dep.dof == 2 ? 2u : 3u);  // z is along the axis
  }
}

TEST(CyclicSymmetry, TheOtherSideDependentTurnsTheOtherWay) {
  const model::Model m = inp::read_deck_text(sector_deck(1.0, "THETA0"), "sector.inp");
  const auto dependent = make_contact_surface(m, m.surfaces.at("DEP")).nodes;
  const auto independent = make_contact_surface(m, m.surfaces.at("IND")).nodes;
  const SectorPairs found =
      pair_sectors(m.mesh.coords, dependent, independent, m.cyclic_symmetry.front(), 1e-3);
  EXPECT_EQ(found.pairs.size(), 6u);
  EXPECT_TRUE(found.unmatched.empty());
  EXPECT_LT((found.rotation - axis_rotation(Vec3::Zero(), Vec3::UnitZ(), -30 * kDeg)).norm(),
            1e-15);
}

TEST(CyclicSymmetry, PrescribedDependentDofsAreLeftWithAWarning) {
  model::Model m = inp::read_deck_text(sector_deck(1.0, "THETA30"), "sector.inp");
  m.steps.front().boundaries.push_back({node(m, 121), 2, 0.0});
  apply_ties(m);
  EXPECT_EQ(m.equations.size(), 17u);
  ASSERT_FALSE(m.warnings.empty());
  EXPECT_NE(m.warnings.back().find("keep directions already constrained"), std::string::npos);
  EXPECT_NE(m.warnings.back().find("121"), std::string::npos);
}

TEST(CyclicSymmetry, ANodeWithoutPartnerOrOnTheAxisIsAnInputError) {
  model::Model off = inp::read_deck_text(sector_deck(1.0, "THETA30", 0.01), "sector.inp");
  try {
    apply_ties(off);
    FAIL() << "a dependent node without partner was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("have no node of IND one sector away"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("121"), std::string::npos) << e.what();
  }
  model::Model axis = inp::read_deck_text(sector_deck(0.0, "THETA30"), "sector.inp");
  try {
    apply_ties(axis);
    FAIL() << "a node on the axis was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("on the axis are not supported: 20, 21"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace kontakt::contact
