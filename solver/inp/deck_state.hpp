// Everything the keyword handlers accumulate while walking the deck, before the Model is
// validated and frozen. Sets and element connectivity are kept by deck label until the end
// because ccx lets them mention labels defined further down.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <variant>
#include <vector>

#include "inp/inp_lexer.hpp"
#include "model/model.hpp"
#include "model/solution_controls.hpp"

namespace kontakt::inp {

/// A set under construction: labels listed one by one, in the order given, each with the data
/// line it came from (a listed label that does not exist is an error), and GENERATE ranges,
/// whose labels without a node or element are skipped (ccx behaviour).
struct RawSet {
  SourceLoc where;               ///< first card that defined it
  std::vector<int> labels;
  std::vector<int> line_ids;     ///< index into DeckState::line_locs, parallel to labels
  std::vector<model::LabelRange> ranges;
  std::vector<model::LabelRange> sequence;  ///< labels and ranges in deck order (print order)
};

struct RawFace {
  int element_label = 0;
  int face = 0;
  int line_id = 0;
};
/// A SPRINGA, GAPUNI or T3D2 element as read; *SPRING / *GAP / *SOLID SECTION give it its
/// law.
struct RawConnector {
  model::Connector::Kind kind = model::Connector::Kind::Spring;
  int label = 0;
  std::array<int, 2> node_labels{};
  SourceLoc where;
};
/// *SPRING or *GAP as read: the law for the connectors of an element set.
struct RawConnectorLaw {
  std::string elset;
  model::Connector law;  ///< kind and the law's fields
  SourceLoc where;
  std::string keyword;
};

/// *DISTRIBUTING COUPLING as read: its DCOUP3D element set and (node or set, weight) lines.
struct RawCoupling {
  std::string elset;
  std::vector<std::pair<std::string, Real>> members;
  SourceLoc where;
};

/// *RIGID BODY as read: its nodes are resolved once the elements are (ELSET=).
struct RawRigidBody {
  std::optional<std::string> nset, elset;  ///< exactly one is set
  int ref = 0, rot = 0;                    ///< internal node indices
  SourceLoc where;
};

struct RawSurface {
  model::Surface::Kind kind = model::Surface::Kind::ElementFaces;
  std::vector<RawFace> faces;
  std::vector<int> node_labels;
  std::vector<int> line_ids;     ///< for node_labels
  SourceLoc where;
};

/// The key of the node variant of a surface name that also names element faces. Deck names
/// lose their blanks, so this key never meets one.
inline std::string node_surface_key(const std::string& name) { return name + " (TYPE=NODE)"; }

struct RawSection {
  std::string elset;
  std::string material;
  SourceLoc where;
  Real thickness = 1;
  Real offset = 0;
  std::string orientation;  ///< ORIENTATION= name; empty: none
  /// The data line's first field as given, whatever its sign: a truss's cross-sectional area.
  std::optional<Real> area;
};

/// Where the cards of a *SURFACE INTERACTION block were, for the end-of-deck resolution
/// (defaults from the first material, which may come later in the deck; missing cards).
struct RawInteraction {
  bool has_behavior = false;
  SourceLoc behavior_where;      ///< the *SURFACE BEHAVIOR card
  SourceLoc friction_where;      ///< the *FRICTION card
};

/// A *CONTACT PAIR data line before the names are resolved.
struct RawContactPair {
  model::ContactPair pair;       ///< everything but the interaction index
  std::string interaction;       ///< INTERACTION= name
};

/// One entry of ccx's single print list: *NODE PRINT and *EL PRINT requests, or a
/// *CONTACT PRINT request.
using PrintEntry = std::variant<model::PrintRequest, model::ContactRequest>;

using DofKey = std::pair<int, int>;  ///< (internal node, dof 0..2)
using FaceKey = std::pair<int, int>; ///< (internal element, 1-based face)
/// A body load of the same element set (as written), kind and, for gravity, direction as an
/// earlier one is the same load to ccx: it adds within a step and replaces across steps.
using BodyLoadKey = std::tuple<std::string, model::BodyLoad::Kind, std::array<Real, 3>>;

/// Loads and constraints in force, carried from step to step (ccx OP=MOD semantics).
struct ActiveLoads {
  std::map<DofKey, model::Boundary> boundaries;
  std::map<DofKey, model::ConcentratedLoad> cloads;
  std::map<FaceKey, model::PressureLoad> pressures;
  /// *DLOAD PnNP ("network pressure"): face -> the node whose prescribed dof 2 (*BOUNDARY) is
  /// the pressure, resolved at each *END STEP (ccx reads it from the boundary in force), and
  /// the data line that named it.
  std::map<FaceKey, std::pair<int, SourceLoc>> network_pressures;
  std::map<BodyLoadKey, model::BodyLoad> body_loads;
  std::map<int, Real> temperatures;  ///< internal node -> temperature
  /// In ccx's order: the first card of a kind in a step removes the earlier entries of that
  /// kind, new requests are appended (so the .dat blocks follow this list).
  std::vector<PrintEntry> prints;
  std::vector<model::FileRequest> node_files, element_files;
  std::vector<model::ContactRequest> contact_files;
  int output_frequency = 1;  ///< ccx: the last FREQUENCY= given applies to all outputs
  /// ccx: TIME POINTS= on an output request replaces FREQUENCY= for all outputs, until a later
  /// FREQUENCY= (index into Model::time_points; -1: none).
  int output_time_points = -1;
  bool nlgeom = false;       ///< ccx: NLGEOM stays active in later steps
  model::SolutionControls controls;  ///< *CONTROLS stay in force until RESET
  model::ContactControls contact_controls;  ///< likewise
  /// *CHANGE FRICTION: interaction index -> the friction that replaces the model's one.
  std::map<int, model::Friction> friction_changes;
  /// *CHANGE SOLID SECTION cards so far, in deck order (ELSET, MATERIAL and the card's place).
  std::vector<RawSection> section_changes;
  /// *MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE: indices into DeckState::contact_pairs.
  std::set<int> removed_contact_pairs;
  std::set<int> removed_elements;  ///< internal element indices (*MODEL CHANGE, TYPE=ELEMENT)
  /// *CHANGE SURFACE BEHAVIOR: interaction index -> the behavior that replaces the model's one
  /// (defaults resolved at its card).
  std::map<int, model::SurfaceBehavior> behavior_changes;
};

/// Which keywords already appeared in the open step: OP= acts on the first card only, and the
/// first output request of a kind replaces the earlier ones.
struct StepProgress {
  model::Step step;
  bool has_procedure = false;
  std::set<std::string> seen;               ///< record keys seen in this step
  std::set<DofKey> cloads_in_step;          ///< repeated CLOADs in one step add up
  std::set<FaceKey> pressures_in_step;      ///< likewise for DLOADs
  std::set<BodyLoadKey> body_loads_in_step; ///< and for GRAV / CENTRIF
};

struct DeckState {
  model::Model model;
  std::vector<SourceLoc> line_locs;         ///< interned data-line locations
  std::vector<Vec3> coords;
  std::vector<std::vector<int>> element_node_labels;  ///< parallel to model.mesh.elements
  std::vector<int> element_line_ids;
  std::map<std::string, RawSet> node_sets, element_sets;
  /// By name; a node surface that shares its name with an element-face surface (ccx keeps
  /// both and picks by role) is kept under node_surface_key(name).
  std::map<std::string, RawSurface> surfaces;
  std::vector<RawSection> sections;
  std::vector<RawRigidBody> rigid_bodies;
  std::vector<RawConnector> connectors;
  std::unordered_map<int, int> connector_index;  ///< label -> index into connectors
  std::vector<RawConnectorLaw> connector_laws;
  /// DCOUP3D elements: label -> node label (the reference node of a distributing coupling).
  std::unordered_map<int, int> coupling_elements;
  std::vector<RawCoupling> couplings;
  std::map<std::string, int> material_index;
  std::map<std::string, model::Orientation> orientations;  ///< *ORIENTATION by name
  std::map<std::string, int> amplitude_index;
  std::map<std::string, int> time_points_index;  ///< *TIME POINTS by name
  std::map<std::string, int> interaction_index;
  std::vector<RawInteraction> raw_interactions;  ///< parallel to model.interactions
  std::vector<RawContactPair> contact_pairs;
  /// Per finished step: ActiveLoads::friction_changes at its end (combined with the model's
  /// frictions once those are resolved, into Step::interaction_friction).
  std::vector<std::map<int, model::Friction>> step_friction_changes;
  /// Per finished step: ActiveLoads::section_changes at its end.
  std::vector<std::vector<RawSection>> step_section_changes;
  /// Per finished step: ActiveLoads::behavior_changes at its end, with the card of each.
  std::vector<std::map<int, model::SurfaceBehavior>> step_behavior_changes;
  /// The *SURFACE BEHAVIOR card of each change (interaction index -> card), for messages.
  std::map<int, SourceLoc> behavior_change_where;
  std::map<int, Real> initial_temperatures;  ///< internal node -> value
  /// The first *INITIAL CONDITIONS, TYPE=STRESS card, for errors found at the end of the deck.
  std::optional<SourceLoc> initial_stress_where;
  /// *INITIAL CONDITIONS, TYPE=PLASTIC STRAIN per element (n_ip x 6, tensor components; empty:
  /// none), turned into initial stresses once the materials are known; its first card.
  std::vector<MatX> initial_inelastic_strains;
  std::optional<SourceLoc> initial_inelastic_strain_where;
  int current_material = -1;                 ///< target of *ELASTIC, *DENSITY, ...
  /// Target of *SURFACE BEHAVIOR and *FRICTION: the open *SURFACE INTERACTION block or, in a
  /// step, the interaction named by *CHANGE FRICTION or *CHANGE SURFACE BEHAVIOR.
  int current_interaction = -1;
  std::string open_change;  ///< in a step: which of the two *CHANGE cards names it
  std::optional<StepProgress> open_step;
  bool any_step_seen = false;
  bool nonlinear_mpc = false;  ///< an *MPC was read: every step runs with NLGEOM (ccx)
  /// The first *MODEL CHANGE, TYPE=ELEMENT, when there is one.
  std::optional<SourceLoc> element_change_where;
  ActiveLoads active;

  int intern(const SourceLoc& where) {
    line_locs.push_back(where);
    return static_cast<int>(line_locs.size()) - 1;
  }
  void warn(const SourceLoc& where, const std::string& keyword, const std::string& message) {
    model.warnings.push_back(where.file + ":" + std::to_string(where.line) + ": " + keyword +
                             ": " + message);
  }
};

}  // namespace kontakt::inp
