// (method, path pattern) -> handler, and the checks every request passes first (bearer token).
// Patterns are literal segments and {name} placeholders: "/v1/jobs/{id}/results/{name}".
#pragma once

#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "server/http_types.hpp"

namespace kontakt::server {

using PathParams = std::map<std::string, std::string>;
using Handler = std::function<HttpResponse(const HttpRequest&, const PathParams&)>;

class Router {
 public:
  /// Requests must carry `Authorization: Bearer <one of tokens>` (or, for clients that cannot
  /// set headers such as a browser's EventSource, `?access_token=`); empty = no auth.
  /// Paths in `open_paths` never need a token.
  void require_tokens(std::set<std::string> tokens, std::set<std::string> open_paths);
  void add(const std::string& method, const std::string& pattern, Handler handler);

  /// Never throws: an exception in a handler becomes a 500 problem.
  HttpResponse handle(const HttpRequest& request) const;

 private:
  struct Route {
    std::string method;
    std::vector<std::string> segments;
    Handler handler;
  };
  bool authorized(const HttpRequest& request) const;

  std::vector<Route> routes_;
  std::set<std::string> tokens_, open_paths_;
};

/// "/a/b/" -> {"a", "b"}.
std::vector<std::string> split_path(const std::string& path);

}  // namespace kontakt::server
