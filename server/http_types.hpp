// The plain request and response the handlers see: no sockets, no Beast types, so every
// route can be tested in-process. The HTTP session translates to and from the wire.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace kontakt::server {

struct HttpRequest {
  std::string method;                                      ///< GET, POST, ...
  std::string path;                                        ///< decoded, without the query
  std::vector<std::pair<std::string, std::string>> query;  ///< decoded, in order, repeats kept
  std::map<std::string, std::string> headers;              ///< names in lower case
  std::string body;

  /// The first value of a query parameter.
  std::optional<std::string> param(const std::string& name) const;
  /// Every value of a repeated query parameter.
  std::vector<std::string> params(const std::string& name) const;
  std::optional<std::string> header(const std::string& lower_case_name) const;
};

/// A byte range of a file sent as the body (downloads).
struct FileBody {
  std::string path;
  std::uint64_t offset = 0, length = 0;
};

/// An event stream: the session sends the job's events after `after_seq`, live until the job
/// is finished (or, without `follow`, until it has caught up).
struct EventStreamBody {
  std::string job_id;
  std::int64_t after_seq = 0;
  bool follow = true;
};

struct HttpResponse {
  int status = 200;
  std::string content_type = "application/json";
  std::vector<std::pair<std::string, std::string>> headers;
  std::string body;
  std::optional<FileBody> file;            ///< instead of body
  std::optional<EventStreamBody> events;   ///< instead of body

  std::optional<std::string> header(const std::string& name) const;
};

/// Splits "a=1&b=x%20y" into decoded pairs; nullopt for malformed percent escapes.
std::optional<std::vector<std::pair<std::string, std::string>>> parse_query(const std::string& q);
/// Decodes %XX escapes (and '+' as space when `plus_is_space`); nullopt when malformed.
std::optional<std::string> percent_decode(const std::string& s, bool plus_is_space);

}  // namespace kontakt::server

namespace kontakt::server {
/// Escapes everything but unreserved characters (RFC 3986), for links the API builds.
std::string percent_encode(const std::string& s);
}  // namespace kontakt::server
