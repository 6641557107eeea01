// Service endpoints: liveness, Prometheus metrics, the OpenAPI document, the dashboard.
#include <nlohmann/json.hpp>

#include "server/embedded_assets.hpp"
#include "server/handlers/routes.hpp"
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

HttpResponse asset(const std::string& path) {
  const auto found = find_asset(path);
  if (!found) return problem(404, "not_found", "no resource " + path);
  HttpResponse r;
  r.content_type = std::string(found->media_type);
  r.body = std::string(found->body);
  return r;
}

}  // namespace

void add_service_routes(Router& router, ApiContext& ctx) {
  router.add("GET", "/healthz", [&ctx](const HttpRequest&, const PathParams&) { return healthz(ctx); });
  router.add("GET", "/metrics", [&ctx](const HttpRequest&, const PathParams&) { return metrics(ctx); });
  for (const char* path : {"/v1/openapi.json", "/", "/dashboard.js", "/dashboard.css"})
    router.add("GET", path, [path](const HttpRequest&, const PathParams&) { return asset(path); });
}

Router make_router(ApiContext& ctx) {
  Router router;
  add_job_routes(router, ctx);
  add_event_routes(router, ctx);
  add_result_routes(router, ctx);
  add_service_routes(router, ctx);
  return router;
}

}  // namespace kontakt::server::handlers
