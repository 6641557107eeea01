// kontakt: the command-line front end.
//
//   kontakt solve MODEL.inp [-o DIR] [--scheme NAME] [--threads N] [--quiet]
//
// reads the deck, runs the analysis its plan calls for, and writes DIR/MODEL.dat (ccx layout),
// DIR/MODEL.hdf + DIR/MODEL.xdmf (ParaView), DIR/MODEL.log.jsonl (events) and
// DIR/MODEL.sta / DIR/MODEL.cvg (ccx-style increment and iteration summaries).
// Exit codes: 0 converged, 2 input error, 3 not converged, 4 numerical or internal error.
#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "analysis/event_log.hpp"
#include "analysis/linear_static.hpp"
#include "analysis/nonlinear_static.hpp"
#include "app/monitor_files.hpp"
#include "app/progress_printer.hpp"
#include "app/result_writers.hpp"
#include "core/error.hpp"
#include "inp/read_deck.hpp"
#include "linsolve/blas_threads.hpp"

namespace fs = std::filesystem;
using namespace kontakt;

namespace {

constexpr int kExitOk = 0, kExitUsage = 1, kExitInput = 2, kExitNotConverged = 3, kExitError = 4;

/// Set by SIGINT/SIGTERM; the Newton driver polls it once per iteration and stops cleanly.
std::atomic<bool> g_cancel{false};
extern "C" void request_cancel(int) { g_cancel.store(true); }

void print_usage(std::FILE* out) {
  std::fputs(
      "usage: kontakt solve MODEL.inp [-o DIR] [--scheme NAME] [--threads N] [--quiet]\n"
      "       kontakt --version\n"
      "\n"
      "  -o DIR       write results to DIR (default: the deck's folder)\n"
      "  --scheme S   contact discretisation of every pair: nts, gauss, lgauss, gc1, gc3, gc7,\n"
      "               gc12, lgc1, lgc3, lgc7, lgc12 (default: the deck's SCHEME= or lgc7 for\n"
      "               SURFACE TO SURFACE, nts for NODE TO SURFACE)\n"
      "  --threads N  threads for assembly, recovery and the factorisation (default: all cores)\n"
      "  --quiet      no progress output\n"
      "\n"
      "exit codes: 0 converged, 2 input error, 3 not converged or cancelled (converged increments\n"
      "kept), 4 numerical/internal error\n",
      out);
}

struct SolveArgs {
  fs::path deck;
  fs::path out_dir;
  int threads = 0;
  bool quiet = false;
  std::optional<model::ContactScheme> scheme;
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
      args.scheme = model::contact_scheme_from_name(v);
      if (!args.scheme) {
        std::fprintf(stderr, "kontakt: unknown contact scheme '%s' (nts, gauss, lgauss, gc1, gc3, "
                             "gc7, gc12, lgc1, lgc3, lgc7, lgc12)\n", v);
        return false;
      }
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

int run_solve(const SolveArgs& args) {
  const std::string job = args.deck.stem().string();
  std::error_code ec;
  fs::create_directories(args.out_dir, ec);
  if (ec) {
    std::fprintf(stderr, "kontakt: cannot create %s: %s\n", args.out_dir.c_str(),
                 ec.message().c_str());
    return kExitError;
  }
  analysis::JsonlEventLog log(args.out_dir / (job + ".log.jsonl"));
  app::ProgressPrinter progress(stdout);
  app::MonitorFiles monitor(args.out_dir, job);
  analysis::EventFanout events;
  events.add(log);
  events.add(monitor);
  if (!args.quiet) events.add(progress);

  auto fail = [&](const char* status, const std::string& message, int code) {
    std::fprintf(stderr, "kontakt: error: %s\n", message.c_str());
    analysis::Event done{.kind = analysis::Event::Kind::Done, .status = status, .message = message};
    log.on_event(done);
    return code;
  };
  if (args.threads > 0) linsolve::set_blas_threads(args.threads);
  try {
    const model::Model model = inp::read_deck(args.deck);
    for (const auto& w : model.warnings) std::fprintf(stderr, "kontakt: warning: %s\n", w.c_str());
    app::ResultWriters writers(model, args.out_dir, job);
    events.add(writers);
    // The results of every converged increment are kept, whatever ends the run.
    try {
      if (analysis::needs_newton(model)) {
        analysis::NonlinearOptions options;
        options.threads = args.threads;
        options.cancel = &g_cancel;
        options.scheme = args.scheme;
        analysis::run_nonlinear_static(model, options, writers, events);
      } else {
        analysis::run_linear_static(model, {.threads = args.threads}, writers, events);
      }
    } catch (const NonConvergence&) {
      writers.finish();
      throw;
    } catch (const analysis::Cancelled&) {
      writers.finish();
      throw;
    }
    writers.finish();
    return kExitOk;
  } catch (const InputError& e) {
    return fail("input_error", e.what(), kExitInput);
  } catch (const NonConvergence& e) {
    return fail("not_converged", e.what(), kExitNotConverged);
  } catch (const analysis::Cancelled& e) {
    return fail("cancelled", e.what(), kExitNotConverged);
  } catch (const std::exception& e) {
    return fail("error", e.what(), kExitError);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "help")) {
    print_usage(argc < 2 ? stderr : stdout);
    return argc < 2 ? kExitUsage : kExitOk;
  }
  if (!std::strcmp(argv[1], "--version")) {
    std::printf("kontakt %s\n", KONTAKT_VERSION);
    return kExitOk;
  }
  if (std::strcmp(argv[1], "solve") != 0) {
    std::fprintf(stderr, "kontakt: unknown command '%s'\n", argv[1]);
    print_usage(stderr);
    return kExitUsage;
  }
  SolveArgs args;
  if (!parse_solve_args(argc, argv, args)) return kExitUsage;
  std::signal(SIGINT, request_cancel);
  std::signal(SIGTERM, request_cancel);
  return run_solve(args);
}
