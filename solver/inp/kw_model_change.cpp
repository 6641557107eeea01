// *MODEL CHANGE (ccx), step keyword: TYPE=CONTACT PAIR with ADD or REMOVE and "slave, master"
// lines naming pairs of the model's *CONTACT PAIR cards; the change holds from this step on.
// TYPE=ELEMENT (element deactivation) is refused.
#include "inp/keyword_handlers.hpp"
#include "inp/record_access.hpp"

namespace kontakt::inp {

void handle_model_change(const Record& record, DeckState& state) {
  check_params(record, {"TYPE", "ADD", "REMOVE"});
  const std::string type = remove_blanks(to_upper(required_value(record, "TYPE")));
  if (type == "ELEMENT")
    fail(record, "TYPE=ELEMENT (deactivating and activating elements) is not supported");
  if (type != "CONTACTPAIR")
    fail(record, "TYPE=" + type + ": expected CONTACT PAIR (or ELEMENT, not supported)");
  const bool add = has_param(record, "ADD"), remove = has_param(record, "REMOVE");
  if (add == remove) fail(record, "exactly one of ADD and REMOVE is required");
  require_line_count(record, 1, 100000);
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
