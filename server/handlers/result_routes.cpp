// Published results: the artifact list, downloads (ETag = the sha256, Range), the summary.
#include <algorithm>

#include "server/byte_range.hpp"
#include "server/handlers/routes.hpp"
#include "server/job_json.hpp"
#include "server/problem.hpp"

namespace kontakt::server::handlers {

namespace {

HttpResponse list_results(ApiContext& ctx, const std::string& id) {
  if (!ctx.store.find_job(id)) return job_not_found(id);
  return json_response(200, artifacts_document(ctx.store.artifacts(id)));
}

HttpResponse download(ApiContext& ctx, const HttpRequest& request, const std::string& id,
                      const std::string& name) {
  if (!ctx.store.find_job(id)) return job_not_found(id);
  // Only names the store published are served, so a name can never reach outside the folder.
  const auto artifacts = ctx.store.artifacts(id);
  const auto it = std::find_if(artifacts.begin(), artifacts.end(),
                               [&](const Artifact& a) { return a.name == name; });
  if (it == artifacts.end()) return problem(404, "not_found", "job " + id + " has no result " + name);
  const std::string etag = "\"" + it->sha256 + "\"";
  HttpResponse r;
  r.headers = {{"ETag", etag}, {"Accept-Ranges", "bytes"},
               {"Content-Disposition", "attachment; filename=\"" + name + "\""}};
  if (request.header("if-none-match") == etag) {
    r.status = 304;
    r.content_type.clear();
    return r;
  }
  const auto size = static_cast<std::uint64_t>(it->size);
  ByteRange range{0, size};
  // If-Range: a range of a different version would splice two files; send the whole one.
  const auto if_range = request.header("if-range");
  const auto range_header = if_range && *if_range != etag ? std::nullopt : request.header("range");
  switch (parse_byte_range(range_header, size, range)) {
    case RangeResult::Unsatisfiable: {
      HttpResponse bad = problem(416, "range_not_satisfiable", "the file has " + std::to_string(size) + " bytes");
      bad.headers.emplace_back("Content-Range", "bytes */" + std::to_string(size));
      return bad;
    }
    case RangeResult::Partial:
      r.status = 206;
      r.headers.emplace_back("Content-Range", "bytes " + std::to_string(range.offset) + "-" +
                                                  std::to_string(range.offset + range.length - 1) +
                                                  "/" + std::to_string(size));
      break;
    case RangeResult::Whole: break;
  }
  r.content_type = it->media_type;
  r.file = FileBody{(ctx.files.results_dir(id) / name).string(), range.offset, range.length};
  return r;
}

HttpResponse summary(ApiContext& ctx, const std::string& id) {
  const auto job = ctx.store.find_job(id);
  if (!job) return job_not_found(id);
  return json_response(200, summary_document(*job));
}

}  // namespace

void add_result_routes(Router& router, ApiContext& ctx) {
  router.add("GET", "/v1/jobs/{id}/results", [&ctx](const HttpRequest&, const PathParams& p) {
    return list_results(ctx, p.at("id"));
  });
  router.add("GET", "/v1/jobs/{id}/results/{name}", [&ctx](const HttpRequest& r, const PathParams& p) {
    return download(ctx, r, p.at("id"), p.at("name"));
  });
  router.add("GET", "/v1/jobs/{id}/summary", [&ctx](const HttpRequest&, const PathParams& p) {
    return summary(ctx, p.at("id"));
  });
}

}  // namespace kontakt::server::handlers
