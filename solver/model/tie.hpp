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
  SourceLoc where;                ///< the data line
};

}  // namespace kontakt::model
