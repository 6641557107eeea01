#include "output/hdf5_writer.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "material/von_mises.hpp"
#include "output/time_stamp.hpp"
#include "output/vtk_cells.hpp"

#ifndef KONTAKT_VERSION
#define KONTAKT_VERSION "unknown"
#endif

namespace kontakt::output {

namespace {

// ---------------------------------------------------------------- small HDF5 helpers
// No clean-up by the library at exit: after a failed write (a full disk) HDF5 1.10 crashes
// closing that file again there (H5F__close_cb); the writer closes its files itself. No error
// stack on stderr either: a failure becomes an exception with the system's reason.
[[maybe_unused]] const bool kHdf5Configured = [] {
  H5dont_atexit();  // before any other HDF5 call
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  return true;
}();

/// The system's reason for the innermost HDF5 error ("No space left on device", "File too
/// large"), empty when it gave none.
std::string system_reason() {
  std::string desc;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_UPWARD,
      [](unsigned, const H5E_error2_t* error, void* out) -> herr_t {
        auto& d = *static_cast<std::string*>(out);
        if (d.empty() && error->desc) d = error->desc;
        return 0;
      },
      &desc);
  const std::string key = "error message = '";
  const std::size_t start = desc.find(key);
  if (start == std::string::npos) return {};
  const std::size_t end = desc.find('\'', start + key.size());
  return desc.substr(start + key.size(), end - start - key.size());
}

[[noreturn]] void fail(const std::string& what) {
  const std::string reason = system_reason();
  throw SolverError("HDF5: " + what + " failed" + (reason.empty() ? "" : " (" + reason + ")"));
}

class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t), const std::string& what) : id_(id), close_(close) {
    if (id_ < 0) fail(what);
  }
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(Handle&& o) noexcept : id_(o.id_), close_(o.close_) { o.id_ = -1; }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle& operator=(Handle&&) = delete;
  operator hid_t() const { return id_; }  // NOLINT(google-explicit-constructor)

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

void check(herr_t status, const std::string& what) {
  if (status < 0) fail(what);
}

Handle make_group(hid_t loc, const std::string& name) {
  return Handle(H5Gcreate2(loc, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                "create group " + name);
}

/// Datasets smaller than this are stored contiguous: zlib sets up and clears a quarter megabyte
/// of state per compressed chunk, which on a small model costs more than its whole solve.
constexpr hsize_t kDeflateFromBytes = 64 * 1024;

/// Dataset in 1 MiB chunks with deflate (level 4) from kDeflateFromBytes on, contiguous below;
/// 64-bit types throughout.
void write_dataset(hid_t loc, const std::string& name, hid_t mem_type, hid_t file_type,
                   const std::vector<hsize_t>& dims, const void* data) {
  Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose,
               "dataspace for " + name);
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "dcpl");
  hsize_t total = 1;
  for (auto d : dims) total *= d;
  if (total > 0 && total * H5Tget_size(file_type) >= kDeflateFromBytes) {
    std::vector<hsize_t> chunk = dims;
    hsize_t row_bytes = H5Tget_size(file_type);
    for (std::size_t i = 1; i < dims.size(); ++i) row_bytes *= dims[i];
    const hsize_t max_rows = std::max<hsize_t>(1, (1u << 20) / std::max<hsize_t>(1, row_bytes));
    chunk[0] = std::min(dims[0], max_rows);
    check(H5Pset_chunk(dcpl, static_cast<int>(chunk.size()), chunk.data()), "set_chunk");
    check(H5Pset_deflate(dcpl, 4), "set_deflate");
  }
  Handle ds(H5Dcreate2(loc, name.c_str(), file_type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
            H5Dclose, "create dataset " + name);
  if (total > 0) check(H5Dwrite(ds, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write " + name);
}

void write_i64(hid_t loc, const std::string& name, const std::vector<std::int64_t>& v,
               std::vector<hsize_t> dims = {}) {
  if (dims.empty()) dims = {v.size()};
  write_dataset(loc, name, H5T_NATIVE_INT64, H5T_STD_I64LE, dims, v.data());
}
void write_f64(hid_t loc, const std::string& name, const double* data, std::vector<hsize_t> dims) {
  write_dataset(loc, name, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, dims, data);
}

/// Fixed-length ASCII string type of exactly `size` bytes, NULLPAD (no terminator stored).
Handle string_type(std::size_t size) {
  Handle t(H5Tcopy(H5T_C_S1), H5Tclose, "copy string type");
  check(H5Tset_size(t, std::max<std::size_t>(1, size)), "set string size");
  check(H5Tset_strpad(t, H5T_STR_NULLPAD), "set strpad");
  check(H5Tset_cset(t, H5T_CSET_ASCII), "set cset");
  return t;
}

void attr_string(hid_t obj, const std::string& name, const std::string& value) {
  Handle type = string_type(value.size());
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "scalar space");
  Handle a(H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
           "create attribute " + name);
  std::string buf = value.empty() ? std::string(1, '\0') : value;
  check(H5Awrite(a, type, buf.data()), "write attribute " + name);
}

template <class T>
void attr_scalar(hid_t obj, const std::string& name, hid_t mem_type, hid_t file_type, T value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "scalar space");
  Handle a(H5Acreate2(obj, name.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
           "create attribute " + name);
  check(H5Awrite(a, mem_type, &value), "write attribute " + name);
}

void attr_i64_array(hid_t obj, const std::string& name, const std::vector<std::int64_t>& v) {
  const hsize_t n = v.size();
  Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose, "attribute space");
  Handle a(H5Acreate2(obj, name.c_str(), H5T_STD_I64LE, space, H5P_DEFAULT, H5P_DEFAULT),
           H5Aclose, "create attribute " + name);
  check(H5Awrite(a, H5T_NATIVE_INT64, v.data()), "write attribute " + name);
}

