#include "app/run_job.hpp"

#include "analysis/event_log.hpp"
#include "analysis/linear_static.hpp"
#include "analysis/nonlinear_static.hpp"
#include "app/monitor_files.hpp"
#include "app/process_heap.hpp"
#include "app/result_writers.hpp"
#include "contact/adjust_nodes.hpp"
#include "contact/tie_constraints.hpp"
#include "core/error.hpp"
#include "inp/read_deck.hpp"
#include "linsolve/blas_threads.hpp"
#include "model/contact.hpp"

namespace fs = std::filesystem;

namespace kontakt::app {

namespace {

DeckError deck_error_of(const InputError& e) {
  return {.file = e.where().file, .line = e.where().line, .keyword = e.keyword(),
          .message = e.what()};
}

/// The deck's model, set up for the analysis: the scheme override applied to every contact
/// pair of the deck, the *TIE constraints generated (their slave nodes moved; a tie with its
/// own SCHEME= keeps it), and the slave nodes ADJUST asks for moved onto their master surfaces.
model::Model read_model(const fs::path& deck, const std::optional<std::string>& scheme) {
  model::Model model = inp::read_deck(deck);
  if (scheme) {
    const auto parsed = model::contact_scheme_from_name(*scheme);
    if (!parsed)
      throw InputError({deck.string(), 0}, "scheme",
                       "unknown contact scheme '" + *scheme + "' (" +
                           model::contact_scheme_names() + ")");
    for (auto& pair : model.contact_pairs) pair.scheme = *parsed;
  }
  contact::apply_ties(model);
  contact::adjust_slave_nodes(model);
  return model;
}

RunOutcome outcome(RunStatus status, std::string message = {}) {
  RunOutcome result;
  result.status = status;
  result.exit_code = exit_code_for(status);
  result.message = std::move(message);
  return result;
}

/// Runs the analysis the model needs, completing the result files whatever ends it.
void solve(const model::Model& model, const RunRequest& request, ResultWriters& writers,
           analysis::EventSink& events, const std::atomic<bool>& cancel) {
  try {
    if (analysis::needs_newton(model)) {
      analysis::NonlinearOptions options;
      options.threads = request.threads;
      options.cancel = &cancel;
      options.contact_stabilisation =
          contact_stabilisation_from_name(request.contact_stabilisation)
              .value_or(analysis::ContactStabilisation::Auto);
      options.drift_check = request.drift_check;
      analysis::run_nonlinear_static(model, options, writers, events);
    } else {
      analysis::run_linear_static(model, {.threads = request.threads, .cancel = &cancel}, writers,
                                  events);
    }
  } catch (const NonConvergence&) {
    writers.finish();
    throw;
  } catch (const analysis::Cancelled&) {
    writers.finish();
    throw;
  }
  writers.finish();
}

}  // namespace

std::optional<analysis::ContactStabilisation> contact_stabilisation_from_name(
    const std::string& name) {
  using analysis::ContactStabilisation;
  if (name == "auto") return ContactStabilisation::Auto;
  if (name == "always") return ContactStabilisation::Always;
  if (name == "never") return ContactStabilisation::Never;
  return std::nullopt;
}

int exit_code_for(RunStatus status) {
  switch (status) {
    case RunStatus::Converged: return 0;
    case RunStatus::InputError: return 2;
    case RunStatus::NotConverged:
    case RunStatus::Cancelled: return 3;
    case RunStatus::Error: return 4;
  }
  return 4;
}

const char* run_status_name(RunStatus status) {
  switch (status) {
    case RunStatus::Converged: return "converged";
    case RunStatus::NotConverged: return "not_converged";
    case RunStatus::InputError: return "input_error";
    case RunStatus::Cancelled: return "cancelled";
    case RunStatus::Error: return "error";
  }
  return "error";
}

DeckCheck check_deck(const fs::path& deck, const std::optional<std::string>& scheme) {
  DeckCheck check;
  try {
    const model::Model model = read_model(deck, scheme);
    check.n_steps = static_cast<int>(model.steps.size());
    for (const auto& step : model.steps) check.total_time += step.procedure.period;
    check.warnings = model.warnings;
  } catch (const InputError& e) {
    check.error = deck_error_of(e);
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    check.error = DeckError{.file = deck.string(), .line = 0, .keyword = {}, .message = e.what()};
  }
  return check;
}

RunOutcome run_job(const RunRequest& request, analysis::EventSink& events,
                   const std::atomic<bool>& cancel) {
  std::error_code ec;
  fs::create_directories(request.out_dir, ec);
  if (ec) return outcome(RunStatus::Error, "cannot create " + request.out_dir.string() + ": " +
                                               ec.message());
  RunOutcome result;
  try {
    analysis::JsonlEventLog log(request.out_dir / (request.job_name + ".log.jsonl"));
    analysis::EventFanout fanout;
    fanout.add(log);
    fanout.add(events);
    try {
      MonitorFiles monitor(request.out_dir, request.job_name);
      fanout.add(monitor);
      if (request.threads > 0) linsolve::set_blas_threads(request.threads);
      keep_freed_memory_in_process();  // a sanitizer's allocator keeps its own policy
      const model::Model model = read_model(request.deck, request.scheme);
      for (const auto& w : model.warnings)
        fanout.on_event({.kind = analysis::Event::Kind::Warning, .message = w});
      ResultWriters writers(model, request.out_dir, request.job_name);
      fanout.add(writers);
      solve(model, request, writers, fanout, cancel);
      return outcome(RunStatus::Converged);
    } catch (const InputError& e) {
      result = outcome(RunStatus::InputError, e.what());
      result.deck_error = deck_error_of(e);
    } catch (const NonConvergence& e) {
      result = outcome(RunStatus::NotConverged, e.what());
    } catch (const analysis::Cancelled& e) {
      result = outcome(RunStatus::Cancelled, e.what());
    } catch (const std::bad_alloc&) {
      result = outcome(RunStatus::Error, "out of memory");
      result.out_of_memory = true;
    } catch (const std::exception& e) {
      result = outcome(RunStatus::Error, e.what());
    }
    // The drivers end a converged run with Done; every other ending gets one here.
    const analysis::Event done{.kind = analysis::Event::Kind::Done,
                               .status = run_status_name(result.status),
                               .message = result.message};
    log.on_event(done);
    events.on_event(done);
  } catch (const std::exception& e) {  // the event log itself could not be written
    result = outcome(RunStatus::Error, e.what());
  }
  return result;
}

}  // namespace kontakt::app
