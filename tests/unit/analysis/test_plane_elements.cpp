// Plane stress, plane strain and axisymmetric elements through the whole linear driver: the
// constant-strain patch test on a distorted 2 x 2 patch for every 2D type (the boundary nodes
// prescribed to a linear field, the interior ones free) must reproduce the field exactly, and
// the stresses of the 3D layer must be the 2D state's (plane strain: s_zz = nu (s_xx + s_yy);
// plane stress: s_zz = 0; axisymmetric: the hoop strain u_r / r).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/linear_static.hpp"
#include "analysis/nonlinear_static.hpp"
#include "collect_results.hpp"
#include "contact/tie_constraints.hpp"
#include "inp/read_deck.hpp"
#include "model/plane_expansion.hpp"

using namespace kontakt;

namespace {

using testing_decks::Collect;

constexpr Real kE = 1000, kNu = 0.3;
constexpr Real kA = 1e-3, kB = -2e-3, kC = 5e-4, kD = 1.5e-3;  // the linear field's slopes

/// Corner grid 3 x 3 over [x0, x0 + 2] x [0, 2] with the centre node moved off the middle;
/// `quadratic` adds midside nodes, `triangles` splits every quad along its 1-3 diagonal.
struct Patch {
  std::vector<Vec2> nodes;            ///< label k + 1
  std::vector<std::vector<int>> elements;
  std::vector<bool> interior;         ///< parallel to nodes
};

Patch make_patch(Real x0, bool quadratic, bool triangles) {
  Patch p;
  auto add = [&](Vec2 x, bool inside) {
    for (std::size_t k = 0; k < p.nodes.size(); ++k)
      if ((p.nodes[k] - x).norm() < 1e-12) return static_cast<int>(k) + 1;
    p.nodes.push_back(x);
    p.interior.push_back(inside);
    return static_cast<int>(p.nodes.size());
  };
  std::array<std::array<Vec2, 3>, 3> grid;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) grid[i][j] = Vec2(x0 + i, j);
  grid[1][1] = Vec2(x0 + 1.15, 0.9);
  const auto on_boundary = [&](const Vec2& x) {
    return std::abs(x.x() - x0) < 1e-12 || std::abs(x.x() - x0 - 2) < 1e-12 ||
           std::abs(x.y()) < 1e-12 || std::abs(x.y() - 2) < 1e-12;
  };
  const auto node = [&](const Vec2& x) { return add(x, !on_boundary(x)); };
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const std::array<Vec2, 4> q{grid[i][j], grid[i + 1][j], grid[i + 1][j + 1], grid[i][j + 1]};
      std::vector<std::vector<Vec2>> cells;
      if (triangles) cells = {{q[0], q[1], q[2]}, {q[0], q[2], q[3]}};
      else cells = {{q[0], q[1], q[2], q[3]}};
      for (const auto& cell : cells) {
        std::vector<int> el;
        for (const Vec2& x : cell) el.push_back(node(x));
        if (quadratic)
          for (std::size_t a = 0; a < cell.size(); ++a)
            el.push_back(node((cell[a] + cell[(a + 1) % cell.size()]) / 2));
        p.elements.push_back(el);
      }
    }
  return p;
}

/// In-plane displacement of the field at x: a general linear field for plane elements, a
/// radial and axial stretch (u_r proportional to r) for axisymmetric ones.
Vec2 field(const Vec2& x, bool axisymmetric) {
  if (axisymmetric) return Vec2(kA * x.x(), kB * x.y());
  return Vec2(kA * x.x() + kC * x.y(), kD * x.x() + kB * x.y());
}

