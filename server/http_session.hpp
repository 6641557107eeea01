// One HTTP/1.1 connection (after Beast's advanced_server): read a request with a fresh parser
// (body limit, timeout), hand it to the router on the handler pool (never on an I/O thread:
// handlers parse decks and query SQLite), write the response, repeat while keep-alive.
// Event streams stay open and are fed from the store until the job ends.
#pragma once

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/thread_pool.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>

#include "server/http_types.hpp"
#include "server/job_store.hpp"
#include "server/router.hpp"

namespace kontakt::server {

/// What every session shares; outlives them all.
struct SessionContext {
  const Router& router;
  JobStore& store;
  boost::asio::thread_pool& handler_pool;
  std::uint64_t max_body = 64ull << 20;
  std::chrono::seconds request_timeout{30};
};

class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(boost::asio::ip::tcp::socket&& socket, SessionContext& ctx);
  void start();

 private:
  void do_read();
  void on_read(boost::beast::error_code ec, std::size_t bytes);
  void reply(HttpResponse response);
  template <class Message>
  void write(std::shared_ptr<Message> message);
  void on_write(bool close, boost::beast::error_code ec, std::size_t bytes);
  void refuse_oversized_body();
  void drain_and_close();
  void do_close();

  // Server-Sent Events
  void stream_events(const EventStreamBody& body);
  void poll_events();
  void on_events(std::string frames, bool finished);

  boost::beast::tcp_stream stream_;
  boost::beast::flat_buffer buffer_;
  SessionContext& ctx_;
  std::optional<boost::beast::http::request_parser<boost::beast::http::string_body>> parser_;
  bool keep_alive_ = false;
  bool head_ = false;
  std::shared_ptr<void> in_flight_;  ///< the response being written
  // event stream state
  boost::asio::steady_timer timer_;
  std::string stream_job_;
  std::int64_t stream_seq_ = 0;
  bool stream_follow_ = true;
  std::uint64_t seen_generation_ = 0;
  bool waiting_for_change_ = false;  ///< registered with the store's on_next_change
  bool closed_ = false;
  bool stream_behind_ = false;  ///< the last read hit kEventsPerWrite: more are stored already
  std::chrono::steady_clock::time_point last_write_;
  std::string frames_;
  std::array<char, 4096> discard_{};
  std::size_t drained_ = 0;  ///< bytes of a refused body dropped so far
};

}  // namespace kontakt::server
