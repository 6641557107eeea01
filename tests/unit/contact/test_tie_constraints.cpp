// *TIE constraints: ccx's default tolerance, the foot and MPC coefficients on distorted
// quadratic faces, ADJUST, free nodes, constrained slave dofs, chains and cycles of ties.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "assembly/dof_map.hpp"
#include "contact/tie_constraints.hpp"
#include "../inp/deck_fixtures.hpp"
#include "contact_test_util.hpp"
#include "inp/read_deck.hpp"
#include "two_blocks.hpp"

using namespace kontakt;
using namespace kontakt::contact;
using element::ElementType;
using element::Topology;

namespace {

/// Face `face` of one element whose nodes are rows 0.. of `coords`.
SurfaceFace element_face(ElementType type, int face) {
  SurfaceFace f{0, face, element::face_topology(type, face), type, {}};
  for (int local : element::face_nodes(type, face)) f.nodes.push_back(local);
  return f;
}

/// Corner nodes (ccx order) and then midside nodes of a hexahedron [0,a] x [0,b] x [0,c].
MatX3 hex20_box(Real a, Real b, Real c) {
  const int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                            {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int edge[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                           {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  MatX3 x(20, 3);
  for (int i = 0; i < 8; ++i) x.row(i) << a * corner[i][0], b * corner[i][1], c * corner[i][2];
  for (int e = 0; e < 12; ++e) x.row(8 + e) = 0.5 * (x.row(edge[e][0]) + x.row(edge[e][1]));
  return x;
}

/// A master side of one face, for the foot search.
TieMaster single_face_master(const FaceGeometry& g) {
  TieMaster m;
  SurfaceFace f{0, 1, g.topo, ElementType::C3D20, {}};
  for (int a = 0; a < g.x.rows(); ++a) f.nodes.push_back(a);
  m.faces.push_back(f);
  m.nodes = f.nodes;
  m.geometry.push_back(g);
  m.largest_face = face_size(g);
  m.tree = AabbTree({face_box(g)});
  return m;
}

bool has_warning(const model::Model& m, const std::string& fragment) {
  return std::any_of(m.warnings.begin(), m.warnings.end(),
                     [&](const std::string& w) { return w.find(fragment) != std::string::npos; });
}

/// Node index of a deck label.
int node(const model::Model& m, int label) { return m.mesh.node_index.at(label); }

/// The two-blocks deck (no contact) with one tie SLAVE -> MASTER.
model::Model tied_blocks(const fixtures::TwoBlocks& t, model::Tie tie = {}) {
  model::Model m = inp::read_deck_text(fixtures::two_blocks_deck(t), "two_blocks.inp");
  tie.name = "T";
  tie.slave = "SLAVE";
  tie.master = "MASTER";
  tie.where = {"two_blocks.inp", 7};
  m.ties.push_back(tie);
  return m;
}

/// Displacements u = A x + b at every node, expanded through the DofMap from the free dofs
/// (the dependent ones follow their constraints).
VecX expand_linear_field(const model::Model& m, const assembly::DofMap& dofs, const Mat3& A,
                         const Vec3& b) {
  VecX x(dofs.n_equations());
  for (int eq = 0; eq < dofs.n_equations(); ++eq) {
    const int d = dofs.equation_dof(eq);
    x(eq) = (A * m.mesh.coords.row(d / 3).transpose() + b)(d % 3);
  }
  return dofs.expand(x, VecX::Zero(dofs.n_prescribed()));
}

}  // namespace

TEST(TieConstraints, DefaultToleranceIsCcxsTypicalSizeOnEveryFaceOrder) {
  // Measured with ccx 2.20 ("tolerance:" of gentiedmpc for a node just out of reach): master
  // face S1 of a 2 x 1 C3D8 box, S1 of the C3D20 box, S4 of a C3D10. ccx starts hexahedron
  // face S1 and tetrahedron face S4 at another corner than we do; the split into triangles,
  // hence the size, follows ccx's order.
  const MatX3 box = hex20_box(2, 1, 1);
  const SurfaceFace quad4 = element_face(ElementType::C3D8, 1);
  EXPECT_NEAR(kDefaultToleranceFraction * typical_master_size({&quad4, 1}, box),
              7.8934466291663147e-3, 1e-15);
  const SurfaceFace top = element_face(ElementType::C3D8, 2);  // same rectangle, our order = ccx's
  EXPECT_NEAR(typical_master_size({&top, 1}, box), typical_master_size({&quad4, 1}, box), 1e-15);
  const SurfaceFace quad8 = element_face(ElementType::C3D20, 1);
  EXPECT_NEAR(kDefaultToleranceFraction * typical_master_size({&quad8, 1}, box),
              6.7245010923609357e-3, 1e-15);
  MatX3 tet(10, 3);
  tet.topRows(4) << 0, 0, 0, 2, 0, 0, 0, 1, 0, 0, 0, 3;
  const int edge[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  for (int e = 0; e < 6; ++e) tet.row(4 + e) = 0.5 * (tet.row(edge[e][0]) + tet.row(edge[e][1]));
  const SurfaceFace tri6 = element_face(ElementType::C3D10, 4);
  EXPECT_NEAR(kDefaultToleranceFraction * typical_master_size({&tri6, 1}, tet),
              4.0063019730745232e-3, 1e-15);
  // The mean runs over all triangles of all faces.
  const SurfaceFace both[] = {quad4, quad8};
  const Real quad4_size = typical_master_size({&quad4, 1}, box);
  const Real quad8_size = typical_master_size({&quad8, 1}, box);
  EXPECT_NEAR(typical_master_size(both, box), (2 * quad4_size + 6 * quad8_size) / 8, 1e-15);
}

TEST(TieConstraints, CoefficientsOnDistortedQuadraticFacesInterpolateTheFoot) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(-1, 1);
  for (Topology topo : {Topology::Quad8, Topology::Tri6, Topology::Quad4, Topology::Tri3}) {
    for (int k = 0; k < 5; ++k) {
      const FaceGeometry g = fixtures::curved_face(topo, 1.0, 0.2, 0.1, rng);
      const TieMaster master = single_face_master(g);
      const Vec2 xi0 = is_triangle(topo)
                           ? Vec2(0.1 + 0.175 * (u(rng) + 1), 0.1 + 0.175 * (u(rng) + 1))
                           : Vec2(0.85 * u(rng), 0.85 * u(rng));
      const SurfacePoint sp = surface_point(g, xi0);
      const Real gap = 0.004 * u(rng);
      const std::optional<TieFoot> foot = find_tie_foot(master, sp.x + gap * sp.normal, 0.005);
      ASSERT_TRUE(foot.has_value());
      EXPECT_EQ(foot->face, 0);
      EXPECT_LT((foot->xi - xi0).norm(), 1e-9);
      EXPECT_NEAR(foot->distance, std::abs(gap), 1e-12);
      const int slave = static_cast<int>(g.x.rows());
      const model::Equation eq = tie_equation(slave, 1, master.faces[0], foot->xi, {"t.inp", 3});
      EXPECT_EQ(eq.keyword, "*TIE");
      EXPECT_EQ(eq.where.line, 3);
      ASSERT_EQ(eq.terms.size(), static_cast<std::size_t>(g.x.rows()) + 1);
      EXPECT_EQ(eq.terms[0].node, slave);
      EXPECT_EQ(eq.terms[0].dof, 1);
      EXPECT_EQ(eq.terms[0].coef, 1.0);
      // u_slave = sum_a w_a u_a with w_a = -coef: the weights sum to 1, place the foot, and
      // carry any linear field (u = A x + b) exactly onto the foot.
      Real sum = 0;
      Vec3 placed = Vec3::Zero();
      const Mat3 A = Mat3::Random();
      const Vec3 b = Vec3::Random();
      Vec3 carried = Vec3::Zero();
      bool negative = false;
      for (std::size_t a = 1; a < eq.terms.size(); ++a) {
        const Real w = -eq.terms[a].coef;
        EXPECT_EQ(eq.terms[a].dof, 1);
        sum += w;
        negative |= w < 0;
        const Vec3 xa = g.x.row(eq.terms[a].node).transpose();
        placed += w * xa;
        carried += w * (A * xa + b);
      }
      EXPECT_NEAR(sum, 1.0, 1e-13);
      EXPECT_LT((placed - foot->x).norm(), 1e-13);
      EXPECT_LT((carried - (A * foot->x + b)).norm(), 1e-12);
      // Serendipity and tri6 weights at interior points include negative corner weights.
      if (topo == Topology::Quad8 || topo == Topology::Tri6) {
        EXPECT_TRUE(negative);
      }
    }
  }
}

TEST(TieConstraints, NoFootBeyondTheToleranceOrBesideTheFace) {
  std::mt19937 rng(3);
  const FaceGeometry g = fixtures::curved_face(Topology::Quad8, 1.0, 0.2, 0.05, rng);
  const TieMaster master = single_face_master(g);
  const SurfacePoint sp = surface_point(g, Vec2(0.3, -0.2));
  EXPECT_TRUE(find_tie_foot(master, sp.x + 0.009 * sp.normal, 0.01).has_value());
  EXPECT_FALSE(find_tie_foot(master, sp.x + 0.011 * sp.normal, 0.01).has_value());
  EXPECT_FALSE(find_tie_foot(master, sp.x - 0.011 * sp.normal, 0.01).has_value());
  // In the face's plane but well beyond its edge.
  const SurfacePoint edge = surface_point(g, Vec2(1, 0));
  EXPECT_FALSE(find_tie_foot(master, edge.x + 0.5 * edge.a1.normalized(), 0.01).has_value());
}

TEST(ApplyTies, TiesNonMatchingBlocksAndMovesSlaveNodesOntoTheMaster) {
  for (const bool adjust : {true, false}) {
    fixtures::TwoBlocks t;
    t.lower = {"C3D8", 3, 1};
    t.upper = {"C3D20", 2, 1};
    t.rotation_deg = 20;
    t.upper_size = 0.6;
    t.gap = 1e-3;  // within ccx's default tolerance on faces of 1/3: 0.025 * 0.0948 = 2.4e-3
    model::Tie tie;
    tie.adjust = adjust;
    model::Model m = tied_blocks(t, tie);
    const ContactSurface slave = make_contact_surface(m, m.surfaces.at("SLAVE"));
    ASSERT_EQ(slave.nodes.size(), 21u);  // quad8 2 x 2: 25 - 4 centre nodes
    EXPECT_EQ(apply_ties(m), 21);
    ASSERT_EQ(m.equations.size(), 63u);
    for (int n : slave.nodes) EXPECT_NEAR(m.mesh.coords(n, 2), adjust ? 1.0 : 1.001, 1e-12);
    EXPECT_EQ(has_warning(m, "21 slave node(s) moved onto the master surface MASTER, the "
                             "farthest by 0.001"),
              adjust);
    EXPECT_FALSE(has_warning(m, "stay free"));
    // Tied nodes follow the master surface's interpolation: a linear field given on the free
    // nodes arrives on them exactly (they lie on the flat master, moved or not: the field is
    // linear, so the gap does not matter for x and y, and u_z is evaluated at the foot).
    const assembly::DofMap dofs(m, m.steps[0].boundaries);
    const Mat3 A = Mat3::Random();
    const Vec3 b = Vec3::Random();
    const VecX u = expand_linear_field(m, dofs, A, b);
    for (int n : slave.nodes) {
      Vec3 foot = m.mesh.coords.row(n).transpose();
      foot(2) = 1.0;
      const Vec3 expected = A * foot + b;
      for (int c = 0; c < 3; ++c) {
        if (dofs.is_prescribed(3 * n + c)) continue;
        EXPECT_NEAR(u(3 * n + c), expected(c), 1e-12) << n << " " << c;
      }
    }
  }
}

TEST(ApplyTies, ASchemeTiesThroughATiedContactPairInsteadOfEquations) {
  fixtures::TwoBlocks t;
  t.lower = {"C3D8", 3, 1};
  t.upper = {"C3D8", 2, 1};
  t.gap = 1e-3;
  model::Tie tie;
  tie.scheme = model::contact_scheme_from_name("lgc7");
  model::Model m = tied_blocks(t, tie);
  ASSERT_FALSE(m.steps.empty());
  const std::size_t interactions = m.interactions.size();
  EXPECT_EQ(apply_ties(m), 9);
  EXPECT_TRUE(m.equations.empty());
  ASSERT_EQ(m.contact_pairs.size(), 1u);
  const model::ContactPair& pair = m.contact_pairs[0];
  EXPECT_EQ(pair.type, model::ContactPair::Type::SurfaceToSurface);
  EXPECT_EQ(pair.slave, "SLAVE");
  EXPECT_EQ(pair.master, "MASTER");
  EXPECT_EQ(model::contact_scheme_name(pair.scheme), "lgc7");
  ASSERT_EQ(m.interactions.size(), interactions + 1);
  const model::SurfaceInteraction& tied = m.interactions.at(static_cast<std::size_t>(pair.interaction));
  EXPECT_EQ(tied.behavior.law, model::SurfaceBehavior::Law::Tied);
  const Real k = 50 * m.materials.front().elastic.rows.front()[0];
  EXPECT_DOUBLE_EQ(tied.behavior.stiffness, k);
  for (const model::Step& step : m.steps) {  // in force in every step
    ASSERT_EQ(step.interaction_behavior.size(), m.interactions.size());
    EXPECT_EQ(step.interaction_behavior.back().law, model::SurfaceBehavior::Law::Tied);
    ASSERT_TRUE(step.interaction_friction.back().has_value());
    EXPECT_DOUBLE_EQ(step.interaction_friction.back()->stick_slope, k);
  }
  const ContactSurface slave = make_contact_surface(m, m.surfaces.at("SLAVE"));
  for (int n : slave.nodes) EXPECT_NEAR(m.mesh.coords(n, 2), 1.0, 1e-12);  // ADJUST: moved
  EXPECT_TRUE(has_warning(m, "through TIED contact (lgc7)"));
}

TEST(ApplyTies, NodesOutOfReachStayFreeWithAWarningNamingThem) {
  // The upper block hangs over the lower one's edge: its slave nodes beyond x = 1 have no
  // master face.
  fixtures::TwoBlocks t;
  t.lower = {"C3D8", 2, 1};
  t.upper = {"C3D8", 2, 1};
  t.offset_x = 0.75;
  model::Model m = tied_blocks(t);
  EXPECT_EQ(apply_ties(m), 3);  // the column x = 0.75 lies over the lower block
  EXPECT_EQ(m.equations.size(), 9u);
  // Upper labels 100000 + i + 5 j on the half-step grid: x = 1.25 (i = 2) and 1.75 (i = 4).
  // Faces of 0.5: typical size 0.5 * 0.2845, default tolerance 0.025 times that.
  EXPECT_TRUE(has_warning(m, "two_blocks.inp:7: *TIE: tie T: 6 slave node(s) of SLAVE have no "
                             "master face of MASTER within the position tolerance 0.003556 (the "
                             "default: 2.5 % of a typical master element size) and stay free, "
                             "not tied: 100002, 100004, 100012, 100014, 100022, 100024"));

  // An explicit tolerance below the gap leaves every node free.
  t.offset_x = 0;
  t.gap = 2e-3;
  model::Tie tie;
  tie.position_tolerance = 1e-3;
  model::Model far = tied_blocks(t, tie);
  EXPECT_EQ(apply_ties(far), 0);
  EXPECT_TRUE(far.equations.empty());
  EXPECT_TRUE(has_warning(far, "9 slave node(s) of SLAVE have no master face of MASTER within "
                               "the position tolerance 0.001 and stay free"));
  EXPECT_NEAR(far.mesh.coords(node(far, 100000), 2), 1.002, 1e-15);
}

TEST(ApplyTies, DefaultToleranceAveragesOverTheMastersOfEveryTie) {
  // ccx computes one default from all ties' master faces, also those of a tie with a
  // tolerance of its own. Lower top: 16 faces of 0.25; upper top: 4 faces of 0.5.
  fixtures::TwoBlocks t;
  t.lower = {"C3D8", 4, 1};
  t.upper = {"C3D8", 2, 1};
  t.gap = 0.004;  // beyond every default here: the warning states the tolerance
  const auto faces_of = [](const model::Model& m, const std::string& elset, int face) {
    model::Surface s{elset, model::Surface::Kind::ElementFaces, {}, {}, {}};
    for (int e : m.element_sets.at(elset).elements) s.faces.push_back({e, face});
    return s;
  };
  const auto tolerance_in_warning = [](const model::Model& m, Real tolerance) {
    char text[80];
    std::snprintf(text, sizeof text, "within the position tolerance %.4g (the default", tolerance);
    return has_warning(m, text);
  };
  const Real square = (1 / (3 * std::sqrt(2.0)) + 1.0 / 3) / 2;  // a unit square's size
  model::Model alone = tied_blocks(t);
  apply_ties(alone);
  EXPECT_TRUE(tolerance_in_warning(alone, kDefaultToleranceFraction * square * 0.25));
  model::Model both = tied_blocks(t);
  both.surfaces["LOWERBOTTOM"] = faces_of(both, "LOWER_BOTTOM", 1);
  both.surfaces["UPPERTOP"] = faces_of(both, "UPPER_TOP", 2);
  model::Tie other;
  other.name = "OTHER";
  other.slave = "LOWERBOTTOM";
  other.master = "UPPERTOP";
  other.position_tolerance = 0.5;
  both.ties.push_back(other);
  apply_ties(both);
  const Real mean = (32 * 0.25 + 8 * 0.5) / 40;  // over the triangles of both masters
  EXPECT_TRUE(tolerance_in_warning(both, kDefaultToleranceFraction * square * mean));
}

TEST(ApplyTies, ConstrainedSlaveDofsAreLeftAsCcxDoes) {
  fixtures::TwoBlocks t;
  t.lower = {"C3D8", 2, 1};
  t.upper = {"C3D8", 2, 1};
  model::Model m = tied_blocks(t);
  // Slave node 100000: x prescribed in step 1; node 100002: y dependent in an *EQUATION.
  m.steps[0].boundaries.push_back({node(m, 100000), 0, 0.0});
  model::Equation eq;
  eq.terms = {{node(m, 100002), 1, 1.0}, {node(m, 100004), 1, -1.0}};
  eq.where = {"e.inp", 3};
  m.equations.push_back(eq);
  EXPECT_EQ(apply_ties(m), 9);
  EXPECT_EQ(m.equations.size(), 1u + 27u - 2u);
  EXPECT_TRUE(has_warning(m, "2 slave node(s) are not tied in directions already constrained"));
  EXPECT_TRUE(has_warning(m, "100000 (x), 100002 (y)"));
  const assembly::DofMap dofs(m, m.steps[0].boundaries);  // no contradiction left
  EXPECT_TRUE(dofs.is_prescribed(3 * node(m, 100000)));
  // A *BOUNDARY on a tied direction in a later step contradicts the tie: an error at the tie.
  std::vector<model::Boundary> later = m.steps[0].boundaries;
  later.push_back({node(m, 100004), 2, 1e-3});
  try {
    const assembly::DofMap contradicted(m, later);
    FAIL() << "a prescribed tied dof must be refused";
  } catch (const InputError& e) {
    EXPECT_EQ(e.keyword(), "*TIE");
    EXPECT_EQ(e.where().line, 7);
    EXPECT_NE(std::string(e.what()).find("node 100004 dof z) is also prescribed"),
              std::string::npos)
        << e.what();
  }
}

TEST(ApplyTies, NodesSharedWithTheMasterNeedNoConstraint) {
  // Two cubes sharing the face x = 1 (nodes 2, 3, 6, 7): both faces carry the same nodes.
  const std::string deck = inp::test::two_cubes_surfaces() +
                           "*TIE, NAME=SHARED\nSLAVE, MASTER\n*STEP\n*STATIC\n*END STEP\n";
  model::Model m = inp::read_deck_text(deck, "shared.inp");
  EXPECT_EQ(apply_ties(m), 0);
  EXPECT_TRUE(m.equations.empty());
  EXPECT_TRUE(m.warnings.empty());
}

TEST(ApplyTies, ChainedTiesResolveAndACycleIsAnInputError) {
  // Three coincident faces at z = 1: A's top, B's bottom, C's top (C overlaps A: geometry
  // only). Tie AB makes A's top nodes follow B's bottom, tie BC makes B's bottom follow C's
  // top: a chain, A -> B -> C. Tie CA closes it into a cycle.
  std::string nodes = "*NODE\n";
  const auto cube = [&](int base, Real z0) {
    const int c[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                         {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    std::string conn;
    for (int i = 0; i < 8; ++i) {
      nodes += std::to_string(base + i) + ", " + std::to_string(c[i][0]) + ", " +
               std::to_string(c[i][1]) + ", " + std::to_string(z0 + c[i][2]) + "\n";
      conn += ", " + std::to_string(base + i);
    }
    return conn;
  };
  const std::string a = cube(1, 0), b = cube(11, 1), c = cube(21, 0);
  const std::string mesh = nodes + "*ELEMENT, TYPE=C3D8, ELSET=EALL\n1" + a + "\n2" + b + "\n3" +
                           c + "\n*SURFACE, NAME=ATOP\n1, S2\n*SURFACE, NAME=BBOTTOM\n2, S1\n" +
                           "*SURFACE, NAME=CTOP\n3, S2\n*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.\n" +
                           "*SOLID SECTION, ELSET=EALL, MATERIAL=M\n";
  const std::string step = "*STEP\n*STATIC\n*END STEP\n";
  const std::string chain = "*TIE, NAME=AB\nATOP, BBOTTOM\n*TIE, NAME=BC\nBBOTTOM, CTOP\n";
  model::Model m = inp::read_deck_text(mesh + chain + step, "chain.inp");
  EXPECT_EQ(apply_ties(m), 8);
  const assembly::DofMap dofs(m, {});
  const VecX u = expand_linear_field(m, dofs, Mat3::Random(), Vec3::Random());
  // A's top follows B's bottom, which follows C's top: all three move together.
  for (int k = 0; k < 4; ++k)
    for (int d = 0; d < 3; ++d) {
      EXPECT_NEAR(u(3 * node(m, 5 + k) + d), u(3 * node(m, 25 + k) + d), 1e-14);
      EXPECT_NEAR(u(3 * node(m, 11 + k) + d), u(3 * node(m, 25 + k) + d), 1e-14);
    }
  model::Model cycle = inp::read_deck_text(mesh + chain + "*TIE, NAME=CA\nCTOP, ATOP\n" + step,
                                           "cycle.inp");
  apply_ties(cycle);
  try {
    const assembly::DofMap broken(cycle, {});
    FAIL() << "a cycle of ties must be refused";
  } catch (const InputError& e) {
    EXPECT_EQ(e.keyword(), "*TIE");
    EXPECT_EQ(e.where().file, "cycle.inp");
    EXPECT_NE(std::string(e.what()).find("form a cycle"), std::string::npos) << e.what();
  }
}
