#include "server/handlers/submit_job.hpp"

#include <nlohmann/json.hpp>

#include "server/deck_upload.hpp"
#include "server/handlers/submission.hpp"
#include "server/digest.hpp"
#include "server/include_check.hpp"
#include "server/job_json.hpp"
#include "server/problem.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace kontakt::server::handlers {

namespace {

constexpr std::size_t kMaxIdempotencyKey = 255;

/// Same key, same submission <=> same fingerprint.
std::string fingerprint_of(const Submission& s) {
  const json options{{"media_type", s.media_type}, {"name", s.name.value_or("")},
                     {"scheme", s.scheme.value_or("")}, {"main", s.main.value_or("")},
                     {"labels", s.labels}};
  return sha256_hex(json_text(options) + '\n' + sha256_hex(s.deck));
}

/// Paths in the reader's messages are the server's; clients see them relative to the upload.
std::string relative_to(const std::string& text, const fs::path& input_dir) {
  std::string out = text;
  const std::string prefix = input_dir.string() + "/";
  for (std::size_t at; (at = out.find(prefix)) != std::string::npos;) out.erase(at, prefix.size());
  return out;
}

HttpResponse deck_rejected(const app::DeckError& error, const fs::path& input_dir) {
  const std::string message = relative_to(error.message, input_dir);
  json detail{{"file", relative_to(error.file, input_dir)},
              {"line", error.line},
              {"keyword", error.keyword},
              {"message", message}};
  return problem(422, "input_error", message, {{"errors", json::array({detail})}});
}

HttpResponse created(ApiContext& ctx, const JobRecord& job, bool replayed) {
  // A replayed submission may be long finished; a fresh one may be claimed already.
  const std::optional<int> position =
      job.status == JobStatus::Queued ? ctx.store.queue_position(job) : std::nullopt;
  HttpResponse r = json_response(201, job_document(job, position, false));
  r.headers.emplace_back("Location", "/v1/jobs/" + job.id);
  if (replayed) r.headers.emplace_back("Idempotent-Replayed", "true");
  return r;
}

HttpResponse key_reused() {
  return problem(422, "idempotency_key_reused",
                 "this Idempotency-Key was used for a different submission");
}

/// Writes the deck into the job's folder and parses it; a 4xx response when it is refused.
std::optional<HttpResponse> store_and_check(ApiContext& ctx, const Submission& s,
                                            const std::string& id, NewJob& job) {
  const fs::path input_dir = ctx.files.input_dir(id);
  try {
    job.main_file = s.media_type == "application/zip"
                        ? write_zip_deck(s.deck, s.main, input_dir, ctx.max_unpacked)
                        : write_raw_deck(s.deck, s.main, input_dir);
  } catch (const UploadError& e) {
    return problem(400, "invalid_upload", e.field() + ": " + e.what(), {{"field", e.field()}});
  }
  if (const auto escape = find_escaping_include(input_dir, job.main_file))
    return deck_rejected(*escape, input_dir);
  const DeckCheckResult result = ctx.check_deck(input_dir / job.main_file, s.scheme);
  if (result.failure)
    return problem(422, "deck_check_failed", "the deck could not be checked: " + *result.failure);
  if (result.check.error) return deck_rejected(*result.check.error, input_dir);
  job.n_steps = result.check.n_steps;
  job.planned_time = result.check.total_time;
  return std::nullopt;
}

}  // namespace

HttpResponse submit_job(ApiContext& ctx, const HttpRequest& request) {
  Submission s;
  if (auto bad = read_submission(request, s)) return *bad;
  const auto key = request.header("idempotency-key");
  if (key && (key->empty() || key->size() > kMaxIdempotencyKey || has_control_chars(*key)))
    return invalid_parameter("Idempotency-Key", "1 to 255 printable characters");
  const std::string fingerprint = fingerprint_of(s);
  if (key) {
    if (auto existing = ctx.store.find_by_key(*key))
      return existing->fingerprint == fingerprint ? created(ctx, *existing, true) : key_reused();
  }
  NewJob job;
  job.id = new_job_id();
  job.scheme = s.scheme;
  job.labels = s.labels;
  job.idempotency_key = key;
  job.fingerprint = fingerprint;
  if (auto refused = store_and_check(ctx, s, job.id, job)) {
    ctx.files.remove(job.id);
    return *refused;
  }
  job.name = s.name.value_or(fs::path(job.main_file).stem().string());
  try {
    const auto [result, record] = ctx.store.insert_job(job);
    if (result != InsertResult::Created) ctx.files.remove(job.id);  // lost a race on the key
    if (result == InsertResult::KeyConflict) return key_reused();
    if (result == InsertResult::Created) ctx.control.job_queued();
    return created(ctx, record, result == InsertResult::Replayed);
  } catch (...) {
    ctx.files.remove(job.id);
    throw;
  }
}

}  // namespace kontakt::server::handlers
