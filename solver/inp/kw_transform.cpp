// *TRANSFORM: a local rectangular or cylindrical system for the nodes of a set (ccx). The frame
// of each node is fixed here, from its coordinates: a degenerate definition is refused at this
// card, nodes on a cylinder's axis get ccx's frame with a warning.
#include <stdexcept>

#include "inp/keyword_handlers.hpp"
#include "inp/model_builder.hpp"
#include "inp/record_access.hpp"
#include "model/local_frame.hpp"

namespace kontakt::inp {

const DataLine& read_frame_points(const Record& record, model::Transform& frame) {
  require_line_count(record, 1, 1);
  const DataLine& line = record.lines.front();
  require_field_count(record, line, 6, 6);
  for (int c = 0; c < 3; ++c) {
    frame.a[c] = real_field(record, line, c);
    frame.b[c] = real_field(record, line, 3 + c);
  }
  return line;
}

void handle_transform(const Record& record, DeckState& state) {
  check_params(record, {"NSET", "TYPE"});
  const std::string name = remove_blanks(to_upper(required_value(record, "NSET")));
  const std::string type = remove_blanks(to_upper(name_value(record, "TYPE").value_or("R")));
  model::Transform transform;
  if (type == "C")
    transform.kind = model::Transform::Kind::Cylindrical;
  else if (type != "R")
    fail(record, "TYPE=" + type + ": expected R (rectangular) or C (cylindrical)");
  const DataLine& line = read_frame_points(record, transform);
  const auto set = state.node_sets.find(name);
  if (set == state.node_sets.end()) fail(record, "node set " + name + " is not defined");
  std::vector<int> on_axis;
  for (int node : node_set_members(state, set->second, name)) {
    try {
      state.model.local_frames[node] = model::local_frame(transform, state.coords[node]);
    } catch (const std::invalid_argument& e) {
      fail(record, line, e.what());
    }
    if (model::on_cylinder_axis(transform, state.coords[node]))
      on_axis.push_back(state.model.mesh.node_ids[node]);
  }
  if (!on_axis.empty())
    state.warn(line.where, record.keyword,
               std::to_string(on_axis.size()) + " node(s) on the cylinder's axis (first: " +
                   std::to_string(on_axis.front()) +
                   "), where the radial direction is undefined: their local y' is global z "
                   "projected normal to the axis (global y for an axis along z), as in ccx");
}

}  // namespace kontakt::inp
