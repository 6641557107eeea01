#include "contact/unsolved_interactions.hpp"

#include <sstream>
#include <string>

#include "core/error.hpp"

namespace kontakt::contact {

void reject_unsolved_interactions(const model::Model& model) {
  for (const model::ContactPair& pair : model.contact_pairs) {
    const auto index = static_cast<std::size_t>(pair.interaction);
    const model::SurfaceInteraction& interaction = model.interactions.at(index);
    if (interaction.behavior.law == model::SurfaceBehavior::Law::Tied)
      throw InputError(interaction.where, "*SURFACE INTERACTION",
                       "interaction " + interaction.name +
                           " is TIED: tied contact is not solved yet (Kontakt solves "
                           "frictionless normal contact only)");
    for (std::size_t s = 0; s < model.steps.size(); ++s) {
      const auto& frictions = model.steps[s].interaction_friction;
      if (index >= frictions.size() || !frictions[index]) continue;
      std::ostringstream mu;
      mu << frictions[index]->mu;
      throw InputError(frictions[index]->where, "*FRICTION",
                       "friction (mu = " + mu.str() +
                           " in interaction " + interaction.name + ", step " +
                           std::to_string(s + 1) +
                           ") is not solved yet: Kontakt solves frictionless contact only; "
                           "remove the *FRICTION card to analyse the pair without friction");
    }
  }
}

}  // namespace kontakt::contact
