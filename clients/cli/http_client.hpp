// A small synchronous HTTP/1.1 client (Boost.Beast) for the `kontakt` daemon commands: one
// connection per request, a timeout on every operation, bodies read whole or streamed.
#pragma once

#include <chrono>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>

namespace kontakt::cli {

/// Could not talk to the daemon (connection refused, timeout, malformed reply).
class TransportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct HttpReply {
  int status = 0;
  std::map<std::string, std::string> headers;  ///< names in lower case
  std::string body;                            ///< empty for streamed replies
};

class HttpClient {
 public:
  /// `base_url`: http://HOST[:PORT]; `token`: bearer token, empty for none.
  HttpClient(const std::string& base_url, std::string token, std::chrono::seconds timeout);

  HttpReply request(const std::string& method, const std::string& target,
                    const std::string& body = {}, const std::string& content_type = {},
                    const std::map<std::string, std::string>& headers = {});

  /// Sends a GET and hands the body to `on_data` as it arrives; `on_data` returns false to stop.
  /// Each read may wait `idle_timeout` (event streams send a keep-alive every 15 s).
  HttpReply stream(const std::string& target, const std::map<std::string, std::string>& headers,
                   const std::function<bool(std::string_view)>& on_data,
                   std::chrono::seconds idle_timeout);

 private:
  std::string host_, port_, token_;
  std::chrono::seconds timeout_;
};

}  // namespace kontakt::cli
