#include "server/wire_request.hpp"

#include <cctype>

namespace http = boost::beast::http;

namespace kontakt::server {

std::optional<HttpRequest> to_plain_request(http::request<http::string_body>&& req) {
  HttpRequest r;
  r.method = std::string(req.method_string());
  const std::string target(req.target());
  const std::size_t q = target.find('?');
  const auto path = percent_decode(target.substr(0, q), false);
  const auto query = parse_query(q == std::string::npos ? "" : target.substr(q + 1));
  if (!path || !query) return std::nullopt;
  r.path = *path;
  r.query = *query;
  for (const auto& field : req) {
    std::string name(field.name_string());
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    r.headers[name] = std::string(field.value());
  }
  r.body = std::move(req.body());
  return r;
}

}  // namespace kontakt::server
