#include "server/http_session.hpp"

#include <boost/asio/dispatch.hpp>
#include <boost/asio/post.hpp>

#include "server/file_range_body.hpp"
#include "server/problem.hpp"
#include "server/sse_format.hpp"
#include "server/wire_request.hpp"

namespace beast = boost::beast;
namespace http = beast::http;
namespace net = boost::asio;

namespace kontakt::server {

namespace {

/// An idle stream wakes at the store's next change; this is only the keep-alive check.
constexpr auto kStreamRecheck = std::chrono::seconds(1);
constexpr auto kStreamKeepAlive = std::chrono::seconds(15);
constexpr int kEventsPerWrite = 500;
constexpr std::size_t kMaxDrained = 16u << 20;  ///< bytes of a refused body read and dropped

template <class Body>
void copy_headers(const HttpResponse& from, http::response<Body>& to) {
  to.set(http::field::server, "kontaktd");
  if (!from.content_type.empty()) to.set(http::field::content_type, from.content_type);
  for (const auto& [name, value] : from.headers) to.set(name, value);
}

}  // namespace

HttpSession::HttpSession(net::ip::tcp::socket&& socket, SessionContext& ctx)
    : stream_(std::move(socket)), ctx_(ctx), timer_(stream_.get_executor()) {}

void HttpSession::start() {
  net::dispatch(stream_.get_executor(), [self = shared_from_this()] { self->do_read(); });
}

void HttpSession::do_read() {
  parser_.emplace();  // a fresh parser per request: limits apply to each message
  parser_->body_limit(ctx_.max_body);
  stream_.expires_after(ctx_.request_timeout);
  http::async_read(stream_, buffer_, *parser_,
                   beast::bind_front_handler(&HttpSession::on_read, shared_from_this()));
}

void HttpSession::on_read(beast::error_code ec, std::size_t) {
  if (ec == http::error::end_of_stream) return do_close();
  if (ec == http::error::body_limit) return refuse_oversized_body();
  if (ec == beast::error::timeout || ec == net::error::operation_aborted) return do_close();
  if (ec) {
    if (!parser_->is_header_done() && buffer_.size() == 0) return do_close();  // peer went away
    keep_alive_ = false;
    return reply(problem(400, "bad_request", "malformed HTTP request: " + ec.message()));
  }
  auto message = parser_->release();
  keep_alive_ = message.keep_alive();
  head_ = message.method() == http::verb::head;
  auto plain = to_plain_request(std::move(message));
  if (!plain) return reply(invalid_parameter("target", "malformed percent escape in the URL"));
  // The handler may parse a deck or wait on SQLite: run it off the I/O threads.
  net::post(ctx_.handler_pool, [self = shared_from_this(), request = std::move(*plain)] {
    HttpResponse response = self->ctx_.router.handle(request);
    net::post(self->stream_.get_executor(),
              [self, response = std::move(response)]() mutable { self->reply(std::move(response)); });
  });
}

void HttpSession::reply(HttpResponse r) {
  if (r.events && !head_) return stream_events(*r.events);
  if (r.file && !head_) {
    beast::error_code ec;
    auto res = std::make_shared<http::response<FileRangeBody>>();
    res->body().file.open(r.file->path.c_str(), beast::file_mode::scan, ec);
    if (!ec) res->body().file.seek(r.file->offset, ec);
    if (ec) return reply(problem(500, "internal", "cannot read the result file: " + ec.message()));
    res->body().length = r.file->length;
    res->result(static_cast<unsigned>(r.status));
    copy_headers(r, *res);
    res->keep_alive(keep_alive_);
    res->prepare_payload();
    return write(res);
  }
  auto res = std::make_shared<http::response<http::string_body>>();
  res->result(static_cast<unsigned>(r.status));
  copy_headers(r, *res);
  res->keep_alive(keep_alive_);
  if (r.file) {  // HEAD of a download: the length the GET would send, no body
    res->content_length(r.file->length);
  } else if (r.status != 204 && r.status != 304) {
    res->body() = std::move(r.body);
    res->prepare_payload();
    if (head_) res->body().clear();  // HEAD: Content-Length of the GET, no body
  }
  write(res);
}

template <class Message>
void HttpSession::write(std::shared_ptr<Message> message) {
  in_flight_ = message;
  stream_.expires_after(ctx_.request_timeout);
  http::async_write(stream_, *message,
                    beast::bind_front_handler(&HttpSession::on_write, shared_from_this(),
                                              message->need_eof()));
}

void HttpSession::on_write(bool close, beast::error_code ec, std::size_t) {
  in_flight_.reset();
  if (ec || close) return do_close();
  do_read();
}

void HttpSession::refuse_oversized_body() {
  auto res = std::make_shared<http::response<http::string_body>>();
  const HttpResponse r = problem(413, "body_too_large",
                                 "the request body exceeds the limit of " +
                                     std::to_string(ctx_.max_body) + " bytes");
  res->result(http::status::payload_too_large);
  copy_headers(r, *res);
  res->keep_alive(false);
  res->body() = r.body;
  res->prepare_payload();
  in_flight_ = res;
  stream_.expires_after(ctx_.request_timeout);
  http::async_write(stream_, *res, [self = shared_from_this(), res](beast::error_code, std::size_t) {
    self->drain_and_close();
  });
}

void HttpSession::drain_and_close() {
  // Stop sending, then read (and drop) what the client still sends for a moment, so it gets
  // to read the 413 instead of a connection reset.
  beast::error_code ec;
  stream_.socket().shutdown(net::ip::tcp::socket::shutdown_send, ec);
  stream_.expires_after(std::chrono::seconds(2));
  stream_.async_read_some(net::buffer(discard_), [self = shared_from_this()](beast::error_code e,
                                                                              std::size_t n) {
    self->drained_ += n;
    if (e || self->drained_ > kMaxDrained) return self->do_close();
    self->drain_and_close();
  });
}

void HttpSession::do_close() {
  beast::error_code ec;
  closed_ = true;
  timer_.cancel();
  stream_.socket().shutdown(net::ip::tcp::socket::shutdown_both, ec);
  stream_.close();
}

void HttpSession::stream_events(const EventStreamBody& body) {
  stream_job_ = body.job_id;
  stream_seq_ = body.after_seq;
  stream_follow_ = body.follow;
  auto res = std::make_shared<http::response<http::empty_body>>();
  res->result(http::status::ok);
  res->set(http::field::server, "kontaktd");
  res->set(http::field::content_type, "text/event-stream");
  res->set(http::field::cache_control, "no-cache");
  res->keep_alive(false);  // the stream ends when the job ends, by closing the connection
  auto sr = std::make_shared<http::response_serializer<http::empty_body>>(*res);
  in_flight_ = std::make_shared<std::pair<decltype(res), decltype(sr)>>(res, sr);
  stream_.expires_after(ctx_.request_timeout);
  http::async_write_header(stream_, *sr, [self = shared_from_this()](beast::error_code ec, std::size_t) {
    self->in_flight_.reset();
    if (ec) return self->do_close();
    self->last_write_ = std::chrono::steady_clock::now();
    self->seen_generation_ = self->ctx_.store.generation() - 1;  // force a first look
    self->poll_events();
  });
}

void HttpSession::poll_events() {
  const std::uint64_t generation = ctx_.store.generation();
  const bool idle_too_long = std::chrono::steady_clock::now() - last_write_ > kStreamKeepAlive;
  // A replay longer than one batch goes on at once: no new commit will announce the rest.
  if (generation == seen_generation_ && !idle_too_long && !stream_behind_) {
    stream_.expires_never();
    if (!waiting_for_change_) {
      waiting_for_change_ = true;
      // The store wakes the stream from a committing thread: back onto the session's strand.
      ctx_.store.on_next_change(generation, weak_from_this(), [weak = weak_from_this()] {
        if (const auto self = weak.lock())
          net::post(self->stream_.get_executor(), [self] {
            self->waiting_for_change_ = false;
            self->timer_.cancel();
          });
      });
    }
    timer_.expires_after(kStreamRecheck);
    timer_.async_wait([self = shared_from_this()](beast::error_code) {
      if (!self->closed_) self->poll_events();  // the recheck, or woken by a change
    });
    return;
  }
  seen_generation_ = generation;
  net::post(ctx_.handler_pool, [self = shared_from_this()] {
    std::string frames;
    bool finished = true;
    try {
      // Status first: a terminal status seen here guarantees its event is in the query below.
      const auto job = self->ctx_.store.find_job(self->stream_job_);
      const auto events = self->ctx_.store.events_since(self->stream_job_, self->stream_seq_, {},
                                                        kEventsPerWrite);
      for (const auto& e : events) frames += sse_frame(e);
      const bool caught_up = static_cast<int>(events.size()) < kEventsPerWrite;
      finished = !job || (caught_up && (is_terminal(job->status) || !self->stream_follow_));
      if (!events.empty()) self->stream_seq_ = events.back().seq;
      self->stream_behind_ = !caught_up;
    } catch (const std::exception&) {  // store trouble: end the stream, the client resumes
    }
    net::post(self->stream_.get_executor(), [self, frames = std::move(frames), finished]() mutable {
      self->on_events(std::move(frames), finished);
    });
  });
}

void HttpSession::on_events(std::string frames, bool finished) {
  if (frames.empty() && finished) return do_close();
  if (frames.empty()) {
    if (std::chrono::steady_clock::now() - last_write_ <= kStreamKeepAlive) return poll_events();
    frames = kSseKeepAlive;
  }
  frames_ = std::move(frames);
  stream_.expires_after(ctx_.request_timeout);
  net::async_write(stream_, net::buffer(frames_),
                   [self = shared_from_this(), finished](beast::error_code ec, std::size_t) {
                     if (ec || finished) return self->do_close();
                     self->last_write_ = std::chrono::steady_clock::now();
                     self->poll_events();
                   });
}

}  // namespace kontakt::server
