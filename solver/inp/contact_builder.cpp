#include "inp/contact_builder.hpp"

#include <cstdio>
#include <set>

namespace kontakt::inp {

namespace {

using Law = model::SurfaceBehavior::Law;
using PairType = model::ContactPair::Type;

std::string number(Real value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

/// Young's modulus of the first material of the deck: ccx scales its contact defaults with it.
Real first_young(const DeckState& state, const SourceLoc& where, const std::string& keyword,
                 const std::string& what) {
  const auto& materials = state.model.materials;
  if (materials.empty())
    throw InputError(where, keyword, what + " needs the first material's Young's modulus; the "
                                            "deck has no *MATERIAL");
  if (materials.front().elastic.empty())
    throw InputError(where, keyword, what + " needs the first material's Young's modulus; " +
                                         materials.front().name +
                                         (materials.front().anisotropic.empty()
                                              ? " has no *ELASTIC"
                                              : " is not isotropic (*ELASTIC, TYPE=ISO)"));
  return materials.front().elastic.rows.front()[0];  // ccx: the first row of a table
}

std::string default_origin(const DeckState& state) {
  const model::Material& first = state.model.materials.front();
  return "E = " + number(first.elastic.rows.front()[0]) + " of " + first.name +
         ", the first material";
}

/// ccx's *SURFACE BEHAVIOR defaults: c0 <= 0 -> 1e-3; LINEAR/TIED K <= 0 -> 50 E; LINEAR
/// sigma_inf <= 0 -> E / 70000; TIED has no default K. The warning names the defaults that
/// matter: sigma_inf only acts in node-to-surface contact.
void resolve_behavior(DeckState& state, const SourceLoc& where, model::SurfaceBehavior& b,
                      bool tension_matters) {
  if (b.clearance_c0 <= 0) b.clearance_c0 = 1e-3;
  if (b.law != Law::Linear && b.law != Law::Tied) return;
  const bool default_k = b.stiffness <= 0;
  if (b.law == Law::Tied && default_k)
    throw InputError(where, "*SURFACE BEHAVIOR",
                     "PRESSURE-OVERCLOSURE=TIED needs its stiffness K on a data line (ccx would "
                     "silently solve the card as LINEAR)");
  const bool default_tension = b.law == Law::Linear && b.tension_limit <= 0;
  if (!default_k && !default_tension) return;
  const Real young = first_young(state, where, "*SURFACE BEHAVIOR", "the default stiffness");
  std::string used;
  if (default_k) {
    b.stiffness = 50 * young;
    used = "K = 50 E = " + number(b.stiffness);
  }
  if (default_tension) {
    b.tension_limit = young / 70000;
    if (tension_matters)
      used += std::string(used.empty() ? "" : ", ") + "sigma_inf = E / 70000 = " +
              number(b.tension_limit);
  }
  if (!used.empty())
    state.warn(where, "*SURFACE BEHAVIOR",
               "defaults used: " + used + " (" + default_origin(state) + ")");
}

/// Interactions used by node-to-surface pairs (where a LINEAR law's tension tail acts).
std::set<std::string> node_to_surface_interactions(const DeckState& state) {
  std::set<std::string> names;
  for (const RawContactPair& raw : state.contact_pairs)
    if (raw.pair.type == PairType::NodeToSurface) names.insert(raw.interaction);
  return names;
}

void resolve_interaction(DeckState& state, std::size_t index, bool tension_matters) {
  model::SurfaceInteraction& interaction = state.model.interactions[index];
  const RawInteraction& raw = state.raw_interactions[index];
  if (!raw.has_behavior) return;  // an error only when a contact pair uses it
  resolve_behavior(state, raw.behavior_where, interaction.behavior, tension_matters);
  if (interaction.friction) resolve_stick_slope(state, raw.friction_where, *interaction.friction);
  if (interaction.behavior.law == Law::Tied && !interaction.friction)
    throw InputError(raw.behavior_where, "*SURFACE BEHAVIOR",
                     "PRESSURE-OVERCLOSURE=TIED needs a *FRICTION card in interaction " +
                         interaction.name + " (its stick slope is the tangential stiffness)");
}

const model::Surface& pair_surface(const DeckState& state, const model::ContactPair& pair,
                                   const std::string& name, const std::string& role) {
  const auto found = state.model.surfaces.find(name);
  if (found == state.model.surfaces.end())
    throw InputError(pair.where, "*CONTACT PAIR", role + " surface " + name + " is not defined");
  if (found->second.faces.empty() && found->second.nodes.empty())
    throw InputError(pair.where, "*CONTACT PAIR", role + " surface " + name + " is empty");
  return found->second;
}

model::ContactPair resolve_pair(const DeckState& state, const RawContactPair& raw) {
  model::ContactPair pair = raw.pair;
  const auto fail_at = [&](const std::string& message) {
    throw InputError(pair.where, "*CONTACT PAIR", message);
  };
  const auto found = state.interaction_index.find(raw.interaction);
  if (found == state.interaction_index.end())
    fail_at("surface interaction " + raw.interaction + " is not defined");
  pair.interaction = found->second;
  const auto index = static_cast<std::size_t>(found->second);
  const model::SurfaceInteraction& interaction = state.model.interactions[index];
  if (!state.raw_interactions[index].has_behavior)
    throw InputError(interaction.where, "*SURFACE INTERACTION",
                     "interaction " + interaction.name +
                         " has no *SURFACE BEHAVIOR, which contact needs");

  // A node-to-surface slave named for both node and element-face surfaces is the nodes one.
  if (pair.type == PairType::NodeToSurface && state.surfaces.contains(node_surface_key(pair.slave)))
    pair.slave = node_surface_key(pair.slave);
  const model::Surface& slave = pair_surface(state, pair, pair.slave, "slave");
  const model::Surface& master = pair_surface(state, pair, pair.master, "master");
  if (master.kind != model::Surface::Kind::ElementFaces)
    fail_at("master surface " + pair.master + " must be made of element faces");
  if (slave.kind == model::Surface::Kind::Nodes) {
    if (pair.type == PairType::SurfaceToSurface)
      fail_at("SURFACE TO SURFACE contact needs element faces on the slave side too; " +
              pair.slave + " is a node surface");
    if (pair.scheme.kind != model::ContactScheme::Kind::NodeToSurface)
      fail_at("SCHEME=" + model::contact_scheme_name(pair.scheme) +
              " integrates over slave faces; slave surface " + pair.slave +
              " is a node surface");
  }
  const model::SurfaceBehavior& behavior = interaction.behavior;
  if (pair.type == PairType::NodeToSurface && behavior.law == Law::Tied)
    fail_at("PRESSURE-OVERCLOSURE=TIED (interaction " + interaction.name +
            ") is only available for SURFACE TO SURFACE contact");
  if (pair.type == PairType::NodeToSurface && behavior.law == Law::Linear &&
      behavior.tension_limit < 1e-30)
    fail_at("NODE TO SURFACE contact with a LINEAR law needs a tension at large clearances "
            "above 1e-30 (interaction " + interaction.name + ")");
  if (!pair.adjust_set.empty() && !state.model.node_sets.contains(pair.adjust_set))
    fail_at("ADJUST node set " + pair.adjust_set + " is not defined");
  return pair;
}

/// Step::interaction_friction and interaction_behavior: the model's, as changed so far. A
/// TIED behavior needs a *FRICTION in every step it is in force (its stick slope).
void set_step_interactions(DeckState& state) {
  auto& steps = state.model.steps;
  const auto& interactions = state.model.interactions;
  for (std::size_t s = 0; s < steps.size(); ++s) {
    const auto& friction_changes = state.step_friction_changes[s];
    const auto& behavior_changes = state.step_behavior_changes[s];
    auto& friction = steps[s].interaction_friction;
    auto& behavior = steps[s].interaction_behavior;
    friction.clear();
    behavior.clear();
    for (std::size_t i = 0; i < interactions.size(); ++i) {
      const int index = static_cast<int>(i);
      const auto f = friction_changes.find(index);
      friction.push_back(f != friction_changes.end() ? std::optional(f->second)
                                                     : interactions[i].friction);
      const auto b = behavior_changes.find(index);
      behavior.push_back(b != behavior_changes.end() ? b->second : interactions[i].behavior);
      if (b != behavior_changes.end() && b->second.law == Law::Tied && !friction.back())
        throw InputError(state.behavior_change_where.at(index), "*SURFACE BEHAVIOR",
                         "PRESSURE-OVERCLOSURE=TIED needs a *FRICTION card in interaction " +
                             interactions[i].name + " (its stick slope is the tangential "
                             "stiffness); step " + std::to_string(s + 1) + " has none");
    }
  }
}

}  // namespace

void resolve_stick_slope(DeckState& state, const SourceLoc& where, model::Friction& friction) {
  if (friction.stick_slope > 0) return;
  friction.stick_slope =
      first_young(state, where, "*FRICTION", "the default stick slope") / 2;
  state.warn(where, "*FRICTION", "stick slope not positive: default lambda = E / 2 = " +
                                     number(friction.stick_slope) + " (" +
                                     default_origin(state) + ")");
}

void resolve_contact(DeckState& state) {
  const std::set<std::string> node_to_surface = node_to_surface_interactions(state);
  for (std::size_t i = 0; i < state.model.interactions.size(); ++i)
    resolve_interaction(state, i, node_to_surface.contains(state.model.interactions[i].name));
  for (const RawContactPair& raw : state.contact_pairs)
    state.model.contact_pairs.push_back(resolve_pair(state, raw));
  set_step_interactions(state);
}

void resolve_changed_behavior(DeckState& state, const SourceLoc& where, int interaction,
                              model::SurfaceBehavior& behavior) {
  const std::string& name = state.model.interactions.at(static_cast<std::size_t>(interaction)).name;
  resolve_behavior(state, where, behavior, node_to_surface_interactions(state).contains(name));
}

}  // namespace kontakt::inp
