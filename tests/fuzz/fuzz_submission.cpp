// libFuzzer harness of the submission parser of POST /v1/jobs (server/handlers/submission):
// the first byte picks the body's media type, the first line is the query string, the rest is
// the body (a JSON submission, mostly). It must answer - a Submission or a 400/415 - and never
// throw.
#include <cstdint>
#include <string>

#include "server/handlers/submission.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace kontakt::server;
  if (size == 0) return 0;
  static const char* const kTypes[] = {"application/json", "application/json; charset=utf-8",
                                       "text/plain", "application/zip", "image/png", ""};
  const std::string input(reinterpret_cast<const char*>(data) + 1, size - 1);
  const std::size_t newline = input.find('\n');
  HttpRequest request;
  request.method = "POST";
  request.path = "/v1/jobs";
  request.headers["content-type"] = kTypes[data[0] % std::size(kTypes)];
  const auto query = parse_query(input.substr(0, newline));
  if (query) request.query = *query;
  request.body = newline == std::string::npos ? "" : input.substr(newline + 1);
  handlers::Submission submission;
  const auto refused = handlers::read_submission(request, submission);
  if (refused && refused->status != 400 && refused->status != 415) __builtin_trap();
  return 0;
}
