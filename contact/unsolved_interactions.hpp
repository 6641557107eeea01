// Contact input the reader accepts for the friction issue but the solver does not solve yet.
// Solving it frictionless would be a silent wrong answer, so a job with it is an input error.
#pragma once

#include "model/model.hpp"

namespace kontakt::contact {

/// Throws InputError at the card when a contact pair uses a TIED interaction, or an
/// interaction with friction in any step (*FRICTION or *CHANGE FRICTION).
void reject_unsolved_interactions(const model::Model& model);

}  // namespace kontakt::contact
