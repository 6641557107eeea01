// kontakt: the command-line front end, a dispatcher over two families of commands.
//
//   kontakt solve MODEL.inp [-o DIR] [--scheme S] [--threads N] [--quiet]   run a job here
//   kontakt submit|status|logs|wait|cancel|fetch|list ...         talk to kontaktd (clients/cli)
//
// Exit codes of solve: 0 converged, 2 input error, 3 not converged, 4 numerical or internal
// error; the daemon commands' codes are listed by `kontakt help`.
#include <cstdio>
#include <cstring>

#include "app/solve_command.hpp"
#include "cli/client_commands.hpp"

namespace {

void print_usage(std::FILE* out) {
  std::fputs(
      "usage: kontakt solve MODEL.inp [-o DIR] [--scheme NAME] [--threads N] [--quiet]\n"
      "                     [--contact-stabilisation auto|always|never] [--drift-check on|off]\n"
      "       kontakt submit|status|logs|wait|cancel|fetch|list ...   (a kontaktd daemon)\n"
      "       kontakt --version\n"
      "\n"
      "solve:\n"
      "  -o DIR       write results to DIR (default: the deck's folder)\n"
      "  --threads N  threads for assembly, recovery and the factorisation (default: all cores)\n"
      "  --quiet      no progress output\n"
      "  --scheme NAME  contact scheme of every pair (nts, gauss, lgauss, gc1..gc12, lgc1..lgc12)\n"
      "  --contact-stabilisation MODE  springs that hold bodies only contact holds: auto (when\n"
      "               an increment needs them), always, never; released before an increment ends\n"
      "  --drift-check on|off  freeze a linear variant's contact geometry again at the solution\n"
      "               (or redo the increment smaller) when its frozen gaps drift from fresh\n"
      "               projections (default on; off to measure what it does)\n"
      "  exit codes: 0 converged, 2 input error, 3 not converged or cancelled (converged\n"
      "  increments kept), 4 numerical/internal error\n"
      "\n",
      out);
  kontakt::cli::print_client_usage(out);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "help")) {
    print_usage(argc < 2 ? stderr : stdout);
    return argc < 2 ? 1 : 0;
  }
  if (!std::strcmp(argv[1], "--version")) {
    std::printf("kontakt %s\n", KONTAKT_VERSION);
    return 0;
  }
  if (!std::strcmp(argv[1], "solve")) return kontakt::app::solve_command(argc, argv);
  if (kontakt::cli::is_client_command(argv[1])) return kontakt::cli::client_command(argc, argv);
  std::fprintf(stderr, "kontakt: unknown command '%s'\n", argv[1]);
  print_usage(stderr);
  return 1;
}
