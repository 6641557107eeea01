#include "app/result_writers.hpp"

#include <limits>

namespace kontakt::app {

ResultWriters::ResultWriters(const model::Model& model, const std::filesystem::path& dir,
                             const std::string& job)
    : dat_(model, dir / (job + ".dat")),
      hdf5_(model, dir, job, output::requested_fields(model)) {
  if (output::wants_frd(model)) frd_.emplace(model, dir / (job + ".frd"));
}

void ResultWriters::on_frame(const model::Step& step, const output::Frame& frame) {
  dat_.write(step, frame);
  if (output::file_output_due(step, frame)) hdf5_.write(frame);
  if (frd_) frd_->write(step, frame);
}

void ResultWriters::on_event(const analysis::Event& e) {
  using Kind = analysis::Event::Kind;
  if (e.kind != Kind::Increment && e.kind != Kind::Cutback) return;
  hdf5_.add_increment({.step = e.step,
                       .increment = e.increment,
                       .attempts = e.attempt,
                       .iterations = e.iteration,
                       .total_time = e.total_time,
                       .step_time = e.step_time,
                       .dt = e.dt,
                       .converged = e.kind == Kind::Increment,
                       .stabilisation_energy = e.stabilisation_energy >= 0
                                                   ? e.stabilisation_energy
                                                   : std::numeric_limits<Real>::quiet_NaN(),
                       .strain_energy = e.strain_energy >= 0
                                            ? e.strain_energy
                                            : std::numeric_limits<Real>::quiet_NaN()});
}

void ResultWriters::finish() { hdf5_.finish(); }

}  // namespace kontakt::app
