// Resolving deck labels and set names to internal indices, and the final validation that
// turns a DeckState into a Model.
#pragma once

#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "inp/deck_state.hpp"

namespace kontakt::inp {

/// Internal index of a node label; throws at `line` when the node does not exist.
int node_index_of(const DeckState& state, const Record& record, const DataLine& line,
                  int label);

/// A data field naming a node label or a node set: internal indices (sets sorted by label).
std::vector<int> resolve_node_field(const DeckState& state, const Record& record,
                                    const DataLine& line, std::size_t field);
/// Likewise for an element label or element set.
std::vector<int> resolve_element_field(const DeckState& state, const Record& record,
                                       const DataLine& line, std::size_t field);

/// The labels of a raw set, each with the data line that listed it: every listed label, and
/// the labels of its GENERATE ranges that `index` has (line -1), found by walking the range or
/// the index, whichever is shorter. Sorted by label, one entry per label (its first listing).
std::vector<std::pair<int, int>> set_labels(const RawSet& set,
                                            const std::unordered_map<int, int>& index);

/// Members of a set as internal indices, sorted by deck label and deduplicated; throws at the
/// defining line of the first member that does not exist. Element sets leave out their
/// SPRINGA, GAPUNI, T3D2 (connector_labels) and DCOUP3D elements.
std::vector<int> node_set_members(const DeckState& state, const RawSet& set,
                                  const std::string& name);
std::vector<int> element_set_members(const DeckState& state, const RawSet& set,
                                     const std::string& name);

/// Amplitude index for an AMPLITUDE= parameter, -1 when absent; with TIME DELAY= the index of a
/// copy of the amplitude moved later in time by the delay.
int amplitude_param(DeckState& state, const Record& record);

/// The SPRINGA, GAPUNI and T3D2 labels of an element set (DeckState::connector_index).
std::vector<int> connector_labels(const DeckState& state, const RawSet& set);

/// The kind of element `label` when it is a SPRINGA, GAPUNI or T3D2 element.
std::optional<model::Connector::Kind> connector_kind(const DeckState& state, int label);

/// Builds Model::connectors from their *ELEMENT lines and their *SPRING / *GAP laws
/// (kw_connector.cpp).
void resolve_connectors(DeckState& state);

/// Gives each T3D2 truss of Model::connectors its material and cross-sectional area from the
/// last *SOLID SECTION naming it, refusing what a truss cannot carry (truss_builder.cpp).
void assign_truss_sections(DeckState& state);

/// Turns each *DISTRIBUTING COUPLING into three equations (kw_coupling.cpp).
void resolve_couplings(DeckState& state);

/// Turns the *RIGID BODY cards into Model::nonlinear_constraints, once the elements are
/// resolved (kw_nonlinear_constraint.cpp).
void resolve_rigid_bodies(DeckState& state);

/// Checks cross references and produces the Model.
model::Model finish_model(DeckState& state);

}  // namespace kontakt::inp
