#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "output/dat_headers.hpp"
#include "output/dat_writer.hpp"
#include "test_model.hpp"

namespace kontakt::output {
namespace {

namespace fs = std::filesystem;
using model::PrintRequest;
using model::Totals;

PrintRequest node(std::string set, std::vector<std::string> vars, Totals t = Totals::No,
                  int freq = 1) {
  PrintRequest r;
  r.kind = PrintRequest::Kind::Node;
  r.set = std::move(set);
  r.variables = std::move(vars);
  r.totals = t;
  r.frequency = freq;
  return r;
}
PrintRequest elem(std::string set, std::vector<std::string> vars, Totals t = Totals::No) {
  auto r = node(std::move(set), std::move(vars), t);
  r.kind = PrintRequest::Kind::Element;
  return r;
}

Frame two_tet_frame() {
  Frame f;
  f.step = 1;
  f.increment = 3;
  f.total_time = 1.5;
  f.step_time = 1.5;
  f.is_step_end = true;
  f.U.resize(5, 3);
  for (int i = 0; i < 5; ++i) f.U.row(i) << 0.001 * (i + 1), -0.5 * (i + 1), 0.0;
  f.RF = MatX3::Zero(5, 3);
  f.RF.row(0) << -100, 2.5, 1e-20;
  f.RF.row(1) << -50, -2.5, 3e-20;
  f.ip_offset = {0, 1, 2};
  f.S.resize(2, 6);
  f.S.row(0) << 1e3, 2e3, 3e3, 4e3, 5e3, 6e3;
  f.S.row(1) << -1.5, 0, 0, 0, 0, 9.9999996e99;
  f.E.resize(2, 6);
  f.E.row(0) << 1e-3, 2e-3, 3e-3, 4e-3, 5e-3, 6e-3;
  f.E.row(1) << -1e-5, 0, 0, 0, 0, 0;
  f.ENER.resize(2);
  f.ENER << 0.5, 0.25;
  f.ip_volume.resize(2);
  f.ip_volume << 2, 4;
  f.EVOL.resize(2);
  f.EVOL << 2, 4;
  return f;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path tmp(const std::string& name) {
  auto d = fs::temp_directory_path() / ("kontakt_test_output_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d / name;
}

// Layout established against ccx 2.20 (see proto/results_layout.md).
const char* kGolden = R"(
 displacements (vx,vy,vz) for set NALL and time  0.1500000E+01

        10  1.000000E-03 -5.000000E-01  0.000000E+00
        20  2.000000E-03 -1.000000E+00  0.000000E+00
        30  3.000000E-03 -1.500000E+00  0.000000E+00
        40  4.000000E-03 -2.000000E+00  0.000000E+00
        50  5.000000E-03 -2.500000E+00  0.000000E+00

 forces (fx,fy,fz) for set FIX and time  0.1500000E+01

        10 -1.000000E+02  2.500000E+00  1.000000E-20
        20 -5.000000E+01 -2.500000E+00  3.000000E-20

 total force (fx,fy,fz) for set FIX and time  0.1500000E+01

       -1.500000E+02  0.000000E+00  4.000000E-20

 total force (fx,fy,fz) for set FIX and time  0.1500000E+01

       -1.500000E+02  0.000000E+00  4.000000E-20

 strains (elem, integ.pnt.,exx,eyy,ezz,exy,exz,eyz) for set EALL and time  0.1500000E+01

         7   1  1.000000E-03  2.000000E-03  3.000000E-03  4.000000E-03  5.000000E-03  6.000000E-03
         8   1 -1.000000E-05  0.000000E+00  0.000000E+00  0.000000E+00  0.000000E+00  0.000000E+00

 stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz) for set EALL and time  0.1500000E+01

         7   1  1.000000E+03  2.000000E+03  3.000000E+03  4.000000E+03  5.000000E+03  6.000000E+03
         8   1 -1.500000E+00  0.000000E+00  0.000000E+00  0.000000E+00  0.000000E+00  1.000000+100

 internal energy density (elem, integ.pnt.,energy) for set EALL and time  0.1500000E+01

         7   1  5.000000E-01
         8   1  2.500000E-01

 internal energy (element, energy) for set EALL and time  0.1500000E+01

         7  1.000000E+00
         8  1.000000E+00

 total internal energy for set EALL and time  0.1500000E+01

        2.000000E+00

 volume (element, volume) for set EALL and time  0.1500000E+01

         7  2.000000E+00
         8  4.000000E+00

 total volume for set EALL and time  0.1500000E+01

        6.000000E+00

 total volume for set E2 and time  0.1500000E+01

        4.000000E+00
)";

TEST(DatWriter, GoldenTwoTetModel) {
  auto m = test::two_tets();
  auto& step = m.steps[0];
  step.prints = {node("NALL", {"U"}),
                 node("FIX", {"RF"}, Totals::Yes),
                 node("FIX", {"RF"}, Totals::Only),
                 elem("EALL", {"E", "S"}),
                 elem("EALL", {"ENER", "ELSE", "EVOL"}, Totals::Yes),
                 elem("E2", {"EVOL", "PEEQ", "NOSUCHVAR"}, Totals::Only)};
  const auto path = tmp("golden.dat");
  {
    DatWriter w(m, path);
    w.write(step, two_tet_frame());
  }
  EXPECT_EQ(slurp(path), kGolden);
}

TEST(DatWriter, FrequencyAndStepEnd) {
  auto m = test::two_tets();
  auto& step = m.steps[0];
  step.prints = {node("FIX", {"U"}, Totals::No, 2)};
  const auto path = tmp("freq.dat");
  DatWriter w(m, path);
  auto f = two_tet_frame();
  f.is_step_end = false;
  f.increment = 1;
  w.write(step, f);
  EXPECT_EQ(slurp(path), "");
  f.increment = 2;
  f.total_time = 0.25;
  w.write(step, f);
  const std::string block =
      "\n displacements (vx,vy,vz) for set FIX and time  0.2500000E+00\n\n"
      "        10  1.000000E-03 -5.000000E-01  0.000000E+00\n"
      "        20  2.000000E-03 -1.000000E+00  0.000000E+00\n";
  EXPECT_EQ(slurp(path), block);
  f.increment = 3;  // not due, not the end
  w.write(step, f);
  EXPECT_EQ(slurp(path), block);
  f.is_step_end = true;  // always at the step end
  w.write(step, f);
  EXPECT_EQ(slurp(path), block + block);
}

TEST(DatWriter, PeeqHeaderHasNoBlankBeforeFor) {
  auto m = test::two_tets();
  auto& step = m.steps[0];
  step.prints = {elem("E2", {"PEEQ"})};
  const auto path = tmp("peeq.dat");
  auto f = two_tet_frame();
  f.PEEQ.resize(2);
  f.PEEQ << 0.0, 3.959574e-2;
  {
    DatWriter w(m, path);
    w.write(step, f);
  }
  EXPECT_EQ(slurp(path),
            "\n equivalent plastic strain (elem, integ.pnt.,pe)for set E2 and time  "
            "0.1500000E+01\n\n         8   1  3.959574E-02\n");
}

TEST(DatWriter, MultiplePointsPerElementAndLargeLabels) {
  auto m = test::two_tets();
  m.mesh.elements[1].id = 1234567;
  auto& step = m.steps[0];
  step.prints = {elem("E2", {"ENER"})};
  auto f = two_tet_frame();
  f.ip_offset = {0, 1, 13};
  f.ENER = VecX::Constant(13, 1.0);
  const auto path = tmp("many.dat");
  {
    DatWriter w(m, path);
    w.write(step, f);
  }
  const auto text = slurp(path);
  EXPECT_NE(text.find("\n   1234567   1  1.000000E+00\n"), std::string::npos);
  EXPECT_NE(text.find("\n   1234567  12  1.000000E+00\n"), std::string::npos);
}

TEST(DatWriter, SetsPrintInTheirDeckOrderWithDuplicatesAndZeroRowsUpToTheLargestLabel) {
  auto m = test::two_tets();
  // 10 and 20 are FIX's nodes; the largest node label is 50: 55 is not printed, the other
  // labels without a node are zero rows; 20 twice, and twice in the total.
  m.node_sets["FIX"].print_order = {{20, 20, 1}, {5, 55, 10}, {20, 20, 1}};
  auto& step = m.steps[0];
  step.prints = {node("FIX", {"U", "RF"}, model::Totals::Yes)};
  const auto path = tmp("order.dat");
  {
    DatWriter w(m, path);
    w.write(step, two_tet_frame());
  }
  const std::string zero = "  0.000000E+00  0.000000E+00  0.000000E+00\n";
  const std::string twenty = "        20  2.000000E-03 -1.000000E+00  0.000000E+00\n";
  const std::string rows = twenty + "         5" + zero + "        15" + zero + "        25" +
                           zero + "        35" + zero + "        45" + zero + twenty + "\n";
  EXPECT_NE(slurp(path).find(rows), std::string::npos) << slurp(path);
  EXPECT_NE(slurp(path).find("\n       -1.000000E+02 -5.000000E+00  6.000000E-20\n"),
            std::string::npos)
      << slurp(path);
}

TEST(DatWriter, TrussesPrintEightRowsWhereTheirSetListsThem) {
  auto m = test::two_tets();
  model::Connector bar;  // truss 9 from node 10 to node 20 (length 1), between the tets
  bar.kind = model::Connector::Kind::Truss;
  bar.id = 9;
  bar.nodes = {0, 1};
  bar.area = 0.5;
  m.connectors.push_back(bar);
  m.element_sets["EALL"].print_order = {{7, 7, 1}, {9, 9, 1}, {8, 8, 1}};
  auto& step = m.steps[0];
  step.prints = {elem("EALL", {"S", "ELSE", "EVOL"})};
  auto f = two_tet_frame();
  f.truss_S = MatX6::Zero(1, 6);
  f.truss_S(0, 0) = 7.5;
  f.truss_E = MatX6::Zero(1, 6);
  f.truss_ENER = VecX::Constant(1, 3.0);
  const auto path = tmp("truss.dat");
  {
    DatWriter w(m, path);
    w.write(step, f);
  }
  const std::string text = slurp(path);
  std::string truss_rows;
  for (int p = 1; p <= 8; ++p)
    truss_rows += "         9   " + std::to_string(p) +
                  "  7.500000E+00  0.000000E+00  0.000000E+00  0.000000E+00  0.000000E+00  "
                  "0.000000E+00\n";
  // in the set's order: element 7, truss 9, element 8
  EXPECT_NE(text.find("6.000000E+03\n" + truss_rows + "         8   1"), std::string::npos)
      << text;
  EXPECT_NE(text.find("\n         9  1.500000E+00\n"), std::string::npos) << text;  // ELSE
  EXPECT_NE(text.find("\n         9  5.000000E-01\n"), std::string::npos) << text;  // EVOL
}

TEST(DatWriter, UnknownSetThrows) {
  auto m = test::two_tets();
  m.steps[0].prints = {node("NOPE", {"U"})};
  DatWriter w(m, tmp("bad.dat"));
  EXPECT_THROW(w.write(m.steps[0], two_tet_frame()), SolverError);
}

TEST(DatHeaders, TableIsComplete) {
  for (auto b : {DatBlock::U, DatBlock::RF, DatBlock::RF_TOTAL, DatBlock::S, DatBlock::E,
                 DatBlock::ENER, DatBlock::PEEQ, DatBlock::ELSE, DatBlock::ELSE_TOTAL,
                 DatBlock::EVOL, DatBlock::EVOL_TOTAL}) {
    const auto h = dat_header_prefix(b);
    ASSERT_FALSE(h.empty());
    EXPECT_EQ(h.front(), ' ');
    EXPECT_TRUE(h.ends_with("for set "));
  }
  for (auto b : {DatBlock::CDIS_FACE, DatBlock::CSTR_FACE, DatBlock::CELS_FACE,
                 DatBlock::CDIS_NODE, DatBlock::CSTR_NODE, DatBlock::CELS_NODE}) {
    const auto h = dat_header_prefix(b);
    ASSERT_FALSE(h.empty());
    EXPECT_TRUE(h.ends_with("contact elements and time")) << h;
  }
  EXPECT_TRUE(dat_header_prefix(DatBlock::CELS_TOTAL).ends_with("for time "));
}

// ------------------------------------------------------------------ *CONTACT PRINT
ContactPointRecord contact_point(int element, int face, int node, Real pressure) {
  ContactPointRecord p;
  p.slave_element = element;
  p.slave_face = face;
  p.slave_node = node;
  p.active = true;
  p.pressure = pressure;
  p.clearance = -pressure * 1e-7;
  p.slip = Vec2(1e-6, -2e-6);
  p.shear = Vec2(0.5, -0.25);
  p.energy = pressure * 1e-8;
  return p;
}

model::ContactRequest contact_print(std::vector<std::string> vars, bool totals = false,
                                    bool only = false, std::size_t after = 0) {
  model::ContactRequest r;
  r.variables = std::move(vars);
  r.totals = totals;
  r.totals_only = only;
  r.after_prints = after;
  return r;
}

model::Model with_pair(model::ContactPair::Type type) {
  auto m = test::two_tets();
  model::ContactPair pair;
  pair.type = type;
  if (type == model::ContactPair::Type::NodeToSurface)  // as the reader sets a TYPE's default
    pair.scheme.kind = model::ContactScheme::Kind::NodeToSurface;
  m.contact_pairs.push_back(pair);
  return m;
}

// Headers and rows as ccx 2.20 writes them (contactenergy, friction1 and variants of them).
const char* kGoldenFaces = R"(
 relative contact displacement (slave element+face,normal,tang1,tang2) for all contact elements and time 0.1500000E+01

