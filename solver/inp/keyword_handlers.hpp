// Handlers, one per keyword; grouped by file: kw_mesh, kw_material, kw_contact, kw_tie,
// kw_step, kw_controls, kw_loads, kw_output. Each throws InputError for malformed input.
#pragma once

#include "inp/deck_state.hpp"

namespace kontakt::inp {

// kw_mesh.cpp
void handle_heading(const Record&, DeckState&);
void handle_node(const Record&, DeckState&);
void handle_element(const Record&, DeckState&);
void handle_nset(const Record&, DeckState&);
void handle_elset(const Record&, DeckState&);
void handle_surface(const Record&, DeckState&);

// kw_material.cpp
void handle_material(const Record&, DeckState&);
void handle_elastic(const Record&, DeckState&);
void handle_hyperelastic(const Record&, DeckState&);
void handle_membrane(const Record&, DeckState&);
void handle_hyperfoam(const Record&, DeckState&);
void handle_deformation_plasticity(const Record&, DeckState&);
void handle_change_solid_section(const Record&, DeckState&);
void handle_plastic(const Record&, DeckState&);
void handle_cyclic_hardening(const Record&, DeckState&);
void handle_density(const Record&, DeckState&);
void handle_expansion(const Record&, DeckState&);
void handle_solid_section(const Record&, DeckState&);

// kw_contact.cpp
void handle_surface_interaction(const Record&, DeckState&);
void handle_surface_behavior(const Record&, DeckState&);
void handle_friction(const Record&, DeckState&);
void handle_change_friction(const Record&, DeckState&);
void handle_change_surface_behavior(const Record&, DeckState&);
void handle_contact_pair(const Record&, DeckState&);

// kw_tie.cpp
void handle_tie(const Record&, DeckState&);
void handle_cyclic_symmetry_model(const Record&, DeckState&);

// kw_model_change.cpp
void handle_model_change(const Record&, DeckState&);

// kw_coupling.cpp
void handle_distributing_coupling(const Record&, DeckState&);

// kw_connector.cpp
void handle_spring(const Record&, DeckState&);
void handle_gap(const Record&, DeckState&);

// kw_nonlinear_constraint.cpp
void handle_rigid_body(const Record&, DeckState&);
void handle_mpc(const Record&, DeckState&);

// kw_pretension.cpp
void handle_pretension_section(const Record&, DeckState&);

// kw_transform.cpp
void handle_transform(const Record&, DeckState&);
/// The points a and b of a *TRANSFORM or *ORIENTATION: its one data line of six numbers.
const DataLine& read_frame_points(const Record&, model::Transform& frame);
void handle_orientation(const Record&, DeckState&);

// kw_step.cpp
void handle_step(const Record&, DeckState&);
void handle_static(const Record&, DeckState&);
void handle_end_step(const Record&, DeckState&);
void handle_amplitude(const Record&, DeckState&);
void handle_time_points(const Record&, DeckState&);
void handle_equation(const Record&, DeckState&);
void handle_initial_conditions(const Record&, DeckState&);

// kw_controls.cpp
void handle_controls(const Record&, DeckState&);

// kw_loads.cpp
void handle_boundary(const Record&, DeckState&);
void handle_cload(const Record&, DeckState&);
void handle_dload(const Record&, DeckState&);
void handle_temperature(const Record&, DeckState&);

// kw_output.cpp
void handle_node_print(const Record&, DeckState&);
void handle_el_print(const Record&, DeckState&);
void handle_node_file(const Record&, DeckState&);
void handle_el_file(const Record&, DeckState&);
void handle_output(const Record&, DeckState&);
void handle_contact_print(const Record&, DeckState&);
void handle_contact_file(const Record&, DeckState&);
void handle_ignored_output(const Record&, DeckState&);

}  // namespace kontakt::inp
