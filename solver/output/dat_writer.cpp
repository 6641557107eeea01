#include "output/dat_writer.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <limits>
#include <map>
#include <numeric>
#include <tuple>

#include "core/error.hpp"
#include "material/anisotropic_elastic.hpp"
#include "output/contact_records.hpp"
#include "output/dat_headers.hpp"
#include "output/fortran_format.hpp"

namespace kontakt::output {

namespace {

std::string i10(long long v) {
  char b[32];
  std::snprintf(b, sizeof b, "%10lld", v);
  return b;
}
std::string i3(long long v) {
  char b[32];
  std::snprintf(b, sizeof b, "%3lld", v);
  return b;
}

// (6x,1p,n(1x,e13.6))
template <class It>
std::string total_row(It begin, It end) {
  std::string s(6, ' ');
  for (It it = begin; it != end; ++it) s += ' ' + fortran_e13_6(*it);
  return s;
}

/// One row per entry of a set's print order (model::NodeSet), its labels up to `largest`:
/// (label, internal index or -1 where `index` has no such label). Without a print order, the
/// members in label order. As many entries as the print writes rows.
std::vector<std::pair<int, int>> print_rows(const std::vector<model::LabelRange>& order,
                                            const std::vector<int>& members,
                                            const std::unordered_map<int, int>& index,
                                            int largest, const auto& label_of) {
  std::vector<std::pair<int, int>> rows;
  if (order.empty()) {
    for (int member : members) rows.emplace_back(label_of(member), member);
    return rows;
  }
  for (const model::LabelRange& range : order)
    for (long long label = range.first; label <= std::min<long long>(range.last, largest);
         label += range.step) {
      const auto found = index.find(static_cast<int>(label));
      rows.emplace_back(static_cast<int>(label), found == index.end() ? -1 : found->second);
    }
  return rows;
}

bool output_due(int frequency, const Frame& frame) {
  if (frame.at_time_point) return frame.is_step_end || *frame.at_time_point;
  if (frequency <= 0) return false;
  return frame.is_step_end || frame.increment % frequency == 0;
}

}  // namespace

bool print_due(const model::PrintRequest& request, const Frame& frame) {
  return output_due(request.frequency, frame);
}

bool print_due(const model::ContactRequest& request, const Frame& frame) {
  return output_due(request.frequency, frame);
}

DatWriter::DatWriter(const model::Model& model, std::filesystem::path path)
    : model_(model), path_(std::move(path)), out_(path_, std::ios::out | std::ios::trunc) {
  if (!out_) throw SolverError("cannot create " + path_.string());
  for (int label : model.mesh.node_ids) largest_node_label_ = std::max(largest_node_label_, label);
  printed_node_.resize(static_cast<std::size_t>(model.n_nodes()));
  std::iota(printed_node_.begin(), printed_node_.end(), 0);
  for (const model::PlanarFold& fold : model.planar_folds)
    for (int copy : fold.expanded) printed_node_[static_cast<std::size_t>(copy)] = fold.node;
  for (const model::Element& el : model.mesh.elements)
    largest_element_label_ = std::max(largest_element_label_, el.id);
  for (std::size_t k = 0; k < model.connectors.size(); ++k) {
    const model::Connector& c = model.connectors[k];
    if (c.kind != model::Connector::Kind::Truss) continue;
    truss_index_.emplace(c.id, static_cast<int>(k));
    largest_element_label_ = std::max(largest_element_label_, c.id);
  }
}

void DatWriter::header(std::string_view prefix, const std::string& set, const Frame& f) {
  out_ << '\n' << prefix << set << " and time " << fortran_e14_7(f.total_time) << "\n\n";
}

void DatWriter::write(const model::Step& step, const Frame& frame) {
  // Contact prints sit between the node and element prints (ccx keeps one print list).
  auto contact = step.contact_prints.begin();
  const auto contact_prints_up_to = [&](std::size_t position) {
    for (; contact != step.contact_prints.end() && contact->after_prints <= position; ++contact)
      if (print_due(*contact, frame)) contact_request(*contact, frame);
  };
  for (std::size_t i = 0; i < step.prints.size(); ++i) {
    contact_prints_up_to(i);
    const auto& r = step.prints[i];
    if (!print_due(r, frame)) continue;
    if (r.kind == model::PrintRequest::Kind::Node)
      node_request(r, frame);
    else
      element_request(r, frame);
  }
  contact_prints_up_to(std::numeric_limits<std::size_t>::max());
  out_.flush();
  if (!out_) throw SolverError("write error on " + path_.string());
}

void DatWriter::node_request(const model::PrintRequest& r, const Frame& f) {
  const auto it = model_.node_sets.find(r.set);
  if (it == model_.node_sets.end()) throw SolverError("*NODE PRINT: unknown node set " + r.set);
  const auto& ids = model_.mesh.node_ids;
  // Labels without a node print as zero rows (ccx).
  const std::vector<std::pair<int, int>> printed =
      print_rows(it->second.print_order, it->second.nodes, model_.mesh.node_index,
                 largest_node_label_, [&](int n) { return ids[static_cast<std::size_t>(n)]; });
  // ccx prints a transformed node's vectors in its local system, flagged " L", unless
  // GLOBAL=YES.
  auto rows = [&](const MatX3& m) {
    KONTAKT_REQUIRE(m.rows() == model_.n_nodes(), "DatWriter: nodal array has wrong size");
    for (const auto& [label, n] : printed) {
      out_ << i10(label);
      if (n < 0) {
        out_ << ' ' << fortran_e13_6(0.0) << ' ' << fortran_e13_6(0.0) << ' ' << fortran_e13_6(0.0)
             << '\n';
        continue;
      }
      const auto frame = r.global ? model_.local_frames.end() : model_.local_frames.find(n);
      const bool local = frame != model_.local_frames.end();
      const Vec3 v = local ? Vec3(frame->second.transpose() * m.row(n).transpose())
                           : Vec3(m.row(n).transpose());
      for (int c = 0; c < 3; ++c) out_ << ' ' << fortran_e13_6(v[c]);
      out_ << (local ? " L\n" : "\n");
    }
  };
  for (const auto& var : r.variables) {
    if (var == "U") {
      header(dat_header_prefix(DatBlock::U), r.set, f);
      rows(f.U);
    } else if (var == "RF") {
      if (r.totals != model::Totals::Only) {
        header(dat_header_prefix(DatBlock::RF), r.set, f);
        rows(f.RF);
      }
      if (r.totals != model::Totals::No) {
        Real t[3] = {0, 0, 0};
        for (const auto& [label, n] : printed)
          if (n >= 0)
            for (int c = 0; c < 3; ++c) t[c] += f.RF(n, c);
        header(dat_header_prefix(DatBlock::RF_TOTAL), r.set, f);
        out_ << total_row(t, t + 3) << '\n';
      }
    }
  }
}

void DatWriter::element_request(const model::PrintRequest& r, const Frame& f) {
  const auto it = model_.element_sets.find(r.set);
  if (it == model_.element_sets.end())
    throw SolverError("*EL PRINT: unknown element set " + r.set);
  const auto& mesh = model_.mesh;
  // Labels without an element or truss print nothing (ccx).
  std::vector<int> elems;  // solid elements; trusses as -2 - their connector index
  for (const auto& [label, e] : print_rows(it->second.print_order, it->second.elements,
                                           mesh.element_index, largest_element_label_, [&](int e) {
                                             return mesh.elements[static_cast<std::size_t>(e)].id;
                                           })) {
    if (e >= 0 && (f.element_active.empty() || f.element_active[static_cast<std::size_t>(e)]))
      elems.push_back(e);
    else if (const auto truss = truss_index_.find(label); e < 0 && truss != truss_index_.end())
      elems.push_back(-2 - truss->second);
  }
  const auto truss_of = [](int e) { return static_cast<Index>(-2 - e); };
  // ccx prints a truss at the 8 points of its expanded element, all alike here.
  constexpr int kTrussPoints = 8;
  const auto need_truss_rows = [&](Index rows) {
    KONTAKT_REQUIRE(rows == static_cast<Index>(model_.connectors.size()),
                    "DatWriter: frame has no truss rows");
  };
  const auto truss_label = [&](int e) {
    return model_.connectors[static_cast<std::size_t>(truss_of(e))].id;
  };
  const auto need_ip = [&](Index rows) {
    KONTAKT_REQUIRE(f.ip_offset.size() == static_cast<std::size_t>(model_.n_elements()) + 1,
                    "DatWriter: frame ip_offset has wrong size");
    KONTAKT_REQUIRE(rows == f.ip_offset.back(), "DatWriter: point array has wrong size");
  };
  const auto label = [&](int e) { return mesh.elements[static_cast<std::size_t>(e)].id; };
  const auto truss_volume = [&](int e) {  // initial: A L
    const model::Connector& c = model_.connectors[static_cast<std::size_t>(truss_of(e))];
    return c.area * (mesh.coords.row(c.nodes[1]) - mesh.coords.row(c.nodes[0])).norm();
  };

  // (i10,1x,i3,1p,n(1x,e13.6))
  // Tensors (S, E) of an element with an *ORIENTATION print in its frame unless GLOBAL=YES,
  // each row followed by the orientation's name in 20 columns (ccx).
  auto ip_rows6 = [&](const MatX6& m, const MatX6& truss_m) {
    need_ip(m.rows());
    for (int e : elems) {
      if (e < 0) {
        need_truss_rows(truss_m.rows());
        for (int p = 1; p <= kTrussPoints; ++p) {
          out_ << i10(truss_label(e)) << ' ' << i3(p);
          for (int c = 0; c < 6; ++c) out_ << ' ' << fortran_e13_6(truss_m(truss_of(e), c));
          out_ << '\n';
        }
        continue;
      }
      const Index b = f.ip_offset[static_cast<std::size_t>(e)];
      const Index en = f.ip_offset[static_cast<std::size_t>(e) + 1];
      const model::Element& el = mesh.elements[static_cast<std::size_t>(e)];
      // A model assembled without sections (unit tests, generated models) has no orientation.
      const std::size_t section = static_cast<std::size_t>(el.section);
      const auto* orientation = section < model_.sections.size()
                                    ? &model_.sections[section].orientation
                                    : nullptr;
      std::vector<Mat3> frames;
      if (orientation && *orientation && !r.global) {
        MatX3 X(el.nodes.size(), 3);
        for (std::size_t a = 0; a < el.nodes.size(); ++a) X.row(a) = mesh.coords.row(el.nodes[a]);
        frames = model::point_frames(**orientation, el.type, X);
      }
      for (Index p = b; p < en; ++p) {
        out_ << i10(label(e)) << ' ' << i3(p - b + 1);
        const Vec6 row = frames.empty()
                             ? Vec6(m.row(p).transpose())
                             : material::stress_to_local(m.row(p).transpose(),
                                                         frames[static_cast<std::size_t>(p - b)]);
        for (int c = 0; c < 6; ++c) out_ << ' ' << fortran_e13_6(row(c));
        if (!frames.empty())
          out_ << ' ' << ((*orientation)->name + std::string(20, ' ')).substr(0, 20);
        out_ << '\n';
      }
    }
  };
  // `truss_v` empty: zero at trusses (PEEQ)
  auto ip_rows1 = [&](const VecX& v, const VecX& truss_v) {
    need_ip(v.size());
    for (int e : elems) {
      if (e < 0) {
        const Real value = truss_v.size() ? truss_v(truss_of(e)) : 0.0;
        for (int p = 1; p <= kTrussPoints; ++p)
          out_ << i10(truss_label(e)) << ' ' << i3(p) << ' ' << fortran_e13_6(value) << '\n';
        continue;
      }
      const Index b = f.ip_offset[static_cast<std::size_t>(e)];
      const Index en = f.ip_offset[static_cast<std::size_t>(e) + 1];
      for (Index p = b; p < en; ++p)
        out_ << i10(label(e)) << ' ' << i3(p - b + 1) << ' ' << fortran_e13_6(v(p)) << '\n';
    }
  };
  // (i10,1p,1x,e13.6) per element, then optional total block.
  auto per_element = [&](DatBlock block, DatBlock total_block, auto value_of) {
    Real total = 0;
    if (r.totals != model::Totals::Only) header(dat_header_prefix(block), r.set, f);
    for (int e : elems) {
      const Real v = value_of(e);
      total += v;
      if (r.totals != model::Totals::Only)
        out_ << i10(e < 0 ? truss_label(e) : label(e)) << ' ' << fortran_e13_6(v) << '\n';
    }
    if (r.totals != model::Totals::No) {
      header(dat_header_prefix(total_block), r.set, f);
      out_ << total_row(&total, &total + 1) << '\n';
    }
  };

  for (const auto& var : r.variables) {
    if (var == "S") {
      header(dat_header_prefix(DatBlock::S), r.set, f);
      ip_rows6(f.S, f.truss_S);
    } else if (var == "E") {
      header(dat_header_prefix(DatBlock::E), r.set, f);
      ip_rows6(f.E, f.truss_E);
    } else if (var == "ENER") {
      header(dat_header_prefix(DatBlock::ENER), r.set, f);
      ip_rows1(f.ENER, f.truss_ENER);
    } else if (var == "PEEQ") {
      if (f.PEEQ.size() == 0) continue;  // ccx prints no PEEQ block for elastic models
      header(dat_header_prefix(DatBlock::PEEQ), r.set, f);
      ip_rows1(f.PEEQ, VecX());
    } else if (var == "ELSE") {
      need_ip(f.ENER.size());
      KONTAKT_REQUIRE(f.ip_volume.size() == f.ENER.size(), "DatWriter: ip_volume has wrong size");
      per_element(DatBlock::ELSE, DatBlock::ELSE_TOTAL, [&](int e) {
        if (e < 0) {
          need_truss_rows(f.truss_ENER.size());
          return f.truss_ENER(truss_of(e)) * truss_volume(e);
        }
        Real s = 0;
        for (Index p = f.ip_offset[static_cast<std::size_t>(e)];
             p < f.ip_offset[static_cast<std::size_t>(e) + 1]; ++p)
          s += f.ENER(p) * f.ip_volume(p);
        return s;
      });
    } else if (var == "EVOL") {
      KONTAKT_REQUIRE(f.EVOL.size() == model_.n_elements(), "DatWriter: EVOL has wrong size");
      per_element(DatBlock::EVOL, DatBlock::EVOL_TOTAL,
                  [&](int e) { return e < 0 ? truss_volume(e) : f.EVOL(e); });
    }
  }
}

void DatWriter::contact_request(const model::ContactRequest& r, const Frame& f) {
  if (model_.contact_pairs.empty()) return;
  // The scheme solved (a --scheme override may differ from the pair's TYPE) decides the rows.
  const bool by_node =
      model_.contact_pairs.front().scheme.kind == model::ContactScheme::Kind::NodeToSurface;
  const auto& mesh = model_.mesh;
  std::vector<const ContactPointRecord*> rows;
  for (const auto& p : f.contact_points)
    if (p.active) rows.push_back(&p);
  // The copies of a 2D node print as the 2D node, merged (their values agree but for the
  // expanded layer's shape).
  std::vector<ContactPointRecord> folded;
  if (by_node && !model_.planar_folds.empty()) {
    std::map<std::pair<int, int>, std::vector<ContactPointRecord>> copies;  // (pair, 2D node)
    for (const ContactPointRecord* p : rows) {
      ContactPointRecord r = *p;
      r.slave_node = printed_node_[static_cast<std::size_t>(p->slave_node)];
      copies[{r.pair, r.slave_node}].push_back(r);
    }
    for (const auto& [key, records] : copies) folded.push_back(merged_record(records));
    rows.clear();
    for (const ContactPointRecord& r : folded) rows.push_back(&r);
  }
  // ccx's order of contact elements: pair, then slave node or slave element and face.
  const auto key = [&](const ContactPointRecord* p) {
    if (by_node) {
      KONTAKT_REQUIRE(p->slave_node >= 0, "DatWriter: contact point without slave node");
      return std::make_tuple(p->pair, mesh.node_ids[static_cast<std::size_t>(p->slave_node)], 0);
    }
    KONTAKT_REQUIRE(p->slave_element >= 0, "DatWriter: contact point without slave face");
    return std::make_tuple(p->pair, mesh.elements[static_cast<std::size_t>(p->slave_element)].id,
                           p->slave_face);
  };
  std::stable_sort(rows.begin(), rows.end(),
                   [&](const auto* a, const auto* b) { return key(a) < key(b); });

  const auto header = [&](DatBlock block) {
    out_ << '\n' << dat_header_prefix(block) << fortran_e14_7(f.total_time) << "\n\n";
  };
  // Rows: node (i10,1p,n(1x,e13.6)); element and face (i10,1x,i10,1p,n(1x,e13.6)).
  const auto block = [&](DatBlock by_node_block, DatBlock by_face_block, auto values_of) {
    header(by_node ? by_node_block : by_face_block);
    for (const ContactPointRecord* p : rows) {
      const auto [pair, label, face] = key(p);
      out_ << i10(label);
      if (!by_node) out_ << ' ' << i10(face);
      for (Real v : values_of(*p)) out_ << ' ' << fortran_e13_6(v);
      out_ << '\n';
    }
  };
  using Values3 = std::array<Real, 3>;
  for (const auto& var : r.variables) {
    // TOTALS=ONLY leaves out every per-point block, and only CELS has a total (ccx 2.20).
    if (var == "CDIS" && !r.totals_only) {
      block(DatBlock::CDIS_NODE, DatBlock::CDIS_FACE, [](const ContactPointRecord& p) {
        return Values3{p.clearance, p.slip(0), p.slip(1)};
      });
    } else if (var == "CSTR" && !r.totals_only) {
      block(DatBlock::CSTR_NODE, DatBlock::CSTR_FACE, [](const ContactPointRecord& p) {
        return Values3{p.pressure, p.shear(0), p.shear(1)};
      });
    } else if (var == "CELS") {
      if (!r.totals_only)
        block(DatBlock::CELS_NODE, DatBlock::CELS_FACE,
              [](const ContactPointRecord& p) { return std::array<Real, 1>{p.energy}; });
      if (r.totals || r.totals_only) {
        Real total = 0;
        for (const ContactPointRecord* p : rows) total += p->energy;
        header(DatBlock::CELS_TOTAL);
        out_ << total_row(&total, &total + 1) << '\n';
      }
    }
  }
}

}  // namespace kontakt::output
