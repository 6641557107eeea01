// *TIE (ccx 2.20, ties.f): NAME= (required), POSITION TOLERANCE=, ADJUST=NO, our SCHEME= (tie
// through TIED contact), CYCLIC SYMMETRY (with its *CYCLIC SYMMETRY MODEL), and one "slave,
// master" data line. Multistage ties are another analysis and are refused. The surface names
// are resolved at the end of the deck (tie_builder.cpp): ccx allows the surfaces after the
// *TIE.
#include <algorithm>
#include <string_view>
#include <utility>

#include "inp/keyword_handlers.hpp"
#include "inp/record_access.hpp"

namespace kontakt::inp {

namespace {

/// ccx uses its default for a tolerance below this (including zero and negative values).
constexpr Real kSmallestTolerance = 1e-10;

std::optional<Real> position_tolerance(const Record& record, DeckState& state) {
  const Param* param = find_param(record, "POSITIONTOLERANCE");
  if (param == nullptr) return std::nullopt;
  if (param->value.empty()) fail(record, "POSITION TOLERANCE= needs a value");
  const std::optional<Real> value = parse_real(param->value);
  if (!value) fail(record, "POSITION TOLERANCE=" + param->value + " is not a number");
  if (*value < kSmallestTolerance) {
    state.warn(record.where, record.keyword,
               "POSITION TOLERANCE=" + param->value +
                   " is below 1e-10: the default (2.5 % of a typical master element size) is "
                   "used, as in ccx");
    return std::nullopt;
  }
  return value;
}

/// ADJUST=NO keeps the slave nodes where they are; ADJUST=YES is the default spelled out.
bool adjust(const Record& record) {
  const std::optional<std::string> value = name_value(record, "ADJUST");
  if (!value || *value == "YES") return true;
  if (*value == "NO") return false;
  fail(record, "ADJUST=" + *value + ": expected NO (or YES, the default)");
}

/// SCHEME=: a surface-to-surface scheme (TIED contact is face to face).
std::optional<model::ContactScheme> scheme(const Record& record) {
  const std::optional<std::string> name = name_value(record, "SCHEME");
  if (!name) return std::nullopt;
  const std::optional<model::ContactScheme> parsed = model::contact_scheme_from_name(*name);
  if (!parsed)
    fail(record, "SCHEME=" + *name + " is not a contact scheme (" +
                     model::contact_scheme_names() + ")");
  if (parsed->kind == model::ContactScheme::Kind::NodeToSurface)
    fail(record, "SCHEME=" + *name + ": a tie through contact is face to face; use a "
                 "surface-to-surface scheme (lgc7, the default of surface-to-surface pairs)");
  return parsed;
}

}  // namespace

void handle_tie(const Record& record, DeckState& state) {
  if (has_param(record, "MULTISTAGE"))
    fail(record, "MULTISTAGE ties are not supported (multistage analyses are out of Kontakt's "
                 "scope)");
  check_params(record, {"NAME", "POSITIONTOLERANCE", "ADJUST", "SCHEME", "CYCLICSYMMETRY"});
  const std::optional<std::string> name = name_value(record, "NAME");
  if (!name) fail(record, "NAME= is required (the tie name is lacking)");
  for (const model::Tie& other : state.model.ties)
    if (other.name == *name)
      fail(record, "tie " + *name + " is defined twice (first at " + other.where.file + ":" +
                       std::to_string(other.where.line) + ")");
  model::Tie tie;
  tie.name = *name;
  tie.position_tolerance = position_tolerance(record, state);
  tie.adjust = adjust(record);
  tie.scheme = scheme(record);
  tie.cyclic = has_param(record, "CYCLICSYMMETRY");
  if (tie.cyclic && tie.scheme)
    fail(record, "SCHEME= ties through contact; a CYCLIC SYMMETRY tie is made of equations");
  require_line_count(record, 1, 1);
  const DataLine& line = record.lines.front();
  require_field_count(record, line, 2, 2);
  tie.slave = remove_blanks(to_upper(line.fields[0]));
  tie.master = remove_blanks(to_upper(line.fields[1]));
  if (tie.slave.empty() || tie.master.empty())
    fail(record, line, "expected slave surface, master surface");
  tie.where = line.where;
  state.model.ties.push_back(std::move(tie));
}

void handle_cyclic_symmetry_model(const Record& record, DeckState& state) {
  check_params(record, {"N", "TIE", "ELSET", "NGRAPH", "CHECK"});
  model::CyclicSymmetry cyclic;
  const std::optional<int> sectors = int_param(record, "N");
  if (!sectors || *sectors < 2) fail(record, "N= (the number of sectors, at least 2) is required");
  cyclic.sectors = *sectors;
  const std::optional<int> graphs = int_param(record, "NGRAPH");
  if (graphs && *graphs != 1)
    fail(record, "NGRAPH=" + std::to_string(*graphs) +
                     ": results are written for the modelled sector only (NGRAPH=1)");
  const std::optional<std::string> tie = name_value(record, "TIE");
  if (!tie) fail(record, "TIE= (the CYCLIC SYMMETRY tie) is required");
  const auto found = std::find_if(state.model.ties.begin(), state.model.ties.end(),
                                  [&](const model::Tie& t) { return t.name == *tie; });
  if (found == state.model.ties.end())
    fail(record, "TIE=" + *tie + ": no *TIE of that name before this card");
  if (!found->cyclic) fail(record, "TIE=" + *tie + " is not a CYCLIC SYMMETRY tie");
  for (const model::CyclicSymmetry& other : state.model.cyclic_symmetry)
    if (other.tie == *tie)
      fail(record, "tie " + *tie + " has a *CYCLIC SYMMETRY MODEL already (at " +
                       other.where.file + ":" + std::to_string(other.where.line) + ")");
  cyclic.tie = *tie;
  cyclic.elset = name_value(record, "ELSET").value_or("");
  if (!cyclic.elset.empty() && !state.element_sets.count(cyclic.elset))
    fail(record, "ELSET=" + cyclic.elset + " is not defined");
  require_line_count(record, 1, 1);
  const DataLine& line = record.lines.front();
  require_field_count(record, line, 6, 6);
  for (int k = 0; k < 3; ++k) {
    cyclic.axis_from[k] = real_field(record, line, static_cast<std::size_t>(k));
    cyclic.axis_to[k] = real_field(record, line, static_cast<std::size_t>(k) + 3);
  }
  if ((cyclic.axis_to - cyclic.axis_from).norm() == 0)
    fail(record, line, "the two points of the axis coincide");
  cyclic.where = line.where;
  state.model.cyclic_symmetry.push_back(std::move(cyclic));
}

}  // namespace kontakt::inp