std::string deck(const std::string& type, const Patch& p, bool axisymmetric) {
  std::ostringstream d;
  d.precision(17);
  d << "*NODE, NSET=NALL\n";
  for (std::size_t k = 0; k < p.nodes.size(); ++k)
    d << k + 1 << ", " << p.nodes[k].x() << ", " << p.nodes[k].y() << "\n";
  d << "*ELEMENT, TYPE=" << type << ", ELSET=EALL\n";
  for (std::size_t e = 0; e < p.elements.size(); ++e) {
    d << e + 1;
    for (int n : p.elements[e]) d << ", " << n;
    d << "\n";
  }
  d << "*MATERIAL, NAME=M\n*ELASTIC\n" << kE << ", " << kNu << "\n"
    << "*SOLID SECTION, ELSET=EALL, MATERIAL=M\n0.25\n*STEP\n*STATIC\n*BOUNDARY\n";
  for (std::size_t k = 0; k < p.nodes.size(); ++k) {
    if (p.interior[k]) continue;
    const Vec2 u = field(p.nodes[k], axisymmetric);
    d << k + 1 << ", 1, 1, " << u.x() << "\n" << k + 1 << ", 2, 2, " << u.y() << "\n";
  }
  d << "*END STEP\n";
  return d.str();
}

/// The 3D stress of the 2D strain state (engineering shear gamma).
Vec6 expected_stress(const std::string& type) {
  const Real lambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), mu = kE / (2 * (1 + kNu));
  Vec6 s = Vec6::Zero();
  if (type.starts_with("CAX")) {
    const Real tr = 2 * kA + kB;
    s << lambda * tr + 2 * mu * kA, lambda * tr + 2 * mu * kB, lambda * tr + 2 * mu * kA, 0, 0, 0;
  } else if (type.starts_with("CPE")) {
    const Real tr = kA + kB;
    s << lambda * tr + 2 * mu * kA, lambda * tr + 2 * mu * kB, lambda * tr, mu * (kC + kD), 0, 0;
  } else {
    const Real f = kE / (1 - kNu * kNu);
    s << f * (kA + kNu * kB), f * (kB + kNu * kA), 0, mu * (kC + kD), 0, 0;
  }
  return s;
}

void check_patch(const std::string& type) {
  SCOPED_TRACE(type);
  const bool axisymmetric = type.starts_with("CAX");
  const bool quadratic = type.find('6') != std::string::npos || type.find('8') != std::string::npos;
  const bool triangles = type.find('3') != std::string::npos || type.find('6') != std::string::npos;
  const Patch p = make_patch(axisymmetric ? 1.0 : 0.0, quadratic, triangles);
  const model::Model m = inp::read_deck_text(deck(type, p, axisymmetric), "patch.inp");
  Collect c;
  analysis::run_linear_static(m, {.threads = 1}, c, c);
  ASSERT_EQ(c.frames.size(), 1u);
  const output::Frame& f = c.frames[0];
  const Vec6 s = expected_stress(type);
  for (Index k = 0; k < f.S.rows(); ++k)
    for (int j = 0; j < 6; ++j) EXPECT_NEAR(f.S(k, j), s[j], 1e-9) << "point " << k << " comp " << j;
  // The deck's interior nodes report the field (axisymmetric: the wedge's x, i.e. the mean
  // of the copies at +-1 degree, weighted with the middle copy at quadratic corners).
  const Real cs = std::cos(model::kWedgeHalfAngle);
  for (std::size_t k = 0; k < p.nodes.size(); ++k) {
    if (!p.interior[k]) continue;
    const int n = m.mesh.node_index.at(static_cast<int>(k) + 1);
    const Vec2 u = field(p.nodes[k], axisymmetric);
    Real radial = 1;
    if (axisymmetric) {
      const bool corner = std::any_of(p.elements.begin(), p.elements.end(), [&](const auto& el) {
        const std::size_t n_corner = triangles ? 3 : 4;
        return std::find(el.begin(), el.begin() + static_cast<long>(n_corner),
                         static_cast<int>(k) + 1) != el.begin() + static_cast<long>(n_corner);
      });
      radial = quadratic && corner ? (2 * cs + 4) / 6 : cs;
    }
    EXPECT_NEAR(f.U(n, 0), radial * u.x(), 1e-14) << "node " << k + 1;
    EXPECT_NEAR(f.U(n, 1), u.y(), 1e-14) << "node " << k + 1;
    EXPECT_NEAR(f.U(n, 2), 0.0, 1e-15);  // plane stress: the mean of opposite z motions
  }
}

}  // namespace

