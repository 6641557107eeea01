#include "inp/tie_builder.hpp"

#include <algorithm>

namespace kontakt::inp {

namespace {

const model::Surface& tie_surface(const DeckState& state, const model::Tie& tie,
                                  const std::string& name, const std::string& role) {
  const auto found = state.model.surfaces.find(name);
  if (found == state.model.surfaces.end())
    throw InputError(tie.where, "*TIE",
                     "tie " + tie.name + ": " + role + " surface " + name + " is not defined");
  if (found->second.faces.empty() && found->second.nodes.empty())
    throw InputError(tie.where, "*TIE",
                     "tie " + tie.name + ": " + role + " surface " + name + " is empty");
  return found->second;
}

}  // namespace

void resolve_ties(const DeckState& state) {
  for (const model::Tie& tie : state.model.ties) {
    tie_surface(state, tie, tie.slave, "slave");
    const model::Surface& master = tie_surface(state, tie, tie.master, "master");
    if (tie.cyclic) {  // node to node: either side may be a node surface
      if (std::none_of(state.model.cyclic_symmetry.begin(), state.model.cyclic_symmetry.end(),
                       [&](const model::CyclicSymmetry& c) { return c.tie == tie.name; }))
        throw InputError(tie.where, "*TIE",
                         "CYCLIC SYMMETRY tie " + tie.name +
                             " has no *CYCLIC SYMMETRY MODEL (N= sectors and the axis)");
    } else if (master.kind != model::Surface::Kind::ElementFaces)
      throw InputError(tie.where, "*TIE",
                       "tie " + tie.name + ": master surface " + tie.master +
                           " must be made of element faces (a node surface has no faces to "
                           "tie to)");
    const model::Surface& slave = state.model.surfaces.at(tie.slave);
    if (tie.scheme && slave.kind != model::Surface::Kind::ElementFaces)
      throw InputError(tie.where, "*TIE",
                       "tie " + tie.name + ": SCHEME= ties through surface-to-surface contact, "
                       "which needs element faces on the slave side; " + tie.slave +
                       " is a node surface");
    if (tie.slave == tie.master)
      throw InputError(tie.where, "*TIE",
                       "tie " + tie.name + ": surface " + tie.slave +
                           " is both slave and master");
  }
}

}  // namespace kontakt::inp
