#include "app/solve_command.hpp"

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>

#include "app/progress_printer.hpp"
#include "app/run_job.hpp"
#include "model/contact.hpp"

namespace fs = std::filesystem;

namespace kontakt::app {

namespace {

/// Set by SIGINT/SIGTERM; the Newton driver polls it once per iteration and stops cleanly.
std::atomic<bool> g_cancel{false};
extern "C" void request_cancel(int) { g_cancel.store(true); }

struct SolveArgs {
  fs::path deck;
  fs::path out_dir;
  int threads = 0;
  bool quiet = false;
  std::optional<std::string> scheme;
  std::string contact_stabilisation = "auto";
  bool drift_check = true;
};

/// Parses `solve` arguments; returns false (after printing why) on a usage error.
bool parse_solve_args(int argc, char** argv, SolveArgs& args) {
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const char* name) -> const char* {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "kontakt: %s needs a value\n", name);
        return nullptr;
      }
      return argv[++i];
    };
    if (a == "-o" || a == "--output") {
      const char* v = value("-o");
      if (!v) return false;
      args.out_dir = v;
    } else if (a == "--threads") {
      const char* v = value("--threads");
      if (!v) return false;
      char* end = nullptr;
      const long n = std::strtol(v, &end, 10);
      if (*end != '\0' || n < 0 || n > 1024) {
        std::fprintf(stderr, "kontakt: --threads takes a whole number from 0 to 1024\n");
        return false;
      }
      args.threads = static_cast<int>(n);
    } else if (a == "--scheme") {
      const char* v = value("--scheme");
      if (!v) return false;
      if (!model::contact_scheme_from_name(v)) {
        std::fprintf(stderr, "kontakt: unknown contact scheme '%s' (%s)\n", v,
                     model::contact_scheme_names().c_str());
        return false;
      }
      args.scheme = v;
    } else if (a == "--contact-stabilisation") {
      const char* v = value("--contact-stabilisation");
      if (!v) return false;
      if (!contact_stabilisation_from_name(v)) {
        std::fprintf(stderr, "kontakt: --contact-stabilisation takes auto, always or never\n");
        return false;
      }
      args.contact_stabilisation = v;
    } else if (a == "--drift-check") {
      const char* v = value("--drift-check");
      if (!v) return false;
      if (std::strcmp(v, "on") != 0 && std::strcmp(v, "off") != 0) {
        std::fprintf(stderr, "kontakt: --drift-check takes on or off\n");
        return false;
      }
      args.drift_check = !std::strcmp(v, "on");
    } else if (a == "--quiet" || a == "-q") {
      args.quiet = true;
    } else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "kontakt: unknown option %s\n", a.c_str());
      return false;
    } else if (args.deck.empty()) {
      args.deck = a;
    } else {
      std::fprintf(stderr, "kontakt: more than one deck given (%s)\n", a.c_str());
      return false;
    }
  }
  if (args.deck.empty()) {
    std::fprintf(stderr, "kontakt: solve needs a deck\n");
    return false;
  }
  if (args.out_dir.empty()) args.out_dir = args.deck.parent_path().empty() ? "." : args.deck.parent_path();
  return true;
}

}  // namespace

int solve_command(int argc, char** argv) {
  SolveArgs args;
  if (!parse_solve_args(argc, argv, args)) return 1;
  std::signal(SIGINT, request_cancel);
  std::signal(SIGTERM, request_cancel);
  ProgressPrinter progress(stdout, args.quiet);
  const RunOutcome result = run_job({.deck = args.deck,
                                     .out_dir = args.out_dir,
                                     .job_name = args.deck.stem().string(),
                                     .threads = args.threads,
                                     .scheme = args.scheme,
                                     .contact_stabilisation = args.contact_stabilisation,
                                     .drift_check = args.drift_check},
                                    progress, g_cancel);
  if (result.status != RunStatus::Converged)
    std::fprintf(stderr, "kontakt: error: %s\n", result.message.c_str());
  return result.exit_code;
}

}  // namespace kontakt::app