TEST(PlaneElements, PlaneStrainPatchTestIsExactForEveryType) {
  for (const char* type : {"CPE3", "CPE4", "CPE4R", "CPE6", "CPE8", "CPE8R"}) check_patch(type);
}

TEST(PlaneElements, PlaneStressPatchTestIsExactForEveryType) {
  for (const char* type : {"CPS3", "CPS4", "CPS4R", "CPS6", "CPS8", "CPS8R"}) check_patch(type);
}

TEST(PlaneElements, AxisymmetricStretchIsExactForEveryType) {
  for (const char* type : {"CAX3", "CAX4", "CAX4R", "CAX6", "CAX8", "CAX8R"}) check_patch(type);
}

TEST(PlaneElements, ReactionsAreTheLayersAndBalanceThePull) {
  // Plane strain strip 2 x 1, thickness 0.25, pulled by 3 at its right edge: the reactions at
  // the left edge sum to -3 (the whole layer's), the stress is 3 / (1 * 0.25).
  const model::Model m = inp::read_deck_text(R"(*NODE, NSET=NALL
1, 0, 0
2, 2, 0
3, 2, 1
4, 0, 1
*ELEMENT, TYPE=CPE4, ELSET=EALL
1, 1, 2, 3, 4
*MATERIAL, NAME=M
*ELASTIC
1000, 0.3
*SOLID SECTION, ELSET=EALL, MATERIAL=M
0.25
*BOUNDARY
1, 1, 2
4, 1
*STEP
*STATIC
*CLOAD
2, 1, 1.5
3, 1, 1.5
*END STEP
)", "strip.inp");
  Collect c;
  analysis::run_linear_static(m, {.threads = 1}, c, c);
  const output::Frame& f = c.frames.at(0);
  EXPECT_NEAR(f.RF(0, 0) + f.RF(3, 0), -3.0, 1e-12);
  EXPECT_NEAR(f.RF(1, 0), 1.5, 1e-12);  // a loaded node: its internal force balances the load
  for (Index k = 0; k < f.S.rows(); ++k) EXPECT_NEAR(f.S(k, 0), 12.0, 1e-10);
}

TEST(PlaneElements, PlateOnARigidBodyTurnsRigidly) {
  // The copies of each 2D node follow it through equations while a *RIGID BODY moves the node
  // itself (nonlinear constraint followed by linear equations): turned 2.5 rad about z and
  // shifted, every node must land where the rigid motion puts it, stress-free. (ccx 2.20's
  // scheibe does this for CPE8R and does not stay rigid: measured, tests/peer/README.md.)
  for (const char* type : {"CPE8R", "CPS4"}) {
    const bool quadratic = std::string(type) == "CPE8R";
    std::ostringstream deck;
    deck << "*NODE, NSET=NALL\n1, 0, 0\n2, 1, 0\n3, 1.2, 0.9\n4, -0.1, 1\n"
         << (quadratic ? "5, 0.5, 0\n6, 1.1, 0.45\n7, 0.55, 0.95\n8, -0.05, 0.5\n" : "")
         << "*NODE, NSET=CENTER\n90, 0.3, 0.2\n91, 0.3, 0.2\n"
         << "*ELEMENT, TYPE=" << type << ", ELSET=EALL\n1, 1, 2, 3, 4"
         << (quadratic ? ", 5, 6, 7, 8\n" : "\n")
         << "*MATERIAL, NAME=M\n*ELASTIC\n210000, 0.3\n*SOLID SECTION, ELSET=EALL, MATERIAL=M\n"
            "0.1\n*RIGID BODY, NSET=NALL, REF NODE=90, ROT NODE=91\n*STEP, NLGEOM\n*STATIC\n"
            "0.2, 1\n*BOUNDARY\n90, 1, 1, 0.4\n90, 2, 3, 0\n91, 1, 2, 0\n91, 3, 3, 2.5\n"
            "*END STEP\n";
    const model::Model m = inp::read_deck_text(deck.str(), "plate.inp");
    Collect c;
    analysis::run_nonlinear_static(m, {}, c, c);
    const output::Frame& f = c.frames.back();
    const Mat3 R = Eigen::AngleAxis<Real>(2.5, Vec3::UnitZ()).toRotationMatrix();
    const Vec3 center(0.3, 0.2, 0), shift(0.4, 0, 0);
    for (int k = 0; k < (quadratic ? 8 : 4); ++k) {
      const int n = m.mesh.node_index.at(k + 1);
      const Vec3 X = m.mesh.coords.row(n).transpose();
      const Vec3 expected = center + shift + R * (X - center) - X;
      EXPECT_NEAR((f.U.row(n).transpose() - expected).norm(), 0, 1e-10)
          << type << " node " << k + 1;
    }
    EXPECT_LT(f.S.cwiseAbs().maxCoeff(), 1e-6) << type;
  }
}

