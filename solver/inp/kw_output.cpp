// Output requests. ccx rules (manual, *NODE PRINT/*EL PRINT/*NODE FILE/*EL FILE): the first
// card of a kind within a step wipes the selections of earlier steps; without one, the previous
// step's selections apply. The last FREQUENCY= given applies to all outputs and persists.
#include "inp/keyword_handlers.hpp"
#include "inp/model_builder.hpp"
#include "inp/record_access.hpp"

namespace kontakt::inp {

namespace {

std::vector<std::string> output_variables(const Record& record) {
  std::vector<std::string> variables;
  for (const DataLine& line : record.lines) {
    for (const std::string& field : line.fields) {
      if (field.empty()) continue;
      variables.push_back(remove_blanks(to_upper(field)));
    }
  }
  return variables;
}

void read_frequency(const Record& record, DeckState& state) {
  if (const std::optional<int> frequency = int_param(record, "FREQUENCY")) {
    if (*frequency < 0) fail(record, "FREQUENCY= must not be negative");
    state.active.output_frequency = *frequency;
  }
}

/// True the first time `kind` appears in the open step.
bool first_in_step(DeckState& state, const std::string& kind) {
  return state.open_step->seen.insert(kind).second;
}

bool yes_no(const Record& record, std::string_view name, bool fallback) {
  const std::optional<std::string> value = name_value(record, name);
  if (!value) return fallback;
  if (*value != "YES" && *value != "NO") fail(record, std::string(name) + "= must be YES or NO");
  return *value == "YES";
}

model::PrintRequest print_request(const Record& record, DeckState& state,
                                  model::PrintRequest::Kind kind, std::string_view set_param) {
  check_params(record, {set_param, "TOTALS", "GLOBAL", "FREQUENCY"});
  model::PrintRequest request;
  request.kind = kind;
  request.where = record.where;
  request.set = remove_blanks(to_upper(required_value(record, set_param)));
  const auto& sets = kind == model::PrintRequest::Kind::Node ? state.node_sets
                                                             : state.element_sets;
  if (!sets.contains(request.set)) fail(record, "set " + request.set + " is not defined");
  const std::string totals = name_value(record, "TOTALS").value_or("NO");
  if (totals == "YES") request.totals = model::Totals::Yes;
  else if (totals == "ONLY") request.totals = model::Totals::Only;
  else if (totals != "NO") fail(record, "TOTALS=" + totals + ": expected YES, ONLY or NO");
  request.global = yes_no(record, "GLOBAL", false);  // ccx default GLOBAL=NO for prints
  read_frequency(record, state);
  request.variables = output_variables(record);
  if (request.variables.empty()) fail(record, "no output variables given");
  return request;
}

/// Options of file output that only change how the file is written: accepted, noted.
void warn_file_layout_params(const Record& record, DeckState& state) {
  for (std::string_view name : {"OUTPUT", "NSET", "ELSET"}) {
    if (has_param(record, name)) {
      state.warn(record.where, record.keyword, std::string(name) + "= ignored");
    }
  }
}

model::FileRequest file_request(const Record& record, DeckState& state) {
  check_params(record, {"FREQUENCY", "GLOBAL", "OUTPUT", "NSET", "ELSET"});
  (void)yes_no(record, "GLOBAL", true);  // no transforms: global and local coincide
  warn_file_layout_params(record, state);
  read_frequency(record, state);
  model::FileRequest request;
  request.variables = output_variables(record);
  if (request.variables.empty()) fail(record, "no output variables given");
  return request;
}

}  // namespace

void handle_node_print(const Record& record, DeckState& state) {
  auto request = print_request(record, state, model::PrintRequest::Kind::Node, "NSET");
  if (first_in_step(state, "NODEPRINT")) state.active.node_prints.clear();
  state.active.node_prints.push_back(std::move(request));
}

void handle_el_print(const Record& record, DeckState& state) {
  auto request = print_request(record, state, model::PrintRequest::Kind::Element, "ELSET");
  if (first_in_step(state, "ELPRINT")) state.active.element_prints.clear();
  state.active.element_prints.push_back(std::move(request));
}

void handle_node_file(const Record& record, DeckState& state) {
  auto request = file_request(record, state);
  // *NODE OUTPUT is ccx's synonym of *NODE FILE: one kind for the wipe rule.
  if (first_in_step(state, "NODEFILE")) state.active.node_files.clear();
  state.active.node_files.push_back(std::move(request));
}

void handle_el_file(const Record& record, DeckState& state) {
  auto request = file_request(record, state);
  if (first_in_step(state, "ELFILE")) state.active.element_files.clear();
  state.active.element_files.push_back(std::move(request));
}

void handle_output(const Record& record, DeckState& state) {
  check_params(record, {"FIELD", "HISTORY", "FREQUENCY"});
  if (!record.lines.empty()) fail(record, record.lines.front(), "unexpected data line");
  read_frequency(record, state);
}

void handle_ignored_output(const Record& record, DeckState& state) {
  state.warn(record.where, record.keyword, "output formatting keyword ignored");
}

}  // namespace kontakt::inp
