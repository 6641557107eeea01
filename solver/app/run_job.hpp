// The solver's one entry point for a whole job, shared by `kontakt solve` and the daemon:
// read the deck, run the analysis its plan calls for, write every result file, report events
// to the caller's sink and stop when the caller's cancel flag is raised.
#pragma once

#include <atomic>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "analysis/events.hpp"
#include "analysis/nonlinear_static.hpp"

namespace kontakt::app {

/// What to run and where its files go.
struct RunRequest {
  std::filesystem::path deck;     ///< main .inp file; *INCLUDEs resolve relative to it
  std::filesystem::path out_dir;  ///< created when missing
  std::string job_name;           ///< result files are OUT_DIR/JOB_NAME.{dat,hdf,xdmf,...}
  int threads = 0;                ///< 0 = all cores
  /// Contact scheme for every contact pair (overrides the deck's SCHEME= and type default).
  std::optional<std::string> scheme;
  /// Contact stabilisation: "auto" (default), "always" or "never".
  std::string contact_stabilisation = "auto";
  /// The linear variants' drift check (analysis::NonlinearOptions::drift_check).
  bool drift_check = true;
};

enum class RunStatus { Converged, NotConverged, InputError, Cancelled, Error };

/// A deck error as the reader reports it: where, which keyword, what.
struct DeckError {
  std::string file;
  int line = 0;  ///< 1-based, 0 when unknown
  std::string keyword;
  std::string message;  ///< full text, "file:line: keyword: ..."
};

struct RunOutcome {
  RunStatus status = RunStatus::Error;
  int exit_code = 4;        ///< the `kontakt solve` exit code for this status
  std::string message;      ///< empty when converged
  std::optional<DeckError> deck_error;  ///< set for InputError
  bool out_of_memory = false;  ///< an Error because an allocation failed (std::bad_alloc)
};

/// The outcome of reading a deck without solving it (the daemon checks decks on submission).
struct DeckCheck {
  std::optional<DeckError> error;
  int n_steps = 0;
  double total_time = 0;    ///< sum of the step periods: the denominator of progress
  std::vector<std::string> warnings;
};

/// The contact stabilisation modes by name; nullopt for an unknown one.
std::optional<analysis::ContactStabilisation> contact_stabilisation_from_name(
    const std::string& name);

/// Exit codes of `kontakt solve` (README): 0 converged, 2 input error, 3 not converged or
/// cancelled, 4 numerical or internal error.
int exit_code_for(RunStatus status);

/// "converged", "not_converged", "input_error", "cancelled", "error": the Done event's status.
const char* run_status_name(RunStatus status);

/// Reads the deck and applies the scheme override; never throws for a user error (running out
/// of memory, std::bad_alloc, is not one).
DeckCheck check_deck(const std::filesystem::path& deck, const std::optional<std::string>& scheme);

/// Runs the job. Writes OUT_DIR/JOB.{dat,hdf,xdmf,log.jsonl,sta,cvg}; the results of every
/// converged increment are kept whatever ends the run. Every event goes to `events` as well as
/// to the log; a run that fails still ends with a Done event carrying the status and message.
/// `cancel` is polled once per Newton iteration. Never throws.
RunOutcome run_job(const RunRequest& request, analysis::EventSink& events,
                   const std::atomic<bool>& cancel);

}  // namespace kontakt::app
