// Node-order round trip: one undistorted element per type, written to VTKHDF, read back, and
// checked with VTK's conventions (outward faces -> positive volume; midside nodes on the VTK
// edges they belong to).
#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <array>
#include <filesystem>

#include "output/hdf5_writer.hpp"
#include "output/vtk_cells.hpp"
#include "test_model.hpp"

namespace kontakt::output {
namespace {

namespace fs = std::filesystem;
using element::ElementType;
using P = std::array<double, 3>;

// Natural (ccx/Abaqus) node coordinates, ccx local order.
std::vector<P> corners(ElementType t) {
  switch (t) {
    case ElementType::C3D4:
    case ElementType::C3D10:
      return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    case ElementType::C3D6:
    case ElementType::C3D15:
      return {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
    default:
      return {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
              {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  }
}
// Abaqus midside node k (in order) lies on ccx edge (a, b), 1-based.
std::vector<std::pair<int, int>> ccx_midside_edges(ElementType t) {
  switch (t) {
    case ElementType::C3D10:
      return {{1, 2}, {2, 3}, {3, 1}, {1, 4}, {2, 4}, {3, 4}};
    case ElementType::C3D15:
      return {{1, 2}, {2, 3}, {3, 1}, {4, 5}, {5, 6}, {6, 4}, {1, 4}, {2, 5}, {3, 6}};
    case ElementType::C3D20:
    case ElementType::C3D20R:
      return {{1, 2}, {2, 3}, {3, 4}, {4, 1}, {5, 6}, {6, 7},
              {7, 8}, {8, 5}, {1, 5}, {2, 6}, {3, 7}, {4, 8}};
    default:
      return {};
  }
}

// VTK conventions (vtkTetra/vtkHexahedron/vtkWedge and the quadratic cells).
std::vector<std::vector<int>> vtk_faces(int vtk_type) {
  switch (vtk_type) {
    case 10:
    case 24:
      return {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {0, 2, 1}};
    case 12:
    case 25:
      return {{0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 7, 6, 2}, {0, 3, 2, 1}, {4, 5, 6, 7}};
    default:  // 13, 26
      return {{0, 1, 2}, {3, 5, 4}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}};
  }
}
std::vector<std::pair<int, int>> vtk_midside_edges(int vtk_type) {
  switch (vtk_type) {
    case 24:
      return {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
    case 25:
      return {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
              {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    case 26:
      return {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {0, 3}, {1, 4}, {2, 5}};
    default:
      return {};
  }
}

double triple(const P& a, const P& b, const P& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
}

/// Signed volume enclosed by the faces (fan triangulation, divergence theorem).
double signed_volume(const std::vector<P>& x, int vtk_type) {
  double v = 0;
  for (const auto& f : vtk_faces(vtk_type))
    for (std::size_t k = 1; k + 1 < f.size(); ++k)
      v += triple(x[static_cast<std::size_t>(f[0])], x[static_cast<std::size_t>(f[k])],
                  x[static_cast<std::size_t>(f[k + 1])]) / 6.0;
  return v;
}

class VtkOrder : public ::testing::TestWithParam<ElementType> {};

TEST_P(VtkOrder, RoundTripHasPositiveVolumeAndMidsidesOnEdges) {
  const ElementType type = GetParam();
  const auto& cell = vtk_cell(type);
  // Build ccx-ordered coordinates, then map them by a proper affine map (det > 0).
  auto nat = corners(type);
  for (auto [a, b] : ccx_midside_edges(type)) {
    const auto& pa = nat[static_cast<std::size_t>(a - 1)];
    const auto& pb = nat[static_cast<std::size_t>(b - 1)];
    nat.push_back({(pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2, (pa[2] + pb[2]) / 2});
  }
  ASSERT_EQ(static_cast<int>(nat.size()), cell.n_nodes);
  model::Model m;
  std::vector<int> nodes;
  for (std::size_t i = 0; i < nat.size(); ++i) {
    const auto& p = nat[i];
    test::add_node(m, static_cast<int>(100 + i), 2.0 * p[0] + 0.3 * p[1] + 5.0,
                   -0.2 * p[0] + 1.5 * p[1] + 0.1 * p[2], 0.1 * p[1] + 0.7 * p[2] - 1.0);
    nodes.push_back(static_cast<int>(i));
  }
  test::add_element(m, 1, type, nodes);

  const auto dir = fs::temp_directory_path() /
                   ("kontakt_test_vtk_" + std::to_string(::getpid())) /
                   std::string(cell.name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    Hdf5Writer w(m, dir, "one", {"U"});
    w.finish();
  }
  hid_t f = H5Fopen((dir / "one.hdf").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  auto read_all = [&](const char* path, hid_t mem, void* buf) {
    hid_t d = H5Dopen2(f, path, H5P_DEFAULT);
    ASSERT_GE(d, 0) << path;
    EXPECT_GE(H5Dread(d, mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf), 0);
    H5Dclose(d);
  };
  std::vector<double> pts(nat.size() * 3);
  std::vector<std::int64_t> conn(nat.size());
  std::uint8_t vtk_type = 0;
  std::int64_t offsets[2] = {-1, -1};
  read_all("/VTKHDF/Points", H5T_NATIVE_DOUBLE, pts.data());
  read_all("/VTKHDF/Connectivity", H5T_NATIVE_INT64, conn.data());
  read_all("/VTKHDF/Types", H5T_NATIVE_UINT8, &vtk_type);
  read_all("/VTKHDF/Offsets", H5T_NATIVE_INT64, offsets);
  H5Fclose(f);

  EXPECT_EQ(offsets[0], 0);
  EXPECT_EQ(offsets[1], cell.n_nodes);
  std::vector<P> x;
  for (auto c : conn) {
    const auto i = static_cast<std::size_t>(c);
    x.push_back({pts[3 * i], pts[3 * i + 1], pts[3 * i + 2]});
  }
  // Every node appears exactly once.
  auto sorted = conn;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) EXPECT_EQ(sorted[i], static_cast<long>(i));

  EXPECT_GT(signed_volume(x, vtk_type), 1e-9) << cell.name;
  const auto edges = vtk_midside_edges(vtk_type);
  const int n_corner = cell.n_nodes - static_cast<int>(edges.size());
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const auto& a = x[static_cast<std::size_t>(edges[k].first)];
    const auto& b = x[static_cast<std::size_t>(edges[k].second)];
    const auto& mid = x[static_cast<std::size_t>(n_corner) + k];
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(mid[static_cast<std::size_t>(c)],
                  (a[static_cast<std::size_t>(c)] + b[static_cast<std::size_t>(c)]) / 2, 1e-12)
          << cell.name << " midside " << k;
  }
  // Corner-only types: the signed volume must equal the affine image volume of the element.
  const double ref = type == ElementType::C3D4 || type == ElementType::C3D10 ? 1.0 / 6
                     : type == ElementType::C3D6 || type == ElementType::C3D15 ? 1.0
                                                                               : 8.0;
  const double det = 2.0 * (1.5 * 0.7 - 0.1 * 0.1) - 0.3 * (-0.2 * 0.7 - 0.0) + 0.0;
  EXPECT_NEAR(signed_volume(x, vtk_type), ref * det, 1e-9) << cell.name;
}

INSTANTIATE_TEST_SUITE_P(AllTypes, VtkOrder,
                         ::testing::Values(ElementType::C3D4, ElementType::C3D6, ElementType::C3D8,
                                           ElementType::C3D8R, ElementType::C3D8I,
                                           ElementType::C3D10, ElementType::C3D15,
                                           ElementType::C3D20, ElementType::C3D20R),
                         [](const auto& info) { return std::string(vtk_cell(info.param).name); });

TEST(VtkCells, Table) {
  EXPECT_EQ(vtk_cell(ElementType::C3D20R).vtk_type, 25);
  EXPECT_EQ(vtk_cell(ElementType::C3D15).xdmf_type, 40);
  EXPECT_EQ(vtk_cell(ElementType::C3D10).xdmf_type, 38);
  EXPECT_EQ(vtk_cell(ElementType::C3D6).vtk_type, 13);
  for (auto t : {ElementType::C3D4, ElementType::C3D6, ElementType::C3D8, ElementType::C3D8R,
                 ElementType::C3D8I, ElementType::C3D10, ElementType::C3D15, ElementType::C3D20,
                 ElementType::C3D20R})
    EXPECT_EQ(static_cast<int>(vtk_cell(t).perm.size()), vtk_cell(t).n_nodes);
}

}  // namespace
}  // namespace kontakt::output