TEST(PlaneElements, TiedBlocksPassThePatchTest) {
  // Two blocks of 2D elements, r (x) in [1, 2], one on the other with coincident nodes at
  // y = 1, the upper one's bottom tied to the lower one's top, pulled by a pressure of 10 on
  // the top: the stress is 10 in y everywhere (plane strain: nu 10 in z). The slave copies of
  // the expansion are tied through their 2D nodes; ccx 2.20 leaves some of them untied on the
  // same deck (s_yy from 4.0 to 16.1: tests/peer/README.md).
  for (const char* type : {"CAX8", "CPE8", "CPS4"}) {
    const bool quadratic = std::string(type) != "CPS4";
    std::ostringstream deck;
    deck << "*NODE, NSET=NALL\n";
    for (int block = 0; block < 2; ++block) {
      const int base = 100 * block;
      const Real y = block;
      deck << base + 1 << ", 1, " << y << "\n" << base + 2 << ", 2, " << y << "\n"
           << base + 3 << ", 2, " << y + 1 << "\n" << base + 4 << ", 1, " << y + 1 << "\n";
      if (quadratic)
        deck << base + 5 << ", 1.5, " << y << "\n" << base + 6 << ", 2, " << y + 0.5 << "\n"
             << base + 7 << ", 1.5, " << y + 1 << "\n" << base + 8 << ", 1, " << y + 0.5
             << "\n";
    }
    deck << "*ELEMENT, TYPE=" << type << ", ELSET=EALL\n";
    for (int block = 0; block < 2; ++block) {
      deck << block + 1;
      for (int k = 1; k <= (quadratic ? 8 : 4); ++k) deck << ", " << 100 * block + k;
      deck << "\n";
    }
    deck << "*ELSET, ELSET=LOW\n1\n*ELSET, ELSET=UP\n2\n"
            "*SURFACE, NAME=MASTER\nLOW, S3\n*SURFACE, NAME=SLAVE\nUP, S1\n"
            "*MATERIAL, NAME=M\n*ELASTIC\n1000, 0.3\n*SOLID SECTION, ELSET=EALL, MATERIAL=M\n"
            "*TIE, NAME=T\nSLAVE, MASTER\n*BOUNDARY\n1, 2, 2\n2, 2, 2\n"
         << (quadratic ? "5, 2, 2\n" : "") << (std::string(type) == "CAX8" ? "" : "1, 1, 1\n")
         << "*STEP\n*STATIC\n*DLOAD\nUP, P3, -10\n*END STEP\n";
    model::Model m = inp::read_deck_text(deck.str(), "tied.inp");
    EXPECT_GT(contact::apply_ties(m), 0) << type;
    Collect c;
    analysis::run_linear_static(m, {.threads = 1}, c, c);
    const output::Frame& f = c.frames.at(0);
    const Real szz = std::string(type) == "CPE8" ? 0.3 * 10 : 0;
    for (Index k = 0; k < f.S.rows(); ++k) {
      EXPECT_NEAR(f.S(k, 1), 10.0, 1e-9) << type << " point " << k;
      EXPECT_NEAR(f.S(k, 0), 0.0, 1e-9) << type << " point " << k;
      EXPECT_NEAR(f.S(k, 2), szz, 1e-9) << type << " point " << k;
    }
  }
}

