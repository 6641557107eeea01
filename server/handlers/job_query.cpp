#include "server/handlers/job_query.hpp"

#include <cctype>
#include <cstdlib>

#include "server/digest.hpp"
#include "server/handlers/label_key.hpp"
#include "server/problem.hpp"

namespace kontakt::server::handlers {

namespace {

std::optional<std::pair<std::int64_t, std::string>> parse_page_token(const std::string& token) {
  const std::size_t dot = token.find('.');
  if (dot == std::string::npos || dot == 0 || dot > 18) return std::nullopt;
  for (std::size_t i = 0; i < dot; ++i)
    if (!std::isdigit(static_cast<unsigned char>(token[i]))) return std::nullopt;
  const std::string id = token.substr(dot + 1);
  if (!is_job_id(id)) return std::nullopt;
  return std::pair{std::stoll(token.substr(0, dot)), id};
}

}  // namespace

std::optional<HttpResponse> read_label_filters(const HttpRequest& request, JobQuery& query) {
  for (const std::string& label : request.params("label")) {
    const std::size_t eq = label.find('=');
    // Only keys a submission can carry: anything else matches no job, and a NUL or quote
    // would break the JSON path the store builds from it (a 500 found by fuzz_router).
    if (eq == std::string::npos || !is_label_key(label.substr(0, eq)))
      return invalid_parameter("label", "expected key=value with a key of 1 to 64 of "
                                        "A-Z a-z 0-9 _ - ., got '" + label + "'");
    query.labels.emplace_back(label.substr(0, eq), label.substr(eq + 1));
  }
  return std::nullopt;
}

std::string page_token_after(const JobRecord& last) {
  return std::to_string(last.created_ms) + "." + last.id;
}

std::optional<HttpResponse> read_page_parameters(const HttpRequest& request, int default_limit,
                                                 int max_limit, JobQuery& query) {
  query.limit = default_limit;
  if (const auto limit = request.param("limit")) {
    char* end = nullptr;
    const long n = std::strtol(limit->c_str(), &end, 10);
    if (limit->empty() || *end || n < 1 || n > max_limit)
      return invalid_parameter("limit", "a whole number from 1 to " + std::to_string(max_limit));
    query.limit = static_cast<int>(n);
  }
  if (const auto token = request.param("page_token")) {
    query.after = parse_page_token(*token);
    if (!query.after) return invalid_parameter("page_token", "not a token this server issued");
  }
  return std::nullopt;
}

}  // namespace kontakt::server::handlers
