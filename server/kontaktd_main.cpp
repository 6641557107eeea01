// kontaktd: the Kontakt job daemon (HTTP/JSON API in proto/openapi.yaml). Settings come
// from KONTAKTD_* variables and the command line (`kontaktd --help`). The same program is the
// daemon's worker process: `kontaktd job-worker ...` (server/job_worker.hpp), started by the
// daemon itself for every deck check and every job.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>

#include "server/daemon.hpp"
#include "server/job_worker.hpp"
#include "server/worker_protocol.hpp"

int main(int argc, char** argv) {
  using namespace kontakt::server;
  if (argc > 1 && std::strcmp(argv[1], worker::kCommand) == 0)
    return job_worker_main(std::vector<std::string>(argv + 2, argv + argc));
  const auto parsed = parse_settings(std::vector<std::string>(argv + 1, argv + argc),
                                     [](const std::string& name) -> std::optional<std::string> {
                                       const char* v = std::getenv(name.c_str());
                                       return v ? std::optional<std::string>(v) : std::nullopt;
                                     });
  if (const auto* error = std::get_if<std::string>(&parsed)) {
    const bool help = *error == "help";
    if (!help) std::fprintf(stderr, "kontaktd: %s\n\n", error->c_str());
    std::fputs(settings_usage().c_str(), help ? stdout : stderr);
    return help ? 0 : 1;
  }
  try {
    return run_daemon(std::get<Settings>(parsed));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kontaktd: %s\n", e.what());
    return 1;
  }
}
