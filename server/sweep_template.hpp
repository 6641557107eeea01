// A parametric sweep's decks (POST /v1/sweeps): a deck template with `<name>` placeholders,
// the way CalculiX users' param.py scripts substitute them, and a table of rows (name ->
// value), expanded to one complete deck per row. Every placeholder needs a column and every
// column a placeholder, so a misspelt name is an error rather than a sweep of identical
// decks. Pure.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <variant>
#include <vector>

namespace kontakt::server {

/// One row of the parameter table: placeholder name -> the text that replaces it.
using SweepRow = std::map<std::string, std::string>;

/// A sweep has at most this many rows (one job each; a Slurm array of this size is accepted
/// by Slurm's default MaxArraySize of 1001).
inline constexpr std::size_t kMaxSweepRows = 1000;
/// Values become job labels too: at most this many characters, no control characters.
inline constexpr std::size_t kMaxSweepValue = 256;

/// Why a sweep cannot be expanded: the API field, the 0-based row when one row is at fault.
struct SweepError {
  std::string field;
  std::string message;
  std::optional<std::size_t> row;
};

/// The names of the `<name>` placeholders in `deck` (a name: a letter or `_`, then up to 63 of
/// A-Z a-z 0-9 _ - .). Other `<` are text (`<=` in a comment stays as it is).
std::set<std::string> placeholders(const std::string& deck);

/// `deck_template` with each placeholder replaced by the row's value, one deck per row; a
/// SweepError for an empty or oversized table, a placeholder no column fills, a column no
/// placeholder uses, a row without a value of some column, or a bad value.
std::variant<std::vector<std::string>, SweepError> expand_sweep(
    const std::string& deck_template, const std::vector<SweepRow>& rows);

}  // namespace kontakt::server
