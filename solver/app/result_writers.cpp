#include "app/result_writers.hpp"

namespace kontakt::app {

ResultWriters::ResultWriters(const model::Model& model, const std::filesystem::path& dir,
                             const std::string& job)
    : dat_(model, dir / (job + ".dat")),
      hdf5_(model, dir, job, output::requested_fields(model)) {}

void ResultWriters::on_frame(const model::Step& step, const output::Frame& frame) {
  dat_.write(step, frame);
  if (output::file_output_due(step, frame)) hdf5_.write(frame);
  hdf5_.add_increment({.step = frame.step,
                       .increment = frame.increment,
                       .attempts = 1,
                       .iterations = 1,
                       .total_time = frame.total_time,
                       .step_time = frame.step_time,
                       .dt = frame.step_time,
                       .converged = frame.converged});
}

void ResultWriters::finish() { hdf5_.finish(); }

}  // namespace kontakt::app
