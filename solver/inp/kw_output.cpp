// Output requests. ccx rules (manual, *NODE PRINT/*EL PRINT/*CONTACT PRINT/*NODE FILE/*EL FILE/
// *CONTACT FILE): the first card of a kind within a step wipes the selections of earlier steps;
// without one, the previous step's selections apply. The last FREQUENCY= given applies to all
// outputs and persists; TIME POINTS= names a *TIME POINTS sequence that replaces it (output at
// those times and the step end) until a FREQUENCY= comes. Node, element and contact prints share one list, whose order is the
// order of the .dat blocks.
#include <algorithm>
#include <array>

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
    if (has_param(record, "TIMEPOINTS"))
      fail(record, "FREQUENCY= and TIME POINTS= exclude each other");
    state.active.output_frequency = *frequency;
    state.active.output_time_points = -1;
  }
  if (const std::optional<std::string> name = name_value(record, "TIMEPOINTS")) {
    const auto found = state.time_points_index.find(*name);
    if (found == state.time_points_index.end())
      fail(record, "time points " + *name + " are not defined (*TIME POINTS before the steps)");
    state.active.output_time_points = found->second;
    state.active.output_frequency = 1;
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
  check_params(record, {set_param, "TOTALS", "GLOBAL", "FREQUENCY", "TIMEPOINTS"});
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
  for (std::string_view name : {"OUTPUT", "NSET", "ELSET", "POSITION"}) {
    if (has_param(record, name)) {
      state.warn(record.where, record.keyword, std::string(name) + "= ignored");
    }
  }
}

model::FileRequest file_request(const Record& record, DeckState& state) {
  check_params(record,
               {"FREQUENCY", "TIMEPOINTS", "GLOBAL", "OUTPUT", "NSET", "ELSET", "POSITION"});
  (void)yes_no(record, "GLOBAL", true);  // *NODE FILE checks it against *TRANSFORM
  warn_file_layout_params(record, state);
  read_frequency(record, state);
  model::FileRequest request;
  // No variable line is allowed: as ccx 2.20 does, the card then only wipes the step's
  // earlier selection of its kind (nothing is written for it from this step on).
  request.variables = output_variables(record);
  return request;
}

constexpr std::array<std::string_view, 3> kContactVariables{"CDIS", "CSTR", "CELS"};

/// The first *NODE PRINT (or *EL PRINT) of a step removes the earlier node (element) prints.
void add_print(DeckState& state, const std::string& kind, model::PrintRequest request) {
  const model::PrintRequest::Kind wiped = request.kind;
  if (first_in_step(state, kind)) {
    std::erase_if(state.active.prints, [&](const PrintEntry& entry) {
      const auto* print = std::get_if<model::PrintRequest>(&entry);
      return print != nullptr && print->kind == wiped;
    });
  }
  state.active.prints.emplace_back(std::move(request));
}

/// Contact output variables. ccx compares the first four letters (CDISP = CDIS, CSTRESS =
/// CSTR; CF, CFN, CFS are whole names). Variables ccx has but Kontakt does not write
/// (`not_written`) are dropped with a warning, so ccx decks run; anything else is a typo and an
/// error.
std::vector<std::string> contact_variables(const Record& record, DeckState& state,
                                           std::initializer_list<std::string_view> not_written) {
  const auto same = [](const std::string& name, std::string_view label) {
    return label.size() == 4 ? name.starts_with(label) : name == label;
  };
  std::vector<std::string> variables;
  bool any = false;
  for (const DataLine& line : record.lines) {
    for (const std::string& field : line.fields) {
      if (field.empty()) continue;
      any = true;
      const std::string name = remove_blanks(to_upper(field));
      const auto written = std::find_if(kContactVariables.begin(), kContactVariables.end(),
                                        [&](std::string_view v) { return same(name, v); });
      if (written != kContactVariables.end()) {
        if (std::find(variables.begin(), variables.end(), *written) == variables.end())
          variables.emplace_back(*written);
      } else if (std::any_of(not_written.begin(), not_written.end(),
                             [&](std::string_view v) { return same(name, v); })) {
        state.warn(line.where, record.keyword, name + " is not written by Kontakt; dropped");
      } else {
        fail(record, line, "unknown contact output variable " + name + " (CDIS, CSTR or CELS)");
      }
    }
  }
  if (!any) fail(record, "no output variables given");
  if (state.contact_pairs.empty())
    state.warn(record.where, record.keyword, "the deck has no *CONTACT PAIR: nothing to write");
  return variables;
}

}  // namespace

