#include "app/monitor_files.hpp"

#include <cstdio>

#include "core/error.hpp"
#include "output/fortran_format.hpp"

namespace kontakt::app {

namespace {
std::string fixed_int(int value, int width) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%*d", width, value);
  return buf;
}
}  // namespace

MonitorFiles::MonitorFiles(const std::filesystem::path& dir, const std::string& job)
    : sta_(dir / (job + ".sta")), cvg_(dir / (job + ".cvg")) {
  if (!sta_ || !cvg_) throw SolverError("cannot write " + (dir / (job + ".sta")).string());
  sta_ << "SUMMARY OF JOB INFORMATION\n";
  cvg_ << "SUMMARY OF C0NVERGENCE INFORMATION\n"  // sic: ccx's spelling, which scripts match
       << "  STEP   INC  ATT   ITER     CONT.   RESID.        CORR.      RESID.      CORR.\n"
       << "                              EL.    FORCE         DISP       FLUX        TEMP.\n"
       << "                              (#)     (%)           (%)        (%)         (%)\n";
  sta_.flush();
  cvg_.flush();
}

// .sta: 1X,I5,1X,I10,1X,I5,(1X|U),I5,3(1X,E13.6), with contact 2(1X,E13.6) more
void MonitorFiles::sta_line(const analysis::Event& e, bool cut_back) {
  const bool energies = e.contact_elements >= 0;  // a model with contact
  if (!sta_columns_written_) {
    sta_ << "  STEP      INC     ATT  ITRS     TOT TIME     STEP TIME      INC TIME"
         << (energies ? "    STAB. ENER.  STRAIN ENER." : "") << '\n';
    sta_columns_written_ = true;
  }
  sta_ << ' ' << fixed_int(e.step, 5) << ' ' << fixed_int(e.increment, 10) << ' '
       << fixed_int(e.attempt, 5) << (cut_back ? 'U' : ' ') << fixed_int(e.iteration, 5);
  for (Real v : {e.total_time, e.step_time, e.dt}) sta_ << ' ' << output::fortran_e(v, 13, 6, 0);
  if (energies)  // a cut-back attempt committed no energy: blank
    for (Real v : {e.stabilisation_energy, e.strain_energy})
      sta_ << ' ' << (v >= 0 ? output::fortran_e(v, 13, 6, 0) : std::string(13, ' '));
  sta_ << '\n';
  sta_.flush();
}

void MonitorFiles::on_event(const analysis::Event& e) {
  using Kind = analysis::Event::Kind;
  if (e.kind == Kind::Increment) sta_line(e, false);
  if (e.kind == Kind::Cutback) sta_line(e, true);
  if (e.kind == Kind::Iteration) {
    // .cvg: 4(I6),I9,4(2X,E10.4): contact elements, residual and correction in %, then the
    // thermal columns (no thermal field here).
    cvg_ << fixed_int(e.step, 6) << fixed_int(e.increment, 6) << fixed_int(e.attempt, 6)
         << fixed_int(e.iteration, 6) << fixed_int(std::max(e.contact_elements, 0), 9);
    for (Real v : {std::max<Real>(e.residual, 0), std::max<Real>(e.correction, 0), 0.0, 0.0})
      cvg_ << "  " << output::fortran_e(v, 10, 4, 0);
    cvg_ << '\n';
    cvg_.flush();
  }
}

}  // namespace kontakt::app