/// HDF5 link names may not contain '/'; sets are stored under a sanitized name.
std::string link_name(const std::string& s) {
  std::string r = s.empty() ? std::string("_") : s;
  std::replace(r.begin(), r.end(), '/', '_');
  if (r == ".") r = "_";
  return r;
}

/// Voigt xx,yy,zz,xy,xz,yz (Frame) -> VTK xx,yy,zz,xy,yz,xz.
std::vector<double> to_vtk_tensor(const MatX6& m) {
  std::vector<double> out(static_cast<std::size_t>(m.rows()) * 6);
  for (Index i = 0; i < m.rows(); ++i) {
    double* o = &out[static_cast<std::size_t>(i) * 6];
    o[0] = m(i, 0);
    o[1] = m(i, 1);
    o[2] = m(i, 2);
    o[3] = m(i, 3);
    o[4] = m(i, 5);
    o[5] = m(i, 4);
  }
  return out;
}

std::vector<double> mises(const MatX6& s) {
  std::vector<double> out(static_cast<std::size_t>(s.rows()));
  for (Index i = 0; i < s.rows(); ++i) {
    out[static_cast<std::size_t>(i)] = material::von_mises(s.row(i).transpose());
  }
  return out;
}

/// Columns of the nodal contact arrays, named as ccx's CONTACT block components.
void write_contact_nodal(hid_t frame, const ContactNodal& c, hsize_t n,
                         std::vector<std::string>& names) {
  KONTAKT_REQUIRE(static_cast<hsize_t>(c.CPRESS.size()) == n &&
                      static_cast<hsize_t>(c.COPEN.size()) == n &&
                      static_cast<hsize_t>(c.CSHEAR.rows()) == n && c.CSHEAR.cols() == 2 &&
                      static_cast<hsize_t>(c.CSLIP.rows()) == n && c.CSLIP.cols() == 2 &&
                      static_cast<hsize_t>(c.status.size()) == n,
                  "Hdf5Writer: contact arrays have wrong sizes");
  const auto scalar = [&](const char* name, const VecX& v) {
    write_f64(frame, name, v.data(), {n});
    names.emplace_back(name);
  };
  scalar("CPRESS", c.CPRESS);
  scalar("COPEN", c.COPEN);
  scalar("CSHEAR1", c.CSHEAR.col(0));
  scalar("CSHEAR2", c.CSHEAR.col(1));
  scalar("CSLIP1", c.CSLIP.col(0));
  scalar("CSLIP2", c.CSLIP.col(1));
  scalar("CSTATUS", c.status);
}

