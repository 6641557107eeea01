#include "server/sse_format.hpp"

#include <nlohmann/json.hpp>

#include "server/job_json.hpp"

namespace kontakt::server {

std::string event_with_position(const StoredEvent& event) {
  nlohmann::json j = nlohmann::json::parse(event.data);
  j["seq"] = event.seq;
  j["run"] = event.run;
  return json_text(j);
}

std::string sse_frame(const StoredEvent& event) {
  // The JSON dump has no raw newlines, so one data line carries the whole event.
  return "id: " + std::to_string(event.seq) + "\nevent: " + event.kind +
         "\ndata: " + event_with_position(event) + "\n\n";
}

std::optional<std::int64_t> sse_resume_point(const std::optional<std::string>& last_event_id,
                                             const std::optional<std::string>& since) {
  const auto& text = last_event_id ? last_event_id : since;
  if (!text) return 0;
  if (text->empty() || text->size() > 18) return std::nullopt;
  for (char c : *text)
    if (c < '0' || c > '9') return std::nullopt;
  return std::stoll(*text);
}

}  // namespace kontakt::server
