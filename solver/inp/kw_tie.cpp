// *TIE (ccx 2.20, ties.f): NAME= (required), POSITION TOLERANCE=, ADJUST=NO, our SCHEME= (tie
// through TIED contact), and one "slave, master" data line. Ties for cyclic symmetry and multistage periodicity are another
// analysis and are refused. The surface names are resolved at the end of the deck
// (tie_builder.cpp): ccx allows the surfaces after the *TIE.
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
  using Spelling = std::pair<std::string_view, std::string_view>;  // lookup, display
  for (const auto& [key, shown] : {Spelling{"CYCLICSYMMETRY", "CYCLIC SYMMETRY"},
                                   Spelling{"MULTISTAGE", "MULTISTAGE"}})
    if (has_param(record, key))
      fail(record, std::string(shown) +
                       " ties are not supported (Kontakt ties surfaces for tied contact only; "
                       "cyclic symmetry and multistage analyses are out of its scope)");
  check_params(record, {"NAME", "POSITIONTOLERANCE", "ADJUST", "SCHEME"});
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

}  // namespace kontakt::inp