/// /frames/NNNNNN/contact_points: one row per contact point, deck labels, status 0 open,
/// 1 stick, 2 slip.
void write_contact_points(hid_t frame, const model::Model& model,
                          const std::vector<ContactPointRecord>& points) {
  Handle t = make_group(frame, "contact_points");
  const auto p = static_cast<hsize_t>(points.size());
  std::vector<std::int64_t> pair, element, face, node, status;
  std::vector<double> xi, x, clearance, pressure, slip, shear, area, energy;
  for (const ContactPointRecord& r : points) {
    pair.push_back(r.pair);
    element.push_back(r.slave_element < 0
                          ? -1
                          : model.mesh.elements[static_cast<std::size_t>(r.slave_element)].id);
    face.push_back(r.slave_face);
    node.push_back(r.slave_node < 0 ? -1
                                    : model.mesh.node_ids[static_cast<std::size_t>(r.slave_node)]);
    status.push_back(!r.active ? 0 : r.sticking ? 1 : 2);
    xi.insert(xi.end(), {r.xi(0), r.xi(1)});
    x.insert(x.end(), {r.x(0), r.x(1), r.x(2)});
    clearance.push_back(r.clearance);
    pressure.push_back(r.pressure);
    slip.insert(slip.end(), {r.slip(0), r.slip(1)});
    shear.insert(shear.end(), {r.shear(0), r.shear(1)});
    area.push_back(r.area);
    energy.push_back(r.energy);
  }
  write_i64(t, "pair", pair);
  write_i64(t, "slave_element", element);
  write_i64(t, "slave_face", face);
  write_i64(t, "slave_node", node);
  write_i64(t, "status", status);
  write_f64(t, "xi", xi.data(), {p, 2});
  write_f64(t, "x", x.data(), {p, 3});
  write_f64(t, "clearance", clearance.data(), {p});
  write_f64(t, "pressure", pressure.data(), {p});
  write_f64(t, "slip", slip.data(), {p, 2});
  write_f64(t, "shear", shear.data(), {p, 2});
  write_f64(t, "area", area.data(), {p});
  write_f64(t, "energy", energy.data(), {p});
}

struct HistoryRow {
  std::int64_t step, increment, attempts, iterations;
  double total_time, step_time, dt;
  std::int8_t converged;
  double stabilisation_energy, strain_energy;
};

/// The compound type of /history/increments (native layout of HistoryRow).
Handle history_type() {
  Handle t(H5Tcreate(H5T_COMPOUND, sizeof(HistoryRow)), H5Tclose, "compound type");
  check(H5Tinsert(t, "step", HOFFSET(HistoryRow, step), H5T_NATIVE_INT64), "insert");
  check(H5Tinsert(t, "increment", HOFFSET(HistoryRow, increment), H5T_NATIVE_INT64), "insert");
  check(H5Tinsert(t, "attempts", HOFFSET(HistoryRow, attempts), H5T_NATIVE_INT64), "insert");
  check(H5Tinsert(t, "iterations", HOFFSET(HistoryRow, iterations), H5T_NATIVE_INT64), "insert");
  check(H5Tinsert(t, "total_time", HOFFSET(HistoryRow, total_time), H5T_NATIVE_DOUBLE), "insert");
  check(H5Tinsert(t, "step_time", HOFFSET(HistoryRow, step_time), H5T_NATIVE_DOUBLE), "insert");
  check(H5Tinsert(t, "dt", HOFFSET(HistoryRow, dt), H5T_NATIVE_DOUBLE), "insert");
  check(H5Tinsert(t, "converged", HOFFSET(HistoryRow, converged), H5T_NATIVE_INT8), "insert");
  check(H5Tinsert(t, "stabilisation_energy", HOFFSET(HistoryRow, stabilisation_energy),
                  H5T_NATIVE_DOUBLE), "insert");
  check(H5Tinsert(t, "strain_energy", HOFFSET(HistoryRow, strain_energy), H5T_NATIVE_DOUBLE),
        "insert");
  return t;
}

}  // namespace

