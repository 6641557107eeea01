// The .frd writer: ccx 2.20's fixed columns for every line type, the frd element types and node
// orders, the time field's rules, the frequency rule and a file that is whole between frames.
#include "output/frd_writer.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "test_model.hpp"

namespace kontakt::output {
namespace {

namespace fs = std::filesystem;
using element::ElementType;

fs::path temp_dir(const std::string& name) {
  auto d = fs::temp_directory_path() / ("kontakt_frd_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::vector<std::string> read_lines(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// Index of the first line starting with `prefix` at or after `from`; fails the test if none.
std::size_t find_line(const std::vector<std::string>& lines, const std::string& prefix,
                      std::size_t from = 0) {
  for (std::size_t i = from; i < lines.size(); ++i)
    if (lines[i].rfind(prefix, 0) == 0) return i;
  ADD_FAILURE() << "no line starting with '" << prefix << "'";
  return lines.size() - 1;
}

/// One C3D20 (labels 101..120, internal order reversed so sorting by label matters) and one
/// C3D15 sharing nothing; node 999 belongs to no element; one material, one interaction.
model::Model hex_and_wedge() {
  model::Model m;
  for (int k = 20; k >= 1; --k) test::add_node(m, 100 + k, k, 0.5 * k, -k);
  for (int k = 1; k <= 15; ++k) test::add_node(m, 200 + k, k, 2, 3);
  test::add_node(m, 999, 9, 9, 9);
  std::vector<int> hex, wedge;
  for (int k = 1; k <= 20; ++k) hex.push_back(m.mesh.node_index.at(100 + k));
  for (int k = 1; k <= 15; ++k) wedge.push_back(m.mesh.node_index.at(200 + k));
  test::add_element(m, 12, ElementType::C3D15, wedge);
  test::add_element(m, 5, ElementType::C3D20, hex);
  m.materials.emplace_back().name = "STEEL";
  m.sections.emplace_back().material = 0;
  m.mesh.elements[0].section = 0;
  m.mesh.elements[1].section = 0;
  m.interactions.emplace_back().name = "SI1";
  m.steps.resize(1);
  m.steps[0].node_files.push_back({.variables = {"U", "RF", "NT"}, .frequency = 1});
  m.steps[0].element_files.push_back({.variables = {"S", "E", "PEEQ", "ME"}, .frequency = 1});
  return m;
}

Frame frame_for(const model::Model& m, int increment, double time, bool step_end) {
  const Index n = m.n_nodes();
  Frame f;
  f.step = 1;
  f.increment = increment;
  f.total_time = time;
  f.is_step_end = step_end;
  f.U = MatX3::Zero(n, 3);
  f.RF = MatX3::Zero(n, 3);
  f.S_nodal = MatX6::Zero(n, 6);
  f.E_nodal = MatX6::Zero(n, 6);
  f.T = VecX::Constant(n, 20.0);
  for (Index i = 0; i < n; ++i) {
    const double label = m.mesh.node_ids[static_cast<std::size_t>(i)];
    f.U.row(i) << label, -label, 0.5;
    f.S_nodal.row(i) << 1, 2, 3, 4, 5, 6;  // xx yy zz xy xz yz
    f.E_nodal.row(i) << 1e-3, 2e-3, 3e-3, 4e-3, 5e-3, 6e-3;
  }
  return f;
}

TEST(FrdFormat, ValuesAreSinglePrecisionIn12Columns) {
  EXPECT_EQ(frd_value(1.0), " 1.00000E+00");
  EXPECT_EQ(frd_value(-12.6895), "-1.26895E+01");
  EXPECT_EQ(frd_value(0.0), " 0.00000E+00");
  EXPECT_EQ(frd_value(123456789.0), " 1.23457E+08");
  EXPECT_EQ(frd_value(1e-300), " 0.00000E+00");  // below single precision
  EXPECT_EQ(frd_value(1.0 + 1e-9), " 1.00000E+00");
}

TEST(FrdFormat, TimeIsFixedPointFromOneBelowTenToTheTenElseScientific) {
  EXPECT_EQ(frd_time(1.0), " 1.000000000");
  EXPECT_EQ(frd_time(3.01), " 3.010000000");
  EXPECT_EQ(frd_time(12.5), " 12.50000000");
  EXPECT_EQ(frd_time(123456.75), " 123456.7500");
  EXPECT_EQ(frd_time(9999999999.0), "  9999999999");  // no decimal left: no point (%.0f)
  EXPECT_EQ(frd_time(1e10), " 1.00000E+10");
  EXPECT_EQ(frd_time(0.1), " 1.00000E-01");
  EXPECT_EQ(frd_time(0.999), " 9.99000E-01");
  EXPECT_EQ(frd_time(0.0), " 0.00000E+00");
  for (double t : {1.0, 3.01, 0.5, 7e9, 2.5e12, 9.9999999999}) EXPECT_EQ(frd_time(t).size(), 12u);
}

TEST(FrdFormat, ResultLinesCarrySixValuesThenContinue) {
  const double v[8] = {1, 2, 3, 4, 5, 6, 7, -8};
  EXPECT_EQ(frd_result_lines(42, v, 3), " -1        42 1.00000E+00 2.00000E+00 3.00000E+00\n");
  EXPECT_EQ(frd_result_lines(7, v, 8),
            " -1         7 1.00000E+00 2.00000E+00 3.00000E+00 4.00000E+00 5.00000E+00 "
            "6.00000E+00\n -2           7.00000E+00-8.00000E+00\n");
}

TEST(FrdFormat, ElementTypesAndNodeOrders) {
  EXPECT_EQ(frd_element_type(ElementType::C3D8), 1);
  EXPECT_EQ(frd_element_type(ElementType::C3D8R), 1);
  EXPECT_EQ(frd_element_type(ElementType::C3D8I), 1);
  EXPECT_EQ(frd_element_type(ElementType::C3D6), 2);
  EXPECT_EQ(frd_element_type(ElementType::C3D4), 3);
  EXPECT_EQ(frd_element_type(ElementType::C3D20), 4);
  EXPECT_EQ(frd_element_type(ElementType::C3D20R), 4);
  EXPECT_EQ(frd_element_type(ElementType::C3D15), 5);
  EXPECT_EQ(frd_element_type(ElementType::C3D10), 6);
  EXPECT_EQ(frd_node_order(ElementType::C3D20R),
            (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 16, 17, 18, 19, 12, 13, 14,
                              15}));
  EXPECT_EQ(frd_node_order(ElementType::C3D15),
            (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 13, 14, 9, 10, 11}));
  EXPECT_EQ(frd_node_order(ElementType::C3D10),
            (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
  EXPECT_EQ(frd_node_order(ElementType::C3D8I), (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(frd_node_order(ElementType::C3D4).size(), 4u);
  EXPECT_EQ(frd_node_order(ElementType::C3D6).size(), 6u);
}

TEST(FrdWriter, HeaderNodesAndElementsInTheirColumns) {
  const auto dir = temp_dir("mesh");
  const model::Model m = hex_and_wedge();
  FrdWriter w(m, dir / "m.frd");
  const auto lines = read_lines(dir / "m.frd");

  EXPECT_EQ(lines[0], "    1C");
  for (std::size_t i = 1; i <= 9; ++i) {
    EXPECT_EQ(lines[i].substr(0, 6), "    1U");
    EXPECT_EQ(lines[i].size(), 72u) << lines[i];
  }
  EXPECT_EQ(lines[5].substr(6, 18), "PGM               ");
  EXPECT_EQ(lines[5].substr(24, 7), "Kontakt");
  EXPECT_EQ(lines[10].substr(0, 19), "    1UMAT    1STEEL");
  EXPECT_EQ(lines[11].substr(0, 17), "    1UMAT    2SI1");
  EXPECT_EQ(lines[11].size(), 72u);

  // 35 element nodes (999 is in no element), count in columns 24-35, ASCII flag in column 73.
  const std::size_t nodes = find_line(lines, "    2C");
  EXPECT_EQ(lines[nodes], "    2C" + std::string(18, ' ') + "          35" +
                              std::string(37, ' ') + "1");
  EXPECT_EQ(lines[nodes + 1], " -1       101 1.00000E+00 5.00000E-01-1.00000E+00");  // by label
  EXPECT_EQ(lines[nodes + 20].substr(0, 13), " -1       120");
  EXPECT_EQ(lines[nodes + 21].substr(0, 13), " -1       201");
  EXPECT_EQ(lines[nodes + 36], " -3");

  const std::size_t elements = find_line(lines, "    3C", nodes);
  EXPECT_EQ(lines[elements], "    3C" + std::string(18, ' ') + "           2" +
                                 std::string(37, ' ') + "1");
  // By label: the C3D20 (5) first; type in columns 13-17, group 0, material 1.
  EXPECT_EQ(lines[elements + 1], " -1         5    4    0    1");
  EXPECT_EQ(lines[elements + 2],
            " -2       101       102       103       104       105       106       107       "
            "108       109       110");
  EXPECT_EQ(lines[elements + 3],
            " -2       111       112       117       118       119       120       113       "
            "114       115       116");
  EXPECT_EQ(lines[elements + 4], " -1        12    5    0    1");
  EXPECT_EQ(lines[elements + 5],
            " -2       201       202       203       204       205       206       207       "
            "208       209       213");
  EXPECT_EQ(lines[elements + 6], " -2       214       215       210       211       212");
  EXPECT_EQ(lines[elements + 7], " -3");
  EXPECT_EQ(lines.back(), " 9999");
  EXPECT_EQ(lines.size(), elements + 9);
  fs::remove_all(dir);
}

TEST(FrdWriter, ResultBlocksInCcxOrderAndColumns) {
  const auto dir = temp_dir("blocks");
  const model::Model m = hex_and_wedge();
  {
    FrdWriter w(m, dir / "m.frd");
    Frame f = frame_for(m, 3, 1.0, true);
    f.PEEQ_nodal = VecX::Constant(m.n_nodes(), 0.0125);
    w.write(m.steps[0], f);
  }
  const auto lines = read_lines(dir / "m.frd");
  std::vector<std::string> names;
  for (const auto& l : lines)
    if (l.rfind(" -4  ", 0) == 0) names.push_back(l.substr(5, 8));
  // ME is requested but not written.
  EXPECT_EQ(names, (std::vector<std::string>{"DISP    ", "NDTEMP  ", "STRESS  ", "TOSTRAIN",
                                             "FORC    ", "PE      "}));

  const std::size_t p = find_line(lines, "    1PSTEP");
  EXPECT_EQ(lines[p], "    1PSTEP" + std::string(25, ' ') + "1" + std::string(11, ' ') + "3" +
                          std::string(11, ' ') + "1" + std::string(10, ' '));
  EXPECT_EQ(lines[p + 1], "  100CL  101 1.000000000          35" + std::string(21, ' ') + "0" +
                              "    1" + std::string(11, ' ') + "1");
  EXPECT_EQ(lines[p + 1].size(), 75u);
  EXPECT_EQ(lines[p + 2], " -4  DISP        4    1");
  EXPECT_EQ(lines[p + 3], " -5  D1          1    2    1    0");
  EXPECT_EQ(lines[p + 5], " -5  D3          1    2    3    0");
  EXPECT_EQ(lines[p + 6], " -5  ALL         1    2    0    0    1ALL");
  EXPECT_EQ(lines[p + 7], " -1       101 1.01000E+02-1.01000E+02 5.00000E-01");  // no ALL value
  EXPECT_EQ(lines[p + 7 + 35], " -3");

  const std::size_t t = find_line(lines, " -4  NDTEMP");
  EXPECT_EQ(lines[t], " -4  NDTEMP      1    1");
  EXPECT_EQ(lines[t + 1], " -5  T           1    1    0    0");
  EXPECT_EQ(lines[t + 2], " -1       101 2.00000E+01");

  // Tensors: SXX SYY SZZ SXY SYZ SZX, so the frame's xz and yz swap places.
  const std::size_t s = find_line(lines, " -4  STRESS");
  EXPECT_EQ(lines[s], " -4  STRESS      6    1");
  EXPECT_EQ(lines[s + 4], " -5  SXY         1    4    1    2");
  EXPECT_EQ(lines[s + 5], " -5  SYZ         1    4    2    3");
  EXPECT_EQ(lines[s + 6], " -5  SZX         1    4    3    1");
  EXPECT_EQ(lines[s + 7],
            " -1       101 1.00000E+00 2.00000E+00 3.00000E+00 4.00000E+00 6.00000E+00 "
            "5.00000E+00");
  const std::size_t e = find_line(lines, " -4  TOSTRAIN");
  EXPECT_EQ(lines[e + 1], " -5  EXX         1    4    1    1");
  EXPECT_EQ(lines[e + 6], " -5  EZX         1    4    3    1");
  const std::size_t f = find_line(lines, " -4  FORC");
  EXPECT_EQ(lines[f + 4], " -5  ALL         1    2    0    0    1ALL");
  const std::size_t pe = find_line(lines, " -4  PE");
  EXPECT_EQ(lines[pe], " -4  PE          1    1");
  EXPECT_EQ(lines[pe + 1], " -5  PE          1    1    0    0");
  EXPECT_EQ(lines[pe + 2], " -1       101 1.25000E-02");
  EXPECT_EQ(lines.back(), " 9999");
  fs::remove_all(dir);
}

TEST(FrdWriter, AnElasticFrameHasNoPeBlockAsInCcx) {
  const auto dir = temp_dir("elastic");
  const model::Model m = hex_and_wedge();
  {
    FrdWriter w(m, dir / "e.frd");
    w.write(m.steps[0], frame_for(m, 1, 1.0, true));  // PEEQ requested, none computed
  }
  for (const auto& l : read_lines(dir / "e.frd")) EXPECT_NE(l.substr(0, 7), " -4  PE");
  fs::remove_all(dir);
}

TEST(FrdWriter, ContactBlockNamesTheSixComponentsAtEveryNode) {
  const auto dir = temp_dir("contact");
  model::Model m = hex_and_wedge();
  m.contact_pairs.resize(1);
  m.steps[0].node_files.clear();
  m.steps[0].element_files.clear();
  m.steps[0].contact_files.emplace_back().variables = {"CDIS"};
  Frame f = frame_for(m, 1, 0.5, true);
  const Index n = m.n_nodes();
  f.contact_nodal.COPEN = VecX::Constant(n, -1e-5);
  f.contact_nodal.CPRESS = VecX::Constant(n, 250);
  f.contact_nodal.CSLIP = MatX::Constant(n, 2, 0);
  f.contact_nodal.CSLIP.col(1).setConstant(3e-4);
  f.contact_nodal.CSHEAR = MatX::Constant(n, 2, 0);
  f.contact_nodal.CSHEAR.col(0).setConstant(-7);
  f.contact_nodal.status = VecX::Constant(n, 2);
  {
    FrdWriter w(m, dir / "c.frd");
    w.write(m.steps[0], f);
  }
  const auto lines = read_lines(dir / "c.frd");
  const std::size_t c = find_line(lines, " -4  CONTACT");
  EXPECT_EQ(lines[c - 1].substr(12, 12), " 5.00000E-01");  // 0 < t < 1: scientific
  EXPECT_EQ(lines[c], " -4  CONTACT     6    1");
  const char* expected[] = {
      " -5  COPEN       1    4    1    1", " -5  CSLIP1      1    4    2    2",
      " -5  CSLIP2      1    4    3    3", " -5  CPRESS      1    4    1    2",
      " -5  CSHEAR1     1    4    2    3", " -5  CSHEAR2     1    4    3    1"};
  for (int k = 0; k < 6; ++k) EXPECT_EQ(lines[c + 1 + k], expected[k]);
  EXPECT_EQ(lines[c + 7],
            " -1       101-1.00000E-05 0.00000E+00 3.00000E-04 2.50000E+02-7.00000E+00 "
            "0.00000E+00");
  int blocks = 0;  // only what is requested
  for (const auto& l : lines) blocks += l.rfind(" -4", 0) == 0;
  EXPECT_EQ(blocks, 1);
  fs::remove_all(dir);
}

TEST(FrdWriter, FramesFollowTheFrequencyAndTheFileIsWholeBetweenThem) {
  const auto dir = temp_dir("frequency");
  model::Model m = hex_and_wedge();
  m.steps[0].node_files = {{.variables = {"U"}, .frequency = 2}};
  m.steps[0].element_files.clear();
  m.steps.push_back(m.steps[0]);
  m.steps[1].node_files.clear();  // a step without file requests writes nothing
  FrdWriter w(m, dir / "f.frd");
  const auto count = [&](const std::string& prefix) {
    int k = 0;
    for (const auto& l : read_lines(dir / "f.frd")) k += l.rfind(prefix, 0) == 0;
    return k;
  };
  w.write(m.steps[0], frame_for(m, 1, 1.0, false));
  EXPECT_EQ(count("    1PSTEP"), 0);
  w.write(m.steps[0], frame_for(m, 2, 2.0, false));
  EXPECT_EQ(count("    1PSTEP"), 1);
  EXPECT_EQ(count(" 9999"), 1);
  EXPECT_EQ(read_lines(dir / "f.frd").back(), " 9999");
  w.write(m.steps[0], frame_for(m, 3, 3.0, true));  // step end: always
  Frame second = frame_for(m, 1, 4.0, true);
  second.step = 2;
  w.write(m.steps[1], second);
  EXPECT_EQ(count("    1PSTEP"), 2);
  EXPECT_EQ(w.frames_written(), 2);
  EXPECT_EQ(count(" 9999"), 1);
  const auto lines = read_lines(dir / "f.frd");
  EXPECT_EQ(lines.back(), " 9999");
  const std::size_t second_block =
      find_line(lines, "    1PSTEP", find_line(lines, "    1PSTEP") + 1);
  EXPECT_EQ(lines[second_block + 1].substr(0, 24), "  100CL  102 3.000000000");
  EXPECT_EQ(lines[second_block + 1].substr(58, 5), "    2");
  fs::remove_all(dir);
}

TEST(FrdWriter, FieldsAndWhenAFileIsWritten) {
  model::Model m = hex_and_wedge();
  EXPECT_EQ(frd_fields(m.steps[0]), (std::set<std::string>{"U", "RF", "NT", "S", "E", "PEEQ"}));
  EXPECT_TRUE(wants_frd(m));
  m.steps[0].node_files.clear();
  m.steps[0].element_files.clear();
  EXPECT_FALSE(wants_frd(m));
  m.steps[0].contact_files.emplace_back().variables = {"CELS"};
  EXPECT_TRUE(wants_frd(m));  // ccx writes the mesh for it
  EXPECT_TRUE(frd_fields(m.steps[0]).empty());
}

TEST(FrdWriter, AnUnwritableFileIsASolverErrorNamingTheFileAndTheReason) {
  const model::Model m = hex_and_wedge();
  EXPECT_THROW(FrdWriter(m, "/nonexistent-dir/x.frd"), SolverError);
  try {
    FrdWriter w(m, "/dev/full");  // every write fails with ENOSPC
    ADD_FAILURE() << "no error on a full device";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/full: No space left on device"),
              std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace kontakt::output
