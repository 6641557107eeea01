// One contact record from several that stand for one slave node: the shares of a node over an
// edge of the master (contact/master_search) and the expanded copies of a 2D node
// (model/plane_expansion), which ccx prints under the 2D node's label.
#pragma once

#include <span>

#include "output/frame.hpp"

namespace kontakt::output {

/// Areas and energies add up, the rest is averaged by area; active or slipping when any record
/// is, sticking when some record sticks and none slips. Position, pair and labels: the first's.
ContactPointRecord merged_record(std::span<const ContactPointRecord> records);

}  // namespace kontakt::output