// ---------------------------------------------------------------- free functions
std::set<std::string> file_variables(const model::Step& step) {
  std::set<std::string> out;
  const auto add = [&](const auto& requests) {
    for (const auto& req : requests) out.insert(req.variables.begin(), req.variables.end());
  };
  add(step.node_files);
  add(step.element_files);
  add(step.contact_files);
  return out;
}

std::set<std::string> requested_fields(const model::Model& model) {
  std::set<std::string> out;
  for (const auto& step : model.steps)
    for (const auto& v : file_variables(step))
      if (kHdf5Fields.count(v)) out.insert(v);
  if (out.empty()) {
    out = {"U", "S"};
    if (!model.contact_pairs.empty()) out.insert({"CDIS", "CSTR", "CELS"});
  }
  return out;
}

bool file_output_due(const model::Step& step, const Frame& frame) {
  if (frame.is_step_end) return true;
  if (frame.at_time_point) return *frame.at_time_point;
  const auto due = [&](const auto& requests) {
    for (const auto& req : requests)
      if (req.frequency > 0 && frame.increment % req.frequency == 0) return true;
    return false;
  };
  return due(step.node_files) || due(step.element_files) || due(step.contact_files);
}

void warm_up_hdf5() {
  Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "fapl");
  check(H5Pset_fapl_core(fapl, 1 << 16, false), "core driver");  // no backing file
  Handle file(H5Fcreate("warm-up", H5F_ACC_TRUNC, H5P_DEFAULT, fapl), H5Fclose, "warm-up file");
  attr_string(file, "created", time_stamp("%Y-%m-%dT%H:%M:%SZ", true));
  const std::vector<double> values(64, 1.0);
  write_f64(file, "values", values.data(), {values.size()});
}

// ---------------------------------------------------------------- writer
struct Hdf5Writer::Impl {
  hid_t file = -1;
  hsize_t history_rows = 0;  ///< rows of /history/increments on file
  ~Impl() { close(); }
  void close() {
    if (file >= 0) H5Fclose(file);
    file = -1;
  }
};

