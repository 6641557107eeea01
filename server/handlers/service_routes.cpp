// Service endpoints: liveness, Prometheus metrics, the queue, the OpenAPI document, and the
// dashboard's pages and assets (public: they hold no data; the pages call the API).
#include <nlohmann/json.hpp>

#include "server/embedded_assets.hpp"
#include "server/handlers/routes.hpp"
#include "server/job_json.hpp"
#include "server/metrics.hpp"
#include "server/problem.hpp"

namespace kontakt::server::handlers {

namespace {

HttpResponse healthz(ApiContext& ctx) {
  const StoreCounts counts = ctx.store.counts();  // also proves the database answers
  return json_response(200, {{"status", "ok"},
                             {"version", KONTAKT_VERSION},
                             {"workers", ctx.control.n_workers()},
                             {"busy_workers", ctx.control.n_busy()},
                             {"queued", counts.queued}});
}

HttpResponse metrics(ApiContext& ctx) {
  HttpResponse r;
  r.content_type = "text/plain; version=0.0.4; charset=utf-8";
  r.body = prometheus_text(ctx.store.counts(), ctx.store.run_durations(), ctx.control.n_workers(),
                           ctx.control.n_busy());
  return r;
}

HttpResponse queue(ApiContext& ctx) {
  return json_response(200, queue_document(ctx.store.counts(), ctx.control.n_workers(),
                                           ctx.control.n_busy()));
}

// Pages may load only the daemon's own scripts, styles and API: no inline script, no
// third-party origin, no framing.
constexpr const char* kPagePolicy =
    "default-src 'self'; img-src 'self' data: blob:; object-src 'none'; base-uri 'none'; "
    "form-action 'self'; frame-ancestors 'none'";

/// An embedded file, revalidated by ETag on every use (a new daemon may ship a new dashboard).
HttpResponse asset(const HttpRequest& request, const std::string& name) {
  const auto found = find_asset(name);
  if (!found) return problem(404, "not_found", "no resource " + request.path);
  const std::string etag = "\"" + std::string(found->etag) + "\"";
  HttpResponse r;
  r.headers = {{"ETag", etag}, {"Cache-Control", "no-cache"}, {"X-Content-Type-Options", "nosniff"}};
  if (found->media_type.rfind("text/html", 0) == 0) {
    r.headers.emplace_back("Content-Security-Policy", kPagePolicy);
    r.headers.emplace_back("Referrer-Policy", "no-referrer");
  }
  if (request.header("if-none-match") == etag) {
    r.status = 304;
    r.content_type.clear();
    return r;
  }
  r.content_type = std::string(found->media_type);
  r.body = std::string(found->body);
  return r;
}

void add_page(Router& router, const std::string& pattern, const std::string& asset_name) {
  router.add(
      "GET", pattern,
      [asset_name](const HttpRequest& r, const PathParams&) { return asset(r, asset_name); },
      Access::Public);
}

}  // namespace

void add_service_routes(Router& router, ApiContext& ctx) {
  router.add(
      "GET", "/healthz", [&ctx](const HttpRequest&, const PathParams&) { return healthz(ctx); },
      Access::Public);
  router.add("GET", "/metrics", [&ctx](const HttpRequest&, const PathParams&) { return metrics(ctx); });
  router.add("GET", "/v1/queue", [&ctx](const HttpRequest&, const PathParams&) { return queue(ctx); });
  router.add("GET", "/v1/openapi.json", [](const HttpRequest& r, const PathParams&) {
    return asset(r, "v1/openapi.json");
  });
  add_page(router, "/", "index.html");
  add_page(router, "/jobs/{id}", "job.html");
  add_page(router, "/sweeps", "sweeps.html");
  // {name} is one path segment, so "v1/openapi.json" (behind the token) is never reached here.
  router.add(
      "GET", "/assets/{name}",
      [](const HttpRequest& r, const PathParams& p) { return asset(r, p.at("name")); },
      Access::Public);
}

Router make_router(ApiContext& ctx) {
  Router router;
  add_job_routes(router, ctx);
  add_event_routes(router, ctx);
  add_result_routes(router, ctx);
  add_sweep_routes(router, ctx);
  add_service_routes(router, ctx);
  return router;
}

}  // namespace kontakt::server::handlers
