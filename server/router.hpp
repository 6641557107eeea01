// (method, path pattern) -> handler, and the checks every request passes first (bearer token).
// Patterns are literal segments and {name} placeholders: "/v1/jobs/{id}/results/{name}".
// A token travels only in the Authorization header, never in the URL (where it would land in
// access logs, proxies and browser history).
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

/// Public routes answer without a token: liveness and the dashboard's pages and assets, which
/// hold no data (the pages ask for the token and send it with their API calls).
enum class Access { Token, Public };

class Router {
 public:
  /// Requests to routes with Access::Token must carry `Authorization: Bearer <one of
  /// tokens>`; empty = no auth.
  void require_tokens(std::set<std::string> tokens);
  void add(const std::string& method, const std::string& pattern, Handler handler,
           Access access = Access::Token);

  /// Never throws: an exception in a handler becomes a 500 problem.
  HttpResponse handle(const HttpRequest& request) const;

 private:
  struct Route {
    std::string method;
    std::vector<std::string> segments;
    Handler handler;
    Access access;
  };
  bool authorized(const HttpRequest& request) const;

  std::vector<Route> routes_;
  std::set<std::string> tokens_;
};

/// "/a/b/" -> {"a", "b"}.
std::vector<std::string> split_path(const std::string& path);

}  // namespace kontakt::server
