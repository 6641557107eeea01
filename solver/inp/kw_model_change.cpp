// *MODEL CHANGE (ccx), step keyword: TYPE=CONTACT PAIR with ADD or REMOVE and "slave, master"
// lines naming pairs of the model's *CONTACT PAIR cards, or TYPE=ELEMENT with lines of element
// labels and element sets; the change holds from this step on.
#include "inp/keyword_handlers.hpp"
#include "inp/model_builder.hpp"
#include "inp/record_access.hpp"

namespace kontakt::inp {

void handle_model_change(const Record& record, DeckState& state) {
  check_params(record, {"TYPE", "ADD", "REMOVE"});
  const std::string type = remove_blanks(to_upper(required_value(record, "TYPE")));
  if (type != "CONTACTPAIR" && type != "ELEMENT")
    fail(record, "TYPE=" + type + ": expected CONTACT PAIR or ELEMENT");
  const bool add = has_param(record, "ADD"), remove = has_param(record, "REMOVE");
  if (add == remove) fail(record, "exactly one of ADD and REMOVE is required");
  require_line_count(record, 1, 100000);
  if (type == "ELEMENT") {
    const auto& index = state.model.mesh.element_index;
    for (const DataLine& line : record.lines)
      for (const std::string& field : line.fields) {
        if (field.empty()) continue;
        std::vector<int> labels;
        if (const std::optional<int> label = parse_int(field)) {
          labels.push_back(*label);
        } else {
          const std::string name = remove_blanks(to_upper(field));
          const auto set = state.element_sets.find(name);
          if (set == state.element_sets.end())
            fail(record, line, "element set " + name + " is not defined");
          for (const auto& [l, line_id] : set_labels(set->second, index)) labels.push_back(l);
        }
        for (int label : labels) {
          const auto found = index.find(label);
          if (const auto kind = connector_kind(state, label))
            fail(record, line,
                 "element " + std::to_string(label) + " is a " +
                     std::string(model::connector_type_name(*kind)) +
                     " element: TYPE=ELEMENT takes solid elements only");
          if (found == index.end())
            fail(record, line, "element " + std::to_string(label) + " is not defined");
          if (remove)
            state.active.removed_elements.insert(found->second);
          else
            state.active.removed_elements.erase(found->second);
        }
      }
    if (!state.element_change_where) state.element_change_where = record.where;
    return;
  }
  for (const DataLine& line : record.lines) {
    require_field_count(record, line, 2, 2);
    const std::string slave = remove_blanks(to_upper(line.fields[0]));
    const std::string master = remove_blanks(to_upper(line.fields[1]));
    bool found = false;
    for (std::size_t p = 0; p < state.contact_pairs.size(); ++p) {
      const model::ContactPair& pair = state.contact_pairs[p].pair;
      if (pair.slave != slave || pair.master != master) continue;
      found = true;
      if (remove)
        state.active.removed_contact_pairs.insert(static_cast<int>(p));
      else
        state.active.removed_contact_pairs.erase(static_cast<int>(p));
    }
    if (!found)
      fail(record, line, "no *CONTACT PAIR has slave surface " + slave + " and master surface " +
                             master);
  }
}

}  // namespace kontakt::inp
