#include "server/sweep_template.hpp"

#include <cctype>

namespace kontakt::server {

namespace {

constexpr std::size_t kMaxName = 64;

bool starts_name(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }

bool in_name(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
}

/// The placeholder `<name>` starting at `at` (a '<'): its length, or 0 when there is none.
std::size_t placeholder_at(const std::string& deck, std::size_t at, std::string* name) {
  std::size_t end = at + 1;
  if (end >= deck.size() || !starts_name(deck[end])) return 0;
  while (end < deck.size() && in_name(deck[end]) && end - at <= kMaxName) ++end;
  if (end >= deck.size() || deck[end] != '>' || end - at - 1 > kMaxName) return 0;
  if (name) *name = deck.substr(at + 1, end - at - 1);
  return end - at + 1;
}

std::optional<std::string> check_value(const std::string& v) {
  if (v.size() > kMaxSweepValue) return "longer than 256 characters";
  for (unsigned char c : v)
    if (c < 0x20 || c == 0x7f) return "holds a control character (a line break would change the deck's lines)";
  return std::nullopt;
}

std::string substituted(const std::string& deck, const SweepRow& row) {
  std::string out;
  out.reserve(deck.size());
  std::string name;
  for (std::size_t at = 0; at < deck.size();) {
    const std::size_t n = deck[at] == '<' ? placeholder_at(deck, at, &name) : 0;
    if (n == 0) {
      out += deck[at++];
      continue;
    }
    out += row.at(name);
    at += n;
  }
  return out;
}

}  // namespace

std::set<std::string> placeholders(const std::string& deck) {
  std::set<std::string> names;
  std::string name;
  for (std::size_t at = deck.find('<'); at != std::string::npos; at = deck.find('<', at + 1))
    if (placeholder_at(deck, at, &name) > 0) names.insert(name);
  return names;
}

std::variant<std::vector<std::string>, SweepError> expand_sweep(
    const std::string& deck_template, const std::vector<SweepRow>& rows) {
  if (rows.empty()) return SweepError{"rows", "the parameter table has no row", std::nullopt};
  if (rows.size() > kMaxSweepRows)
    return SweepError{"rows",
                      std::to_string(rows.size()) + " rows: a sweep has at most " +
                          std::to_string(kMaxSweepRows),
                      std::nullopt};
  const std::set<std::string> names = placeholders(deck_template);
  if (names.empty())
    return SweepError{"template", "the template has no <name> placeholder", std::nullopt};
  // The first row's columns are the table's; every row must have the same.
  for (const auto& [column, value] : rows.front())
    if (!names.contains(column))
      return SweepError{"rows", "column '" + column + "' is used by no <" + column +
                                    "> placeholder in the template",
                        0};
  for (const std::string& name : names)
    if (!rows.front().contains(name))
      return SweepError{"template", "placeholder <" + name + "> has no column in the rows",
                        std::nullopt};
  std::vector<std::string> decks;
  decks.reserve(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (const std::string& name : names)
      if (!rows[i].contains(name))
        return SweepError{"rows", "row " + std::to_string(i) + " has no value of '" + name + "'", i};
    if (rows[i].size() != names.size())
      for (const auto& [column, value] : rows[i])
        if (!names.contains(column))
          return SweepError{"rows", "row " + std::to_string(i) + ": column '" + column +
                                        "' is used by no placeholder",
                            i};
    for (const auto& [column, value] : rows[i])
      if (const auto bad = check_value(value))
        return SweepError{"rows", "row " + std::to_string(i) + ", '" + column + "': " + *bad, i};
    decks.push_back(substituted(deck_template, rows[i]));
  }
  return decks;
}

}  // namespace kontakt::server
