// *BOUNDARY, *CLOAD, *DLOAD, *TEMPERATURE with ccx's OP=NEW/MOD carry-over rules. The
// running state lives in DeckState::active; *END STEP snapshots it into the Step.
#include "inp/element_names.hpp"
#include "inp/keyword_handlers.hpp"
#include "inp/model_builder.hpp"
#include "inp/record_access.hpp"

namespace kontakt::inp {

namespace {

/// Applies OP=: ccx honours it on the first card of its kind in a step only.
/// Returns true when earlier definitions must be removed.
bool op_new_requested(const Record& record, DeckState& state) {
  const std::string op = name_value(record, "OP").value_or("MOD");
  if (op != "NEW" && op != "MOD") fail(record, "OP=" + op + ": expected NEW or MOD");
  if (!state.open_step) {
    if (op == "NEW") fail(record, "OP=NEW is only meaningful within a step");
    return false;
  }
  const bool first = state.open_step->seen.insert(record.key).second;
  if (op == "NEW" && !first) {
    state.warn(record.where, record.keyword,
               "OP=NEW only acts on the first card of this kind in a step; ignored");
  }
  return op == "NEW" && first;
}

/// A structural translation dof, 1..3 in the deck, returned 0-based.
int translation_dof(const Record& record, const DataLine& line, std::size_t field) {
  const int dof = int_field(record, line, field);
  if (dof < 1 || dof > 3) {
    fail(record, line, "degree of freedom " + std::to_string(dof) +
                           " is not supported (only 1..3, translations)");
  }
  return dof - 1;
}

/// One *BOUNDARY data line; with FIXED the dofs keep their displacement from the end of the
/// previous step (ccx), so the line takes no value.
void read_boundary_line(const Record& record, const DataLine& line, DeckState& state,
                        int amplitude, bool hold_previous) {
  require_field_count(record, line, 2, hold_previous ? 3 : 4);
  const int first = translation_dof(record, line, 1);
  const bool has_last = line.fields.size() > 2 && !line.fields[2].empty();
  const int last = has_last ? translation_dof(record, line, 2) : first;
  if (last < first) fail(record, line, "last degree of freedom is smaller than the first");
  const Real value = real_field_or(record, line, 3, 0);
  for (int node : resolve_node_field(state, record, line, 0)) {
    for (int dof = first; dof <= last; ++dof) {
      // Same node and dof: the later definition replaces the earlier (ccx bounadd).
      state.active.boundaries[{node, dof}] =
          model::Boundary{node, dof, value, amplitude, hold_previous};
    }
  }
}

/// True for ccx's PnNP: a pressure on face n whose value is a node's prescribed dof 2.
bool is_network_pressure(const DataLine& line) {
  const std::string label = to_upper(line.fields[1]);
  return label.size() == 4 && label.front() == 'P' && label.ends_with("NP");
}

/// Pressure faces named by "elem_or_elset, Pn", "surface, P" or "elem_or_elset, PnNP".
std::vector<FaceKey> pressure_faces(const Record& record, const DataLine& line,
                                    const DeckState& state) {
  std::string label = to_upper(line.fields[1]);
  if (is_network_pressure(line)) label.resize(2);
  std::vector<FaceKey> faces;
  if (label == "P") {
    const auto surface = state.surfaces.find(remove_blanks(to_upper(line.fields[0])));
    if (surface == state.surfaces.end() ||
        surface->second.kind != model::Surface::Kind::ElementFaces) {
      fail(record, line, "element face surface " + to_upper(line.fields[0]) + " is not defined");
    }
    for (const RawFace& f : surface->second.faces) {
      const auto element = state.model.mesh.element_index.find(f.element_label);
      if (element == state.model.mesh.element_index.end()) {
        fail(record, line, "surface element " + std::to_string(f.element_label) +
                               " is not defined");
      }
      faces.emplace_back(element->second, f.face);
    }
    return faces;
  }
  const std::optional<int> face = label.starts_with("P") && label.size() == 2
                                      ? parse_int(label.substr(1))
                                      : std::nullopt;
  if (!face) {
    fail(record, line, "load type " + label +
                           " is not supported (only P1..P6, P, PnNP, GRAV and CENTRIF)");
  }
  for (int element : resolve_element_field(state, record, line, 0)) {
    faces.emplace_back(element, *face);
  }
  return faces;
}

void check_face_exists(const Record& record, const DataLine& line, const DeckState& state,
                       const FaceKey& face) {
  const model::Element& element = state.model.mesh.elements[static_cast<std::size_t>(face.first)];
  const ElementName& name = element_name_of(element.type, element.planar);
  if (face.second < 1 || face.second > name.n_faces) {
    fail(record, line, "element " + std::to_string(element.id) + " (" + std::string(name.name) +
                           ") has no face " + std::to_string(face.second));
  }
}

bool is_body_load(const DataLine& line) {
  const std::string label = to_upper(line.fields[1]);
  return label == "GRAV" || label == "CENTRIF";
}

/// A unit vector from fields first..first+2; a non-unit one is normalised as ccx does, with a
/// warning, since a deck giving g as a vector with magnitude 1 would otherwise get |g| times it.
Vec3 unit_vector_field(const Record& record, const DataLine& line, std::size_t first,
                       DeckState& state, const std::string& what) {
  const Vec3 v(real_field(record, line, first), real_field(record, line, first + 1),
               real_field(record, line, first + 2));
  if (v.norm() == 0) fail(record, line, what + " is the zero vector");
  if (std::abs(v.norm() - 1) > 1e-6) {
    state.warn(line.where, record.keyword,
               what + " has length " + std::to_string(v.norm()) + "; normalised (as ccx does)");
  }
  return v.normalized();
}

/// "elset, GRAV, g, dx, dy, dz" or "elset, CENTRIF, omega^2, point, axis".
void read_body_load_line(const Record& record, const DataLine& line, DeckState& state,
                         int amplitude) {
  model::BodyLoad load;
  load.where = line.where;
  load.amplitude = amplitude;
  if (to_upper(line.fields[1]) == "GRAV") {
    require_field_count(record, line, 6, 6);
    load.kind = model::BodyLoad::Kind::Gravity;
    load.direction = unit_vector_field(record, line, 3, state, "the gravity direction");
  } else {
    require_field_count(record, line, 9, 9);
    load.kind = model::BodyLoad::Kind::Centrifugal;
    load.point = Vec3(real_field(record, line, 3), real_field(record, line, 4),
                      real_field(record, line, 5));
    load.direction = unit_vector_field(record, line, 6, state, "the rotation axis");
    if (real_field(record, line, 2) < 0)
      fail(record, line, "CENTRIF magnitude is omega^2 and cannot be negative");
  }
  load.value = real_field(record, line, 2);
  load.elements = resolve_element_field(state, record, line, 0);
  const bool gravity = load.kind == model::BodyLoad::Kind::Gravity;
  const BodyLoadKey key{
      remove_blanks(to_upper(line.fields[0])), load.kind,
      gravity ? std::array<Real, 3>{load.direction.x(), load.direction.y(), load.direction.z()}
              : std::array<Real, 3>{}};
  model::BodyLoad& active = state.active.body_loads[key];
  if (!state.open_step->body_loads_in_step.insert(key).second) load.value += active.value;
  active = std::move(load);
}

}  // namespace

void handle_boundary(const Record& record, DeckState& state) {
  check_params(record, {"OP", "AMPLITUDE", "TIMEDELAY", "FIXED"});
  const bool hold_previous = has_param(record, "FIXED");
  if (hold_previous && !state.open_step)
    fail(record, "FIXED is only allowed inside a step (it refers to the previous step's result)");
  // ccx removes every earlier *BOUNDARY condition, model-level ones included.
  if (op_new_requested(record, state)) state.active.boundaries.clear();
  const int amplitude = amplitude_param(state, record);
  for (const DataLine& line : record.lines)
    read_boundary_line(record, line, state, amplitude, hold_previous);
}

void handle_cload(const Record& record, DeckState& state) {
  check_params(record, {"OP", "AMPLITUDE", "TIMEDELAY"});
  if (op_new_requested(record, state)) state.active.cloads.clear();
  const int amplitude = amplitude_param(state, record);
  StepProgress& progress = *state.open_step;
  for (const DataLine& line : record.lines) {
    require_field_count(record, line, 3, 3);
    const int dof = translation_dof(record, line, 1);
    const Real value = real_field(record, line, 2);
    for (int node : resolve_node_field(state, record, line, 0)) {
      const DofKey key{node, dof};
      model::ConcentratedLoad& load = state.active.cloads[key];
      // ccx: within one step repeated forces add up; across steps they replace.
      const bool again_in_step = !progress.cloads_in_step.insert(key).second;
      load = model::ConcentratedLoad{node, dof, (again_in_step ? load.value : 0) + value,
                                     amplitude};
    }
  }
}

void handle_dload(const Record& record, DeckState& state) {
  check_params(record, {"OP", "AMPLITUDE", "TIMEDELAY"});
  if (op_new_requested(record, state)) {
    state.active.pressures.clear();
    state.active.network_pressures.clear();
    state.active.body_loads.clear();
  }
  const int amplitude = amplitude_param(state, record);
  StepProgress& progress = *state.open_step;
  for (const DataLine& line : record.lines) {
    require_field_count(record, line, 2, 1000);
    if (is_body_load(line)) {
      read_body_load_line(record, line, state, amplitude);
      continue;
    }
    const std::vector<FaceKey> faces = pressure_faces(record, line, state);  // checks the type
    require_field_count(record, line, 3, 3);
    if (is_network_pressure(line)) {
      // The third field is the node, not a value (ccx: its prescribed pressure, dof 2).
      const int node = node_index_of(state, record, line, int_field(record, line, 2));
      for (const FaceKey& key : faces) {
        check_face_exists(record, line, state, key);
        state.active.network_pressures[key] = {node, line.where};
        state.active.pressures[key] = model::PressureLoad{
            model::ElementFace{key.first, key.second}, 0, amplitude};
      }
      continue;
    }
    const Real value = real_field(record, line, 2);
    for (const FaceKey& key : faces) {
      check_face_exists(record, line, state, key);
      state.active.network_pressures.erase(key);
      model::PressureLoad& load = state.active.pressures[key];
      const bool again_in_step = !progress.pressures_in_step.insert(key).second;
      load = model::PressureLoad{model::ElementFace{key.first, key.second},
                                 (again_in_step ? load.value : 0) + value, amplitude};
    }
  }
}

void handle_temperature(const Record& record, DeckState& state) {
  check_params(record, {"OP"});
  // ccx: OP=NEW re-initialises the temperatures to the initial conditions.
  if (op_new_requested(record, state)) state.active.temperatures.clear();
  for (const DataLine& line : record.lines) {
    require_field_count(record, line, 2, 2);
    const Real value = real_field(record, line, 1);
    for (int node : resolve_node_field(state, record, line, 0)) {
      state.active.temperatures[node] = value;
    }
  }
}

}  // namespace kontakt::inp
