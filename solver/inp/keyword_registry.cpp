#include "inp/keyword_registry.hpp"

#include <array>

#include "inp/keyword_handlers.hpp"
#include "inp/record_access.hpp"

namespace kontakt::inp {

namespace {

constexpr auto M = Placement::Model;
constexpr auto S = Placement::Step;
constexpr auto A = Placement::Anywhere;
constexpr auto Ends = MaterialContext::Ends;
constexpr auto Cont = MaterialContext::Continues;

constexpr std::array<KeywordSpec, 31> kKeywords{{
    {"HEADING", M, Ends, handle_heading},
    {"NODE", M, Ends, handle_node},
    {"ELEMENT", M, Ends, handle_element},
    {"NSET", M, Ends, handle_nset},
    {"ELSET", M, Ends, handle_elset},
    {"SURFACE", M, Ends, handle_surface},
    {"MATERIAL", M, Cont, handle_material},
    {"ELASTIC", M, Cont, handle_elastic},
    {"DENSITY", M, Cont, handle_density},
    {"PLASTIC", M, Cont, handle_plastic},
    {"EXPANSION", M, Cont, handle_expansion},
    {"SOLIDSECTION", M, Ends, handle_solid_section},
    {"INITIALCONDITIONS", M, Ends, handle_initial_conditions},
    {"EQUATION", M, Ends, handle_equation},
    {"AMPLITUDE", A, Ends, handle_amplitude},
    {"BOUNDARY", A, Ends, handle_boundary},
    {"STEP", M, Ends, handle_step},  // opens a step: checked as model-level
    {"STATIC", S, Ends, handle_static},
    {"CONTROLS", S, Ends, handle_controls},
    {"ENDSTEP", S, Ends, handle_end_step},
    {"CLOAD", S, Ends, handle_cload},
    {"DLOAD", S, Ends, handle_dload},
    {"TEMPERATURE", S, Ends, handle_temperature},
    {"NODEPRINT", S, Ends, handle_node_print},
    {"ELPRINT", S, Ends, handle_el_print},
    {"NODEFILE", S, Ends, handle_node_file},
    {"NODEOUTPUT", S, Ends, handle_node_file},
    {"ELFILE", S, Ends, handle_el_file},
    {"ELEMENTOUTPUT", S, Ends, handle_el_file},
    {"OUTPUT", S, Ends, handle_output},
    // Only change how results are written, never the solution: accepted with a warning.
    {"FILEFORMAT", A, Ends, handle_ignored_output},
}};

void check_placement(const Record& record, const KeywordSpec& spec, const DeckState& state) {
  const bool in_step = state.open_step.has_value();
  if (spec.placement == Placement::Step && !in_step) {
    fail(record, "only allowed between *STEP and *END STEP");
  }
  if (spec.placement == Placement::Model && in_step) {
    fail(record, record.key == "STEP" ? "*STEP inside a step (missing *END STEP?)"
                                      : "not allowed within a step");
  }
  if (spec.placement == Placement::Model && state.any_step_seen && record.key != "STEP") {
    fail(record, "model definition keyword after the first *STEP");
  }
}

}  // namespace

const KeywordSpec* find_keyword(std::string_view key) {
  for (const KeywordSpec& spec : kKeywords) {
    if (spec.key == key) return &spec;
  }
  return nullptr;
}

void dispatch_records(const std::vector<Record>& records, DeckState& state) {
  for (const Record& record : records) {
    const KeywordSpec* spec = find_keyword(record.key);
    if (spec == nullptr) fail(record, "keyword not supported");
    check_placement(record, *spec, state);
    if (spec->material == MaterialContext::Ends) state.current_material = -1;
    spec->handler(record, state);
  }
}

}  // namespace kontakt::inp