         7          1 -3.000000E-05  1.000000E-06 -2.000000E-06
         8          2 -1.000000E-05  1.000000E-06 -2.000000E-06
         8          2 -2.000000E-05  1.000000E-06 -2.000000E-06

 contact stress (slave element+face,press,tang1,tang2) for all contact elements and time 0.1500000E+01

         7          1  3.000000E+02  5.000000E-01 -2.500000E-01
         8          2  1.000000E+02  5.000000E-01 -2.500000E-01
         8          2  2.000000E+02  5.000000E-01 -2.500000E-01

 contact print energy (slave element+face,energy)for all contact elements and time 0.1500000E+01

         7          1  3.000000E-06
         8          2  1.000000E-06
         8          2  2.000000E-06

 total contact spring energy for time  0.1500000E+01

        6.000000E-06
)";

TEST(DatWriter, ContactPrintSurfaceToSurfaceRowsPerActivePoint) {
  auto m = with_pair(model::ContactPair::Type::SurfaceToSurface);
  auto f = two_tet_frame();
  // Element 8 (internal 1) first in the frame, an inactive point, then element 7: ccx sorts by
  // element and keeps a face's points in their order.
  f.contact_points = {contact_point(1, 2, -1, 100), contact_point(0, 1, -1, 999),
                      contact_point(1, 2, -1, 200), contact_point(0, 1, -1, 300)};
  f.contact_points[1].active = false;
  m.steps[0].contact_prints = {contact_print({"CDIS", "CSTR", "CELS"}, true)};
  const auto path = tmp("contact_faces.dat");
  {
    DatWriter w(m, path);
    w.write(m.steps[0], f);
  }
  EXPECT_EQ(slurp(path), kGoldenFaces);
}

const char* kGoldenNodes = R"(
 contact print energy (slave node,energy) forall contact elements and time 0.1500000E+01

