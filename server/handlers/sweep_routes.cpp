// Sweeps: the jobs that share a label key (a design loop's parameter), one summary row each,
// optionally narrowed by other labels (label=sweep=load-sweep).
#include <nlohmann/json.hpp>

#include "server/handlers/label_key.hpp"
#include "server/handlers/job_query.hpp"
#include "server/handlers/routes.hpp"
#include "server/job_json.hpp"
#include "server/problem.hpp"

using nlohmann::json;

namespace kontakt::server::handlers {

namespace {

// Rows are small (no links, no progress), so a page holds a whole typical sweep.
constexpr int kDefaultRows = 500, kMaxRows = 1000;

HttpResponse list_sweeps(ApiContext& ctx) {
  return json_response(200, sweep_list_document(ctx.store.label_keys()));
}

HttpResponse get_sweep(ApiContext& ctx, const HttpRequest& request, const std::string& key) {
  if (!is_label_key(key)) return invalid_parameter("key", "1 to 64 of A-Z a-z 0-9 _ - .");
  JobQuery query;
  query.label_keys = {key};
  if (auto bad = read_label_filters(request, query)) return *bad;
  if (auto bad = read_page_parameters(request, kDefaultRows, kMaxRows, query)) return *bad;
  const JobPage page = ctx.store.list_jobs(query);
  json rows = json::array();
  for (const JobRecord& job : page.jobs) rows.push_back(sweep_row_document(job, key));
  return json_response(200, {{"key", key},
                             {"jobs", rows},
                             {"next_page_token", page.more ? json(page_token_after(page.jobs.back()))
                                                           : json(nullptr)}});
}

}  // namespace

void add_sweep_routes(Router& router, ApiContext& ctx) {
  router.add("GET", "/v1/sweeps", [&ctx](const HttpRequest&, const PathParams&) {
    return list_sweeps(ctx);
  });
  router.add("GET", "/v1/sweeps/{key}", [&ctx](const HttpRequest& r, const PathParams& p) {
    return get_sweep(ctx, r, p.at("key"));
  });
}

}  // namespace kontakt::server::handlers
