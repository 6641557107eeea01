// *DISTRIBUTING COUPLING: a DCOUP3D element's node as the reference node of a set of weighted
// nodes, as ccx 2.20 builds it (manual, *DISTRIBUTING COUPLING): per direction the equation
// sum_i w_i u_i - (sum_i w_i) u_ref = 0, its first node's dof dependent. A force on the
// reference node spreads over the nodes by their weights; a displacement moves their
// weighted mean.
#include <algorithm>

#include "inp/keyword_handlers.hpp"
#include "inp/model_builder.hpp"
#include "inp/record_access.hpp"

namespace kontakt::inp {

void handle_distributing_coupling(const Record& record, DeckState& state) {
  check_params(record, {"ELSET"});
  const std::optional<std::string> elset = name_value(record, "ELSET");
  if (!elset) fail(record, "parameter ELSET= is required");
  require_line_count(record, 1, record.lines.size() + 1);
  RawCoupling coupling{.elset = *elset, .members = {}, .where = record.where};
  for (const DataLine& line : record.lines) {
    require_field_count(record, line, 2, 2);
    const Real weight = real_field(record, line, 1);
    if (!(weight > 0)) fail(record, line, "the weight must be positive");
    coupling.members.emplace_back(line.fields[0], weight);
  }
  state.couplings.push_back(std::move(coupling));
}

void resolve_couplings(DeckState& state) {
  model::Model& model = state.model;
  const auto& index = model.mesh.node_index;
  for (const RawCoupling& coupling : state.couplings) {
    const auto fail_here = [&](const std::string& why) {
      throw InputError(coupling.where, "*DISTRIBUTING COUPLING", why);
    };
    const auto set = state.element_sets.find(coupling.elset);
    if (set == state.element_sets.end())
      fail_here("element set " + coupling.elset + " is not defined");
    std::vector<int> references;
    for (const auto& [label, line_id] : set_labels(set->second, state.coupling_elements))
      if (const auto e = state.coupling_elements.find(label); e != state.coupling_elements.end())
        references.push_back(e->second);
    if (references.size() != 1 || set->second.labels.size() + set->second.ranges.size() != 1)
      fail_here("element set " + coupling.elset + " must hold exactly one DCOUP3D element");
    const auto ref = index.find(references.front());
    if (ref == index.end())
      fail_here("reference node " + std::to_string(references.front()) + " is not defined");
    std::vector<std::pair<int, Real>> nodes;  // internal index, weight; in the card's order
    for (const auto& [field, weight] : coupling.members) {
      std::vector<int> members;
      if (const std::optional<int> label = parse_int(field)) {
        const auto found = index.find(*label);
        if (found == index.end()) fail_here("node " + field + " is not defined");
        members.push_back(found->second);
      } else {
        const std::string name = remove_blanks(to_upper(field));
        const auto nset = state.node_sets.find(name);
        if (nset == state.node_sets.end()) fail_here("node set " + name + " is not defined");
        members = node_set_members(state, nset->second, name);
      }
      for (int node : members) {
        if (node == ref->second) fail_here("the reference node is one of the coupled nodes");
        if (std::any_of(nodes.begin(), nodes.end(), [&](const auto& n) { return n.first == node; }))
          fail_here("node " + std::to_string(model.mesh.node_ids[static_cast<std::size_t>(node)]) +
                    " is coupled twice");
        nodes.emplace_back(node, weight);
      }
    }
    Real total = 0;
    for (const auto& [node, weight] : nodes) total += weight;
    for (int dof = 0; dof < 3; ++dof) {
      model::Equation eq;
      eq.where = coupling.where;
      eq.keyword = "*DISTRIBUTING COUPLING";
      for (const auto& [node, weight] : nodes) eq.terms.push_back({node, dof, weight});
      eq.terms.push_back({ref->second, dof, -total});
      model.equations.push_back(std::move(eq));
    }
  }
}

}  // namespace kontakt::inp
