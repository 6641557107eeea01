#include "server/router.hpp"

#include <algorithm>
#include <cstdio>

#include "server/problem.hpp"

namespace kontakt::server {

namespace {

bool match(const std::vector<std::string>& pattern, const std::vector<std::string>& path,
           PathParams& params) {
  if (pattern.size() != path.size()) return false;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    const std::string& p = pattern[i];
    if (p.size() > 2 && p.front() == '{' && p.back() == '}') {
      params[p.substr(1, p.size() - 2)] = path[i];
    } else if (p != path[i]) {
      return false;
    }
  }
  return true;
}

}  // namespace

std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> segments;
  std::size_t start = 0;
  while (start < path.size()) {
    const std::size_t end = std::min(path.find('/', start), path.size());
    if (end > start) segments.push_back(path.substr(start, end - start));
    start = end + 1;
  }
  return segments;
}

void Router::require_tokens(std::set<std::string> tokens) { tokens_ = std::move(tokens); }

void Router::add(const std::string& method, const std::string& pattern, Handler handler,
                 Access access) {
  routes_.push_back({method, split_path(pattern), std::move(handler), access});
}

bool Router::authorized(const HttpRequest& request) const {
  if (tokens_.empty()) return true;
  const std::string prefix = "Bearer ";
  const auto auth = request.header("authorization");
  return auth && auth->rfind(prefix, 0) == 0 && tokens_.count(auth->substr(prefix.size())) > 0;
}

HttpResponse Router::handle(const HttpRequest& request) const {
  const auto path = split_path(request.path);
  // A path is public when a public route has its pattern (then a wrong method gets its 405).
  const bool is_public = std::any_of(routes_.begin(), routes_.end(), [&](const Route& route) {
    PathParams ignored;
    return route.access == Access::Public && match(route.segments, path, ignored);
  });
  if (!is_public && !authorized(request)) {
    HttpResponse r = problem(401, "unauthorized", "a valid bearer token is required");
    r.headers.emplace_back("WWW-Authenticate", "Bearer realm=\"kontaktd\"");
    return r;
  }
  std::string allowed;
  for (const Route& route : routes_) {
    PathParams params;
    if (!match(route.segments, path, params)) continue;
    const bool head_as_get = request.method == "HEAD" && route.method == "GET";
    if (route.method != request.method && !head_as_get) {
      allowed += (allowed.empty() ? "" : ", ") + route.method;
      continue;
    }
    try {
      return route.handler(request, params);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "kontaktd: %s %s failed: %s\n", request.method.c_str(),
                   request.path.c_str(), e.what());
      return problem(500, "internal", std::string("internal error: ") + e.what());
    }
  }
  if (!allowed.empty()) {
    HttpResponse r = problem(405, "method_not_allowed",
                             request.method + " is not allowed on " + request.path);
    r.headers.emplace_back("Allow", allowed);
    return r;
  }
  return problem(404, "not_found", "no resource " + request.path);
}

}  // namespace kontakt::server
