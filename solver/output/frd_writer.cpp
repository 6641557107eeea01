#include "output/frd_writer.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/error.hpp"
#include "output/hdf5_writer.hpp"
#include "output/time_stamp.hpp"

#ifndef KONTAKT_VERSION
#define KONTAKT_VERSION "unknown"
#endif

namespace kontakt::output {

namespace {

using element::ElementType;

std::string pad(std::string s, std::size_t width) {
  s.resize(std::max(s.size(), width), ' ');
  return s;
}

std::string fixed(const char* format, long long a) {
  char b[64];
  std::snprintf(b, sizeof b, format, a);
  return b;
}

/// `    1U` header line: key in 18 columns, value in 48 (72 columns, as ccx).
std::string user_line(const std::string& key, const std::string& value) {
  return "    1U" + pad(key, 18) + pad(value, 48) + "\n";
}

/// `    2C` / `    3C` line: the count in columns 24-35, the ASCII flag in column 73.
std::string count_line(char kind, long long count) {
  return std::string("    ") + kind + "C" + std::string(18, ' ') + fixed("%12lld", count) +
         fixed("%38lld", 1) + "\n";
}

/// ` -5` component line: name in 8 columns, then 1, the component type and the two indices.
std::string component_line(const std::string& name, int type, int i, int j) {
  std::string line = " -5  " + pad(name, 8) + fixed("%5lld", 1) + fixed("%5lld", type) +
                     fixed("%5lld", i) + fixed("%5lld", j);
  if (name == "ALL") line += "    1ALL";
  return line + "\n";
}

// Component names and (type, i, j) of the blocks: vectors declare D1 D2 D3 and ALL (the
// magnitude, computed by the reader, not stored); tensors in ccx's frd order xx yy zz xy yz zx.
std::vector<FrdWriter::Component> vector_components(const std::string& prefix) {
  return {{prefix + "1", 2, 1, 0}, {prefix + "2", 2, 2, 0}, {prefix + "3", 2, 3, 0},
          {"ALL", 2, 0, 0}};
}
std::vector<FrdWriter::Component> tensor_components(const std::vector<std::string>& names) {
  static constexpr int kIndex[6][2] = {{1, 1}, {2, 2}, {3, 3}, {1, 2}, {2, 3}, {3, 1}};
  std::vector<FrdWriter::Component> out;
  for (std::size_t k = 0; k < 6; ++k) out.push_back({names[k], 4, kIndex[k][0], kIndex[k][1]});
  return out;
}

/// Frame tensors are xx yy zz xy xz yz; the frd wants xx yy zz xy yz zx.
MatX frd_tensor(const MatX6& m) {
  MatX out(m.rows(), 6);
  out << m.col(0), m.col(1), m.col(2), m.col(3), m.col(5), m.col(4);
  return out;
}

}  // namespace

// ---------------------------------------------------------------- free functions
std::set<std::string> frd_fields(const model::Step& step) {
  std::set<std::string> out;
  for (const auto& v : file_variables(step))
    if (kFrdFields.count(v)) out.insert(v);
  return out;
}

bool wants_frd(const model::Model& model) {
  return std::any_of(model.steps.begin(), model.steps.end(), [](const model::Step& s) {
    return !s.node_files.empty() || !s.element_files.empty() || !s.contact_files.empty();
  });
}

std::string frd_value(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%12.5E", static_cast<double>(static_cast<float>(v)));
  return b;
}

std::string frd_result_lines(int node, const double* values, int count) {
  std::string out = " -1" + fixed("%10lld", node);
  for (int k = 0; k < count; ++k) {
    if (k > 0 && k % 6 == 0) out += "\n -2" + std::string(10, ' ');
    out += frd_value(values[k]);
  }
  return out + "\n";
}

std::string frd_time(double t) {
  char b[64];
  if (t >= 1 && t < 1e10) {
    // A blank, the integer digits, the point and the decimals that fit (11 characters); a
    // rounding that needs more than the 12 columns takes a decimal away.
    const int digits = static_cast<int>(std::floor(std::log10(t))) + 1;
    for (int decimals = 10 - digits; decimals >= 0; --decimals) {
      std::snprintf(b, sizeof b, "%12.*f", decimals, t);
      if (std::string_view(b).size() == 12) return b;
    }
  }
  std::snprintf(b, sizeof b, "%12.5E", t);
  return b;
}

int frd_element_type(ElementType type) {
  switch (type) {
    case ElementType::C3D8:
    case ElementType::C3D8R:
    case ElementType::C3D8I:
      return 1;
    case ElementType::C3D6:
      return 2;
    case ElementType::C3D4:
      return 3;
    case ElementType::C3D20:
    case ElementType::C3D20R:
      return 4;
    case ElementType::C3D15:
      return 5;
    case ElementType::C3D10:
      return 6;
  }
  throw SolverError("frd: element type without an frd type");
}

std::vector<int> frd_node_order(ElementType type) {
  switch (type) {
    case ElementType::C3D20:
    case ElementType::C3D20R:
      return {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 16, 17, 18, 19, 12, 13, 14, 15};
    case ElementType::C3D15:
      return {0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 13, 14, 9, 10, 11};
    default: {  // the deck's nodes in the deck's order (C3D8I: its 8 nodes)
      std::vector<int> order(static_cast<std::size_t>(element::traits(type).n_nodes));
      for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
      return order;
    }
  }
}

// ---------------------------------------------------------------- writer
FrdWriter::FrdWriter(const model::Model& model, std::filesystem::path path)
    : model_(model), path_(std::move(path)), out_(path_, std::ios::trunc | std::ios::binary) {
  if (!out_) throw SolverError("cannot create " + path_.string() + ": " + std::strerror(errno));
  const auto& mesh = model.mesh;
  // ccx lists only the nodes that belong to an element, by label.
  std::vector<char> used(static_cast<std::size_t>(model.n_nodes()), 0);
  for (const auto& e : mesh.elements)
    for (int n : e.nodes) used[static_cast<std::size_t>(n)] = 1;
  for (int n = 0; n < model.n_nodes(); ++n)
    if (used[static_cast<std::size_t>(n)]) nodes_.push_back(n);
  std::sort(nodes_.begin(), nodes_.end(), [&](int a, int b) {
    return mesh.node_ids[static_cast<std::size_t>(a)] < mesh.node_ids[static_cast<std::size_t>(b)];
  });
  std::vector<int> elements(static_cast<std::size_t>(model.n_elements()));
  for (std::size_t e = 0; e < elements.size(); ++e) elements[e] = static_cast<int>(e);
  std::sort(elements.begin(), elements.end(), [&](int a, int b) {
    return mesh.elements[static_cast<std::size_t>(a)].id <
           mesh.elements[static_cast<std::size_t>(b)].id;
  });

  std::string h = "    1C\n";
  h += user_line("USER", "");
  h += user_line("DATE", frd_date_today());
  h += user_line("TIME", time_stamp("%H:%M:%S", false));
  h += user_line("HOST", "");
  h += user_line("PGM", "Kontakt");
  h += user_line("VERSION", std::string("Version ") + KONTAKT_VERSION);
  h += user_line("COMPILETIME", "");
  h += user_line("DIR", "");
  h += user_line("DBN", "");
  // Materials, then the surface interactions (ccx counts them as materials too).
  int number = 0;
  for (const auto& m : model.materials)
    h += "    1UMAT" + fixed("%5lld", ++number) + pad(m.name, 58) + "\n";
  for (const auto& i : model.interactions)
    h += "    1UMAT" + fixed("%5lld", ++number) + pad(i.name, 58) + "\n";
  out_ << h;

  out_ << count_line('2', static_cast<long long>(nodes_.size()));
  for (int n : nodes_) {
    const auto i = static_cast<std::size_t>(n);
    out_ << " -1" << fixed("%10lld", mesh.node_ids[i]) << frd_value(mesh.coords(n, 0))
         << frd_value(mesh.coords(n, 1)) << frd_value(mesh.coords(n, 2)) << '\n';
  }
  out_ << " -3\n";

  out_ << count_line('3', static_cast<long long>(elements.size()));
  for (int index : elements) {
    const auto& e = mesh.elements[static_cast<std::size_t>(index)];
    const int section = e.section;
    const int material =
        section >= 0 ? model.sections[static_cast<std::size_t>(section)].material + 1 : 1;
    out_ << " -1" << fixed("%10lld", e.id) << fixed("%5lld", frd_element_type(e.type))
         << fixed("%5lld", 0) << fixed("%5lld", material) << '\n';
    const std::vector<int> order = frd_node_order(e.type);
    for (std::size_t k = 0; k < order.size(); ++k) {
      if (k % 10 == 0) out_ << " -2";
      const int node = e.nodes[static_cast<std::size_t>(order[k])];
      out_ << fixed("%10lld", mesh.node_ids[static_cast<std::size_t>(node)]);
      if (k % 10 == 9 || k + 1 == order.size()) out_ << '\n';
    }
  }
  out_ << " -3\n";
  end_file();
}

void FrdWriter::end_file() {
  end_line_at_ = out_.tellp();
  out_ << " 9999\n";
  out_.flush();
  if (!out_) throw SolverError("cannot write " + path_.string() + ": " + std::strerror(errno));
}

void FrdWriter::block(const Frame& frame, const std::string& name,
                      const std::vector<Component>& components, const MatX& values) {
  KONTAKT_REQUIRE(values.rows() == model_.n_nodes(), "FrdWriter: " + name + " has wrong size");
  std::string b = "    1PSTEP" + fixed("%26lld", ++blocks_) + fixed("%12lld", frame.increment) +
                  fixed("%12lld", frame.step) + std::string(10, ' ') + "\n";
  b += "  100CL" + fixed("%5lld", 100 + frames_) + frd_time(frame.total_time) +
       fixed("%12lld", static_cast<long long>(nodes_.size())) + fixed("%22lld", 0) +
       fixed("%5lld", frames_) + fixed("%12lld", 1) + "\n";
  b += " -4  " + pad(name, 8) + fixed("%5lld", static_cast<long long>(components.size())) +
       fixed("%5lld", 1) + "\n";
  for (const Component& c : components) b += component_line(c.name, c.type, c.i, c.j);
  out_ << b;
  std::vector<double> row(static_cast<std::size_t>(values.cols()));
  for (int n : nodes_) {
    for (Index k = 0; k < values.cols(); ++k) row[static_cast<std::size_t>(k)] = values(n, k);
    out_ << frd_result_lines(model_.mesh.node_ids[static_cast<std::size_t>(n)], row.data(),
                             static_cast<int>(row.size()));
  }
  out_ << " -3\n";
}

void FrdWriter::write(const model::Step& step, const Frame& frame) {
  const std::set<std::string> fields = frd_fields(step);
  if (fields.empty() || !file_output_due(step, frame)) return;
  const auto want = [&](const char* f) { return fields.count(f) > 0; };
  const Index n = model_.n_nodes();
  ++frames_;
  out_.seekp(end_line_at_);
  if (want("U")) block(frame, "DISP", vector_components("D"), frame.U);
  if (want("NT") && frame.T.size() > 0)
    block(frame, "NDTEMP", {{"T", 1, 0, 0}}, frame.T);
  if (want("S") && frame.S_nodal.rows() > 0)
    block(frame, "STRESS", tensor_components({"SXX", "SYY", "SZZ", "SXY", "SYZ", "SZX"}),
          frd_tensor(frame.S_nodal));
  if (want("E") && frame.E_nodal.rows() > 0)
    block(frame, "TOSTRAIN", tensor_components({"EXX", "EYY", "EZZ", "EXY", "EYZ", "EZX"}),
          frd_tensor(frame.E_nodal));
  if (want("RF") && frame.RF.rows() > 0) block(frame, "FORC", vector_components("F"), frame.RF);
  // Only models with plasticity have PEEQ; ccx 2.20 writes no PE block for elastic ones.
  if (want("PEEQ") && frame.PEEQ_nodal.size() > 0)
    block(frame, "PE", {{"PE", 1, 0, 0}}, frame.PEEQ_nodal);
  if ((want("CDIS") || want("CSTR")) && !model_.contact_pairs.empty() &&
      frame.contact_nodal.CPRESS.size() > 0) {
    const ContactNodal& c = frame.contact_nodal;
    MatX v(n, 6);
    v << c.COPEN, c.CSLIP.col(0), c.CSLIP.col(1), c.CPRESS, c.CSHEAR.col(0), c.CSHEAR.col(1);
    block(frame, "CONTACT",
          tensor_components({"COPEN", "CSLIP1", "CSLIP2", "CPRESS", "CSHEAR1", "CSHEAR2"}), v);
  }
  end_file();
}

}  // namespace kontakt::output
