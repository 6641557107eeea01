// Contact definitions of a deck: surface interactions (*SURFACE INTERACTION with its
// *SURFACE BEHAVIOR and *FRICTION), contact pairs (*CONTACT PAIR), the contact solution controls
// (*CONTROLS, PARAMETERS=CONTACT / LINE SEARCH) and the contact output requests. Defaults that
// ccx derives from the first material (K = 50 E, sigma_inf = E / 70000, lambda = E / 2) are
// already resolved by the reader, so every value here is the one the analysis uses.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"

namespace kontakt::model {

/// *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=... (ccx-behaviour.md section 1.1). HARD is read as
/// LINEAR with ccx's defaults, as ccx does (a warning says so).
struct SurfaceBehavior {
  enum class Law { Linear, Exponential, Tabular, Tied };
  Law law = Law::Linear;
  Real stiffness = 0;        ///< LINEAR / TIED: K, pressure per unit overclosure
  Real tension_limit = 0;    ///< LINEAR: sigma_inf, tension at large clearance (node-to-surface)
  Real clearance_c0 = 1e-3;  ///< LINEAR / TABULAR: c0 (element creation up to c0 * sqrt(A), NTS)
  Real exp_c0 = 0;           ///< EXPONENTIAL: clearance at which the pressure is 1 % of p0
  Real exp_p0 = 0;           ///< EXPONENTIAL: pressure at zero clearance
  /// TABULAR: (overclosure, pressure) rows, overclosure ascending; constant beyond the ends.
  std::vector<std::pair<Real, Real>> table;
};

/// *FRICTION: Coulomb coefficient and stick slope (shear stress per unit slip).
struct Friction {
  Real mu = 0;
  Real stick_slope = 0;      ///< lambda
  SourceLoc where;           ///< the *FRICTION card
};

struct SurfaceInteraction {
  std::string name;          ///< upper case
  SurfaceBehavior behavior;
  /// The model's *FRICTION; *CHANGE FRICTION can replace it from a step on, so the analysis
  /// reads the friction in force from Step::interaction_friction.
  std::optional<Friction> friction;
  SourceLoc where;
};

/// Discretisation of a contact pair (architecture note, "Contact scheme names"): nts, gauss,
/// lgauss, gc1|gc3|gc7|gc12, lgc1|lgc3|lgc7|lgc12.
struct ContactScheme {
  enum class Kind { NodeToSurface, Gauss, GaussCut };
  Kind kind = Kind::GaussCut;
  bool linear = true;        ///< the thesis' linear variant (frozen geometry per increment)
  int points = 7;            ///< Gauss-Cut: points per triangle (1, 3, 7, 12)

  bool operator==(const ContactScheme&) const = default;
};
/// Lower- or upper-case scheme name -> scheme; nullopt for an unknown name.
std::optional<ContactScheme> contact_scheme_from_name(const std::string& name);
/// The canonical (lower-case) name.
std::string contact_scheme_name(const ContactScheme& scheme);
/// Every scheme name, comma-separated, for messages that list the choices.
std::string contact_scheme_names();

struct ContactPair {
  enum class Type { NodeToSurface, SurfaceToSurface };
  Type type = Type::SurfaceToSurface;
  int interaction = -1;      ///< index into Model::interactions
  std::string slave, master;  ///< surface names (keys of Model::surfaces)
  ContactScheme scheme;      ///< SCHEME= or the type's default (lgc7 / nts)
  bool scheme_given = false;  ///< SCHEME= was on the card (a CLI/API override still wins)
  bool small_sliding = false;
  /// ADJUST=value: slave nodes closer than this (and all penetrating ones) are moved onto the
  /// master surface at the start of step 1; ADJUST=nset: the nodes of that set.
  std::optional<Real> adjust_distance;
  std::string adjust_set;
  SourceLoc where;
};

/// *CONTROLS, PARAMETERS=CONTACT and LINE SEARCH (ccx defaults).
struct ContactControls {
  Real delcon = 1e-3;        ///< relative change of the number of contact elements still "unchanged"
  Real alea = 0.1;           ///< fraction of points dropped at random at a local minimum
  Real kscalemax = 100;      ///< factor by which penalties are softened after divergence
  int itf2f = 60;            ///< iteration cap per increment for surface-to-surface contact
  Real line_search_min = 0.25;
  Real line_search_max = 1.01;
};

/// *CONTACT PRINT (to .dat) / *CONTACT FILE, *CONTACT OUTPUT (to the results file).
struct ContactRequest {
  std::vector<std::string> variables;  ///< upper case, 4-letter form: CDIS, CSTR, CELS
  bool totals = false;       ///< TOTALS=YES (print only)
  bool totals_only = false;  ///< TOTALS=ONLY
  int frequency = 1;
  /// *CONTACT PRINT only: ccx keeps node, element and contact prints in one list and writes
  /// the .dat blocks in that order; this request comes after the first `after_prints`
  /// entries of Step::prints (requests with equal values keep their order).
  std::size_t after_prints = 0;
  SourceLoc where;
};

}  // namespace kontakt::model
