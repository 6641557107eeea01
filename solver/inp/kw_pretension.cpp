// *PRE-TENSION SECTION (ccx): SURFACE= (an element-face cut through the bolt) and NODE= (the
// reference node, whose first dof carries the opening or the force), one data line with the
// normal. ELEMENT= (a B31 beam standing for the bolt) is refused with the beam elements. The
// surface is resolved and the mesh cut at the end of the deck (model/pretension).
#include "inp/keyword_handlers.hpp"
#include "inp/model_builder.hpp"
#include "inp/record_access.hpp"

namespace kontakt::inp {

void handle_pretension_section(const Record& record, DeckState& state) {
  check_params(record, {"SURFACE", "ELEMENT", "NODE"});
  if (has_param(record, "ELEMENT"))
    fail(record, "ELEMENT= (a beam element as the bolt) is not supported: beam elements are "
                 "not; cut the bolt's solid mesh with SURFACE=");
  model::PretensionSection section;
  section.surface = remove_blanks(to_upper(required_value(record, "SURFACE")));
  const std::string node = required_value(record, "NODE");
  const std::optional<int> label = parse_int(node);
  if (!label) fail(record, "NODE=" + node + " is not a node label");
  require_line_count(record, 1, 1);
  const DataLine& line = record.lines.front();
  require_field_count(record, line, 3, 3);
  const auto found = state.model.mesh.node_index.find(*label);
  if (found == state.model.mesh.node_index.end())
    fail(record, "reference node " + node +
                     " is not defined (define it with *NODE before this card; its coordinates "
                     "are not used)");
  section.node = found->second;
  for (int c = 0; c < 3; ++c) section.normal[c] = real_field(record, line, static_cast<std::size_t>(c));
  if (section.normal.norm() == 0) fail(record, line, "the normal is the zero vector");
  section.normal.normalize();
  section.where = record.where;
  state.model.pretension_sections.push_back(std::move(section));
}

}  // namespace kontakt::inp
