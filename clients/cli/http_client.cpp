#include "cli/http_client.hpp"

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

namespace beast = boost::beast;
namespace http = beast::http;
namespace net = boost::asio;

namespace kontakt::cli {

namespace {

/// A connected stream to host:port; throws TransportError.
beast::tcp_stream connect(net::io_context& ioc, const std::string& host, const std::string& port,
                          std::chrono::seconds timeout) {
  beast::tcp_stream stream(ioc);
  beast::error_code ec;
  net::ip::tcp::resolver resolver(ioc);
  const auto endpoints = resolver.resolve(host, port, ec);
  if (ec) throw TransportError("cannot resolve " + host + ": " + ec.message());
  stream.expires_after(timeout);
  stream.connect(endpoints, ec);
  if (ec) throw TransportError("cannot connect to " + host + ":" + port + ": " + ec.message());
  return stream;
}

/// Adds the headers every request carries and sends it; throws TransportError.
template <class Body>
void send(beast::tcp_stream& stream, http::request<Body>& req, const std::string& host,
          const std::string& token, const std::map<std::string, std::string>& headers,
          std::chrono::seconds timeout) {
  req.set(http::field::host, host);
  req.set(http::field::user_agent, "kontakt-cli");
  if (!token.empty()) req.set(http::field::authorization, "Bearer " + token);
  for (const auto& [name, value] : headers) req.set(name, value);
  req.prepare_payload();
  beast::error_code ec;
  stream.expires_after(timeout);
  http::write(stream, req, ec);
  if (ec) throw TransportError("cannot send the request: " + ec.message());
}

template <class Message>
void collect_headers(const Message& m, HttpReply& reply) {
  reply.status = static_cast<int>(m.result_int());
  for (const auto& field : m) {
    std::string name(field.name_string());
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    reply.headers[name] = std::string(field.value());
  }
}

}  // namespace

HttpClient::HttpClient(const std::string& base_url, std::string token, std::chrono::seconds timeout)
    : token_(std::move(token)), timeout_(timeout) {
  const std::string prefix = "http://";
  if (base_url.rfind(prefix, 0) != 0)
    throw TransportError("the server URL must start with http:// (got " + base_url + ")");
  std::string rest = base_url.substr(prefix.size());
  rest = rest.substr(0, rest.find('/'));
  const std::size_t colon = rest.rfind(':');
  host_ = colon == std::string::npos ? rest : rest.substr(0, colon);
  port_ = colon == std::string::npos ? "80" : rest.substr(colon + 1);
  if (host_.empty() || port_.empty()) throw TransportError("bad server URL " + base_url);
}

HttpReply HttpClient::request(const std::string& method, const std::string& target,
                              const std::string& body, const std::string& content_type,
                              const std::map<std::string, std::string>& headers) {
  net::io_context ioc;
  beast::tcp_stream stream = connect(ioc, host_, port_, timeout_);
  http::request<http::string_body> req(http::string_to_verb(method), target, 11);
  if (!content_type.empty()) req.set(http::field::content_type, content_type);
  req.body() = body;
  send(stream, req, host_, token_, headers, timeout_);
  beast::error_code ec;
  beast::flat_buffer buffer;
  http::response_parser<http::string_body> parser;
  parser.body_limit(std::numeric_limits<std::uint64_t>::max());
  http::read(stream, buffer, parser, ec);
  if (ec) throw TransportError("no valid reply: " + ec.message());
  HttpReply reply;
  collect_headers(parser.get(), reply);
  reply.body = std::move(parser.get().body());
  stream.socket().shutdown(net::ip::tcp::socket::shutdown_both, ec);
  return reply;
}

HttpReply HttpClient::stream(const std::string& target,
                             const std::map<std::string, std::string>& headers,
                             const std::function<bool(std::string_view)>& on_data,
                             std::chrono::seconds idle_timeout) {
  net::io_context ioc;
  beast::tcp_stream stream = connect(ioc, host_, port_, timeout_);
  http::request<http::empty_body> req(http::verb::get, target, 11);
  send(stream, req, host_, token_, headers, timeout_);
  beast::error_code ec;
  beast::flat_buffer buffer;
  http::response_parser<http::buffer_body> parser;
  parser.body_limit(std::numeric_limits<std::uint64_t>::max());
  stream.expires_after(timeout_);
  http::read_header(stream, buffer, parser, ec);
  if (ec) throw TransportError("no valid reply: " + ec.message());
  HttpReply reply;
  collect_headers(parser.get(), reply);
  char chunk[16384];
  while (!parser.is_done()) {
    parser.get().body().data = chunk;
    parser.get().body().size = sizeof chunk;
    stream.expires_after(idle_timeout);
    http::read(stream, buffer, parser, ec);
    if (ec == http::error::need_buffer) ec = {};
    if (ec == http::error::end_of_stream || ec == http::error::partial_message) break;
    if (ec) throw TransportError("the reply broke off: " + ec.message());
    const std::size_t n = sizeof chunk - parser.get().body().size;
    if (reply.status < 300 && !on_data(std::string_view(chunk, n))) break;
    if (reply.status >= 300) reply.body.append(chunk, n);
  }
  stream.socket().shutdown(net::ip::tcp::socket::shutdown_both, ec);
  return reply;
}

}  // namespace kontakt::cli