void handle_node_print(const Record& record, DeckState& state) {
  add_print(state, "NODEPRINT",
            print_request(record, state, model::PrintRequest::Kind::Node, "NSET"));
}

void handle_el_print(const Record& record, DeckState& state) {
  add_print(state, "ELPRINT",
            print_request(record, state, model::PrintRequest::Kind::Element, "ELSET"));
}

void handle_contact_print(const Record& record, DeckState& state) {
  check_params(record, {"FREQUENCY", "TIMEPOINTS", "TOTALS", "NSET", "SET", "SLAVE", "MASTER"});
  // ccx ignores NSET= and SET= here too (friction1, thread have them); SLAVE= and MASTER=
  // select the surfaces of CF, CFN and CFS, which Kontakt does not print.
  for (std::string_view name : {"NSET", "SET", "SLAVE", "MASTER"})
    if (has_param(record, name))
      state.warn(record.where, record.keyword, std::string(name) + "= ignored");
  model::ContactRequest request;
  request.where = record.where;
  const std::string totals = name_value(record, "TOTALS").value_or("NO");
  if (totals != "YES" && totals != "ONLY" && totals != "NO")
    fail(record, "TOTALS=" + totals + ": expected YES, ONLY or NO");
  request.totals = totals == "YES";
  request.totals_only = totals == "ONLY";
  read_frequency(record, state);
  request.variables = contact_variables(record, state, {"CNUM", "CF", "CFN", "CFS"});
  if (first_in_step(state, "CONTACTPRINT"))
    std::erase_if(state.active.prints, [](const PrintEntry& entry) {
      return std::holds_alternative<model::ContactRequest>(entry);
    });
  if (!request.variables.empty()) state.active.prints.emplace_back(std::move(request));
}

void handle_contact_file(const Record& record, DeckState& state) {
  check_params(record, {"FREQUENCY", "TIMEPOINTS", "GLOBAL", "OUTPUT", "NSET",
                        "LASTITERATIONS", "CONTACTELEMENTS"});
  (void)yes_no(record, "GLOBAL", true);
  warn_file_layout_params(record, state);
  // ccx's debugging files (ResultsForLastIterations.frd, contactelements.inp).
  for (std::string_view name : {"LASTITERATIONS", "CONTACTELEMENTS"})
    if (has_param(record, name))
      state.warn(record.where, record.keyword, std::string(name) + " ignored");
  model::ContactRequest request;
  request.where = record.where;
  read_frequency(record, state);
  request.variables = contact_variables(record, state, {"PCON"});
  // *CONTACT OUTPUT is ccx's synonym of *CONTACT FILE: one kind for the wipe rule.
  if (first_in_step(state, "CONTACTFILE")) state.active.contact_files.clear();
  if (!request.variables.empty()) state.active.contact_files.push_back(std::move(request));
}

void handle_node_file(const Record& record, DeckState& state) {
  auto request = file_request(record, state);
  if (!yes_no(record, "GLOBAL", true) && !state.model.local_frames.empty())
    fail(record, "GLOBAL=NO: results files hold global components only (*TRANSFORM nodes "
                 "print local components with *NODE PRINT)");
  // *NODE OUTPUT is ccx's synonym of *NODE FILE: one kind for the wipe rule.
  if (first_in_step(state, "NODEFILE")) state.active.node_files.clear();
  if (!request.variables.empty()) state.active.node_files.push_back(std::move(request));
}

void handle_el_file(const Record& record, DeckState& state) {
  auto request = file_request(record, state);
  if (first_in_step(state, "ELFILE")) state.active.element_files.clear();
  if (!request.variables.empty()) state.active.element_files.push_back(std::move(request));
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
