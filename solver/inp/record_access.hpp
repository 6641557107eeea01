// Checked access to a record's parameters and data fields: every failure is an InputError
// naming the file, line and keyword.
#pragma once

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

#include "core/types.hpp"
#include "inp/inp_lexer.hpp"

namespace kontakt::inp {

std::string trim(std::string_view text);
std::string to_upper(std::string_view text);
std::string remove_blanks(std::string_view text);

/// Throws for any parameter not in `allowed` and for repeated parameters.
void check_params(const Record& record, std::initializer_list<std::string_view> allowed);

const Param* find_param(const Record& record, std::string_view name);
bool has_param(const Record& record, std::string_view name);
/// Value of a parameter that must carry one ("NSET=A"); throws when missing or empty.
std::string required_value(const Record& record, std::string_view name);
/// Upper-case, blank-free value (how ccx compares names), or nullopt when absent.
std::optional<std::string> name_value(const Record& record, std::string_view name);
std::optional<int> int_param(const Record& record, std::string_view name);

[[noreturn]] void fail(const Record& record, const std::string& message);
[[noreturn]] void fail(const Record& record, const DataLine& line, const std::string& message);

/// Field `index` (0-based) as a number; the error names the field by 1-based position.
Real real_field(const Record& record, const DataLine& line, std::size_t index);
int int_field(const Record& record, const DataLine& line, std::size_t index);
/// Empty or missing fields give the default.
Real real_field_or(const Record& record, const DataLine& line, std::size_t index, Real fallback);
std::optional<Real> optional_real_field(const Record& record, const DataLine& line,
                                        std::size_t index);
/// Parses a Fortran-style real ("1.d3", "5.", ".5e-2"); nullopt when not a number.
std::optional<Real> parse_real(std::string_view text);
std::optional<int> parse_int(std::string_view text);

/// Optional temperature column `index` of a table row: throws (`what` + " is not supported")
/// when it differs from the temperature seen in an earlier row, kept in `seen`.
void require_one_temperature(const Record& record, const DataLine& line, std::size_t index,
                             std::optional<Real>& seen, const std::string& what);

/// Throws unless the record has between min and max data lines.
void require_line_count(const Record& record, std::size_t min, std::size_t max);
/// Throws unless the line has between min and max fields.
void require_field_count(const Record& record, const DataLine& line, std::size_t min,
                         std::size_t max);

}  // namespace kontakt::inp
