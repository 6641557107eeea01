#include "server/store_event_sink.hpp"

#include <algorithm>

namespace kontakt::server {

JobProgress advance_progress(JobProgress p, const analysis::Event& e) {
  using Kind = analysis::Event::Kind;
  switch (e.kind) {
    case Kind::Step:
      p.step = e.step;
      p.increment = p.iteration = p.attempt = 0;
      break;
    case Kind::Iteration:
      p.iteration = e.iteration;
      if (e.residual >= 0) p.residual = e.residual;
      [[fallthrough]];
    case Kind::Increment:
    case Kind::Cutback:
      p.step = e.step;
      p.increment = e.increment;
      p.attempt = e.attempt;
      if (e.kind != Kind::Iteration) p.iteration = e.iteration;
      p.step_time = e.step_time;
      p.total_time = e.total_time;
      p.dt = e.dt;
      if (e.contact_elements >= 0) p.contact_elements = e.contact_elements;
      break;
    default:
      break;
  }
  return p;
}

void StoreEventSink::on_event(const analysis::Event& event) {
  const JobProgress next = advance_progress(progress_, event);
  const bool moved = event.kind == analysis::Event::Kind::Step ||
                     event.kind == analysis::Event::Kind::Increment ||
                     event.kind == analysis::Event::Kind::Iteration ||
                     event.kind == analysis::Event::Kind::Cutback;
  progress_ = next;
  if (event.kind == analysis::Event::Kind::Iteration) ++summary_.iterations;
  if (event.kind == analysis::Event::Kind::Done && event.status == "converged") {
    summary_.iterations = std::max(summary_.iterations, event.iterations);
    summary_.max_displacement = event.max_displacement;
    summary_.max_mises = event.max_mises;
    if (event.has_contact) {
      summary_.max_contact_pressure = event.max_contact_pressure;
      summary_.total_contact_force = event.total_contact_force;
    }
  }
  store_.append_event(id_, analysis::event_kind_name(event.kind), analysis::to_json_line(event),
                      moved ? std::optional(next) : std::nullopt);
}

}  // namespace kontakt::server
