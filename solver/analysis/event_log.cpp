#include "analysis/event_log.hpp"

#include "core/error.hpp"

namespace kontakt::analysis {

JsonlEventLog::JsonlEventLog(const std::filesystem::path& path) : out_(path) {
  if (!out_) throw SolverError("cannot write the event log " + path.string());
}

void JsonlEventLog::on_event(const Event& event) {
  out_ << to_json_line(event) << '\n';
  out_.flush();
}

}  // namespace kontakt::analysis
