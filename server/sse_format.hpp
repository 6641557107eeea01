// Server-Sent Events framing of stored job events (WHATWG HTML, "server-sent events"): each
// event carries `id:` = its sequence number, so a client resumes with Last-Event-ID.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "server/job_record.hpp"

namespace kontakt::server {

/// "id: 7\nevent: iteration\ndata: {...}\n\n"; the data gets "seq" and "run" members.
std::string sse_frame(const StoredEvent& event);

/// A comment frame that keeps idle connections (and proxies) open.
inline constexpr const char* kSseKeepAlive = ": keep-alive\n\n";

/// The resume point of a stream request: Last-Event-ID, else ?since=, else 0. nullopt when
/// the value is not a whole number.
std::optional<std::int64_t> sse_resume_point(const std::optional<std::string>& last_event_id,
                                             const std::optional<std::string>& since);

/// The event as JSON with its "seq" and "run" added (tables and SSE data).
std::string event_with_position(const StoredEvent& event);

}  // namespace kontakt::server
