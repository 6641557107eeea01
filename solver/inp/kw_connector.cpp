// *SPRING and *GAP: the laws of SPRINGA and GAPUNI connectors (model::Connector), given to
// their elements once the deck is read (resolve_connectors). T3D2 trusses take theirs from
// *SOLID SECTION (truss_builder.cpp).
#include <algorithm>
#include <cmath>

#include "inp/keyword_handlers.hpp"
#include "inp/model_builder.hpp"
#include "inp/record_access.hpp"

namespace kontakt::inp {

using model::Connector;

void handle_spring(const Record& record, DeckState& state) {
  check_params(record, {"ELSET", "NONLINEAR"});
  const std::optional<std::string> elset = name_value(record, "ELSET");
  if (!elset) fail(record, "parameter ELSET= is required");
  RawConnectorLaw law{.elset = *elset, .law = {}, .where = record.where, .keyword = "*SPRING"};
  law.law.kind = Connector::Kind::Spring;
  require_line_count(record, 1, record.lines.size() + 1);
  std::optional<Real> temperature;
  for (const DataLine& line : record.lines) {
    require_field_count(record, line, 1, 3);
    if (const std::optional<Real> t = optional_real_field(record, line, 2)) {
      if (temperature && *t != *temperature)
        fail(record, line, "temperature-dependent springs are not supported (one temperature)");
      temperature = t;
    }
  }
  if (!has_param(record, "NONLINEAR")) {
    if (record.lines.size() > 1)
      fail(record, record.lines[1], "a linear spring has one line (its constant)");
    law.law.stiffness = real_field(record, record.lines.front(), 0);
  } else {
    for (const DataLine& line : record.lines) {
      require_field_count(record, line, 2, 3);
      const Real force = real_field(record, line, 0), elongation = real_field(record, line, 1);
      if (!law.law.curve.empty() && elongation <= law.law.curve.back().first)
        fail(record, line, "the elongations must ascend");
      law.law.curve.emplace_back(elongation, force);
    }
  }
  state.connector_laws.push_back(std::move(law));
}

void handle_gap(const Record& record, DeckState& state) {
  check_params(record, {"ELSET"});
  const std::optional<std::string> elset = name_value(record, "ELSET");
  if (!elset) fail(record, "parameter ELSET= is required");
  require_line_count(record, 1, 1);
  const DataLine& line = record.lines.front();
  require_field_count(record, line, 4, 7);
  RawConnectorLaw law{.elset = *elset, .law = {}, .where = record.where, .keyword = "*GAP"};
  law.law.kind = Connector::Kind::Gap;
  law.law.clearance = real_field(record, line, 0);
  const Vec3 direction(real_field(record, line, 1), real_field(record, line, 2),
                       real_field(record, line, 3));
  if (direction.norm() == 0) fail(record, line, "the gap direction is the zero vector");
  law.law.direction = direction.normalized();
  law.law.stiffness = real_field_or(record, line, 5, 1e12);  // ccx's defaults
  law.law.tension = real_field_or(record, line, 6, 1e-3);
  if (law.law.stiffness <= 0 || law.law.tension <= 0)
    fail(record, line, "the gap stiffness and tensile force must be positive");
  state.connector_laws.push_back(std::move(law));
}

void resolve_connectors(DeckState& state) {
  model::Model& model = state.model;
  for (const RawConnector& raw : state.connectors) {
    Connector c;
    c.kind = raw.kind;
    c.id = raw.label;
    c.where = raw.where;
    for (std::size_t k = 0; k < 2; ++k) {
      const auto node = model.mesh.node_index.find(raw.node_labels[k]);
      if (node == model.mesh.node_index.end())
        throw InputError(raw.where, "*ELEMENT",
                         "node " + std::to_string(raw.node_labels[k]) + " of element " +
                             std::to_string(raw.label) + " is not defined");
      c.nodes[k] = node->second;
    }
    if (c.nodes[0] == c.nodes[1])
      throw InputError(raw.where, "*ELEMENT",
                       "element " + std::to_string(raw.label) + " joins a node to itself");
    if (c.kind != Connector::Kind::Gap &&
        model.mesh.coords.row(c.nodes[0]) == model.mesh.coords.row(c.nodes[1]))
      throw InputError(raw.where, "*ELEMENT",
                       std::string(c.kind == Connector::Kind::Spring ? "spring" : "truss") +
                           " element " + std::to_string(raw.label) +
                           " has zero length: its direction is undefined (" +
                           std::string(model::connector_type_name(c.kind)) +
                           " acts along the line between its nodes)");
    model.connectors.push_back(c);
  }
  std::vector<char> has_law(model.connectors.size(), 0);
  for (const RawConnectorLaw& law : state.connector_laws) {
    const auto set = state.element_sets.find(law.elset);
    if (set == state.element_sets.end())
      throw InputError(law.where, law.keyword, "element set " + law.elset + " is not defined");
    for (int label : connector_labels(state, set->second)) {
      const std::size_t k = static_cast<std::size_t>(state.connector_index.at(label));
      Connector& c = model.connectors[k];
      if (c.kind != law.law.kind)
        throw InputError(law.where, law.keyword,
                         "element " + std::to_string(label) + " of set " + law.elset + " is a " +
                             std::string(model::connector_type_name(c.kind)) + " element");
      const Connector element = c;
      c = law.law;
      c.id = element.id;
      c.nodes = element.nodes;
      c.where = element.where;
      has_law[k] = 1;
    }
  }
  for (std::size_t k = 0; k < model.connectors.size(); ++k)
    if (!has_law[k] && model.connectors[k].kind != Connector::Kind::Truss) {
      const Connector& c = model.connectors[k];
      throw InputError(c.where, "*ELEMENT",
                       "element " + std::to_string(c.id) + " has no " +
                           (c.kind == Connector::Kind::Spring ? "*SPRING" : "*GAP") + " card");
    }
}

}  // namespace kontakt::inp
