// Sweeps, two views of one idea. A label key (a design loop's parameter): the jobs that carry
// it, one summary row each, optionally narrowed by other labels (label=sweep=load-sweep) --
// GET /v1/sweeps, /v1/sweeps/{key}. A sweep made by POST /v1/sweeps (submit_sweep.hpp): its
// record, jobs and cancel under /v1/sweeps/id/{id}; its rows carry sweep=<id>, so the label
// views show it too.
#include <nlohmann/json.hpp>

#include "server/handlers/cancel.hpp"
#include "server/handlers/label_key.hpp"
#include "server/handlers/job_query.hpp"
#include "server/handlers/routes.hpp"
#include "server/handlers/submit_sweep.hpp"
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

HttpResponse sweep_not_found(const std::string& id) {
  return problem(404, "sweep_not_found", "no sweep " + id);
}

HttpResponse get_sweep_record(ApiContext& ctx, const std::string& id) {
  const auto sweep = ctx.store.find_sweep(id);
  if (!sweep) return sweep_not_found(id);
  return json_response(200, sweep_document_of(ctx, *sweep));
}

HttpResponse list_sweep_jobs(ApiContext& ctx, const std::string& id) {
  if (!ctx.store.find_sweep(id)) return sweep_not_found(id);
  json rows = json::array();
  for (const JobRecord& job : ctx.store.sweep_jobs(id)) rows.push_back(sweep_job_document(job));
  return json_response(200, {{"sweep", id}, {"jobs", rows}});
}

/// Every unfinished row: queued ones end canceled, running ones are stopped. 202 while some
/// are canceling, else 200. Queued rows go first: a running row stopped first frees its
/// throttle slot, and the scheduler could start the next row before its cancel arrives.
HttpResponse cancel_sweep(ApiContext& ctx, const std::string& id) {
  const auto sweep = ctx.store.find_sweep(id);
  if (!sweep) return sweep_not_found(id);
  bool stopping = false;
  const auto jobs = ctx.store.sweep_jobs(id);
  for (const bool queued : {true, false})
    for (const JobRecord& job : jobs) {
      if (is_terminal(job.status) || (job.status == JobStatus::Queued) != queued) continue;
      const auto now = cancel_one(ctx, job.id);
      stopping = stopping || (now && !is_terminal(now->status));
    }
  return json_response(stopping ? 202 : 200, sweep_document_of(ctx, *sweep));
}

}  // namespace

void add_sweep_routes(Router& router, ApiContext& ctx) {
  router.add("GET", "/v1/sweeps", [&ctx](const HttpRequest&, const PathParams&) {
    return list_sweeps(ctx);
  });
  router.add("POST", "/v1/sweeps", [&ctx](const HttpRequest& r, const PathParams&) {
    return submit_sweep(ctx, r);
  });
  router.add("GET", "/v1/sweeps/id/{id}", [&ctx](const HttpRequest&, const PathParams& p) {
    return get_sweep_record(ctx, p.at("id"));
  });
  router.add("GET", "/v1/sweeps/id/{id}/jobs", [&ctx](const HttpRequest&, const PathParams& p) {
    return list_sweep_jobs(ctx, p.at("id"));
  });
  router.add("POST", "/v1/sweeps/id/{id}/cancel", [&ctx](const HttpRequest&, const PathParams& p) {
    return cancel_sweep(ctx, p.at("id"));
  });
  router.add("GET", "/v1/sweeps/{key}", [&ctx](const HttpRequest& r, const PathParams& p) {
    return get_sweep(ctx, r, p.at("key"));
  });
}

}  // namespace kontakt::server::handlers
