// *HEADING, *NODE, *ELEMENT, *NSET, *ELSET, *SURFACE.
#include <algorithm>
#include <cctype>
#include <limits>

#include "inp/element_names.hpp"
#include "inp/keyword_handlers.hpp"
#include "inp/model_builder.hpp"
#include "inp/record_access.hpp"

namespace kontakt::inp {

namespace {

/// Set names are compared the way ccx does: upper case, blanks removed.
std::string set_name(std::string_view text) { return remove_blanks(to_upper(text)); }

RawSet& open_set(std::map<std::string, RawSet>& sets, const std::string& name,
                 const SourceLoc& where) {
  auto [it, inserted] = sets.try_emplace(name);
  if (inserted) it->second.where = where;
  return it->second;
}

void add_label(RawSet& set, int label, int line_id) {
  set.labels.push_back(label);
  set.line_ids.push_back(line_id);
  set.sequence.push_back(model::LabelRange{label, label, 1});
}

/// GENERATE data: first, last[, increment].
void add_generated(const Record& record, const DataLine& line, RawSet& set) {
  require_field_count(record, line, 2, 3);
  const int first = int_field(record, line, 0);
  const int last = int_field(record, line, 1);
  const int step = line.fields.size() > 2 ? int_field(record, line, 2) : 1;
  if (step <= 0) fail(record, line, "GENERATE increment must be positive");
  if (last < first) fail(record, line, "GENERATE range ends before it starts");
  set.ranges.push_back(model::LabelRange{first, last, step});
  set.sequence.push_back(set.ranges.back());
}

/// Labels and names of other sets, mixed; a name means all members of that set.
void add_listed(const Record& record, const DataLine& line, std::map<std::string, RawSet>& sets,
                const std::string& target, int line_id) {
  for (std::size_t i = 0; i < line.fields.size(); ++i) {
    const std::string& field = line.fields[i];
    if (field.empty()) continue;
    if (const std::optional<int> label = parse_int(field)) {
      add_label(sets[target], *label, line_id);
      continue;
    }
    if (parse_real(field) || std::isdigit(static_cast<unsigned char>(field[0])) ||
        field[0] == '-') {
      fail(record, line, "field " + std::to_string(i + 1) + " ('" + field +
                             "') is neither a label nor a set name");
    }
    const auto source = sets.find(set_name(field));
    if (source == sets.end()) fail(record, line, "set " + set_name(field) + " is not defined");
    const RawSet copy = source->second;  // copy: the target may be the same set
    RawSet& set = sets[target];
    set.labels.insert(set.labels.end(), copy.labels.begin(), copy.labels.end());
    set.line_ids.insert(set.line_ids.end(), copy.line_ids.begin(), copy.line_ids.end());
    set.ranges.insert(set.ranges.end(), copy.ranges.begin(), copy.ranges.end());
    set.sequence.insert(set.sequence.end(), copy.sequence.begin(), copy.sequence.end());
  }
}

void handle_set(const Record& record, DeckState& state, std::map<std::string, RawSet>& sets,
                std::string_view name_param) {
  // ccx ignores other parameters of a set card with a warning (friction2 has *NSET,
  // FREQUENCY=100): the data lines alone decide the members, so we do the same.
  for (const Param& param : record.params)
    if (param.name != name_param && param.name != "GENERATE")
      state.warn(record.where, record.keyword, param.name + " ignored (as ccx does)");
  const std::string name = set_name(required_value(record, name_param));
  open_set(sets, name, record.where);
  const bool generate = has_param(record, "GENERATE");
  for (const DataLine& line : record.lines) {
    const int line_id = state.intern(line.where);
    if (generate) add_generated(record, line, sets[name]);
    else add_listed(record, line, sets, name, line_id);
  }
}

/// Gathers "label, n1, n2, ..." possibly continued over several lines.
std::vector<std::string> element_fields(const Record& record, std::size_t& i,
                                        std::size_t needed) {
  std::vector<std::string> fields = record.lines[i].fields;
  while (fields.size() < needed && i + 1 < record.lines.size() &&
         record.lines[i].ends_with_comma) {
    ++i;
    const auto& more = record.lines[i].fields;
    fields.insert(fields.end(), more.begin(), more.end());
  }
  return fields;
}

}  // namespace

void handle_heading(const Record& record, DeckState& state) {
  check_params(record, {});
  for (const DataLine& line : record.lines) {
    std::string text;
    for (std::size_t i = 0; i < line.fields.size(); ++i) text += (i ? "," : "") + line.fields[i];
    if (!state.model.heading.empty()) state.model.heading += '\n';
    state.model.heading += text;
  }
}

void handle_node(const Record& record, DeckState& state) {
  check_params(record, {"NSET"});
  const std::optional<std::string> nset = name_value(record, "NSET");
  if (nset) open_set(state.node_sets, *nset, record.where);
  model::Mesh& mesh = state.model.mesh;
  // ccx reads a node line by position: label, x, y, z; an empty coordinate is 0 and fields
  // past the fourth are not read. It says nothing; we warn once per card when such a field
  // holds something (planestress.inp has "0.75, 1.0, ,0.0": which z was meant?).
  std::size_t ignored = 0;
  const DataLine* first_ignored = nullptr;
  for (const DataLine& line : record.lines) {
    // A label alone is a node at the origin: ccx reads missing coordinates as 0
    // (planestress3.inp's node 1).
    require_field_count(record, line, 1, std::numeric_limits<std::size_t>::max());
    const int label = int_field(record, line, 0);
    const Vec3 xyz(real_field_or(record, line, 1, 0), real_field_or(record, line, 2, 0),
                   real_field_or(record, line, 3, 0));
    if (std::any_of(line.fields.begin() + std::min<std::size_t>(4, line.fields.size()),
                    line.fields.end(), [](const std::string& f) { return !f.empty(); })) {
      if (ignored++ == 0) first_ignored = &line;
    }
    const auto [it, inserted] = mesh.node_index.try_emplace(label, state.coords.size());
    if (inserted) {
      mesh.node_ids.push_back(label);
      state.coords.push_back(xyz);
    } else {
      // ccx stores coordinates by label, so a repeated label overwrites the earlier ones.
      state.coords[it->second] = xyz;
      state.warn(line.where, record.keyword,
                 "node " + std::to_string(label) + " defined again; coordinates overwritten");
    }
    if (nset) add_label(state.node_sets[*nset], label, state.intern(line.where));
  }
  if (first_ignored)
    state.warn(first_ignored->where, record.keyword,
               std::to_string(ignored) + " line(s) with fields past x, y, z (first here): " +
                   "not read, as ccx does not read them");
}

namespace {

/// SPRINGA, GAPUNI and T3D2 lines (label, node 1, node 2): connectors, not solid elements.
void read_connectors(const Record& record, DeckState& state, model::Connector::Kind kind) {
  const std::optional<std::string> elset = name_value(record, "ELSET");
  if (elset) open_set(state.element_sets, *elset, record.where);
  for (const DataLine& line : record.lines) {
    require_field_count(record, line, 3, 3);
    const int label = int_field(record, line, 0);
    if (state.model.mesh.element_index.contains(label) || state.coupling_elements.contains(label) ||
        !state.connector_index.try_emplace(label, state.connectors.size()).second)
      fail(record, line, "element " + std::to_string(label) + " defined twice");
    state.connectors.push_back(
        {kind, label, {int_field(record, line, 1), int_field(record, line, 2)}, line.where});
    if (elset) add_label(state.element_sets[*elset], label, state.intern(line.where));
  }
}

/// DCOUP3D lines (label, node): the reference node of a *DISTRIBUTING COUPLING, no element.
void read_coupling_elements(const Record& record, DeckState& state) {
  const std::optional<std::string> elset = name_value(record, "ELSET");
  if (elset) open_set(state.element_sets, *elset, record.where);
  for (const DataLine& line : record.lines) {
    require_field_count(record, line, 2, 2);
    const int label = int_field(record, line, 0);
    if (state.model.mesh.element_index.contains(label) || state.connector_index.contains(label) ||
        !state.coupling_elements.try_emplace(label, int_field(record, line, 1)).second)
      fail(record, line, "element " + std::to_string(label) + " defined twice");
    if (elset) add_label(state.element_sets[*elset], label, state.intern(line.where));
  }
}

}  // namespace

void handle_element(const Record& record, DeckState& state) {
  check_params(record, {"TYPE", "ELSET"});
  const std::string type_name = remove_blanks(required_value(record, "TYPE"));
  for (const auto kind : {model::Connector::Kind::Spring, model::Connector::Kind::Gap,
                          model::Connector::Kind::Truss})
    if (to_upper(type_name) == model::connector_type_name(kind))
      return read_connectors(record, state, kind);
  if (to_upper(type_name) == "DCOUP3D") return read_coupling_elements(record, state);
  const std::optional<ElementName> type = find_element_name(type_name);
  if (!type) fail(record, "element type " + to_upper(type_name) + " is not supported");
  const std::optional<std::string> elset = name_value(record, "ELSET");
  if (elset) open_set(state.element_sets, *elset, record.where);
  model::Mesh& mesh = state.model.mesh;
  const std::size_t needed = static_cast<std::size_t>(type->n_nodes) + 1;
  for (std::size_t i = 0; i < record.lines.size(); ++i) {
    const DataLine& first = record.lines[i];
    const std::vector<std::string> fields = element_fields(record, i, needed);
    const DataLine joined{fields, false, first.where};
    if (fields.size() < needed) {
      fail(record, first, "element needs " + std::to_string(type->n_nodes) +
                              " node numbers, got " + std::to_string(fields.size() - 1));
    }
    if (fields.size() > needed) {
      if (type->type != element::ElementType::C3D8I) {
        fail(record, first, "too many node numbers for " + std::string(type->name));
      }
      // Some generators write C3D8I with 10 numbers; ccx reads the first 8.
      state.warn(first.where, record.keyword, "extra node numbers of C3D8I element ignored");
    }
    const int label = int_field(record, joined, 0);
    std::vector<int> nodes(static_cast<std::size_t>(type->n_nodes));
    for (std::size_t n = 0; n < nodes.size(); ++n) nodes[n] = int_field(record, joined, n + 1);
    const auto [it, inserted] = mesh.element_index.try_emplace(label, mesh.elements.size());
    if (!inserted || state.connector_index.contains(label) ||
        state.coupling_elements.contains(label))
      fail(record, first, "element " + std::to_string(label) + " defined twice");
    mesh.elements.push_back(model::Element{label, type->type, {}, -1, type->planar});
    state.element_node_labels.push_back(std::move(nodes));
    const int line_id = state.intern(first.where);
    state.element_line_ids.push_back(line_id);
    if (elset) add_label(state.element_sets[*elset], label, line_id);
  }
}

void handle_nset(const Record& record, DeckState& state) {
  handle_set(record, state, state.node_sets, "NSET");
}

void handle_elset(const Record& record, DeckState& state) {
  handle_set(record, state, state.element_sets, "ELSET");
}

namespace {

int face_number(const Record& record, const DataLine& line, std::string_view prefix) {
  const std::string text = line.fields.size() > 1 ? to_upper(line.fields[1]) : "";
  const std::optional<int> n =
      text.starts_with(prefix) ? parse_int(text.substr(prefix.size())) : std::nullopt;
  if (!n || *n < 1 || *n > 6) {
    fail(record, line, "field 2 ('" + text + "') is not a face label " + std::string(prefix) +
                           "1.." + std::string(prefix) + "6");
  }
  return *n;
}

/// Labels of an element or node field: a label itself, or the members of a named set (its
/// GENERATE'd labels where `index` has them).
std::vector<std::pair<int, int>> expand_field(const Record& record, const DataLine& line,
                                              const std::map<std::string, RawSet>& sets,
                                              const std::unordered_map<int, int>& index,
                                              int line_id) {
  if (const std::optional<int> label = parse_int(line.fields[0])) return {{*label, line_id}};
  const auto set = sets.find(set_name(line.fields[0]));
  if (set == sets.end()) fail(record, line, "set " + set_name(line.fields[0]) + " is not defined");
  return set_labels(set->second, index);
}

}  // namespace

void handle_surface(const Record& record, DeckState& state) {
  check_params(record, {"NAME", "TYPE"});
  const std::string name = set_name(required_value(record, "NAME"));
  const std::string type = name_value(record, "TYPE").value_or("ELEMENT");
  if (type != "ELEMENT" && type != "NODE") fail(record, "TYPE=" + type + " is not supported");
  RawSurface surface;
  surface.where = record.where;
  surface.kind = type == "NODE" ? model::Surface::Kind::Nodes : model::Surface::Kind::ElementFaces;
  for (const DataLine& line : record.lines) {
    const int line_id = state.intern(line.where);
    if (surface.kind == model::Surface::Kind::Nodes) {
      require_field_count(record, line, 1, 2);  // the optional weight is ignored
      for (const auto& labelled :
           expand_field(record, line, state.node_sets, state.model.mesh.node_index, line_id)) {
        surface.node_labels.push_back(labelled.first);
        surface.line_ids.push_back(line_id);
      }
    } else {
      require_field_count(record, line, 2, 2);
      const int face = face_number(record, line, "S");
      for (const auto& labelled :
           expand_field(record, line, state.element_sets, state.model.mesh.element_index, line_id)) {
        surface.faces.push_back(RawFace{labelled.first, face, line_id});
      }
    }
  }
  // ccx adds a repeated definition to the surface (metalformingmortar), and keeps a node and
  // an element-face surface of one name apart, picking by role (metalforming): the element
  // faces stay under the name, the nodes go under node_surface_key().
  std::string key = name;
  if (const auto other = state.surfaces.find(name);
      other != state.surfaces.end() && other->second.kind != surface.kind) {
    key = node_surface_key(name);
    if (surface.kind == model::Surface::Kind::ElementFaces) {  // the nodes move aside
      auto nodes = state.surfaces.extract(other);
      nodes.key() = key;
      state.surfaces.insert(std::move(nodes));
      key = name;
    }
  }
  const auto [it, fresh] = state.surfaces.try_emplace(key, surface);
  if (fresh) return;
  RawSurface& to = it->second;
  to.faces.insert(to.faces.end(), surface.faces.begin(), surface.faces.end());
  to.node_labels.insert(to.node_labels.end(), surface.node_labels.begin(),
                        surface.node_labels.end());
  to.line_ids.insert(to.line_ids.end(), surface.line_ids.begin(), surface.line_ids.end());
}

}  // namespace kontakt::inp
