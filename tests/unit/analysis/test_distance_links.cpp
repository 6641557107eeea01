// *MPC DIST: when a pair links and lets go (DistanceLinks), and the driver holding a tethered
// cube at its distance in between.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/distance_links.hpp"
#include "analysis/nonlinear_static.hpp"
#include "collect_results.hpp"
#include "cube_deck.hpp"
#include "inp/read_deck.hpp"

using namespace kontakt;

namespace {

using testing_decks::Collect;

/// The unit cube on rollers, its corner node 7 (1, 1, 1) tethered to node 1 (0, 0, 0), which
/// the rollers hold, by a DIST of at most `limit` (node 9's x); `step` appended.
std::string tethered_cube(Real limit, const std::string& step) {
  return testing_decks::cube_model("*ELASTIC\n1000, 0.25\n") + testing_decks::kRollers +
         "*NODE\n9, " + std::to_string(limit) + ", 0, 0\n*MPC\nDIST, 7, 7, 7, 1, 1, 1, 9\n" + step;
}

constexpr const char* kNoStep = "*STEP, NLGEOM\n*STATIC\n*BOUNDARY\n9, 1, 1, 0.\n*END STEP\n";

/// Node 7's displacement u7 (node 1 stays at the origin) as a full vector.
VecX moved_corner(const model::Model& m, const Vec3& u7) {
  VecX u = VecX::Zero(3 * m.n_nodes());
  u.segment<3>(3 * m.mesh.node_index.at(7)) = u7;
  return u;
}

}  // namespace

TEST(DistanceLinks, LinksOnceTheDistanceIsReachedAndLetsGoWhenItPushes) {
  const model::Model m = inp::read_deck_text(tethered_cube(1.75, kNoStep), "tether.inp");
  analysis::DistanceLinks links(m);
  ASSERT_EQ(links.in_force().size(), 1u);
  EXPECT_EQ(links.in_force()[0], 0);  // sqrt(3) < 1.75 at rest: free
  EXPECT_TRUE(links.begin_increment().empty());
  // Converged 1.79 apart: the next increment links, and a redone one decides alike.
  const VecX beyond = moved_corner(m, Vec3(0.1, 0, 0));
  links.commit(beyond, VecX::Zero(beyond.size()));
  const std::vector<std::string> changes = links.begin_increment();
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_NE(changes[0].find("tether.inp:28: *MPC DIST between nodes 7 and 1 linked"), std::string::npos)
      << changes[0];
  EXPECT_EQ(links.in_force()[0], 1);
  EXPECT_TRUE(links.begin_increment().empty());
  // Linked, its force on node 7 along -x (towards node 1): it pulls, and stays.
  const int x7 = 3 * m.mesh.node_index.at(7);
  const VecX at_limit = moved_corner(m, Vec3(std::sqrt(1.75 * 1.75 - 2) - 1, 0, 0));
  VecX force = VecX::Zero(at_limit.size());
  force[x7] = -3;
  links.commit(at_limit, force);
  EXPECT_TRUE(links.begin_increment().empty());
  EXPECT_EQ(links.in_force()[0], 1);
  // Along +x: it pushes the nodes apart, and lets go at the next increment.
  force[x7] = 3;
  links.commit(at_limit, force);
  EXPECT_EQ(links.begin_increment().size(), 1u);
  EXPECT_EQ(links.in_force()[0], 0);
}

TEST(DistanceLinks, APairFartherApartThanItsDistanceLinksAtTheFirstIncrement) {
  const model::Model m = inp::read_deck_text(tethered_cube(1.7, kNoStep), "tether.inp");
  analysis::DistanceLinks links(m);
  EXPECT_EQ(links.begin_increment().size(), 1u);
  EXPECT_EQ(links.in_force()[0], 1);
}

TEST(DistanceLinks, ATetheredCubeIsHeldAtTheDistanceOnlyWhileTheTetherPulls) {
  // The cube pulled along x by a load that rises to 100 and falls back to 0 in increments of
  // 0.1. Free, the corner would reach 1.763 from the origin; the tether links one increment
  // after its 1.75 is passed, holds the corner there while it pulls, and lets go one increment
  // after it starts to push. Free again, the cube is where the same load put it on the way up
  // (elastic), and back at rest at the end.
  const std::string deck = tethered_cube(1.75, R"(*AMPLITUDE, NAME=UPDOWN
0., 0., 0.5, 1., 1., 0.
*STEP, NLGEOM, INC=100
*STATIC, DIRECT
0.1, 1.
*BOUNDARY
9, 1, 1, 0.
*CLOAD, AMPLITUDE=UPDOWN
X1, 1, 25.
*END STEP
)");
  const model::Model m = inp::read_deck_text(deck, "tether.inp");
  Collect c;
  analysis::run_nonlinear_static(m, {}, c, c);
  ASSERT_EQ(c.frames.size(), 10u);
  const int n7 = m.mesh.node_index.at(7);
  std::vector<Real> distance;
  for (const auto& f : c.frames)
    distance.push_back((m.mesh.coords.row(n7) + f.U.row(n7)).norm());
  std::size_t first_beyond = 0;
  while (first_beyond < distance.size() && distance[first_beyond] <= 1.75) ++first_beyond;
  ASSERT_LT(first_beyond, 4u) << "the free cube never reaches the tether's length";
  std::size_t released = first_beyond + 1;
  while (released < distance.size() && std::abs(distance[released] - 1.75) < 1e-10) ++released;
  EXPECT_GT(released, first_beyond + 2) << "held for more than one increment";
  ASSERT_LT(released, distance.size() - 1) << "let go before the end";
  EXPECT_LT(distance[released], 1.75);  // let go after it pushed: the free cube is shorter
  // Loads 0.2 (t = 0.1) and 0.8 (t = 0.4) on the way up are those of t = 0.9 and 0.6 down.
  const std::size_t mirror = c.frames.size() - 2 - released;
  EXPECT_NEAR(distance[released], distance[mirror], 1e-9);
  EXPECT_NEAR(distance[8], distance[0], 1e-9);
  EXPECT_LT(c.frames.back().U.cwiseAbs().maxCoeff(), 1e-9);
}
