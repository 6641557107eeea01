// A job's event log: the SSE stream and the .sta-like / .cvg-like tables with a `since` cursor.
#include <nlohmann/json.hpp>

#include "server/handlers/routes.hpp"
#include "server/problem.hpp"
#include "server/sse_format.hpp"

using nlohmann::json;

namespace kontakt::server::handlers {

namespace {

constexpr int kDefaultRows = 1000, kMaxRows = 10000;

HttpResponse event_stream(ApiContext& ctx, const HttpRequest& request, const std::string& id) {
  if (!ctx.store.find_job(id)) return job_not_found(id);
  const auto after = sse_resume_point(request.header("last-event-id"), request.param("since"));
  if (!after) return invalid_parameter("Last-Event-ID", "a whole number (an event id)");
  HttpResponse r;
  r.content_type = "text/event-stream";
  const auto follow = request.param("follow");
  if (follow && *follow != "true" && *follow != "false")
    return invalid_parameter("follow", "true or false");
  r.events = EventStreamBody{.job_id = id, .after_seq = *after, .follow = follow != "false"};
  return r;
}

/// {"<table>": [event rows with seq and run], "next_since": cursor for the next call}.
HttpResponse event_table(ApiContext& ctx, const HttpRequest& request, const std::string& id,
                         const std::string& table, const std::vector<std::string>& kinds) {
  if (!ctx.store.find_job(id)) return job_not_found(id);
  const auto since = sse_resume_point(std::nullopt, request.param("since"));
  if (!since) return invalid_parameter("since", "a whole number (a seq of an earlier row)");
  int limit = kDefaultRows;
  if (const auto text = request.param("limit")) {
    char* end = nullptr;
    const long n = std::strtol(text->c_str(), &end, 10);
    if (text->empty() || *end || n < 1 || n > kMaxRows)
      return invalid_parameter("limit", "a whole number from 1 to 10000");
    limit = static_cast<int>(n);
  }
  const auto events = ctx.store.events_since(id, *since, kinds, limit);
  json rows = json::array();
  for (const StoredEvent& e : events) {
    json row = json::parse(event_with_position(e));
    if (table == "increments") row["converged"] = e.kind == "increment";
    rows.push_back(std::move(row));
  }
  return json_response(200, {{table, rows}, {"next_since", events.empty() ? *since : events.back().seq}});
}

}  // namespace

void add_event_routes(Router& router, ApiContext& ctx) {
  router.add("GET", "/v1/jobs/{id}/events", [&ctx](const HttpRequest& r, const PathParams& p) {
    return event_stream(ctx, r, p.at("id"));
  });
  router.add("GET", "/v1/jobs/{id}/iterations", [&ctx](const HttpRequest& r, const PathParams& p) {
    return event_table(ctx, r, p.at("id"), "iterations", {"iteration"});
  });
  router.add("GET", "/v1/jobs/{id}/increments", [&ctx](const HttpRequest& r, const PathParams& p) {
    return event_table(ctx, r, p.at("id"), "increments", {"increment", "cutback"});
  });
}

}  // namespace kontakt::server::handlers
