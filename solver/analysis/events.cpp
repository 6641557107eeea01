#include "analysis/events.hpp"

#include <limits>
#include <nlohmann/json.hpp>

namespace kontakt::analysis {

namespace {

using nlohmann::json;

constexpr Event::Kind kKinds[] = {Event::Kind::Step,    Event::Kind::Increment,
                                  Event::Kind::Iteration, Event::Kind::Cutback,
                                  Event::Kind::Output,  Event::Kind::Warning,
                                  Event::Kind::Done,    Event::Kind::Error};

/// Kinds that carry the time position of the solver.
bool has_times(Event::Kind kind) {
  return kind == Event::Kind::Increment || kind == Event::Kind::Iteration ||
         kind == Event::Kind::Output || kind == Event::Kind::Cutback;
}

/// Reads field `name` of `j` into `out` when present; false when it has the wrong type.
/// A null number (how nlohmann writes NaN) leaves the default.
bool read(const json& j, const char* name, int& out) {
  const auto it = j.find(name);
  if (it == j.end()) return true;
  if (!it->is_number_integer()) return false;
  const auto v = it->get<std::int64_t>();
  if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) return false;
  out = static_cast<int>(v);
  return true;
}

bool read(const json& j, const char* name, Real& out) {
  const auto it = j.find(name);
  if (it == j.end() || it->is_null()) return true;
  if (!it->is_number()) return false;
  out = it->get<Real>();
  return true;
}

bool read(const json& j, const char* name, std::string& out) {
  const auto it = j.find(name);
  if (it == j.end()) return true;
  if (!it->is_string()) return false;
  out = it->get<std::string>();
  return true;
}

bool read_summary(const json& j, Event& e) {
  const auto it = j.find("summary");
  if (it == j.end()) return true;
  if (!it->is_object()) return false;
  const json& s = *it;
  e.has_contact = s.contains("max_contact_pressure");
  if (const auto t = s.find("times"); t != s.end()) {
    if (!t->is_object()) return false;
    PhaseTimes& times = e.times;
    if (!(read(*t, "contact_search", times.contact_search) && read(*t, "pattern", times.pattern) &&
          read(*t, "elements", times.elements) && read(*t, "contact", times.contact) &&
          read(*t, "factorisation", times.factorisation) && read(*t, "solve", times.solve)))
      return false;
  }
  return read(s, "iterations", e.iterations) && read(s, "max_displacement", e.max_displacement) &&
         read(s, "max_mises", e.max_mises) &&
         read(s, "max_contact_pressure", e.max_contact_pressure) &&
         read(s, "total_contact_force", e.total_contact_force) &&
         read(s, "drift_redos", e.drift_redos) &&
         read(s, "drift_refreezes", e.drift_refreezes);
}

}  // namespace

const char* event_kind_name(Event::Kind kind) {
  switch (kind) {
    case Event::Kind::Step: return "step";
    case Event::Kind::Increment: return "increment";
    case Event::Kind::Iteration: return "iteration";
    case Event::Kind::Cutback: return "cutback";
    case Event::Kind::Output: return "output";
    case Event::Kind::Warning: return "warning";
    case Event::Kind::Done: return "done";
    case Event::Kind::Error: return "error";
  }
  return "unknown";
}

std::string to_json_line(const Event& e) {
  json j;
  j["event"] = event_kind_name(e.kind);
  if (e.step > 0) j["step"] = e.step;
  if (e.increment > 0) j["increment"] = e.increment;
  if (e.attempt > 0) j["attempt"] = e.attempt;
  if (e.iteration > 0) j["iteration"] = e.iteration;
  if (has_times(e.kind)) {
    j["step_time"] = e.step_time;
    j["total_time"] = e.total_time;
    j["dt"] = e.dt;
  }
  if (e.residual >= 0) j["residual"] = e.residual;
  if (e.correction >= 0) j["correction"] = e.correction;
  if (e.contact_elements >= 0) j["contact_elements"] = e.contact_elements;
  if (e.stick >= 0) j["stick"] = e.stick;
  if (e.slip >= 0) j["slip"] = e.slip;
  if (e.stabilisation > 0) j["stabilisation"] = e.stabilisation;
  if (e.stabilisation_energy >= 0) j["stabilisation_energy"] = e.stabilisation_energy;
  if (e.strain_energy >= 0) j["strain_energy"] = e.strain_energy;
  if (!e.status.empty()) j["status"] = e.status;
  if (!e.message.empty()) j["message"] = e.message;
  if (e.kind == Event::Kind::Done) {
    j["summary"] = {{"iterations", e.iterations},
                    {"max_displacement", e.max_displacement},
                    {"max_mises", e.max_mises}};
    const PhaseTimes& t = e.times;
    if (t.elements > 0)
      j["summary"]["times"] = {{"contact_search", t.contact_search}, {"pattern", t.pattern},
                               {"elements", t.elements}, {"contact", t.contact},
                               {"factorisation", t.factorisation}, {"solve", t.solve}};
    if (e.has_contact) {
      j["summary"]["max_contact_pressure"] = e.max_contact_pressure;
      j["summary"]["total_contact_force"] = e.total_contact_force;
      j["summary"]["drift_redos"] = e.drift_redos;
      j["summary"]["drift_refreezes"] = e.drift_refreezes;
    }
  }
  j["wall_time"] = e.wall_time;
  // Replacement, not an exception, for invalid UTF-8 in a message (a deck's bytes quoted back).
  return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::optional<Event> from_json_line(std::string_view line) {
  const json j = json::parse(line.begin(), line.end(), nullptr, false);
  if (j.is_discarded() || !j.is_object()) return std::nullopt;
  const auto kind = j.find("event");
  if (kind == j.end() || !kind->is_string()) return std::nullopt;
  Event e;
  bool known = false;
  for (const Event::Kind k : kKinds)
    if (*kind == event_kind_name(k)) {
      e.kind = k;
      known = true;
    }
  if (!known) return std::nullopt;
  const bool ok = read(j, "step", e.step) && read(j, "increment", e.increment) &&
                  read(j, "attempt", e.attempt) && read(j, "iteration", e.iteration) &&
                  read(j, "step_time", e.step_time) && read(j, "total_time", e.total_time) &&
                  read(j, "dt", e.dt) && read(j, "residual", e.residual) &&
                  read(j, "correction", e.correction) &&
                  read(j, "contact_elements", e.contact_elements) &&
                  read(j, "stick", e.stick) && read(j, "slip", e.slip) &&
                  read(j, "stabilisation", e.stabilisation) &&
                  read(j, "stabilisation_energy", e.stabilisation_energy) &&
                  read(j, "strain_energy", e.strain_energy) &&
                  read(j, "status", e.status) && read(j, "message", e.message) &&
                  read(j, "wall_time", e.wall_time) && read_summary(j, e);
  if (!ok) return std::nullopt;
  return e;
}

}  // namespace kontakt::analysis
