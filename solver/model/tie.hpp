// *TIE (ccx's MPC-based tied contact): the slave side's nodes follow the master surface. The
// model-setup step contact::apply_ties turns each tie into linear equations (Model::equations),
// or with SCHEME= into a TIED contact pair, and, unless ADJUST=NO, moves the slave nodes onto
// the master surface.
#pragma once

#include <optional>
#include <string>

#include "core/error.hpp"
#include "core/types.hpp"
#include "model/contact.hpp"

namespace kontakt::model {

struct Tie {
  std::string name;               ///< NAME=, upper case
  std::string slave, master;      ///< surface names (keys of Model::surfaces); master: faces
  /// POSITION TOLERANCE: slave nodes farther from the master surface stay free. Absent (or
  /// given below 1e-10): ccx's default, 2.5 % of a typical master element size.
  std::optional<Real> position_tolerance;
  bool adjust = true;             ///< move the tied slave nodes onto the master surface
  /// SCHEME= (Kontakt's extension): tie through segment-to-segment TIED contact with this
  /// scheme (thesis §5.5, exact on the tied patch test) instead of ccx's MPCs.
  std::optional<ContactScheme> scheme;
  /// CYCLIC SYMMETRY: the slave (dependent) side is the master (independent) side turned by a
  /// sector about the axis of its *CYCLIC SYMMETRY MODEL; either may be a node surface.
  bool cyclic = false;
  SourceLoc where;                ///< the data line
};

/// *CYCLIC SYMMETRY MODEL for a static analysis: one of `sectors` equal sectors is modelled,
/// and each dependent node of the cyclic tie moves as its independent node turned by 2 pi /
/// sectors about the axis through `axis_from` and `axis_to` (a load that is the same on every
/// sector: ccx's nodal diameter 0).
struct CyclicSymmetry {
  std::string tie;                ///< TIE=, a CYCLIC SYMMETRY tie
  int sectors = 0;                ///< N=
  std::string elset;              ///< ELSET=: the sector's elements (ccx: what it expands)
  Vec3 axis_from = Vec3::Zero(), axis_to = Vec3::Zero();
  SourceLoc where;                ///< the data line
};

}  // namespace kontakt::model
