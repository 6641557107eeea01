// *CONTACT PAIR, ADJUST (ccx-behaviour.md section 1.6): before the analysis, slave nodes within
// the given distance of the master surface (penetrating ones always), or all nodes of the
// given node set, are moved along the master normal onto the master surface, so a mesh that
// should start in contact does.
#pragma once

#include "model/model.hpp"

namespace kontakt::contact {

/// Moves the nodes every pair's ADJUST asks for in `model.mesh.coords`; returns how many
/// nodes moved, and says so in `model.warnings` at the first pair with ADJUST. Pairs without
/// ADJUST are left alone. A model-setup step: run once, after reading, before any analysis.
int adjust_slave_nodes(model::Model& model);

}  // namespace kontakt::contact
