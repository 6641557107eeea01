#include "inp/keyword_registry.hpp"

#include "inp/keyword_handlers.hpp"
#include "inp/record_access.hpp"

namespace kontakt::inp {

namespace {

constexpr auto M = Placement::Model;
constexpr auto S = Placement::Step;
constexpr auto A = Placement::Anywhere;
constexpr auto None = Block::None;
constexpr auto Mat = Block::Material;
constexpr auto Inter = Block::Interaction;

// Sized by its initialiser: a declared size larger than the list would add entries with an
// empty key and no handler.
constexpr KeywordSpec kKeywords[] = {
    {"HEADING", M, None, handle_heading},
    {"NODE", M, None, handle_node},
    {"ELEMENT", M, None, handle_element},
    {"NSET", M, None, handle_nset},
    {"ELSET", M, None, handle_elset},
    {"SURFACE", M, None, handle_surface},
    {"MATERIAL", M, Mat, handle_material},
    {"ELASTIC", M, Mat, handle_elastic},
    {"HYPERELASTIC", M, Mat, handle_hyperelastic},
    {"HYPERFOAM", M, Mat, handle_hyperfoam},
    {"DEFORMATIONPLASTICITY", M, Mat, handle_deformation_plasticity},
    {"DENSITY", M, Mat, handle_density},
    {"PLASTIC", M, Mat, handle_plastic},
    {"CYCLICHARDENING", M, Mat, handle_cyclic_hardening},
    {"EXPANSION", M, Mat, handle_expansion},
    {"SOLIDSECTION", M, None, handle_solid_section},
    {"MEMBRANE", M, None, handle_membrane},
    {"SURFACEINTERACTION", M, Inter, handle_surface_interaction},
    {"SURFACEBEHAVIOR", A, Inter, handle_surface_behavior},  // in a step: after *CHANGE ...
    {"FRICTION", A, Inter, handle_friction},  // in a step: after *CHANGE FRICTION
    {"CONTACTPAIR", M, None, handle_contact_pair},
    {"TIE", M, None, handle_tie},
    {"CYCLICSYMMETRYMODEL", M, None, handle_cyclic_symmetry_model},
    {"TRANSFORM", M, None, handle_transform},
    {"PRE-TENSIONSECTION", M, None, handle_pretension_section},
    {"ORIENTATION", M, None, handle_orientation},
    {"INITIALCONDITIONS", M, None, handle_initial_conditions},
    {"EQUATION", M, None, handle_equation},
    {"RIGIDBODY", M, None, handle_rigid_body},
    {"MPC", M, None, handle_mpc},
    {"SPRING", M, None, handle_spring},
    {"GAP", M, None, handle_gap},
    {"DISTRIBUTINGCOUPLING", M, None, handle_distributing_coupling},
    {"AMPLITUDE", A, None, handle_amplitude},
    {"TIMEPOINTS", M, None, handle_time_points},
    {"BOUNDARY", A, None, handle_boundary},
    {"STEP", M, None, handle_step},  // opens a step: checked as model-level
    {"STATIC", S, None, handle_static},
    {"CONTROLS", S, None, handle_controls},
    {"CHANGEFRICTION", S, Inter, handle_change_friction},
    {"MODELCHANGE", S, None, handle_model_change},
    {"CHANGESOLIDSECTION", S, None, handle_change_solid_section},
    {"CHANGESURFACEBEHAVIOR", S, Inter, handle_change_surface_behavior},
    {"ENDSTEP", S, None, handle_end_step},
    {"CLOAD", S, None, handle_cload},
    {"DLOAD", S, None, handle_dload},
    {"TEMPERATURE", S, None, handle_temperature},
    {"NODEPRINT", S, None, handle_node_print},
    {"ELPRINT", S, None, handle_el_print},
    {"NODEFILE", S, None, handle_node_file},
    {"NODEOUTPUT", S, None, handle_node_file},
    {"ELFILE", S, None, handle_el_file},
    {"ELEMENTOUTPUT", S, None, handle_el_file},
    {"OUTPUT", S, None, handle_output},
    {"CONTACTPRINT", S, None, handle_contact_print},
    {"CONTACTFILE", S, None, handle_contact_file},
    {"CONTACTOUTPUT", S, None, handle_contact_file},
    // Only change how results are written, never the solution: accepted with a warning.
    {"FILEFORMAT", A, None, handle_ignored_output},
};

constexpr bool every_keyword_has_a_handler() {
  for (const KeywordSpec& spec : kKeywords)
    if (spec.key.empty() || spec.handler == nullptr) return false;
  return true;
}
static_assert(every_keyword_has_a_handler());

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
    if (spec->block != Block::Material) state.current_material = -1;
    if (spec->block != Block::Interaction) state.current_interaction = -1;
    spec->handler(record, state);
  }
}

}  // namespace kontakt::inp