TEST(PlaneElements, ANodeSurfaceOnPlaneNodesTouchesThroughItsCopiesWithTheEdgeArea) {
  // Two CPE4 strips 2 x 1 (4 elements, thickness 0.5), the upper one on the lower one by
  // node-to-surface contact from a node surface of its bottom 2D nodes. Each copy of an inner
  // node carries its share of the bottom edges, 2 x 0.5 x 0.5 / 4 = 0.125: the front and
  // back of the expanded layer are no boundary of the 2D body and add nothing.
  std::ostringstream deck;
  deck << "*NODE, NSET=NALL\n";
  for (int block = 0; block < 2; ++block)
    for (int row = 0; row < 2; ++row)
      for (int i = 0; i <= 4; ++i)
        deck << 100 * block + 10 * row + i + 1 << ", " << 0.5 * i << ", " << block + row << "\n";
  deck << "*ELEMENT, TYPE=CPE4, ELSET=EALL\n";
  for (int block = 0; block < 2; ++block)
    for (int i = 0; i < 4; ++i) {
      const int n = 100 * block + i + 1;
      deck << 10 * block + i + 1 << ", " << n << ", " << n + 1 << ", " << n + 11 << ", " << n + 10
           << "\n";
    }
  deck << "*ELSET, ELSET=LOW, GENERATE\n1, 4\n*ELSET, ELSET=UP, GENERATE\n11, 14\n"
          "*NSET, NSET=UPBOT, GENERATE\n101, 105\n*SURFACE, NAME=MASTER\nLOW, S3\n"
          "*SURFACE, NAME=SLAVE, TYPE=NODE\nUPBOT\n"
          "*MATERIAL, NAME=M\n*ELASTIC\n1000, 0.3\n*SOLID SECTION, ELSET=EALL, MATERIAL=M\n0.5\n"
          "*SURFACE INTERACTION, NAME=I\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1000\n"
          "*CONTACT PAIR, INTERACTION=I, TYPE=NODE TO SURFACE\nSLAVE, MASTER\n"
          "*BOUNDARY\n1, 1, 2\n2, 2, 2\n3, 2, 2\n4, 2, 2\n5, 2, 2\n101, 1, 1\n"
          "*STEP\n*STATIC\n*DLOAD\nUP, P3, 10\n*END STEP\n";
  const model::Model m = inp::read_deck_text(deck.str(), "stack.inp");
  Collect c;
  analysis::run_nonlinear_static(m, {}, c, c);
  const output::Frame& f = c.frames.back();
  int inner = 0;
  for (const output::ContactPointRecord& p : f.contact_points) {
    const Real x = m.mesh.coords(p.slave_node, 0);
    if (x < 0.25 || x > 1.75) continue;  // the strip's ends also carry a share of its sides
    ++inner;
    EXPECT_TRUE(p.active);
    // In the deformed configuration: the strip widens by about 5e-3 under the load.
    EXPECT_NEAR(p.area, 0.125, 1e-3) << "node " << m.mesh.node_ids[p.slave_node];
  }
  EXPECT_EQ(inner, 6);  // front and back copies of nodes 102, 103, 104
}
