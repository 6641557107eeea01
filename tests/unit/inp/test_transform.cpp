// *TRANSFORM: the frames it gives the nodes of its set, the last card winning, and every
// malformed form (run by test_errors.cpp through transform_bad_decks()).
#include <gtest/gtest.h>

#include "bad_deck.hpp"
#include "deck_fixtures.hpp"
#include "inp/read_deck.hpp"

namespace kontakt::inp {

namespace test {

std::vector<BadDeck> transform_bad_decks() {
  // The two cubes end at line 26: a *TRANSFORM appended is line 27, its data line 28.
  const auto plus = [](const std::string& tail) { return two_cubes_model() + tail; };
  const std::string step = "*STEP\n*STATIC\n";
  return {
      {"transform without nset", plus("*TRANSFORM\n1, 0, 0, 0, 1, 0\n"), 27, "*TRANSFORM",
       "NSET= is required"},
      {"transform unknown set", plus("*TRANSFORM, NSET=NOPE\n1, 0, 0, 0, 1, 0\n"), 27,
       "*TRANSFORM", "node set NOPE is not defined"},
      {"transform unknown type", plus("*TRANSFORM, NSET=FIX, TYPE=S\n1, 0, 0, 0, 1, 0\n"), 27,
       "*TRANSFORM", "TYPE=S: expected R (rectangular) or C (cylindrical)"},
      {"transform five numbers", plus("*TRANSFORM, NSET=FIX\n1, 0, 0, 0, 1\n"), 28,
       "*TRANSFORM", "expected at least 6 field(s)"},
      {"transform two lines", plus("*TRANSFORM, NSET=FIX\n1, 0, 0, 0, 1, 0\n1, 0, 0, 0, 1, 0\n"),
       29, "*TRANSFORM", "expected at most 1 data line"},
      {"transform not a number", plus("*TRANSFORM, NSET=FIX\n1, 0, 0, 0, one, 0\n"), 28,
       "*TRANSFORM", "one"},
      {"transform b on the x axis", plus("*TRANSFORM, NSET=FIX\n1, 0, 0, 2, 0, 0\n"), 28,
       "*TRANSFORM", "point b lies on the local x' axis"},
      {"transform a at the origin", plus("*TRANSFORM, NSET=FIX\n0, 0, 0, 0, 1, 0\n"), 28,
       "*TRANSFORM", "is the origin"},
      {"cylinder axis points coincide", plus("*TRANSFORM, NSET=FIX, TYPE=C\n0, 0, 5, 0, 0, 5\n"),
       28, "*TRANSFORM", "points a and b of the axis coincide"},
      {"node file local with transforms",
       plus("*TRANSFORM, NSET=FIX\n0, 1, 0, 0, 0, 1\n" + step + "*NODE FILE, GLOBAL=NO\nU\n"
            "*END STEP\n"),
       31, "*NODE FILE", "GLOBAL=NO: results files hold global components only"},
  };
}

}  // namespace test

namespace {

TEST(inpTransform, FramesForTheSetNodesTheLastCardWins) {
  const model::Model m = read_deck_text(test::two_cubes_model() +
                                        "*TRANSFORM, NSET=FIX\n0, 1, 0, 0, 0, 1\n"
                                        "*TRANSFORM, NSET=TIP, TYPE=C\n0, 0, 0, 0, 0, 1\n"
                                        "*NSET, NSET=ONE\n9\n"
                                        "*TRANSFORM, NSET=ONE, TYPE=R\n1, 0, 0, 0, 0, 1\n");
  ASSERT_EQ(m.local_frames.size(), 8u);  // FIX (1, 4, 5, 8) and TIP (9..12)
  const auto frame = [&](int label) { return m.local_frames.at(m.mesh.node_index.at(label)); };
  EXPECT_LT((frame(4).col(0) - Vec3(0, 1, 0)).norm(), 1e-15);  // TYPE=R is the default
  EXPECT_LT((frame(4).col(2) - Vec3(1, 0, 0)).norm(), 1e-15);
  // Node 10 at (2, 1, 0) on the cylinder about z: radial (2, 1, 0)/sqrt5.
  EXPECT_LT((frame(10).col(0) - Vec3(2, 1, 0) / std::sqrt(5.0)).norm(), 1e-15);
  EXPECT_LT((frame(10).col(2) - Vec3(0, 0, 1)).norm(), 1e-15);
  // Node 9 was in TIP (cylindrical) and then in ONE: the rectangular frame wins.
  EXPECT_LT((frame(9).col(1) - Vec3(0, 0, 1)).norm(), 1e-15);
  EXPECT_FALSE(m.local_frames.contains(m.mesh.node_index.at(2)));
  EXPECT_TRUE(m.warnings.empty());
}

TEST(inpTransform, NodesOnTheCylinderAxisAreAcceptedWithAWarning) {
  // Nodes 1 and 5 of FIX lie on the z axis: ccx's frame (global axes for an axis along z).
  const model::Model m = read_deck_text(test::two_cubes_model() +
                                            "*TRANSFORM, NSET=FIX, TYPE=C\n0, 0, 0, 0, 0, 1\n",
                                        "deck.inp");
  EXPECT_LT((m.local_frames.at(m.mesh.node_index.at(5)) - Mat3::Identity()).norm(), 1e-15);
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("deck.inp:28: *TRANSFORM: 2 node(s) on the cylinder's axis "
                               "(first: 1)"),
            std::string::npos)
      << m.warnings[0];
}

}  // namespace
}  // namespace kontakt::inp
