#include "analysis/events.hpp"

#include <nlohmann/json.hpp>

namespace kontakt::analysis {

namespace {
const char* kind_name(Event::Kind kind) {
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
}  // namespace

std::string to_json_line(const Event& e) {
  nlohmann::json j;
  j["event"] = kind_name(e.kind);
  if (e.step > 0) j["step"] = e.step;
  if (e.increment > 0) j["increment"] = e.increment;
  if (e.attempt > 0) j["attempt"] = e.attempt;
  if (e.iteration > 0) j["iteration"] = e.iteration;
  if (e.kind == Event::Kind::Increment || e.kind == Event::Kind::Iteration ||
      e.kind == Event::Kind::Output) {
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
    }
  }
  j["wall_time"] = e.wall_time;
  return j.dump();
}

}  // namespace kontakt::analysis
