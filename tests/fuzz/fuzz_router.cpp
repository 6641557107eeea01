// libFuzzer harness of the whole request path without sockets: raw bytes -> Beast's request
// parser (the session's limits) -> the plain request -> the router with every API route over a
// scratch store. Deck checks are answered in-process (a stand-in: the reader has harnesses of
// its own), jobs are never run. Every request must get an answer that is not a 500, the
// router must never throw, and nothing may crash.
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/http/parser.hpp>
#include <boost/beast/http/string_body.hpp>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <unistd.h>

#include "server/handlers/routes.hpp"
#include "server/wire_request.hpp"

namespace fs = std::filesystem;
namespace http = boost::beast::http;
using namespace kontakt::server;

namespace {

/// Requests before the scratch store starts afresh (it grows with every accepted job).
constexpr int kRequestsPerStore = 5000;
constexpr std::uint64_t kBodyLimit = 1u << 20;

class NoWorkers final : public handlers::JobControl {
 public:
  void job_queued() override {}
  void cancel_running(const std::string&) override {}
  int n_workers() const override { return 1; }
  int n_busy() const override { return 0; }
};

/// The store, folders and routers of one scratch data folder.
struct Api {
  explicit Api(const fs::path& dir)
      : store(dir / "kontakt.db"), files(dir),
        ctx{.store = store, .files = files, .control = control,
            .check_deck = [](const fs::path& deck, const std::optional<std::string>&) {
              DeckCheckResult r;
              r.check.n_steps = fs::file_size(deck) % 3;
              r.check.total_time = 1;
              return r;
            },
            .max_unpacked = 1u << 20},
        open(handlers::make_router(ctx)),
        guarded(handlers::make_router(ctx)) {
    guarded.require_tokens({"secret-token"});  // public routes are declared by make_router
  }
  JobStore store;
  JobFiles files;
  NoWorkers control;
  handlers::ApiContext ctx;
  Router open, guarded;
};

Api& api() {
  static int requests = 0;
  static const fs::path dir = fs::temp_directory_path() / ("fuzz_router_" + std::to_string(getpid()));
  static std::unique_ptr<Api> current;
  if (!current || ++requests % kRequestsPerStore == 0) {
    current.reset();
    fs::remove_all(dir);
    fs::create_directories(dir);
    current = std::make_unique<Api>(dir);
  }
  return *current;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const bool with_tokens = data[0] & 1;
  http::request_parser<http::string_body> parser;
  parser.body_limit(kBodyLimit);
  parser.eager(true);
  boost::beast::error_code ec;
  std::size_t used = 0;
  while (used < size - 1 && !parser.is_done()) {
    const std::size_t n = parser.put(boost::asio::buffer(data + 1 + used, size - 1 - used), ec);
    if (ec == http::error::need_more) break;
    if (ec) return 0;  // the session answers 400 or 413 without the router
    if (n == 0) break;
    used += n;
  }
  if (!parser.is_done()) {  // the peer closed: what Beast makes of the bytes so far
    if (!parser.got_some()) return 0;
    parser.put_eof(ec);
    if (ec || !parser.is_done()) return 0;
  }
  auto plain = to_plain_request(parser.release());
  if (!plain) return 0;
  Api& a = api();
  const HttpResponse response = (with_tokens ? a.guarded : a.open).handle(*plain);
  if (response.status == 500) __builtin_trap();
  return 0;
}
