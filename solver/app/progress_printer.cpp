#include "app/progress_printer.hpp"

#include <unistd.h>

namespace kontakt::app {

ProgressPrinter::ProgressPrinter(std::FILE* out, bool quiet)
    : out_(out), tty_(isatty(fileno(out)) != 0), quiet_(quiet) {}

void ProgressPrinter::on_event(const analysis::Event& e) {
  using Kind = analysis::Event::Kind;
  if (e.kind == Kind::Warning) {
    std::fprintf(stderr, "%skontakt: warning: %s\n", tty_ && !quiet_ ? "\n" : "", e.message.c_str());
    return;
  }
  if (quiet_) return;
  switch (e.kind) {
    case Kind::Step:
      if (!tty_) std::fprintf(out_, "step %d\n", e.step);
      break;
    case Kind::Increment:
      std::fprintf(out_, tty_ ? "\rstep %d  increment %d  iterations %d  time %.6g  (%.2f s)\033[K"
                              : "step %d increment %d iterations %d time %.6g (%.2f s)\n",
                   e.step, e.increment, e.iteration, e.total_time, e.wall_time);
      break;
    case Kind::Done:
      if (e.status != "converged") break;  // the caller reports how the run failed
      std::fprintf(out_, "%s%s: max |u| = %.6g, max von Mises = %.6g, %.2f s\n", tty_ ? "\n" : "",
                   e.status.c_str(), e.max_displacement, e.max_mises, e.wall_time);
      break;
    default:
      break;
  }
  std::fflush(out_);
}

}  // namespace kontakt::app
