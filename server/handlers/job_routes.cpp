// Jobs as resources: submit, list (filters and cursor paging), read, cancel, resubmit, delete.
#include <nlohmann/json.hpp>

#include "server/digest.hpp"
#include "server/handlers/cancel.hpp"
#include "server/handlers/job_query.hpp"
#include "server/handlers/routes.hpp"
#include "server/handlers/submit_job.hpp"
#include "server/job_json.hpp"
#include "server/problem.hpp"

using nlohmann::json;

namespace kontakt::server::handlers {

namespace {

constexpr int kDefaultPageSize = 50, kMaxPageSize = 200;

json document_of(ApiContext& ctx, const JobRecord& job) {
  const std::optional<int> position =
      job.status == JobStatus::Queued ? ctx.store.queue_position(job) : std::nullopt;
  return job_document(job, position, !ctx.store.artifacts(job.id).empty());
}

/// Reads status=, label=, limit=, page_token=; a 400 naming the bad one.
std::optional<HttpResponse> read_job_query(const HttpRequest& request, JobQuery& query) {
  for (const std::string& list : request.params("status")) {
    std::size_t start = 0;
    while (start <= list.size()) {
      const std::size_t end = std::min(list.find(',', start), list.size());
      const std::string name = list.substr(start, end - start);
      const auto status = status_from_name(name);
      if (!status) return invalid_parameter("status", "unknown status '" + name + "'");
      query.statuses.push_back(*status);
      start = end + 1;
    }
  }
  if (auto bad = read_label_filters(request, query)) return bad;
  return read_page_parameters(request, kDefaultPageSize, kMaxPageSize, query);
}

std::string next_link(const HttpRequest& request, const std::string& token) {
  std::string link = "/v1/jobs?page_token=" + percent_encode(token);
  for (const auto& [k, v] : request.query)
    if (k != "page_token") link += "&" + percent_encode(k) + "=" + percent_encode(v);
  return link;
}

HttpResponse list_jobs(ApiContext& ctx, const HttpRequest& request) {
  JobQuery query;
  if (auto bad = read_job_query(request, query)) return *bad;
  const JobPage page = ctx.store.list_jobs(query);
  json jobs = json::array();
  for (const JobRecord& job : page.jobs) jobs.push_back(document_of(ctx, job));
  json body{{"jobs", jobs}, {"next_page_token", nullptr}};
  HttpResponse r;
  if (page.more) {
    const std::string token = page_token_after(page.jobs.back());
    body["next_page_token"] = token;
    r.headers.emplace_back("Link", "<" + next_link(request, token) + ">; rel=\"next\"");
  }
  r.body = json_text(body);
  return r;
}

HttpResponse get_job(ApiContext& ctx, const std::string& id) {
  const auto job = ctx.store.find_job(id);
  if (!job) return job_not_found(id);
  return json_response(200, document_of(ctx, *job));
}

/// 202 while the solver stops, 200 when the job is (already) finished: idempotent.
HttpResponse cancel_job(ApiContext& ctx, const std::string& id) {
  const auto job = cancel_one(ctx, id);
  if (!job) return job_not_found(id);
  return json_response(is_terminal(job->status) ? 200 : 202, document_of(ctx, *job));
}

HttpResponse delete_job(ApiContext& ctx, const std::string& id) {
  switch (ctx.store.delete_job(id)) {
    case JobStore::DeleteResult::NotFound: return job_not_found(id);
    case JobStore::DeleteResult::NotFinished:
      return problem(409, "job_not_finished", "job " + id + " is not finished: cancel it first");
    case JobStore::DeleteResult::Deleted: break;
  }
  ctx.files.remove(id);
  HttpResponse r;
  r.status = 204;
  r.content_type.clear();
  return r;
}

}  // namespace

void add_job_routes(Router& router, ApiContext& ctx) {
  router.add("POST", "/v1/jobs", [&ctx](const HttpRequest& r, const PathParams&) {
    return submit_job(ctx, r);
  });
  router.add("GET", "/v1/jobs", [&ctx](const HttpRequest& r, const PathParams&) {
    return list_jobs(ctx, r);
  });
  router.add("GET", "/v1/jobs/{id}", [&ctx](const HttpRequest&, const PathParams& p) {
    return get_job(ctx, p.at("id"));
  });
  router.add("DELETE", "/v1/jobs/{id}", [&ctx](const HttpRequest&, const PathParams& p) {
    return delete_job(ctx, p.at("id"));
  });
  router.add("POST", "/v1/jobs/{id}/cancel", [&ctx](const HttpRequest&, const PathParams& p) {
    return cancel_job(ctx, p.at("id"));
  });
  router.add("POST", "/v1/jobs/{id}/resubmit", [&ctx](const HttpRequest& r, const PathParams& p) {
    return resubmit_job(ctx, r, p.at("id"));
  });
}

}  // namespace kontakt::server::handlers
