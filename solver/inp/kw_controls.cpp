// *CONTROLS: the mechanical solution controls of ccx (TIME INCREMENTATION, FIELD), the
// contact controls (CONTACT, LINE SEARCH), RESET. Settings stay in force for later steps until
// RESET, as in ccx.
#include <type_traits>

#include "inp/keyword_handlers.hpp"
#include "inp/record_access.hpp"

namespace kontakt::inp {

namespace {

/// Overwrites `target` with field `index` when the field is given (blank keeps the value).
template <class T>
void set_if_given(const Record& record, const DataLine& line, std::size_t index, T& target) {
  if (const std::optional<Real> v = optional_real_field(record, line, index)) {
    if constexpr (std::is_integral_v<T>) {
      if (*v != static_cast<Real>(static_cast<T>(*v)) || *v <= 0)
        fail(record, line, "field " + std::to_string(index + 1) + " must be a positive whole number");
      target = static_cast<T>(*v);
    } else {
      if (!(*v >= 0)) fail(record, line, "field " + std::to_string(index + 1) + " must not be negative");
      target = *v;
    }
  }
}

void read_time_incrementation(const Record& record, model::SolutionControls& c) {
  require_line_count(record, 1, 2);
  const DataLine& ints = record.lines[0];
  require_field_count(record, ints, 1, 8);
  // I_0 I_R I_P I_C I_L I_G I_S I_A (I_S unused by ccx)
  int unused = 0;
  int* targets[] = {&c.divergence_check_from, &c.log_estimate_from, &c.loose_residual_after,
                    &c.max_iterations,       &c.slow_increment_iterations,
                    &c.fast_increment_iterations, &unused, &c.max_cutbacks};
  for (std::size_t k = 0; k < ints.fields.size(); ++k) set_if_given(record, ints, k, *targets[k]);
  if (record.lines.size() < 2) return;
  const DataLine& reals = record.lines[1];
  require_field_count(record, reals, 1, 8);
  // D_F D_C D_B D_A D_S D_H D_D W_G (D_A, D_S, D_H, W_G have no mechanical effect)
  Real ignored = 0;
  Real* factors[] = {&c.divergence_cutback, &c.slow_cutback, &c.slow_next_factor, &ignored,
                     &ignored, &ignored, &c.growth_factor, &ignored};
  for (std::size_t k = 0; k < reals.fields.size(); ++k) set_if_given(record, reals, k, *factors[k]);
}

/// The one data line of FIELD, LINE SEARCH and CONTACT, with up to `max_fields` values.
const DataLine& single_data_line(const Record& record, std::size_t max_fields) {
  require_line_count(record, 1, 1);
  const DataLine& line = record.lines[0];
  require_field_count(record, line, 1, max_fields);
  return line;
}

void read_field(const Record& record, model::SolutionControls& c) {
  const DataLine& line = single_data_line(record, 8);
  // R_n C_n q_0 q_u R_p epsilon C_epsilon R_l
  Real* targets[] = {&c.residual_tolerance, &c.correction_tolerance, &c.initial_force_average,
                     &c.fixed_force_average, &c.loose_residual_tolerance, &c.zero_flux_ratio,
                     &c.zero_flux_correction_tolerance, &c.linear_residual_ratio};
  for (std::size_t k = 0; k < line.fields.size(); ++k) set_if_given(record, line, k, *targets[k]);
}

/// LINE SEARCH: "unused, lower bound, upper bound, unused, unused". ccx's manual labels the
/// 2nd value the maximum, but its code uses it as the lower bound (defaults 0.25 and 1.01), so
/// decks written for ccx mean that (ccx-behaviour.md section 1.6).
void read_line_search(const Record& record, model::ContactControls& c) {
  const DataLine& line = single_data_line(record, 5);
  set_if_given(record, line, 1, c.line_search_min);
  set_if_given(record, line, 2, c.line_search_max);
  if (!(c.line_search_min > 0)) fail(record, line, "the lower bound (field 2) must be positive");
  if (c.line_search_max < c.line_search_min)
    fail(record, line, "the upper bound (field 3) is below the lower bound (field 2)");
}

/// CONTACT: "delcon, alea, kscalemax, itf2f" with ccx's ranges.
void read_contact(const Record& record, model::ContactControls& c) {
  const DataLine& line = single_data_line(record, 4);
  set_if_given(record, line, 0, c.delcon);
  set_if_given(record, line, 1, c.alea);
  set_if_given(record, line, 2, c.kscalemax);
  set_if_given(record, line, 3, c.itf2f);
  if (c.alea > 1) fail(record, line, "alea (field 2) must lie in [0, 1]");
  if (c.kscalemax < 1) fail(record, line, "kscalemax (field 3) must be at least 1");
}

}  // namespace

void handle_controls(const Record& record, DeckState& state) {
  check_params(record, {"PARAMETERS", "RESET", "FIELD"});
  model::SolutionControls& c = state.active.controls;
  model::ContactControls& contact = state.active.contact_controls;
  if (has_param(record, "RESET")) {
    c = model::SolutionControls{};
    contact = model::ContactControls{};
  } else {
    const std::optional<std::string> which = name_value(record, "PARAMETERS");
    if (!which)
      fail(record,
           "PARAMETERS= (TIME INCREMENTATION, FIELD, CONTACT or LINE SEARCH) or RESET is required");
    // Blanks inside keyword values do not count (ccx): TIME INCREMENTATION = TIMEINCREMENTATION.
    const std::string kind = remove_blanks(to_upper(*which));
    if (kind == "TIMEINCREMENTATION") {
      read_time_incrementation(record, c);
    } else if (kind == "FIELD") {
      if (const auto field = name_value(record, "FIELD"); field && to_upper(*field) != "DISPLACEMENT")
        fail(record, "FIELD=" + *field + " is not supported (only DISPLACEMENT)");
      read_field(record, c);
    } else if (kind == "LINESEARCH") {
      read_line_search(record, contact);
    } else if (kind == "CONTACT") {
      read_contact(record, contact);
    } else {
      fail(record, "PARAMETERS=" + kind + " is not supported");
    }
  }
  state.open_step->step.controls = c;
  state.open_step->step.contact_controls = contact;
}

}  // namespace kontakt::inp
