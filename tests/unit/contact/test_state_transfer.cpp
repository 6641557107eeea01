// Moving friction states to the next increment's points (thesis 4.3.1): the Delaunay
// triangulation covers the points' hull, a linear field moves exactly, and a face without old
// points passes nothing on.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "contact/state_transfer.hpp"

using namespace kontakt;
using namespace kontakt::contact;
using element::Topology;

namespace {

Real cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

std::vector<Vec2> random_points(int n, unsigned seed, bool triangle) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1, 1), v(0, 1);
  std::vector<Vec2> out;
  while (static_cast<int>(out.size()) < n) {
    const Vec2 p = triangle ? Vec2(v(rng), v(rng)) : Vec2(u(rng), u(rng));
    if (!triangle || p.sum() < 1) out.push_back(p);
  }
  return out;
}

MatX linear_field(const std::vector<Vec2>& xi) {
  MatX v(static_cast<Index>(xi.size()), 6);
  for (std::size_t k = 0; k < xi.size(); ++k)
    for (int c = 0; c < 6; ++c) v(k, c) = 0.3 * c + (1 + c) * xi[k].x() - 0.7 * c * xi[k].y();
  return v;
}

}  // namespace

TEST(StateTransfer, DelaunayTilesTheSquare) {
  std::vector<Vec2> points = corner_coordinates(Topology::Quad4);
  for (const Vec2& p : random_points(40, 3, false)) points.push_back(p);
  const auto tris = delaunay(points);
  Real area = 0;
  for (const auto& t : tris) {
    const Real a = 0.5 * cross2(points[t[1]] - points[t[0]], points[t[2]] - points[t[0]]);
    EXPECT_GT(a, 0);  // counter-clockwise, none degenerate
    area += a;
    // Empty circumcircles: no other point inside (the Delaunay property).
    for (std::size_t k = 0; k < points.size(); ++k) {
      if (static_cast<int>(k) == t[0] || static_cast<int>(k) == t[1] || static_cast<int>(k) == t[2])
        continue;
      const Vec2 da = points[t[0]] - points[k], db = points[t[1]] - points[k],
                 dc = points[t[2]] - points[k];
      const Real det = da.squaredNorm() * cross2(db, dc) - db.squaredNorm() * cross2(da, dc) +
                       dc.squaredNorm() * cross2(da, db);
      EXPECT_LE(det, 1e-12);
    }
  }
  EXPECT_NEAR(area, 4.0, 1e-12);
}

TEST(StateTransfer, ALinearFieldMovesExactly) {
  for (const Topology face : {Topology::Quad4, Topology::Quad8, Topology::Tri3, Topology::Tri6}) {
    const bool tri = face == Topology::Tri3 || face == Topology::Tri6;
    const std::vector<Vec2> old_xi = random_points(28, 11, tri), new_xi = random_points(50, 12, tri);
    const MatX old_states = linear_field(old_xi);
    const MatX corners = corner_states(face, old_xi, old_states);
    const MatX moved = transfer_states(face, old_xi, old_states, corners, new_xi);
    EXPECT_LT((moved - linear_field(new_xi)).cwiseAbs().maxCoeff(), 1e-10);
  }
}

TEST(StateTransfer, AFaceWithoutOldPointsPassesNothingOn) {
  const MatX moved = transfer_states(Topology::Quad4, {}, MatX(0, 6), MatX::Zero(4, 6),
                                     random_points(7, 5, false));
  EXPECT_EQ(moved.rows(), 7);
  EXPECT_EQ(moved.cwiseAbs().maxCoeff(), 0);
}

TEST(StateTransfer, InterpolationStaysWithinTheValuesOfTheOldPointsAndCorners) {
  // A convex combination inside the triangulation: no value beyond the extremes given.
  const std::vector<Vec2> old_xi = random_points(9, 21, false), new_xi = random_points(60, 22, false);
  MatX old_states(9, 6);
  std::mt19937 rng(4);
  std::uniform_real_distribution<Real> u(-1, 1);
  for (Index i = 0; i < old_states.size(); ++i) old_states.data()[i] = u(rng);
  const MatX corners = MatX::Constant(4, 6, 0.25);
  const MatX moved = transfer_states(Topology::Quad4, old_xi, old_states, corners, new_xi);
  for (int c = 0; c < 6; ++c) {
    EXPECT_GE(moved.col(c).minCoeff(), std::min(old_states.col(c).minCoeff(), 0.25) - 1e-12);
    EXPECT_LE(moved.col(c).maxCoeff(), std::max(old_states.col(c).maxCoeff(), 0.25) + 1e-12);
  }
}

TEST(StateTransfer, PackingRoundTrips) {
  const FrictionState s{.tangential = Vec3(1, 2, 3), .slip = Vec3(-4, 5, -6)};
  const FrictionState back = unpack(pack(s));
  EXPECT_EQ(back.tangential, s.tangential);
  EXPECT_EQ(back.slip, s.slip);
}