Hdf5Writer::Hdf5Writer(const model::Model& model, std::filesystem::path dir,
                       std::string model_name, std::set<std::string> fields)
    : model_(model),
      dir_(std::move(dir)),
      name_(std::move(model_name)),
      fields_(std::move(fields)),
      impl_(std::make_unique<Impl>()) {
  const auto p = partial_path();
  impl_->file = H5Fcreate(p.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (impl_->file < 0) fail("creating " + p.string());
  const hid_t f = impl_->file;
  attr_string(f, "format", "kontakt-results");
  attr_string(f, "format_version", "1.0");
  attr_string(f, "solver", "kontakt");
  attr_string(f, "solver_version", KONTAKT_VERSION);
  attr_string(f, "created", time_stamp("%Y-%m-%dT%H:%M:%SZ", true));
  write_mesh();
  Handle frames = make_group(f, "frames");
  Handle history = make_group(f, "history");
  create_history(history);
  publish();
}

Hdf5Writer::~Hdf5Writer() = default;

std::filesystem::path Hdf5Writer::partial_path() const { return dir_ / (name_ + ".hdf.partial"); }
std::filesystem::path Hdf5Writer::final_path() const { return dir_ / (name_ + ".hdf"); }
std::filesystem::path Hdf5Writer::xdmf_path() const { return dir_ / (name_ + ".xdmf"); }

void Hdf5Writer::write_mesh() {
  const hid_t f = impl_->file;
  const auto& mesh = model_.mesh;
  const auto n = static_cast<hsize_t>(model_.n_nodes());
  const auto m = static_cast<hsize_t>(model_.n_elements());
  KONTAKT_REQUIRE(static_cast<hsize_t>(mesh.coords.rows()) == n, "Hdf5Writer: coords size");

  Handle g = make_group(f, "mesh");
  write_i64(g, "node_ids", std::vector<std::int64_t>(mesh.node_ids.begin(), mesh.node_ids.end()));
  std::vector<std::int64_t> eids;
  std::size_t name_len = 1;
  for (const auto& e : mesh.elements) {
    eids.push_back(e.id);
    name_len = std::max(name_len, vtk_cell(e.type).name.size());
  }
  write_i64(g, "element_ids", eids);
  {
    std::string names(m * name_len, '\0');
    for (std::size_t i = 0; i < mesh.elements.size(); ++i) {
      const auto nm = vtk_cell(mesh.elements[i].type).name;
      std::copy(nm.begin(), nm.end(), names.begin() + static_cast<std::ptrdiff_t>(i * name_len));
    }
    Handle t = string_type(name_len);
    write_dataset(g, "element_type", t, t, {m}, names.data());
  }
  {
    Handle sets = make_group(g, "sets");
    Handle ns = make_group(sets, "nsets");
    for (const auto& [key, set] : model_.node_sets) {
      std::vector<std::int64_t> labels;
      for (int i : set.nodes) labels.push_back(mesh.node_ids[static_cast<std::size_t>(i)]);
      write_i64(ns, link_name(key), labels);
    }
    Handle es = make_group(sets, "elsets");
    for (const auto& [key, set] : model_.element_sets) {
      std::vector<std::int64_t> labels;
      for (int i : set.elements) labels.push_back(mesh.elements[static_cast<std::size_t>(i)].id);
      write_i64(es, link_name(key), labels);
    }
  }

  // VTK connectivity (VTK node order) and XDMF topology.
  std::vector<std::uint8_t> types;
  std::vector<std::int64_t> offsets{0}, conn, xdmf;
  bool single = true;
  for (const auto& e : mesh.elements) {
    const auto& c = vtk_cell(e.type);
    KONTAKT_REQUIRE(static_cast<int>(e.nodes.size()) == c.n_nodes,
                    "Hdf5Writer: element " + std::to_string(e.id) + " has wrong node count");
    types.push_back(c.vtk_type);
    if (c.xdmf_type != vtk_cell(mesh.elements.front().type).xdmf_type) single = false;
    for (int k : c.perm) conn.push_back(e.nodes[static_cast<std::size_t>(k)]);
    offsets.push_back(static_cast<std::int64_t>(conn.size()));
  }
  if (single && m > 0) {
    const auto nn = static_cast<hsize_t>(vtk_cell(mesh.elements.front().type).n_nodes);
    write_i64(g, "xdmf_topology", conn, {m, nn});
  } else {
    for (std::size_t i = 0; i < mesh.elements.size(); ++i) {
      xdmf.push_back(vtk_cell(mesh.elements[i].type).xdmf_type);
      xdmf.insert(xdmf.end(), conn.begin() + offsets[i], conn.begin() + offsets[i + 1]);
    }
    write_i64(g, "xdmf_topology", xdmf);
  }

  Handle v = make_group(f, "VTKHDF");
  attr_i64_array(v, "Version", {1, 0});
  attr_string(v, "Type", "UnstructuredGrid");  // 16 bytes, NULLPAD, no terminator
  Handle point_data = make_group(v, "PointData");
  Handle cell_data = make_group(v, "CellData");
  write_i64(v, "NumberOfPoints", {static_cast<std::int64_t>(n)});
  write_i64(v, "NumberOfCells", {static_cast<std::int64_t>(m)});
  write_i64(v, "NumberOfConnectivityIds", {static_cast<std::int64_t>(conn.size())});
  write_f64(v, "Points", mesh.coords.data(), {n, 3});
  write_dataset(v, "Types", H5T_NATIVE_UINT8, H5T_STD_U8LE, {m}, types.data());
  write_i64(v, "Offsets", offsets);
  write_i64(v, "Connectivity", conn);
}

void Hdf5Writer::write(const Frame& fr) {
  KONTAKT_REQUIRE(!finished_, "Hdf5Writer::write after finish");
  begin_update();
  const hid_t f = impl_->file;
  const auto n = static_cast<hsize_t>(model_.n_nodes());
  const auto m = static_cast<hsize_t>(model_.n_elements());

  if (!ip_offset_written_ && !fr.ip_offset.empty()) {
    KONTAKT_REQUIRE(fr.ip_offset.size() == m + 1, "Hdf5Writer: ip_offset has wrong size");
    Handle g(H5Gopen2(f, "mesh", H5P_DEFAULT), H5Gclose, "open /mesh");
    write_i64(g, "ip_offset", std::vector<std::int64_t>(fr.ip_offset.begin(), fr.ip_offset.end()));
    ip_offset_written_ = true;
  }
  const auto n_ip = static_cast<hsize_t>(fr.ip_offset.empty() ? 0 : fr.ip_offset.back());

  char num[16];
  std::snprintf(num, sizeof num, "%06d", static_cast<int>(frames_.size()) + 1);
  FrameInfo info{num, fr.total_time, {}, {}};
  Handle g = make_group(f, std::string("frames/") + num);
  attr_scalar<std::int64_t>(g, "step", H5T_NATIVE_INT64, H5T_STD_I64LE, fr.step);
  attr_scalar<std::int64_t>(g, "increment", H5T_NATIVE_INT64, H5T_STD_I64LE, fr.increment);
  attr_scalar<double>(g, "step_time", H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, fr.step_time);
  attr_scalar<double>(g, "total_time", H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, fr.total_time);
  attr_scalar<std::int8_t>(g, "converged", H5T_NATIVE_INT8, H5T_STD_I8LE, fr.converged ? 1 : 0);

  const auto want = [&](const char* s) { return fields_.count(s) > 0; };
  auto nodal3 = [&](const char* name, const MatX3& a) {
    if (a.rows() == 0) return;
    KONTAKT_REQUIRE(static_cast<hsize_t>(a.rows()) == n, std::string("Hdf5Writer: ") + name);
    write_f64(g, name, a.data(), {n, 3});
    info.node_arrays.push_back(name);
  };
  auto tensor = [&](const char* name, const MatX6& nodal, const MatX6& ip) {
    if (nodal.rows() > 0) {
      KONTAKT_REQUIRE(static_cast<hsize_t>(nodal.rows()) == n, std::string("Hdf5Writer: ") + name);
      write_f64(g, name, to_vtk_tensor(nodal).data(), {n, 6});
      info.node_arrays.push_back(name);
    }
    if (ip.rows() > 0) {
      KONTAKT_REQUIRE(static_cast<hsize_t>(ip.rows()) == n_ip,
                      std::string("Hdf5Writer: ") + name + "_ip");
      write_f64(g, std::string(name) + "_ip", ip.data(), {n_ip, 6});
    }
  };
  auto ip_scalar = [&](const char* name, const VecX& v) {
    if (v.size() == 0) return;
    KONTAKT_REQUIRE(static_cast<hsize_t>(v.size()) == n_ip, std::string("Hdf5Writer: ") + name);
    write_f64(g, std::string(name) + "_ip", v.data(), {n_ip});
  };

  if (want("U")) nodal3("U", fr.U);
  if (want("RF")) nodal3("RF", fr.RF);
  if (want("S")) {
    tensor("S", fr.S_nodal, fr.S);
    if (fr.S_nodal.rows() > 0) {
      write_f64(g, "S_Mises", mises(fr.S_nodal).data(), {n});
      info.node_arrays.push_back("S_Mises");
    }
  }
  if (want("E")) tensor("E", fr.E_nodal, fr.E);
  if (want("ENER")) ip_scalar("ENER", fr.ENER);
  if (want("PEEQ")) ip_scalar("PEEQ", fr.PEEQ);
  if (want("EVOL") && fr.EVOL.size() > 0) {
    KONTAKT_REQUIRE(static_cast<hsize_t>(fr.EVOL.size()) == m, "Hdf5Writer: EVOL");
    write_f64(g, "EVOL", fr.EVOL.data(), {m});
    info.cell_arrays.push_back("EVOL");
  }
  // Models without contact pairs get no contact data, whatever the deck requests.
  if (!model_.contact_pairs.empty()) {
    if ((want("CDIS") || want("CSTR")) && fr.contact_nodal.CPRESS.size() > 0)
      write_contact_nodal(g, fr.contact_nodal, n, info.node_arrays);
    if (want("CDIS") || want("CSTR") || want("CELS")) {
      write_contact_points(g, model_, fr.contact_points);
    }
  }
  link_view_to(info);
  frames_.push_back(std::move(info));
  publish();
}

void Hdf5Writer::link_view_to(const FrameInfo& frame) {
  const hid_t f = impl_->file;
  const auto relink = [&](const char* group, const std::vector<std::string>& old_arrays,
                          const std::vector<std::string>& new_arrays) {
    Handle g(H5Gopen2(f, (std::string("/VTKHDF/") + group).c_str(), H5P_DEFAULT), H5Gclose,
             std::string("open /VTKHDF/") + group);
    for (const auto& a : old_arrays) check(H5Ldelete(g, a.c_str(), H5P_DEFAULT), "unlink " + a);
    for (const auto& a : new_arrays)
      check(H5Lcreate_hard(f, ("/frames/" + frame.group + "/" + a).c_str(), g, a.c_str(),
                           H5P_DEFAULT, H5P_DEFAULT),
            std::string("hard link ") + group + "/" + a);
  };
  const FrameInfo none{};
  const FrameInfo& previous = frames_.empty() ? none : frames_.back();
  relink("PointData", previous.node_arrays, frame.node_arrays);
  relink("CellData", previous.cell_arrays, frame.cell_arrays);
}

void Hdf5Writer::add_increment(const IncrementRecord& r) { history_.push_back(r); }

void Hdf5Writer::create_history(hid_t group) {
  Handle type = history_type();
  const hsize_t none = 0, unlimited = H5S_UNLIMITED, chunk = 256;
  Handle space(H5Screate_simple(1, &none, &unlimited), H5Sclose, "history dataspace");
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "dcpl");
  check(H5Pset_chunk(dcpl, 1, &chunk), "set_chunk");
  check(H5Pset_deflate(dcpl, 4), "set_deflate");
  Handle ds(H5Dcreate2(group, "increments", type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
            H5Dclose, "create /history/increments");
}

void Hdf5Writer::append_history() {
  const hsize_t old_rows = impl_->history_rows, new_rows = history_.size() - old_rows;
  if (new_rows == 0) return;
  std::vector<HistoryRow> rows;
  for (std::size_t i = old_rows; i < history_.size(); ++i) {
    const IncrementRecord& r = history_[i];
    rows.push_back({r.step, r.increment, r.attempts, r.iterations, r.total_time, r.step_time,
                    r.dt, static_cast<std::int8_t>(r.converged ? 1 : 0), r.stabilisation_energy,
                    r.strain_energy});
  }
  Handle ds(H5Dopen2(impl_->file, "/history/increments", H5P_DEFAULT), H5Dclose,
            "open /history/increments");
  const hsize_t total = old_rows + new_rows;
  check(H5Dset_extent(ds, &total), "extend /history/increments");
  Handle file_space(H5Dget_space(ds), H5Sclose, "history file space");
  check(H5Sselect_hyperslab(file_space, H5S_SELECT_SET, &old_rows, nullptr, &new_rows, nullptr),
        "select history rows");
  Handle memory_space(H5Screate_simple(1, &new_rows, nullptr), H5Sclose, "history rows");
  Handle type = history_type();
  check(H5Dwrite(ds, type, memory_space, file_space, H5P_DEFAULT, rows.data()),
        "write /history/increments");
  impl_->history_rows = total;
}

void Hdf5Writer::begin_update() {
  // The sidecar goes too: a file cut short by a failed write leaves no sidecar pointing at it.
  for (const auto& [published, partial] :
       {std::pair{final_path(), partial_path()},
        std::pair{xdmf_path(), std::filesystem::path(xdmf_path().string() + ".partial")}})
    if (std::filesystem::exists(published)) std::filesystem::rename(published, partial);
}

void Hdf5Writer::publish() {
  append_history();
  check(H5Fflush(impl_->file, H5F_SCOPE_GLOBAL), "flush");
  std::filesystem::rename(partial_path(), final_path());
  write_xdmf();
}

void Hdf5Writer::finish() {
  KONTAKT_REQUIRE(!finished_, "Hdf5Writer::finish called twice");
  begin_update();
  append_history();
  check(H5Fflush(impl_->file, H5F_SCOPE_GLOBAL), "flush");
  const herr_t closed = H5Fclose(impl_->file);
  impl_->file = -1;
  if (closed < 0) fail("closing " + partial_path().string());
  std::filesystem::rename(partial_path(), final_path());
  write_xdmf();
  finished_ = true;
}

void Hdf5Writer::write_xdmf() const {
  const auto& mesh = model_.mesh;
  const auto n = model_.n_nodes();
  const auto m = model_.n_elements();
  const std::string h5 = final_path().filename().string() + ":";

  bool single = m > 0;
  for (const auto& e : mesh.elements)
    if (vtk_cell(e.type).xdmf_type != vtk_cell(mesh.elements.front().type).xdmf_type) single = false;
  std::size_t topo_len = 0;
  for (const auto& e : mesh.elements) topo_len += 1 + e.nodes.size();
  static constexpr std::pair<int, const char*> kTopoNames[] = {
      {6, "Tetrahedron"}, {38, "Tetrahedron_10"}, {9, "Hexahedron"},
      {48, "Hexahedron_20"}, {8, "Wedge"}, {40, "Wedge_15"}};
  std::string topology;
  if (single) {
    const auto& c = vtk_cell(mesh.elements.front().type);
    const char* tn = "Mixed";
    for (const auto& [code, nm] : kTopoNames)
      if (code == c.xdmf_type) tn = nm;
    topology = std::string("      <Topology TopologyType=\"") + tn + "\" NumberOfElements=\"" +
               std::to_string(m) + "\">\n        <DataItem Dimensions=\"" + std::to_string(m) +
               " " + std::to_string(c.n_nodes) +
               "\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">" + h5 +
               "/mesh/xdmf_topology</DataItem>\n      </Topology>\n";
  } else {
    topology = "      <Topology TopologyType=\"Mixed\" NumberOfElements=\"" + std::to_string(m) +
               "\">\n        <DataItem Dimensions=\"" + std::to_string(topo_len) +
               "\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">" + h5 +
               "/mesh/xdmf_topology</DataItem>\n      </Topology>\n";
  }
  const std::string geometry =
      "      <Geometry GeometryType=\"XYZ\">\n        <DataItem Dimensions=\"" +
      std::to_string(n) + " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" + h5 +
      "/VTKHDF/Points</DataItem>\n      </Geometry>\n";

  std::ostringstream x;
  x.precision(17);
  x << "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
    << "<Xdmf Version=\"3.0\">\n  <Domain>\n"
    << "    <Grid Name=\"" << name_ << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const auto& fr : frames_) {
    x << "    <Grid Name=\"frame_" << fr.group << "\" GridType=\"Uniform\">\n"
      << "      <Time Value=\"" << fr.time << "\"/>\n"
      << geometry << topology;
    auto attribute = [&](const std::string& a, const char* center, Index rows) {
      int comps = 1;
      const char* type = "Scalar";
      if (a == "U" || a == "RF") comps = 3, type = "Vector";
      if (a == "S" || a == "E") comps = 6, type = "Tensor6";
      x << "      <Attribute Name=\"" << a << "\" AttributeType=\"" << type << "\" Center=\""
        << center << "\">\n        <DataItem Dimensions=\"" << rows;
      if (comps > 1) x << ' ' << comps;
      x << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5 << "/frames/"
        << fr.group << '/' << a << "</DataItem>\n      </Attribute>\n";
    };
    for (const auto& a : fr.node_arrays) attribute(a, "Node", n);
    for (const auto& a : fr.cell_arrays) attribute(a, "Cell", m);
    x << "    </Grid>\n";
  }
  x << "    </Grid>\n  </Domain>\n</Xdmf>\n";
  // Written aside and renamed: the sidecar on disk always lists frames the file holds.
  const std::filesystem::path partial = xdmf_path().string() + ".partial";
  {
    std::ofstream out(partial, std::ios::trunc);
    out << x.str();
    out.flush();
    if (!out) throw SolverError("cannot write " + partial.string());
  }
  std::filesystem::rename(partial, xdmf_path());
}

}  // namespace kontakt::output