        20  2.000000E-06
        40  1.000000E-06

 contact stress (slave node,press,tang1,tang2) for all contact elements and time 0.1500000E+01

        20  2.000000E+02  5.000000E-01 -2.500000E-01
        40  1.000000E+02  5.000000E-01 -2.500000E-01
)";

TEST(DatWriter, ContactPrintNodeToSurfaceRowsPerSlaveNode) {
  auto m = with_pair(model::ContactPair::Type::NodeToSurface);
  auto f = two_tet_frame();
  f.contact_points = {contact_point(-1, 0, 3, 100), contact_point(-1, 0, 1, 200)};
  m.steps[0].contact_prints = {contact_print({"CELS", "CSTR"})};
  const auto path = tmp("contact_nodes.dat");
  {
    DatWriter w(m, path);
    w.write(m.steps[0], f);
  }
  EXPECT_EQ(slurp(path), kGoldenNodes);
}

TEST(DatWriter, ContactPrintNamesTheExpandedCopiesOfA2DNodeByTheNodeOnce) {
  // Internal nodes 3 and 2 are the copies of the 2D node 1 (label 20): one row for 20, its
  // pressure the copies' mean by area, (100 * 1 + 300 * 3) / 4, as ccx prints 2D models.
  auto m = with_pair(model::ContactPair::Type::NodeToSurface);
  m.planar_folds.push_back({.node = 1, .expanded = {3, 2}, .weights = {0.5, 0.5}});
  auto f = two_tet_frame();
  f.contact_points = {contact_point(-1, 0, 3, 100), contact_point(-1, 0, 2, 300)};
  f.contact_points[0].area = 1;
  f.contact_points[1].area = 3;
  m.steps[0].contact_prints = {contact_print({"CSTR"})};
  const auto path = tmp("contact_folded.dat");
  {
    DatWriter w(m, path);
    w.write(m.steps[0], f);
  }
  EXPECT_EQ(slurp(path), R"(
 contact stress (slave node,press,tang1,tang2) for all contact elements and time 0.1500000E+01

        20  2.500000E+02  5.000000E-01 -2.500000E-01
)");
}

