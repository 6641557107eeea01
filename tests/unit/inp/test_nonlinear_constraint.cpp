// *RIGID BODY and *MPC (PLANE, STRAIGHT, MEANROT, DIST): the constraints the reader builds (roles of
// the nodes, dependent dofs, NLGEOM switched on by *MPC as in ccx) and every malformed form
// (run by test_errors.cpp through nonlinear_constraint_bad_decks()). Against ccx 2.20: the
// suite's beamprb, beamrb, beamrb2, beamplane, beamstraight, beammr and beammrlin in
// tests/peer/coverage_baseline.txt.
#include <gtest/gtest.h>

#include "bad_deck.hpp"
#include "deck_fixtures.hpp"
#include "inp/read_deck.hpp"

namespace kontakt::inp {

namespace test {

namespace {

/// The two cubes (lines 1-26) with a reference node 100 and a rotation node 101: lines 27-29;
/// a card appended starts at line 30.
std::string constraint_model() {
  return two_cubes_model() + "*NODE\n100, 2, .5, .5\n101, 0, 0, 0\n";
}

}  // namespace

std::vector<BadDeck> nonlinear_constraint_bad_decks() {
  const auto plus = [](const std::string& tail) { return constraint_model() + tail; };
  const std::string rigid = "*RIGID BODY, NSET=TIP, ";
  return {
      {"rigid body without rot node", plus(rigid + "REF NODE=100\n"), 30, "*RIGID BODY",
       "REF NODE= and ROT NODE= are required here"},
      {"rigid body undefined ref node", plus(rigid + "REF NODE=555, ROT NODE=101\n"), 30,
       "*RIGID BODY", "node 555 (REFNODE=) is not defined"},
      {"rigid body ref node not a label", plus(rigid + "REF NODE=A, ROT NODE=101\n"), 30,
       "*RIGID BODY", "REFNODE=A is not a node label"},
      {"rigid body one node twice", plus(rigid + "REF NODE=100, ROT NODE=100\n"), 30, "*RIGID BODY",
       "must be different nodes"},
      {"rigid body rot node in an element", plus(rigid + "REF NODE=100, ROT NODE=9\n"), 30,
       "*RIGID BODY", "ROT NODE 9 belongs to the rigid body"},
      {"rigid body rot node of the mesh", plus("*RIGID BODY, NSET=TIP, REF NODE=100, ROT NODE=2\n"),
       30, "*RIGID BODY", "ROT NODE 2 belongs to an element"},
      {"rigid body both sets", plus(rigid + "ELSET=EALL, REF NODE=100, ROT NODE=101\n"), 30,
       "*RIGID BODY", "give exactly one of NSET= and ELSET="},
      {"rigid body undefined set", plus("*RIGID BODY, NSET=NOPE, REF NODE=100, ROT NODE=101\n"), 30,
       "*RIGID BODY", "node set NOPE is not defined"},
      {"rigid body data line", plus(rigid + "REF NODE=100, ROT NODE=101\n1, 2\n"), 31,
       "*RIGID BODY", "this card has no data lines"},
      {"mpc beam", plus("*MPC\nBEAM, 1, 2\n"), 31, "*MPC", "MPC type BEAM is not supported"},
      {"mpc plane collinear", plus("*MPC\nPLANE, 1, 2, 9, 5\n"), 31, "*MPC",
       "the three defining nodes lie on one line"},
      {"mpc straight coincident", plus("*NODE\n102, 0, 0, 0\n*MPC\nSTRAIGHT, 1, 102, 5\n"), 33,
       "*MPC", "the two defining nodes coincide"},
      {"mpc plane too few nodes", plus("*MPC\nPLANE, 1, 2, 3\n"), 31, "*MPC",
       "PLANE needs 3 defining nodes and at least one more node"},
      {"mpc node twice", plus("*MPC\nSTRAIGHT, 1, 2, 5, 1\n"), 31, "*MPC",
       "a node is listed twice"},
      {"mpc undefined node", plus("*MPC\nSTRAIGHT, 1, 2, 77\n"), 31, "*MPC",
       "node 77 is not defined"},
      {"meanrot not three times", plus("*MPC\nMEANROT, 9, 9, 10, 10, 10, 101\n"), 31, "*MPC",
       "MEANROT lists each node three times"},
      {"meanrot not in a row", plus("*MPC\nMEANROT, 9, 10, 9, 10, 9, 10, 101\n"), 31, "*MPC",
       "node 9 is not listed three times in a row"},
      {"meanrot zero axis",
       plus("*MPC\nMEANROT, 9, 9, 9, 10, 10, 10, 11, 11, 11, 12, 12, 12, 101\n"), 31, "*MPC",
       "the coordinates of node 101 (the rotation axis) are zero"},
      {"meanrot node on the axis",
       plus("*NODE\n102, 0, 1, 0\n*MPC\nMEANROT, 9, 9, 9, 10, 10, 10, 102\n"), 33, "*MPC",
       "node 9 lies on the rotation axis through the nodes' centre"},
      {"dist not three times", plus("*MPC\nDIST, 12, 12, 1, 1, 1, 100\n"), 31, "*MPC",
       "DIST lists node a three times, node b three times"},
      {"dist one node both ends", plus("*MPC\nDIST, 12, 12, 12, 12, 12, 12, 100\n"), 31, "*MPC",
       "DIST: node 12 is both ends"},
      {"dist no distance", plus("*MPC\nDIST, 12, 12, 12, 1, 1, 1, 101\n"), 31, "*MPC",
       "the first coordinate of node 101 (the largest distance) must be positive"},
      {"dist coincident ends", plus("*NODE\n102, 0, 0, 0\n*MPC\nDIST, 1, 1, 1, 102, 102, 102, 100\n"),
       33, "*MPC", "DIST: nodes 1 and 102 coincide"},
  };
}

}  // namespace test

namespace {

using Kind = model::NonlinearConstraint::Kind;

TEST(inpNonlinearConstraint, ARigidBodyTiesEveryNodeButTheReferenceInEachComponent) {
  const model::Model m = read_deck_text(
      test::constraint_model() +
      "*NSET, NSET=BODY\n9, 10, 11, 12, 100\n*RIGID BODY, NSET=BODY, REF NODE=100, ROT NODE=101\n");
  ASSERT_EQ(m.nonlinear_constraints.size(), 12u);  // the reference node itself is not tied
  const auto& idx = m.mesh.node_index;
  for (std::size_t k = 0; k < 12; ++k) {
    const auto& c = m.nonlinear_constraints[k];
    EXPECT_EQ(c.kind, Kind::Rigid);
    EXPECT_EQ(c.nodes,
              (std::vector<int>{idx.at(9 + static_cast<int>(k / 3)), idx.at(100), idx.at(101)}));
    EXPECT_EQ(c.component, static_cast<int>(k % 3));
    EXPECT_EQ(c.where.line, 32);
  }
  EXPECT_TRUE(m.steps.empty() || !m.steps.front().nlgeom);
}

TEST(inpNonlinearConstraint, MpcSolvesAcrossThePlaneAndTheLineAndSwitchesNlgeomOn) {
  const model::Model m =
      read_deck_text(test::constraint_model() +
                     "*NSET, NSET=P\n5, 1, 2, 6\n*MPC\nPLANE, P\n*MPC\nSTRAIGHT, 1, 9, 3, 0,\n4\n"
                     "*STEP\n*STATIC\n*END STEP\n");
  ASSERT_EQ(m.nonlinear_constraints.size(), 1u + 4u);
  const auto& idx = m.mesh.node_index;
  const auto& plane = m.nonlinear_constraints[0];  // the set in its definition order
  EXPECT_EQ(plane.nodes, (std::vector<int>{idx.at(6), idx.at(5), idx.at(1), idx.at(2)}));
  EXPECT_EQ(plane.component, 1);         // the plane y = 0
  for (std::size_t k = 1; k < 5; ++k) {  // nodes 3 and 4 on the x axis: y and z constrained
    const auto& line = m.nonlinear_constraints[k];
    EXPECT_EQ(line.kind, Kind::Straight);
    EXPECT_EQ(line.nodes, (std::vector<int>{idx.at(k < 3 ? 3 : 4), idx.at(1), idx.at(9)}));
    EXPECT_EQ(line.pivot, 0);
    EXPECT_EQ(line.component, k % 2 ? 1 : 2);
  }
  ASSERT_EQ(m.steps.size(), 1u);
  EXPECT_TRUE(m.steps.front().nlgeom);
}

TEST(inpNonlinearConstraint, DistTakesItsLimitFromTheThirdNodeAndSwitchesNlgeomOn) {
  const model::Model m = read_deck_text(test::constraint_model() +
                                        "*MPC\nDIST, 12, 12, 12, 1, 1, 1, 100\n"
                                        "*STEP\n*STATIC\n*END STEP\n");
  ASSERT_EQ(m.nonlinear_constraints.size(), 1u);
  const auto& c = m.nonlinear_constraints.front();
  EXPECT_EQ(c.kind, Kind::Distance);
  EXPECT_EQ(c.nodes, (std::vector<int>{m.mesh.node_index.at(12), m.mesh.node_index.at(1)}));
  EXPECT_EQ(c.distance, 2);   // node 100's x
  EXPECT_EQ(c.component, 0);  // node 12 lies farthest from node 1 in x
  EXPECT_TRUE(m.steps.front().nlgeom);
}

TEST(inpNonlinearConstraint, MeanRotationKeepsItsStepLinear) {
  const model::Model m = read_deck_text(
      test::constraint_model() +
      "*NODE\n102, 1, 0, 0\n*MPC\nMEANROT, 9, 9, 9, 10, 10, 10, 12, 12, 12, 11, 11, 11, 102\n"
      "*STEP\n*STATIC\n*END STEP\n");
  ASSERT_EQ(m.nonlinear_constraints.size(), 1u);
  const auto& c = m.nonlinear_constraints.front();
  EXPECT_EQ(c.kind, Kind::MeanRotation);
  ASSERT_EQ(c.nodes.size(), 5u);
  EXPECT_EQ(c.nodes.back(), m.mesh.node_index.at(102));
  EXPECT_NE(c.component, 0);  // nothing turns about x in x
  EXPECT_FALSE(m.steps.front().nlgeom);
}

}  // namespace
}  // namespace kontakt::inp
