#include <gtest/gtest.h>

#include <cmath>
#include <hdf5.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "output/hdf5_writer.hpp"
#include "output/vtk_cells.hpp"
#include "test_model.hpp"

namespace kontakt::output {
namespace {

namespace fs = std::filesystem;
using element::ElementType;

fs::path fresh_dir(const std::string& name) {
  auto d = fs::temp_directory_path() /
           ("kontakt_test_h5_" + std::to_string(::getpid())) / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// ------------------------------------------------------------------ reading helpers
struct H5File {
  hid_t id;
  explicit H5File(const fs::path& p) : id(H5Fopen(p.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT)) {}
  ~H5File() {
    if (id >= 0) H5Fclose(id);
  }
};

bool exists(hid_t f, const std::string& path) {
  // Check each component so intermediate groups may be absent.
  std::string cur;
  std::stringstream ss(path);
  std::string part;
  while (std::getline(ss, part, '/')) {
    if (part.empty()) continue;
    cur += "/" + part;
    if (H5Lexists(f, cur.c_str(), H5P_DEFAULT) <= 0) return false;
  }
  return true;
}

std::vector<hsize_t> shape(hid_t f, const std::string& path) {
  hid_t d = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
  EXPECT_GE(d, 0) << path;
  hid_t s = H5Dget_space(d);
  std::vector<hsize_t> dims(static_cast<std::size_t>(H5Sget_simple_extent_ndims(s)));
  H5Sget_simple_extent_dims(s, dims.data(), nullptr);
  H5Sclose(s);
  H5Dclose(d);
  return dims;
}

/// class, size, sign of a dataset's stored type
std::tuple<H5T_class_t, std::size_t, H5T_sign_t> dtype(hid_t f, const std::string& path) {
  hid_t d = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
  hid_t t = H5Dget_type(d);
  auto r = std::make_tuple(H5Tget_class(t), H5Tget_size(t),
                           H5Tget_class(t) == H5T_INTEGER ? H5Tget_sign(t) : H5T_SGN_ERROR);
  H5Tclose(t);
  H5Dclose(d);
  return r;
}

template <class T>
std::vector<T> read(hid_t f, const std::string& path, hid_t mem_type) {
  hsize_t n = 1;
  for (auto d : shape(f, path)) n *= d;
  std::vector<T> v(n);
  hid_t d = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
  if (n > 0) {
    EXPECT_GE(H5Dread(d, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), 0);
  }
  H5Dclose(d);
  return v;
}
std::vector<std::int64_t> read_i64(hid_t f, const std::string& p) {
  return read<std::int64_t>(f, p, H5T_NATIVE_INT64);
}
std::vector<double> read_f64(hid_t f, const std::string& p) {
  return read<double>(f, p, H5T_NATIVE_DOUBLE);
}

struct StringAttr {
  std::string value;
  std::size_t size = 0;
  H5T_str_t pad = H5T_STR_ERROR;
  bool variable = false;
};
StringAttr string_attr(hid_t f, const std::string& obj, const std::string& name) {
  StringAttr r;
  hid_t a = H5Aopen_by_name(f, obj.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  EXPECT_GE(a, 0) << obj << " @" << name;
  hid_t t = H5Aget_type(a);
  EXPECT_EQ(H5Tget_class(t), H5T_STRING);
  r.variable = H5Tis_variable_str(t) > 0;
  r.size = H5Tget_size(t);
  r.pad = H5Tget_strpad(t);
  if (!r.variable) {
    std::string buf(r.size, '\0');
    H5Aread(a, t, buf.data());
    r.value = buf.substr(0, buf.find('\0'));
  }
  H5Tclose(t);
  H5Aclose(a);
  return r;
}

template <class T>
T scalar_attr(hid_t f, const std::string& obj, const std::string& name, hid_t mem) {
  T v{};
  hid_t a = H5Aopen_by_name(f, obj.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  EXPECT_GE(a, 0) << obj << " @" << name;
  H5Aread(a, mem, &v);
  H5Aclose(a);
  return v;
}

// HDF5 1.10 API: objects are identified by their header address.
haddr_t address(hid_t f, const std::string& path) {
  H5O_info_t info;
  EXPECT_GE(H5Oget_info_by_name2(f, path.c_str(), &info, H5O_INFO_BASIC, H5P_DEFAULT), 0) << path;
  return info.addr;
}
bool same_object(hid_t f, const std::string& a, const std::string& b) {
  return address(f, a) == address(f, b);
}

bool uses_deflate(hid_t f, const std::string& path) {
  hid_t d = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
  hid_t p = H5Dget_create_plist(d);
  bool deflate = false;
  const int nf = H5Pget_nfilters(p);
  for (int i = 0; i < nf; ++i) {
    unsigned flags = 0;
    size_t n = 0;
    if (H5Pget_filter2(p, static_cast<unsigned>(i), &flags, &n, nullptr, 0, nullptr, nullptr) ==
        H5Z_FILTER_DEFLATE)
      deflate = true;
  }
  const bool chunked = H5Pget_layout(p) == H5D_CHUNKED;
  H5Pclose(p);
  H5Dclose(d);
  return deflate && chunked && nf == 1;
}

// ------------------------------------------------------------------ fixtures
Frame frame_for(const model::Model& m, int inc, double t) {
  const int n = m.n_nodes(), e = m.n_elements();
  Frame f;
  f.step = 1;
  f.increment = inc;
  f.step_time = t;
  f.total_time = t;
  f.U = MatX3::Constant(n, 3, t);
  f.RF = MatX3::Constant(n, 3, -t);
  f.S_nodal.resize(n, 6);
  f.E_nodal.resize(n, 6);
  for (int i = 0; i < n; ++i) {
    f.S_nodal.row(i) << 1, 2, 3, 4, 5, 6;  // xx yy zz xy xz yz
    f.E_nodal.row(i) << 1, 2, 3, 4, 5, 6;
  }
  f.ip_offset.resize(static_cast<std::size_t>(e) + 1);
  for (int i = 0; i <= e; ++i) f.ip_offset[static_cast<std::size_t>(i)] = i;
  f.S = MatX6::Constant(e, 6, 7.0);
  f.E = MatX6::Constant(e, 6, 8.0);
  f.ENER = VecX::Constant(e, 9.0);
  f.ip_volume = VecX::Constant(e, 1.0);
  f.EVOL = VecX::Constant(e, 0.5);
  return f;
}

TEST(Hdf5Writer, RequestedFieldsDefaultAndUnion) {
  auto m = test::two_tets();
  EXPECT_EQ(requested_fields(m), (std::set<std::string>{"U", "S"}));
  m.steps.resize(2);
  m.steps[0].node_files.push_back({{"RF", "NT"}, 1});
  m.steps[1].element_files.push_back({{"E", "EVOL"}, 1});
  EXPECT_EQ(requested_fields(m), (std::set<std::string>{"E", "EVOL", "RF"}));
}

TEST(Hdf5Writer, FileIsCompleteBetweenWritesAndPartialOnlyDuringOne) {
  auto m = test::two_tets();
  const auto dir = fresh_dir("rename");
  {
    Hdf5Writer w(m, dir, "job", {"U"});
    // A results file from the start (mesh, no frame yet), never a .partial between writes.
    EXPECT_TRUE(fs::exists(dir / "job.hdf"));
    EXPECT_TRUE(fs::exists(dir / "job.xdmf"));
    EXPECT_FALSE(fs::exists(dir / "job.hdf.partial"));
    w.write(frame_for(m, 1, 1.0));
    EXPECT_FALSE(fs::exists(dir / "job.hdf.partial"));
    w.finish();
    EXPECT_FALSE(fs::exists(dir / "job.hdf.partial"));
    EXPECT_FALSE(fs::exists(dir / "job.xdmf.partial"));
    EXPECT_TRUE(fs::exists(dir / "job.hdf"));
  }
  // Abandoned writer (no finish): the file keeps every frame, with its VTKHDF view.
  const auto dir2 = fresh_dir("abandon");
  {
    Hdf5Writer w(m, dir2, "job", {"U"});
    w.write(frame_for(m, 1, 1.0));
  }
  EXPECT_FALSE(fs::exists(dir2 / "job.hdf.partial"));
  H5File f(dir2 / "job.hdf");
  ASSERT_GE(f.id, 0);
  EXPECT_TRUE(exists(f.id, "/frames/000001/U"));
  EXPECT_TRUE(same_object(f.id, "/VTKHDF/PointData/U", "/frames/000001/U"));
}

TEST(Hdf5Writer, KilledProcessLeavesEveryWrittenFrameReadable) {
  // A job process killed (SIGKILL) between frames: no destructor, no close. The file on disk
  // must hold every frame written, the history so far and a VTKHDF view of the newest frame.
  auto m = test::two_tets();
  const auto dir = fresh_dir("killed");
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    Hdf5Writer w(m, dir, "job", {"U"});
    w.write(frame_for(m, 1, 0.5));
    w.add_increment({1, 1, 1, 3, 0.5, 0.5, 0.5, true});
    w.add_increment({1, 2, 1, 2, 0.75, 0.75, 0.25, true});
    w.write(frame_for(m, 2, 0.75));
    raise(SIGKILL);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_FALSE(fs::exists(dir / "job.hdf.partial"));
  EXPECT_FALSE(fs::exists(dir / "job.xdmf.partial"));
  H5File f(dir / "job.hdf");
  ASSERT_GE(f.id, 0);
  EXPECT_EQ(read_f64(f.id, "/frames/000002/U")[0], 0.75);
  EXPECT_EQ(shape(f.id, "/history/increments"), (std::vector<hsize_t>{2}));
  EXPECT_TRUE(same_object(f.id, "/VTKHDF/PointData/U", "/frames/000002/U"));
  std::ifstream xdmf(dir / "job.xdmf");
  std::stringstream text;
  text << xdmf.rdbuf();
  EXPECT_NE(text.str().find("frame_000002"), std::string::npos);
}

TEST(Hdf5Writer, AFailedWriteNamesTheSystemsReasonAndTheProcessExitsCleanly) {
  // A job past its file size limit (RLIMIT_FSIZE, SIGXFSZ ignored as the job worker does):
  // the write fails with EFBIG. HDF5 1.10 used to crash at exit closing that file again.
  auto m = test::two_tets();
  const auto dir = fresh_dir("full");
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{32 << 10, 32 << 10};
    setrlimit(RLIMIT_FSIZE, &limit);
    try {
      Hdf5Writer w(m, dir, "job", {"U", "S", "E"});
      for (int i = 1; i < 100000; ++i) w.write(frame_for(m, i, i));
    } catch (const SolverError& e) {
      std::exit(std::string(e.what()).find("File too large") != std::string::npos ? 7 : 8);
    }
    std::exit(9);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 7);
  EXPECT_TRUE(fs::exists(dir / "job.hdf.partial")) << "the write that failed is never published";
  EXPECT_FALSE(fs::exists(dir / "job.hdf"));
}

TEST(Hdf5Writer, Structure) {
  auto m = test::two_tets();
  const auto dir = fresh_dir("structure");
  {
    Hdf5Writer w(m, dir, "model", {"U", "RF", "S", "E", "ENER", "EVOL"});
    w.write(frame_for(m, 1, 0.5));
    w.add_increment({1, 1, 1, 3, 0.5, 0.5, 0.5, true, 0.25, 3.5});
    w.write(frame_for(m, 2, 1.0));
    w.add_increment({1, 2, 2, 4, 1.0, 1.0, 0.5, false});
    EXPECT_EQ(w.frames_written(), 2);
    w.finish();
  }
  H5File file(dir / "model.hdf");
  const hid_t f = file.id;
  ASSERT_GE(f, 0);

  // Root attributes.
  EXPECT_EQ(string_attr(f, "/", "format").value, "kontakt-results");
  EXPECT_EQ(string_attr(f, "/", "format_version").value, "1.0");
  EXPECT_EQ(string_attr(f, "/", "solver").value, "kontakt");
  EXPECT_FALSE(string_attr(f, "/", "solver_version").value.empty());
  EXPECT_TRUE(std::regex_match(string_attr(f, "/", "created").value,
                               std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")));
  EXPECT_FALSE(string_attr(f, "/", "format").variable);

  // /VTKHDF attributes.
  const auto type = string_attr(f, "/VTKHDF", "Type");
  EXPECT_FALSE(type.variable);
  EXPECT_EQ(type.size, 16u);
  EXPECT_EQ(type.pad, H5T_STR_NULLPAD);
  EXPECT_EQ(type.value, "UnstructuredGrid");
  {
    hid_t a = H5Aopen_by_name(f, "/VTKHDF", "Version", H5P_DEFAULT, H5P_DEFAULT);
    hid_t t = H5Aget_type(a);
    EXPECT_EQ(H5Tget_class(t), H5T_INTEGER);
    EXPECT_EQ(H5Tget_size(t), 8u);
    hid_t s = H5Aget_space(a);
    EXPECT_EQ(H5Sget_simple_extent_npoints(s), 2);
    std::int64_t v[2] = {0, 0};
    H5Aread(a, H5T_NATIVE_INT64, v);
    EXPECT_EQ(v[0], 1);
    EXPECT_EQ(v[1], 0);
    H5Sclose(s);
    H5Tclose(t);
    H5Aclose(a);
  }
  // /VTKHDF datasets: dtypes and shapes.
  EXPECT_EQ(read_i64(f, "/VTKHDF/NumberOfPoints"), std::vector<std::int64_t>{5});
  EXPECT_EQ(read_i64(f, "/VTKHDF/NumberOfCells"), std::vector<std::int64_t>{2});
  EXPECT_EQ(read_i64(f, "/VTKHDF/NumberOfConnectivityIds"), std::vector<std::int64_t>{8});
  EXPECT_EQ(shape(f, "/VTKHDF/Points"), (std::vector<hsize_t>{5, 3}));
  EXPECT_EQ(dtype(f, "/VTKHDF/Points"), std::make_tuple(H5T_FLOAT, std::size_t{8}, H5T_SGN_ERROR));
  EXPECT_EQ(dtype(f, "/VTKHDF/Types"), std::make_tuple(H5T_INTEGER, std::size_t{1}, H5T_SGN_NONE));
  EXPECT_EQ(read<std::uint8_t>(f, "/VTKHDF/Types", H5T_NATIVE_UINT8),
            (std::vector<std::uint8_t>{10, 10}));
  EXPECT_EQ(dtype(f, "/VTKHDF/Offsets"), std::make_tuple(H5T_INTEGER, std::size_t{8}, H5T_SGN_2));
  EXPECT_EQ(read_i64(f, "/VTKHDF/Offsets"), (std::vector<std::int64_t>{0, 4, 8}));
  EXPECT_EQ(read_i64(f, "/VTKHDF/Connectivity"),
            (std::vector<std::int64_t>{0, 1, 2, 3, 1, 4, 2, 3}));
  EXPECT_FALSE(uses_deflate(f, "/VTKHDF/Connectivity"));  // small: contiguous
  EXPECT_FALSE(uses_deflate(f, "/frames/000002/U"));

  // /mesh
  EXPECT_EQ(read_i64(f, "/mesh/node_ids"), (std::vector<std::int64_t>{10, 20, 30, 40, 50}));
  EXPECT_EQ(read_i64(f, "/mesh/element_ids"), (std::vector<std::int64_t>{7, 8}));
  EXPECT_EQ(read_i64(f, "/mesh/sets/nsets/FIX"), (std::vector<std::int64_t>{10, 20}));
  EXPECT_EQ(read_i64(f, "/mesh/sets/elsets/E2"), (std::vector<std::int64_t>{8}));
  EXPECT_EQ(read_i64(f, "/mesh/ip_offset"), (std::vector<std::int64_t>{0, 1, 2}));
  EXPECT_EQ(shape(f, "/mesh/xdmf_topology"), (std::vector<hsize_t>{2, 4}));
  {
    auto [cls, size, sign] = dtype(f, "/mesh/element_type");
    EXPECT_EQ(cls, H5T_STRING);
    EXPECT_EQ(size, 4u);  // "C3D4"
    (void)sign;
  }

  // Frames.
  EXPECT_TRUE(exists(f, "/frames/000001"));
  EXPECT_TRUE(exists(f, "/frames/000002"));
  EXPECT_FALSE(exists(f, "/frames/000003"));
  EXPECT_EQ(scalar_attr<std::int64_t>(f, "/frames/000002", "increment", H5T_NATIVE_INT64), 2);
  EXPECT_EQ(scalar_attr<std::int64_t>(f, "/frames/000002", "step", H5T_NATIVE_INT64), 1);
  EXPECT_EQ(scalar_attr<double>(f, "/frames/000002", "total_time", H5T_NATIVE_DOUBLE), 1.0);
  EXPECT_EQ(scalar_attr<double>(f, "/frames/000001", "step_time", H5T_NATIVE_DOUBLE), 0.5);
  EXPECT_EQ(scalar_attr<std::int8_t>(f, "/frames/000002", "converged", H5T_NATIVE_INT8), 1);
  EXPECT_EQ(shape(f, "/frames/000002/U"), (std::vector<hsize_t>{5, 3}));
  EXPECT_EQ(shape(f, "/frames/000002/S"), (std::vector<hsize_t>{5, 6}));
  EXPECT_EQ(shape(f, "/frames/000002/S_Mises"), (std::vector<hsize_t>{5}));
  EXPECT_EQ(shape(f, "/frames/000002/S_ip"), (std::vector<hsize_t>{2, 6}));
  EXPECT_EQ(shape(f, "/frames/000002/E_ip"), (std::vector<hsize_t>{2, 6}));
  EXPECT_EQ(shape(f, "/frames/000002/ENER_ip"), (std::vector<hsize_t>{2}));
  EXPECT_EQ(shape(f, "/frames/000002/EVOL"), (std::vector<hsize_t>{2}));
  EXPECT_FALSE(exists(f, "/frames/000002/PEEQ_ip"));  // elastic: no PEEQ
  // VTK tensor order xx,yy,zz,xy,yz,xz; the IP arrays keep the Frame order.
  const auto s = read_f64(f, "/frames/000002/S");
  EXPECT_EQ(std::vector<double>(s.begin(), s.begin() + 6),
            (std::vector<double>{1, 2, 3, 4, 6, 5}));
  const auto mises = read_f64(f, "/frames/000002/S_Mises");
  EXPECT_NEAR(mises[0], std::sqrt(0.5 * (1 + 1 + 4) + 3 * (16 + 25 + 36)), 1e-12);
  EXPECT_EQ(read_f64(f, "/frames/000001/U")[0], 0.5);

  // Hard links to the final frame.
  for (const char* a : {"U", "RF", "S", "E", "S_Mises"}) {
    ASSERT_TRUE(exists(f, std::string("/VTKHDF/PointData/") + a)) << a;
    H5L_info_t li;
    H5Lget_info(f, (std::string("/VTKHDF/PointData/") + a).c_str(), &li, H5P_DEFAULT);
    EXPECT_EQ(li.type, H5L_TYPE_HARD);
    EXPECT_TRUE(same_object(f, std::string("/VTKHDF/PointData/") + a,
                            std::string("/frames/000002/") + a));
  }
  EXPECT_TRUE(same_object(f, "/VTKHDF/CellData/EVOL", "/frames/000002/EVOL"));
  EXPECT_FALSE(exists(f, "/VTKHDF/PointData/S_ip"));

  // History table.
  EXPECT_EQ(shape(f, "/history/increments"), (std::vector<hsize_t>{2}));
  {
    hid_t d = H5Dopen2(f, "/history/increments", H5P_DEFAULT);
    hid_t t = H5Dget_type(d);
    EXPECT_EQ(H5Tget_class(t), H5T_COMPOUND);
    EXPECT_EQ(H5Tget_nmembers(t), 10);
    EXPECT_GE(H5Tget_member_index(t, "attempts"), 0);
    EXPECT_GE(H5Tget_member_index(t, "dt"), 0);
    struct Row {
      std::int64_t attempts;
      std::int8_t converged;
      double stabilisation_energy, strain_energy;
    };
    hid_t mt = H5Tcreate(H5T_COMPOUND, sizeof(Row));
    H5Tinsert(mt, "attempts", HOFFSET(Row, attempts), H5T_NATIVE_INT64);
    H5Tinsert(mt, "converged", HOFFSET(Row, converged), H5T_NATIVE_INT8);
    H5Tinsert(mt, "stabilisation_energy", HOFFSET(Row, stabilisation_energy), H5T_NATIVE_DOUBLE);
    H5Tinsert(mt, "strain_energy", HOFFSET(Row, strain_energy), H5T_NATIVE_DOUBLE);
    Row rows[2];
    H5Dread(d, mt, H5S_ALL, H5S_ALL, H5P_DEFAULT, rows);
    EXPECT_EQ(rows[1].attempts, 2);
    EXPECT_EQ(rows[0].converged, 1);
    EXPECT_EQ(rows[1].converged, 0);
    EXPECT_EQ(rows[0].stabilisation_energy, 0.25);
    EXPECT_EQ(rows[0].strain_energy, 3.5);
    EXPECT_TRUE(std::isnan(rows[1].strain_energy));  // a cut-back attempt has none
    H5Tclose(mt);
    H5Tclose(t);
    H5Dclose(d);
  }
}

// Compressing costs zlib's set-up per chunk: worth it on a model's large arrays only.
TEST(Hdf5Writer, LargeDatasetsAreDeflatedAndSmallOnesContiguous) {
  model::Model m;
  const int n = 3000;  // U: 3000 x 3 doubles = 72 kB; node ids 24 kB
  for (int i = 0; i < n; ++i) test::add_node(m, i + 1, i, (i % 2), (i % 3));
  for (int i = 0; i + 3 < n; ++i)
    test::add_element(m, i + 1, element::ElementType::C3D4, {i, i + 1, i + 2, i + 3});
  m.steps.resize(1);
  const auto dir = fresh_dir("deflate");
  Frame frame = frame_for(m, 1, 1.0);
  for (int i = 0; i < n; ++i) frame.U.row(i) << i, -i, 0.5 * i;
  {
    Hdf5Writer w(m, dir, "model", {"U"});
    w.write(frame);
    w.finish();
  }
  H5File file(dir / "model.hdf");
  EXPECT_TRUE(uses_deflate(file.id, "/frames/000001/U"));
  EXPECT_TRUE(uses_deflate(file.id, "/VTKHDF/Connectivity"));
  EXPECT_FALSE(uses_deflate(file.id, "/mesh/node_ids"));
  const auto u = read_f64(file.id, "/frames/000001/U");
  ASSERT_EQ(u.size(), 3u * n);
  EXPECT_EQ(u[3 * 2999 + 1], -2999.0);
  EXPECT_EQ(read_i64(file.id, "/mesh/node_ids").back(), n);
}

TEST(Hdf5Writer, OnlyRequestedFields) {
  auto m = test::two_tets();
  const auto dir = fresh_dir("fields");
  {
    Hdf5Writer w(m, dir, "m", {"RF"});
    w.write(frame_for(m, 1, 1.0));
    w.finish();
  }
  H5File f(dir / "m.hdf");
  EXPECT_TRUE(exists(f.id, "/frames/000001/RF"));
  for (const char* a : {"U", "S", "E", "S_ip", "S_Mises", "EVOL", "ENER_ip"})
    EXPECT_FALSE(exists(f.id, std::string("/frames/000001/") + a)) << a;
}

// ------------------------------------------------------------------ XDMF
/// Minimal well-formedness check: balanced tags, proper nesting; returns tag counts.
std::map<std::string, int> parse_xml(const std::string& text, bool& ok) {
  std::map<std::string, int> count;
  std::vector<std::string> stack;
  ok = true;
  std::size_t pos = 0;
  while ((pos = text.find('<', pos)) != std::string::npos) {
    const auto end = text.find('>', pos);
    if (end == std::string::npos) {
      ok = false;
      break;
    }
    std::string tag = text.substr(pos + 1, end - pos - 1);
    pos = end + 1;
    if (tag.starts_with('?')) continue;
    if (tag.starts_with('/')) {
      if (stack.empty() || stack.back() != tag.substr(1)) ok = false;
      if (!stack.empty()) stack.pop_back();
      continue;
    }
    const bool self_closing = tag.ends_with('/');
    const std::string name = tag.substr(0, tag.find_first_of(" /"));
    if (std::count(tag.begin(), tag.end(), '"') % 2 != 0) ok = false;
    ++count[name];
    if (!self_closing) stack.push_back(name);
  }
  if (!stack.empty()) ok = false;
  return count;
}

TEST(Hdf5Writer, XdmfSidecar) {
  auto m = test::two_tets();
  test::add_node(m, 60, 2, 0, 0);
  test::add_node(m, 70, 2, 1, 0);
  test::add_node(m, 80, 2, 0, 1);
  test::add_node(m, 90, 2, 1, 1);
  test::add_element(m, 9, ElementType::C3D6, {1, 5, 6, 3, 7, 4});  // mixed mesh
  const auto dir = fresh_dir("xdmf");
  {
    Hdf5Writer w(m, dir, "mixed", {"U", "S", "EVOL"});
    for (int i = 1; i <= 3; ++i) w.write(frame_for(m, i, 0.25 * i));
    w.finish();
  }
  std::ifstream in(dir / "mixed.xdmf");
  std::stringstream ss;
  ss << in.rdbuf();
  const auto text = ss.str();
  bool ok = false;
  auto count = parse_xml(text, ok);
  EXPECT_TRUE(ok) << text;
  EXPECT_EQ(count["Xdmf"], 1);
  EXPECT_EQ(count["Grid"], 4);                // collection + 3 frames
  EXPECT_EQ(count["Time"], 3);
  EXPECT_EQ(count["Attribute"], 3 * 4);      // U, S, S_Mises, EVOL
  EXPECT_NE(text.find("CollectionType=\"Temporal\""), std::string::npos);
  EXPECT_NE(text.find("TopologyType=\"Mixed\" NumberOfElements=\"3\""), std::string::npos);
  EXPECT_NE(text.find(">mixed.hdf:/frames/000003/S</DataItem>"), std::string::npos);
  EXPECT_NE(text.find("AttributeType=\"Tensor6\""), std::string::npos);
  EXPECT_NE(text.find("Center=\"Cell\""), std::string::npos);
  EXPECT_EQ(text.find(dir.string()), std::string::npos);  // relative file name only
  // Mixed topology: [code, nodes...] per cell; total length 2*(1+4) + (1+6).
  H5File f(dir / "mixed.hdf");
  const auto topo = read_i64(f.id, "/mesh/xdmf_topology");
  ASSERT_EQ(topo.size(), 17u);
  EXPECT_EQ(topo[0], 6);
  EXPECT_EQ(topo[10], 8);
  // wedge in VTK order: ccx (1,5,6,3,7,4) -> (1,6,5,3,4,7)
  EXPECT_EQ(std::vector<std::int64_t>(topo.begin() + 11, topo.end()),
            (std::vector<std::int64_t>{1, 6, 5, 3, 4, 7}));
  EXPECT_NE(text.find("Dimensions=\"17\""), std::string::npos);
}

// ------------------------------------------------------------------ contact
model::Model with_contact_pair() {
  auto m = test::two_tets();
  m.contact_pairs.emplace_back();
  return m;
}

/// A frame with nodal contact values on nodes 20 and 30 and three contact points: a sticking
/// one on element 8 face 2, a sliding one and an open one.
Frame contact_frame(const model::Model& m, int inc, double t) {
  Frame f = frame_for(m, inc, t);
  const int n = m.n_nodes();
  auto& c = f.contact_nodal;
  c.CPRESS = VecX::Zero(n);
  c.COPEN = VecX::Zero(n);
  c.CSHEAR = MatX::Zero(n, 2);
  c.CSLIP = MatX::Zero(n, 2);
  c.status = VecX::Zero(n);
  c.CPRESS(1) = 100;
  c.COPEN(1) = -1e-5;
  c.CSHEAR.row(1) << 3, 4;
  c.CSLIP.row(2) << 5, 6;
  c.status(1) = 1;
  c.status(2) = 2;
  for (int k = 0; k < 3; ++k) {
    ContactPointRecord p;
    p.slave_element = 1;
    p.slave_face = 2;
    p.xi = Vec2(0.1 * k, 0.2);
    p.x = Vec3(1, 2, k);
    p.active = k < 2;
    p.sticking = k == 0;
    p.clearance = k == 2 ? 1e-3 : -1e-5;
    p.pressure = k == 2 ? 0 : 100;
    p.shear = Vec2(k, -k);
    p.area = 0.25;
    p.energy = 1e-4 * k;
    f.contact_points.push_back(p);
  }
  f.n_active_contact = 2;
  return f;
}

TEST(Hdf5Writer, RequestedFieldsWithContact) {
  auto m = with_contact_pair();
  EXPECT_EQ(requested_fields(m), (std::set<std::string>{"U", "S", "CDIS", "CSTR", "CELS"}));
  m.steps[0].contact_files.push_back({{"CELS"}, false, false, 1, 0, {}});
  EXPECT_EQ(requested_fields(m), (std::set<std::string>{"CELS"}));  // only what is asked
  m.steps[0].node_files.push_back({{"U"}, 1});
  EXPECT_EQ(requested_fields(m), (std::set<std::string>{"CELS", "U"}));
  // Contact file requests count for the frequency too.
  m.steps[0].node_files[0].frequency = 100;
  m.steps[0].contact_files[0].frequency = 2;
  Frame f;
  f.is_step_end = false;
  f.increment = 4;
  EXPECT_TRUE(file_output_due(m.steps[0], f));
  f.increment = 3;
  EXPECT_FALSE(file_output_due(m.steps[0], f));
}

TEST(Hdf5Writer, ContactArraysAndPointTable) {
  const auto m = with_contact_pair();
  const auto dir = fresh_dir("contact");
  {
    Hdf5Writer w(m, dir, "c", {"U", "CSTR"});
    w.write(contact_frame(m, 1, 0.5));
    Frame open = contact_frame(m, 2, 1.0);
    open.contact_points.clear();  // no points: a table without rows
    w.write(open);
    w.finish();
  }
  H5File file(dir / "c.hdf");
  const hid_t f = file.id;
  for (const char* a : {"CPRESS", "COPEN", "CSHEAR1", "CSHEAR2", "CSLIP1", "CSLIP2", "CSTATUS"}) {
    EXPECT_EQ(shape(f, std::string("/frames/000001/") + a), (std::vector<hsize_t>{5})) << a;
    EXPECT_TRUE(same_object(f, std::string("/VTKHDF/PointData/") + a,
                            std::string("/frames/000002/") + a))
        << a;
  }
  EXPECT_EQ(read_f64(f, "/frames/000001/CPRESS")[1], 100);
  EXPECT_EQ(read_f64(f, "/frames/000001/CSHEAR2")[1], 4);
  EXPECT_EQ(read_f64(f, "/frames/000001/CSLIP1")[2], 5);
  EXPECT_EQ(read_f64(f, "/frames/000001/CSTATUS"), (std::vector<double>{0, 1, 2, 0, 0}));
  const std::string t = "/frames/000001/contact_points/";
  EXPECT_EQ(read_i64(f, t + "status"), (std::vector<std::int64_t>{1, 2, 0}));
  EXPECT_EQ(read_i64(f, t + "slave_element"), (std::vector<std::int64_t>{8, 8, 8}));  // labels
  EXPECT_EQ(read_i64(f, t + "slave_face"), (std::vector<std::int64_t>{2, 2, 2}));
  EXPECT_EQ(read_i64(f, t + "slave_node"), (std::vector<std::int64_t>{-1, -1, -1}));
  EXPECT_EQ(read_i64(f, t + "pair"), (std::vector<std::int64_t>{0, 0, 0}));
  EXPECT_EQ(shape(f, t + "x"), (std::vector<hsize_t>{3, 3}));
  EXPECT_EQ(read_f64(f, t + "x")[8], 2.0);
  EXPECT_EQ(shape(f, t + "xi"), (std::vector<hsize_t>{3, 2}));
  EXPECT_EQ(read_f64(f, t + "clearance")[2], 1e-3);
  EXPECT_EQ(read_f64(f, t + "pressure")[0], 100);
  EXPECT_EQ(read_f64(f, t + "shear")[3], -1);
  EXPECT_EQ(read_f64(f, t + "area")[1], 0.25);
  EXPECT_EQ(read_f64(f, t + "energy")[2], 2e-4);
  EXPECT_EQ(shape(f, "/frames/000002/contact_points/pressure"), (std::vector<hsize_t>{0}));

  std::ifstream main_xdmf(dir / "c.xdmf");
  std::stringstream main_text;
  main_text << main_xdmf.rdbuf();
  EXPECT_NE(main_text.str().find("Name=\"CPRESS\" AttributeType=\"Scalar\" Center=\"Node\""),
            std::string::npos);
}

TEST(Hdf5Writer, NoContactDataWithoutContactPairs) {
  auto m = test::two_tets();  // no pairs: the contact parts of a frame are ignored
  const auto dir = fresh_dir("nocontact");
  {
    Hdf5Writer w(m, dir, "n", {"U", "CDIS", "CSTR", "CELS"});
    w.write(contact_frame(m, 1, 1.0));
    w.finish();
  }
  H5File f(dir / "n.hdf");
  EXPECT_FALSE(exists(f.id, "/frames/000001/CPRESS"));
  EXPECT_FALSE(exists(f.id, "/frames/000001/contact_points"));
}

/// Writes a contact results file where KONTAKT_CONTACT_LAYOUT_FILE says, for
/// check_results_layout.py (ctest results_layout_contact); skipped otherwise.
TEST(Hdf5Writer, ContactLayoutFileForTheChecker) {
  const char* target = std::getenv("KONTAKT_CONTACT_LAYOUT_FILE");
  if (target == nullptr) GTEST_SKIP() << "KONTAKT_CONTACT_LAYOUT_FILE not set";
  const fs::path path(target);
  fs::create_directories(path.parent_path());
  const auto m = with_contact_pair();
  Hdf5Writer w(m, path.parent_path(), path.stem().string(),
               {"U", "RF", "S", "E", "ENER", "EVOL", "CDIS", "CSTR", "CELS"});
  w.write(contact_frame(m, 1, 0.5));
  w.add_increment({1, 1, 1, 3, 0.5, 0.5, 0.5, true});
  w.finish();
  EXPECT_TRUE(fs::exists(path));
}

}  // namespace
}  // namespace kontakt::output
