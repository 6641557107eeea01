// End-of-deck checks of the *TIE cards: their surfaces exist, are not empty, and the master is
// made of element faces (ccx: the slave may be a node or a face surface).
#pragma once

#include "inp/deck_state.hpp"

namespace kontakt::inp {

/// Throws InputError at the tie's data line for the first surface that does not qualify.
/// Needs the model's surfaces already built.
void resolve_ties(const DeckState& state);

}  // namespace kontakt::inp
