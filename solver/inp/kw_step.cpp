// *STEP, *STATIC, *END STEP, and the model-level *AMPLITUDE, *EQUATION, *INITIAL CONDITIONS.
#include <algorithm>

#include "element/element_type.hpp"
#include "inp/keyword_handlers.hpp"
#include "inp/model_builder.hpp"
#include "inp/record_access.hpp"

namespace kontakt::inp {

void handle_step(const Record& record, DeckState& state) {
  if (has_param(record, "PERTURBATION")) fail(record, "PERTURBATION is not supported");
  check_params(record, {"NLGEOM", "INC", "AMPLITUDE"});
  if (!record.lines.empty()) fail(record, record.lines.front(), "unexpected data line");
  // AMPLITUDE=RAMP is what a static step does anyway (ccx's default); loads applied at once
  // (STEP) are not built.
  if (const Param* amplitude = find_param(record, "AMPLITUDE")) {
    if (to_upper(amplitude->value) != "RAMP")
      fail(record, "AMPLITUDE=" + to_upper(amplitude->value) + " is not supported (only RAMP)");
  }
  StepProgress progress;
  progress.step.where = record.where;
  // ccx: once NLGEOM is selected it stays active in subsequent steps unless switched off.
  progress.step.nlgeom = state.active.nlgeom;
  progress.step.controls = state.active.controls;
  progress.step.contact_controls = state.active.contact_controls;
  if (const Param* nlgeom = find_param(record, "NLGEOM")) {
    const std::string value = nlgeom->has_value ? to_upper(nlgeom->value) : "YES";
    if (value != "YES" && value != "NO") fail(record, "NLGEOM=" + value + ": expected YES or NO");
    progress.step.nlgeom = value == "YES";
  }
  if (state.nonlinear_mpc && !progress.step.nlgeom) {  // ccx: *MPC triggers NLGEOM
    progress.step.nlgeom = true;
    state.warn(record.where, "*STEP", "NLGEOM switched on: the deck has an *MPC (as in ccx)");
  }
  if (const std::optional<int> inc = int_param(record, "INC")) {
    if (*inc <= 0) fail(record, "INC= must be positive");
    progress.step.max_increments = *inc;
  }
  state.open_step = std::move(progress);
  state.any_step_seen = true;
}

void handle_static(const Record& record, DeckState& state) {
  check_params(record, {"DIRECT", "SOLVER"});
  StepProgress& progress = *state.open_step;
  if (progress.has_procedure) fail(record, "the step already has a procedure");
  progress.has_procedure = true;
  if (has_param(record, "SOLVER")) {
    state.warn(record.where, record.keyword, "SOLVER= ignored; Kontakt uses its own solver");
  }
  model::StaticProcedure& procedure = progress.step.procedure;
  procedure.direct = has_param(record, "DIRECT");
  require_line_count(record, 0, 1);
  // Without a data line the step runs over (1, 1); like ccx, only a nonlinear step warns
  // about it, which the analysis decides (data_line_given stays false).
  if (record.lines.empty()) return;
  const DataLine& line = record.lines.front();
  require_field_count(record, line, 1, 4);
  procedure.data_line_given = true;
  procedure.initial_increment = real_field_or(record, line, 0, 1);
  procedure.period = real_field_or(record, line, 1, 1);
  procedure.min_increment = optional_real_field(record, line, 2);
  procedure.max_increment = optional_real_field(record, line, 3);
  if (procedure.initial_increment <= 0) fail(record, line, "initial increment must be positive");
  if (procedure.period <= 0) fail(record, line, "step period must be positive");
}

namespace {

template <typename Map>
auto values_of(const Map& map) {
  std::vector<typename Map::mapped_type> out;
  out.reserve(map.size());
  for (const auto& entry : map) out.push_back(entry.second);
  return out;
}

/// *DLOAD PnNP: the pressure is the node's prescribed dof 2 in force at the step's end, ramped
/// and scaled by its amplitude as the boundary value is (ccx).
void resolve_network_pressures(ActiveLoads& active, const std::vector<int>& node_ids) {
  for (const auto& [face, source] : active.network_pressures) {
    const auto& [node, where] = source;
    const auto boundary = active.boundaries.find({node, 1});
    if (boundary == active.boundaries.end() || boundary->second.hold_previous)
      throw InputError(where, "*DLOAD",
                       "network pressure node " +
                           std::to_string(node_ids[static_cast<std::size_t>(node)]) +
                           " has no prescribed value of dof 2 (*BOUNDARY) in this step");
    model::PressureLoad& load = active.pressures[face];
    load.value = boundary->second.value;
    load.amplitude = boundary->second.amplitude;
  }
}

VecX step_temperatures(const DeckState& state) {
  if (state.active.temperatures.empty()) return {};
  VecX temps = VecX::Zero(state.model.n_nodes());
  for (const auto& [node, value] : state.initial_temperatures) temps[node] = value;
  for (const auto& [node, value] : state.active.temperatures) temps[node] = value;
  return temps;
}

/// Splits ccx's one print list into the step's node/element and contact prints, keeping where
/// each contact print sits in it.
void set_step_prints(const ActiveLoads& active, model::Step& step) {
  for (const PrintEntry& entry : active.prints) {
    if (const auto* print = std::get_if<model::PrintRequest>(&entry)) {
      step.prints.push_back(*print);
      step.prints.back().frequency = active.output_frequency;
    } else {
      model::ContactRequest contact = std::get<model::ContactRequest>(entry);
      contact.frequency = active.output_frequency;
      contact.after_prints = step.prints.size();
      step.contact_prints.push_back(std::move(contact));
    }
  }
}

template <class Request>
std::vector<Request> with_frequency(std::vector<Request> requests, int frequency) {
  for (auto& r : requests) r.frequency = frequency;
  return requests;
}

}  // namespace

void handle_end_step(const Record& record, DeckState& state) {
  check_params(record, {});
  if (!record.lines.empty()) fail(record, record.lines.front(), "unexpected data line");
  StepProgress& progress = *state.open_step;
  if (!progress.has_procedure) {
    throw InputError(progress.step.where, "*STEP", "step has no procedure (*STATIC)");
  }
  model::Step step = std::move(progress.step);
  ActiveLoads& active = state.active;
  resolve_network_pressures(active, state.model.mesh.node_ids);
  step.boundaries = values_of(active.boundaries);
  step.cloads = values_of(active.cloads);
  step.pressures = values_of(active.pressures);
  step.body_loads = values_of(active.body_loads);
  step.temperatures = step_temperatures(state);
  set_step_prints(active, step);
  step.time_points = active.output_time_points;
  // ccx refuses the combination: DIRECT fixes the increments, the points would move them.
  if (step.time_points >= 0 && step.procedure.direct)
    throw InputError(step.where, "*STEP",
                     "TIME POINTS= of an output request in force with *STATIC, DIRECT");
  step.node_files = with_frequency(active.node_files, active.output_frequency);
  step.element_files = with_frequency(active.element_files, active.output_frequency);
  step.contact_files = with_frequency(active.contact_files, active.output_frequency);
  step.contact_pair_active.assign(state.contact_pairs.size(), 1);
  for (int p : active.removed_contact_pairs) step.contact_pair_active[static_cast<std::size_t>(p)] = 0;
  if (!active.removed_elements.empty()) {
    step.element_active.assign(state.model.mesh.elements.size(), 1);
    for (int e : active.removed_elements) step.element_active[static_cast<std::size_t>(e)] = 0;
  }
  state.step_friction_changes.push_back(active.friction_changes);
  state.step_section_changes.push_back(active.section_changes);
  state.step_behavior_changes.push_back(active.behavior_changes);
  active.nlgeom = step.nlgeom;

  const auto& amplitudes = state.model.amplitudes;
  const Real period = step.procedure.period;
  // ccx: at the end of a step a load's reference value is replaced by its actual value and
  // kept constant afterwards, unless its amplitude runs on total time.
  auto freeze = [&](auto& loads) {
    for (auto& [key, load] : loads) {
      if (load.amplitude < 0) continue;
      const model::Amplitude& amp = amplitudes[static_cast<std::size_t>(load.amplitude)];
      if (amp.total_time) continue;
      load.value *= amp.value_at(period);
      load.amplitude = -1;
    }
  };
  freeze(active.boundaries);
  freeze(active.cloads);
  freeze(active.pressures);
  freeze(active.body_loads);
  state.model.steps.push_back(std::move(step));
  state.open_step.reset();
}

void handle_amplitude(const Record& record, DeckState& state) {
  check_params(record, {"NAME", "TIME", "DEFINITION", "VALUE"});
  const std::string name = remove_blanks(to_upper(required_value(record, "NAME")));
  const std::string time = name_value(record, "TIME").value_or("STEPTIME");
  if (time != "STEPTIME" && time != "TOTALTIME") fail(record, "TIME=" + time + " is not valid");
  if (name_value(record, "DEFINITION").value_or("TABULAR") != "TABULAR") {
    fail(record, "only DEFINITION=TABULAR is supported");
  }
  if (name_value(record, "VALUE").value_or("RELATIVE") != "RELATIVE") {
    fail(record, "only VALUE=RELATIVE is supported");
  }
  if (state.amplitude_index.contains(name)) fail(record, "amplitude " + name + " defined twice");
  model::Amplitude amplitude;
  amplitude.name = name;
  amplitude.total_time = time == "TOTALTIME";
  for (const DataLine& line : record.lines) {
    if (line.fields.size() % 2 != 0 || line.fields.size() > 8) {
      fail(record, line, "expected up to four (time, value) pairs per line");
    }
    for (std::size_t i = 0; i < line.fields.size(); i += 2) {
      const Real t = real_field(record, line, i);
      const Real a = real_field(record, line, i + 1);
      if (!amplitude.points.empty() && t < amplitude.points.back().first) {
        fail(record, line, "amplitude times must not decrease");
      }
      amplitude.points.emplace_back(t, a);
    }
  }
  if (amplitude.points.empty()) fail(record, "amplitude has no data points");
  state.amplitude_index[name] = static_cast<int>(state.model.amplitudes.size());
  state.model.amplitudes.push_back(std::move(amplitude));
}

void handle_time_points(const Record& record, DeckState& state) {
  check_params(record, {"NAME", "TIME", "GENERATE"});
  const std::string name = remove_blanks(to_upper(required_value(record, "NAME")));
  const std::string time = name_value(record, "TIME").value_or("STEPTIME");
  if (time != "STEPTIME" && time != "TOTALTIME") fail(record, "TIME=" + time + " is not valid");
  if (state.time_points_index.contains(name)) fail(record, "time points " + name + " defined twice");
  model::TimePoints points;
  points.name = name;
  points.total_time = time == "TOTALTIME";
  const bool generate = has_param(record, "GENERATE");
  for (const DataLine& line : record.lines) {
    std::vector<Real> times;
    if (generate) {
      // start, end, step: start, start + k step up to the end, and the end itself (ccx)
      require_field_count(record, line, 3, 3);
      const Real first = real_field(record, line, 0), last = real_field(record, line, 1),
                 step = real_field(record, line, 2);
      if (step <= 0 || last < first)
        fail(record, line, "expected a start, an end not before it and a positive step");
      const auto n = static_cast<long long>((last - first) / step);
      if (n > 1000000) fail(record, line, "more than a million time points");
      for (long long k = 0; k <= n; ++k) times.push_back(first + static_cast<Real>(k) * step);
      times.push_back(last);
    } else {
      require_field_count(record, line, 1, 8);
      for (std::size_t i = 0; i < line.fields.size(); ++i)
        times.push_back(real_field(record, line, i));
    }
    for (const Real t : times) {
      if (!points.times.empty() && t < points.times.back())
        fail(record, line, "time points must not decrease");
      // a repeated point (GENERATE's end) would be an increment of size zero
      if (points.times.empty() || t > points.times.back()) points.times.push_back(t);
    }
  }
  if (points.times.empty()) fail(record, "no time points given");
  state.time_points_index[name] = static_cast<int>(state.model.time_points.size());
  state.model.time_points.push_back(std::move(points));
}

namespace {

model::EquationTerm equation_term(const Record& record, const DataLine& line, std::size_t at,
                                  const DeckState& state) {
  if (!parse_int(line.fields[at]) && !parse_real(line.fields[at])) {
    fail(record, line, "field " + std::to_string(at + 1) + " ('" + line.fields[at] +
                           "'): node sets are not allowed, give node numbers");
  }
  const int node = node_index_of(state, record, line, int_field(record, line, at));
  const int dof = int_field(record, line, at + 1);
  if (dof < 1 || dof > 3) {
    fail(record, line, "degree of freedom " + std::to_string(dof) + " is not supported (1..3)");
  }
  return model::EquationTerm{node, dof - 1, real_field(record, line, at + 2)};
}

}  // namespace

void handle_equation(const Record& record, DeckState& state) {
  check_params(record, {});
  std::size_t i = 0;
  while (i < record.lines.size()) {
    const DataLine& head = record.lines[i++];
    require_field_count(record, head, 1, 1);
    const int n_terms = int_field(record, head, 0);
    if (n_terms < 1) fail(record, head, "number of terms must be positive");
    model::Equation equation;
    equation.where = head.where;
    while (static_cast<int>(equation.terms.size()) < n_terms) {
      if (i >= record.lines.size()) fail(record, head, "equation ends before all its terms");
      const DataLine& line = record.lines[i++];
      const std::size_t remaining = static_cast<std::size_t>(n_terms) - equation.terms.size();
      if (line.fields.size() % 3 != 0 || line.fields.size() > 12 ||
          line.fields.size() / 3 > remaining) {
        fail(record, line, "expected up to four (node, dof, coefficient) triplets, " +
                               std::to_string(remaining) + " term(s) remaining");
      }
      for (std::size_t at = 0; at < line.fields.size(); at += 3) {
        equation.terms.push_back(equation_term(record, line, at, state));
      }
    }
    if (equation.terms.front().coef == 0) {
      fail(record, head, "the dependent (first) term has a zero coefficient");
    }
    state.model.equations.push_back(std::move(equation));
  }
}

namespace {

/// TYPE=STRESS and TYPE=PLASTIC STRAIN lines: element label, integration point (ccx's order),
/// xx yy zz xy xz yz, into `fields` (per element n_ip x 6). Points not listed keep zeros.
void read_point_tensors(const Record& record, DeckState& state, std::vector<MatX>& fields) {
  model::Model& model = state.model;
  if (fields.size() < model.mesh.elements.size()) fields.resize(model.mesh.elements.size());
  for (const DataLine& line : record.lines) {
    require_field_count(record, line, 8, 8);
    const int label = int_field(record, line, 0);
    const auto found = model.mesh.element_index.find(label);
    if (found == model.mesh.element_index.end())
      fail(record, line, "element " + std::to_string(label) + " is not defined");
    const int e = found->second;
    const int n_ip = element::traits(model.mesh.elements[static_cast<std::size_t>(e)].type).n_ip;
    const int ip = int_field(record, line, 1);
    if (ip < 1 || ip > n_ip)
      fail(record, line, "element " + std::to_string(label) + " has integration points 1 to " +
                             std::to_string(n_ip) + ", not " + std::to_string(ip));
    MatX& field = fields[static_cast<std::size_t>(e)];
    if (field.size() == 0) field = MatX::Zero(n_ip, 6);
    for (int c = 0; c < 6; ++c)
      field(ip - 1, c) = real_field(record, line, 2 + static_cast<std::size_t>(c));
  }
}

}  // namespace

void handle_initial_conditions(const Record& record, DeckState& state) {
  check_params(record, {"TYPE"});
  const std::string type = remove_blanks(to_upper(required_value(record, "TYPE")));
  if (type == "STRESS") {
    if (!state.initial_stress_where) state.initial_stress_where = record.where;
    read_point_tensors(record, state, state.model.initial_stresses);
    return;
  }
  if (type == "PLASTICSTRAIN") {
    if (!state.initial_inelastic_strain_where) state.initial_inelastic_strain_where = record.where;
    read_point_tensors(record, state, state.initial_inelastic_strains);
    return;
  }
  if (type != "TEMPERATURE") fail(record, "TYPE=" + type + " is not supported");
  for (const DataLine& line : record.lines) {
    require_field_count(record, line, 2, 2);
    const Real value = real_field(record, line, 1);
    for (int node : resolve_node_field(state, record, line, 0)) {
      state.initial_temperatures[node] = value;
    }
  }
}

}  // namespace kontakt::inp
