// *SURFACE INTERACTION with its *SURFACE BEHAVIOR and *FRICTION, *CHANGE FRICTION, *CHANGE
// SURFACE BEHAVIOR and
// *CONTACT PAIR (ccx-behaviour.md section 1.1). Values are stored as written; the defaults ccx
// derives from the first material, and every name, are resolved at the end of the deck
// (contact_builder.cpp), because ccx allows the pair and the interaction in either order.
#include "inp/contact_builder.hpp"
#include "inp/keyword_handlers.hpp"
#include "inp/record_access.hpp"

namespace kontakt::inp {

namespace {

using Law = model::SurfaceBehavior::Law;

/// The interaction a *SURFACE BEHAVIOR or *FRICTION card belongs to; in a step, the one the
/// `change` card (*CHANGE FRICTION or *CHANGE SURFACE BEHAVIOR) just named.
int current_interaction(const Record& record, const DeckState& state, const std::string& change) {
  if (!state.open_step) {
    if (state.current_interaction >= 0) return state.current_interaction;
    fail(record, "must follow a *SURFACE INTERACTION card");
  }
  if (state.current_interaction >= 0 && state.open_change == change)
    return state.current_interaction;
  fail(record, "in a step it must follow a " + change + " card");
}

/// The interaction *CHANGE FRICTION or *CHANGE SURFACE BEHAVIOR names.
void open_change(const Record& record, DeckState& state, const std::string& change) {
  check_params(record, {"INTERACTION"});
  if (!record.lines.empty()) fail(record, record.lines.front(), "unexpected data line");
  const std::string name = remove_blanks(to_upper(required_value(record, "INTERACTION")));
  const auto found = state.interaction_index.find(name);
  if (found == state.interaction_index.end())
    fail(record, "surface interaction " + name + " is not defined");
  state.current_interaction = found->second;
  state.open_change = change;
}

/// LINEAR, HARD and TIED: "K, sigma_inf, c0"; blank, zero or negative values take ccx's
/// defaults later. No data line at all means all defaults (ccx warns, so do we, later).
void read_linear(const Record& record, model::SurfaceBehavior& behavior) {
  require_line_count(record, 0, 1);
  if (record.lines.empty()) return;
  const DataLine& line = record.lines.front();
  require_field_count(record, line, 1, 3);
  behavior.stiffness = real_field_or(record, line, 0, 0);
  behavior.tension_limit = real_field_or(record, line, 1, 0);
  behavior.clearance_c0 = real_field_or(record, line, 2, 0);
}

/// EXPONENTIAL: "c0, p0" with c0 > 0 (clearance at 1 % of p0) and p0 >= 0.
void read_exponential(const Record& record, model::SurfaceBehavior& behavior) {
  require_line_count(record, 1, 1);
  const DataLine& line = record.lines.front();
  require_field_count(record, line, 2, 2);
  behavior.exp_c0 = real_field(record, line, 0);
  behavior.exp_p0 = real_field(record, line, 1);
  if (!(behavior.exp_c0 > 0)) fail(record, line, "c0 (field 1) must be positive");
  if (!(behavior.exp_p0 >= 0)) fail(record, line, "p0 (field 2) must not be negative");
}

/// TABULAR: "pressure, overclosure[, temperature]" rows with increasing overclosure. Points
/// closer than 1e-10 are pushed apart (ccx: no vertical slope); c0 is fixed at 1e-3.
void read_tabular(const Record& record, DeckState& state, model::SurfaceBehavior& behavior) {
  constexpr Real kMinSpacing = 1e-10;
  require_line_count(record, 1, 100000);
  std::optional<Real> temperature;
  for (const DataLine& line : record.lines) {
    require_field_count(record, line, 2, 3);
    require_one_temperature(record, line, 2, temperature,
                            "a temperature-dependent pressure-overclosure table");
    const Real pressure = real_field(record, line, 0);
    Real overclosure = real_field(record, line, 1);
    if (!behavior.table.empty()) {
      const Real previous = behavior.table.back().first;
      if (overclosure - previous <= -kMinSpacing)
        fail(record, line, "overclosures must increase from row to row");
      if (overclosure - previous < kMinSpacing) {
        overclosure = previous + kMinSpacing;
        state.warn(line.where, record.keyword,
                   "overclosure closer than 1e-10 to the previous row; moved to 1e-10 above it");
      }
    }
    behavior.table.emplace_back(overclosure, pressure);
  }
  behavior.clearance_c0 = 1e-3;
}

/// One *FRICTION data line: "mu, lambda[, temperature]"; mu > 0, lambda <= 0 or blank takes
/// ccx's default E/2 later (or now, in a step, when the materials are all known).
model::Friction read_friction_line(const Record& record, const DataLine& line) {
  require_field_count(record, line, 1, 3);
  model::Friction friction;
  friction.mu = real_field(record, line, 0);
  friction.stick_slope = real_field_or(record, line, 1, 0);
  if (!(friction.mu > 0)) fail(record, line, "the friction coefficient must be positive");
  return friction;
}

model::ContactPair::Type pair_type(const Record& record) {
  const std::optional<std::string> type = name_value(record, "TYPE");
  if (!type) fail(record, "TYPE= is required (NODE TO SURFACE or SURFACE TO SURFACE)");
  if (*type == "NODETOSURFACE") return model::ContactPair::Type::NodeToSurface;
  if (*type == "SURFACETOSURFACE") return model::ContactPair::Type::SurfaceToSurface;
  for (const char* other : {"MORTAR", "LINMORTAR", "PGMORTAR", "PGLINMORTAR", "MASSLESS"})
    if (*type == other)
      fail(record, "TYPE=" + *type +
                       " is not supported (penalty contact only: NODE TO SURFACE or SURFACE TO "
                       "SURFACE)");
  fail(record, "TYPE=" + *type + ": expected NODE TO SURFACE or SURFACE TO SURFACE");
}

std::string type_name(model::ContactPair::Type type) {
  return type == model::ContactPair::Type::NodeToSurface ? "NODE TO SURFACE"
                                                          : "SURFACE TO SURFACE";
}

/// ADJUST=value (a clearance, >= 0) or ADJUST=node set (checked at the end of the deck).
void read_adjust(const Record& record, model::ContactPair& pair) {
  const Param* adjust = find_param(record, "ADJUST");
  if (adjust == nullptr) return;
  if (adjust->value.empty()) fail(record, "ADJUST= needs a clearance or a node set");
  if (const std::optional<Real> distance = parse_real(adjust->value)) {
    if (*distance < 0)
      fail(record, "ADJUST=" + adjust->value + ": the clearance must not be negative");
    pair.adjust_distance = distance;
  } else {
    pair.adjust_set = remove_blanks(to_upper(adjust->value));
  }
}

void read_scheme(const Record& record, model::ContactPair& pair) {
  const std::optional<std::string> name = name_value(record, "SCHEME");
  if (name) {
    const auto scheme = model::contact_scheme_from_name(*name);
    if (!scheme)
      fail(record, "SCHEME=" + *name + " is not a contact scheme (" +
                       model::contact_scheme_names() + ")");
    pair.scheme = *scheme;
    pair.scheme_given = true;
    return;
  }
  const char* fallback = pair.type == model::ContactPair::Type::NodeToSurface ? "nts" : "lgc7";
  pair.scheme = *model::contact_scheme_from_name(fallback);
}

}  // namespace

void handle_surface_interaction(const Record& record, DeckState& state) {
  check_params(record, {"NAME"});
  if (!record.lines.empty()) fail(record, record.lines.front(), "unexpected data line");
  const std::string name = remove_blanks(to_upper(required_value(record, "NAME")));
  if (state.interaction_index.contains(name))
    fail(record, "surface interaction " + name + " defined twice");
  state.current_interaction = static_cast<int>(state.model.interactions.size());
  state.interaction_index[name] = state.current_interaction;
  model::SurfaceInteraction interaction;
  interaction.name = name;
  interaction.where = record.where;
  state.model.interactions.push_back(std::move(interaction));
  state.raw_interactions.emplace_back();
}

void handle_surface_behavior(const Record& record, DeckState& state) {
  check_params(record, {"PRESSURE-OVERCLOSURE"});
  const int index = current_interaction(record, state, "*CHANGE SURFACE BEHAVIOR");
  const std::optional<std::string> law = name_value(record, "PRESSURE-OVERCLOSURE");
  if (!law)
    fail(record, "PRESSURE-OVERCLOSURE= is required (LINEAR, EXPONENTIAL, TABULAR, TIED or HARD)");
  model::SurfaceBehavior behavior;
  behavior.clearance_c0 = 0;  // "not given": resolved to ccx's 1e-3 at the end
  if (*law == "LINEAR" || *law == "HARD") {
    if (*law == "HARD")
      state.warn(record.where, record.keyword, "HARD is treated as LINEAR (as ccx does)");
    behavior.law = Law::Linear;
    read_linear(record, behavior);
  } else if (*law == "TIED") {
    behavior.law = Law::Tied;
    read_linear(record, behavior);
  } else if (*law == "EXPONENTIAL") {
    behavior.law = Law::Exponential;
    read_exponential(record, behavior);
  } else if (*law == "TABULAR") {
    behavior.law = Law::Tabular;
    read_tabular(record, state, behavior);
  } else {
    fail(record, "PRESSURE-OVERCLOSURE=" + *law +
                     ": expected LINEAR, EXPONENTIAL, TABULAR, TIED or HARD");
  }
  if (state.open_step) {
    resolve_changed_behavior(state, record.where, index, behavior);
    state.active.behavior_changes[index] = std::move(behavior);
    state.behavior_change_where[index] = record.where;
    return;
  }
  // ccx: a property defined twice in one interaction block takes the last definition.
  RawInteraction& raw = state.raw_interactions[static_cast<std::size_t>(index)];
  model::SurfaceInteraction& interaction =
      state.model.interactions[static_cast<std::size_t>(index)];
  if (raw.has_behavior)
    state.warn(record.where, record.keyword,
               "replaces the earlier *SURFACE BEHAVIOR of " + interaction.name);
  raw.has_behavior = true;
  raw.behavior_where = record.where;
  interaction.behavior = std::move(behavior);
}

void handle_friction(const Record& record, DeckState& state) {
  check_params(record, {});
  const int index = current_interaction(record, state, "*CHANGE FRICTION");
  require_line_count(record, 1, 100000);
  // ccx: no temperature dependence, the last data line counts.
  if (record.lines.size() > 1)
    state.warn(record.lines[1].where, record.keyword, "only the last data line counts");
  model::Friction friction;
  for (const DataLine& line : record.lines) friction = read_friction_line(record, line);
  friction.where = record.where;
  if (state.open_step) {
    // *CHANGE FRICTION: every material is known by now, so the default is resolved here.
    resolve_stick_slope(state, record.lines.back().where, friction);
    state.active.friction_changes[index] = friction;
    return;
  }
  model::SurfaceInteraction& interaction =
      state.model.interactions[static_cast<std::size_t>(index)];
  if (interaction.friction)
    state.warn(record.where, record.keyword,
               "replaces the earlier *FRICTION of " + interaction.name);
  state.raw_interactions[static_cast<std::size_t>(index)].friction_where = record.where;
  interaction.friction = friction;
}

void handle_change_friction(const Record& record, DeckState& state) {
  open_change(record, state, "*CHANGE FRICTION");
}

void handle_change_surface_behavior(const Record& record, DeckState& state) {
  open_change(record, state, "*CHANGE SURFACE BEHAVIOR");
}

void handle_contact_pair(const Record& record, DeckState& state) {
  if (has_param(record, "LINEAR"))
    fail(record, "LINEAR (contact without Newton iterations) is not supported");
  check_params(record, {"INTERACTION", "TYPE", "SMALLSLIDING", "ADJUST", "SCHEME"});
  model::ContactPair pair;
  pair.type = pair_type(record);
  if (!state.contact_pairs.empty() && state.contact_pairs.front().pair.type != pair.type) {
    const SourceLoc& first = state.contact_pairs.front().pair.where;
    fail(record, "TYPE=" + type_name(pair.type) + " mixed with TYPE=" +
                     type_name(state.contact_pairs.front().pair.type) + " (" + first.file + ":" +
                     std::to_string(first.line) + "); one deck may not mix contact types");
  }
  const std::string interaction = remove_blanks(to_upper(required_value(record, "INTERACTION")));
  if (const Param* sliding = find_param(record, "SMALLSLIDING"); sliding && sliding->has_value)
    fail(record, "SMALL SLIDING takes no value");
  pair.small_sliding = has_param(record, "SMALLSLIDING");
  if (pair.small_sliding && pair.type == model::ContactPair::Type::SurfaceToSurface) {
    state.warn(record.where, record.keyword,
               "SMALL SLIDING only applies to NODE TO SURFACE contact; ignored (as ccx does)");
    pair.small_sliding = false;
  }
  read_adjust(record, pair);
  read_scheme(record, pair);
  require_line_count(record, 1, 100000);
  for (const DataLine& line : record.lines) {
    require_field_count(record, line, 2, 2);
    model::ContactPair one = pair;
    one.slave = remove_blanks(to_upper(line.fields[0]));
    one.master = remove_blanks(to_upper(line.fields[1]));
    if (one.slave.empty() || one.master.empty())
      fail(record, line, "expected slave surface, master surface");
    one.where = line.where;
    state.contact_pairs.push_back(RawContactPair{std::move(one), interaction});
  }
}

}  // namespace kontakt::inp
