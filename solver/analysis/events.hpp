// Progress events of a run: what the JSONL log, the progress line and the daemon see. One
// JSON schema (proto/openapi.yaml, `Event`): to_json_line writes it, from_json_line reads it
// back (the daemon decodes what a job's process reports over its pipe).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "core/types.hpp"

namespace kontakt::analysis {

/// Where a run's wall time went, in seconds (the rest: output, loads, bookkeeping).
struct PhaseTimes {
  Real contact_search = 0;  ///< contact points and pairing at the start of increments
  Real pattern = 0;         ///< sparsity pattern and symbolic factorisation for contact groups
  Real elements = 0;        ///< element tangents and forces, assembled
  Real contact = 0;         ///< contact forces and tangents per evaluation
  Real factorisation = 0;
  Real solve = 0;           ///< triangular solves with refinement
};

/// One event; fields that do not apply to a kind stay at their defaults and are not written.
struct Event {
  enum class Kind { Step, Increment, Iteration, Cutback, Output, Warning, Done, Error };
  Kind kind = Kind::Step;
  int step = 0, increment = 0, attempt = 0, iteration = 0;
  Real step_time = 0, total_time = 0, dt = 0;
  Real residual = -1, correction = -1;  ///< ccx-style ratios in %, -1 when not measured
  int contact_elements = -1;            ///< active contact elements, -1 for models without contact
  int stick = -1, slip = -1;            ///< of them sticking and slipping; -1 without friction
  /// Iteration: the contact stabilisation's spring factor (0: off). Increment (models with
  /// contact): the energy the stabilisation absorbed in it and the strain energy at its end
  /// (-1: not reported).
  Real stabilisation = 0;
  Real stabilisation_energy = -1, strain_energy = -1;
  Real wall_time = 0;                   ///< seconds since the run started
  std::string status{};                 ///< Done: converged | not_converged | input_error | error
  std::string message{};                ///< Warning, Error and Done: human-readable text
  // Done summary
  int iterations = 0;
  Real max_displacement = 0, max_mises = 0;
  bool has_contact = false;             ///< the contact figures below apply
  Real max_contact_pressure = 0, total_contact_force = 0;
  int drift_redos = 0;                  ///< increments redone because frozen projections drifted
  int drift_refreezes = 0;              ///< contact geometries frozen again for the same reason
  PhaseTimes times{};                   ///< nonlinear runs
};

class EventSink {
 public:
  virtual ~EventSink() = default;
  virtual void on_event(const Event& event) = 0;
};

/// Serialises an event as one JSON object (no trailing newline).
std::string to_json_line(const Event& event);

/// The inverse of to_json_line: every field it writes is read back, fields it leaves out keep
/// their defaults. nullopt for anything else: not a JSON object, an unknown `event`, a field of
/// the wrong type or out of range.
std::optional<Event> from_json_line(std::string_view line);

/// "step", "increment", ..., "done": the `event` field of a kind.
const char* event_kind_name(Event::Kind kind);

}  // namespace kontakt::analysis