TEST(DatWriter, ContactPrintTotalsOnlyAndPlaceAmongPrints) {
  auto m = with_pair(model::ContactPair::Type::NodeToSurface);
  auto f = two_tet_frame();
  f.contact_points = {contact_point(-1, 0, 3, 100)};
  auto& step = m.steps[0];
  // ccx's list: U, contact (TOTALS=ONLY: the energy total alone), EVOL, contact.
  step.prints = {node("FIX", {"U"}), elem("E2", {"EVOL"})};
  step.contact_prints = {contact_print({"CDIS", "CELS", "CSTR"}, false, true, 1),
                         contact_print({"CDIS"}, false, false, 2)};
  const auto path = tmp("contact_order.dat");
  {
    DatWriter w(m, path);
    w.write(step, f);
  }
  std::vector<std::string> headers;
  std::istringstream text(slurp(path));
  for (std::string line; std::getline(text, line);)
    if (line.find("time") != std::string::npos) headers.push_back(line.substr(0, 24));
  EXPECT_EQ(headers, (std::vector<std::string>{" displacements (vx,vy,vz",
                                               " total contact spring en",
                                               " volume (element, volume",
                                               " relative contact displa"}));
}

TEST(DatWriter, ContactPrintFrequencyAndDecksWithoutPairs) {
  auto m = with_pair(model::ContactPair::Type::NodeToSurface);
  auto f = two_tet_frame();
  f.is_step_end = false;
  f.increment = 3;
  f.contact_points = {contact_point(-1, 0, 3, 100)};
  m.steps[0].contact_prints = {contact_print({"CDIS"})};
  m.steps[0].contact_prints[0].frequency = 2;
  const auto path = tmp("contact_freq.dat");
  {
    DatWriter w(m, path);
    w.write(m.steps[0], f);  // increment 3, frequency 2: not due
    f.increment = 4;
    w.write(m.steps[0], f);
  }
  const std::string text = slurp(path);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 4);  // one block, no rows
  m.contact_pairs.clear();
  const auto none = tmp("contact_none.dat");
  {
    DatWriter w(m, none);
    w.write(m.steps[0], f);
  }
  EXPECT_EQ(slurp(none), "");
}

}  // namespace
}  // namespace kontakt::output
