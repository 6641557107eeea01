// End-of-deck resolution of the contact definitions: ccx's defaults derived from the first
// material (K = 50 E, sigma_inf = E / 70000, lambda = E / 2), interaction and surface names,
// and the friction in force per step.
#pragma once

#include "inp/deck_state.hpp"

namespace kontakt::inp {

/// A stick slope lambda <= 0 becomes ccx's default E / 2 (E: Young's modulus of the first
/// material in the deck), with a warning at `where`. Throws InputError when there is no E.
void resolve_stick_slope(DeckState& state, const SourceLoc& where, model::Friction& friction);

/// Fills in ccx's defaults of a *SURFACE BEHAVIOR given in a step (after *CHANGE SURFACE
/// BEHAVIOR) for `interaction`; the contact pairs are all known by then.
void resolve_changed_behavior(DeckState& state, const SourceLoc& where, int interaction,
                              model::SurfaceBehavior& behavior);

/// Fills in the defaults of every interaction, resolves the contact pairs into
/// Model::contact_pairs and sets Step::interaction_friction and interaction_behavior. Needs the surfaces and node sets
/// of the model already built. Throws InputError naming the card of the first problem.
void resolve_contact(DeckState& state);

}  // namespace kontakt::inp
