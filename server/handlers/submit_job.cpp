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
  json options{{"media_type", s.media_type}, {"name", s.name.value_or("")},
               {"scheme", s.scheme.value_or("")}, {"main", s.main.value_or("")},
               {"labels", s.labels}};
  // Only when given: the keys of submissions from before resources existed stay valid.
  if (const json r = to_json(s.resources); !r.empty()) options["resources"] = r;
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

/// Writes the submitted deck into the job's folder; a 400 for a bad upload.
std::optional<HttpResponse> store_upload(ApiContext& ctx, const Submission& s, NewJob& job) {
  const fs::path input_dir = ctx.files.input_dir(job.id);
  try {
    job.main_file = s.media_type == "application/zip"
                        ? write_zip_deck(s.deck, s.main, input_dir, ctx.max_unpacked)
                        : write_raw_deck(s.deck, s.main, input_dir);
  } catch (const UploadError& e) {
    return problem(400, "invalid_upload", e.field() + ": " + e.what(), {{"field", e.field()}});
  }
  return std::nullopt;
}

/// A job with this key already: the same submission replays it, another one is refused.
std::optional<HttpResponse> replay_of(ApiContext& ctx, const NewJob& job) {
  if (!job.idempotency_key) return std::nullopt;
  const auto existing = ctx.store.find_by_key(*job.idempotency_key);
  if (!existing) return std::nullopt;
  return existing->fingerprint == job.fingerprint ? created(ctx, *existing, true) : key_reused();
}

/// Queues a job whose input folder `fill` writes; the folder goes again unless a job was
/// created from it.
template <class Fill>
HttpResponse queue_new_job(ApiContext& ctx, NewJob job, Fill fill) {
  if (auto replayed = replay_of(ctx, job)) return *replayed;
  try {
    std::optional<HttpResponse> refused = fill(job);
    if (!refused) refused = check_stored_deck(ctx, job);
    if (refused) {
      ctx.files.remove(job.id);
      return *refused;
    }
    if (job.name.empty()) job.name = fs::path(job.main_file).stem().string();
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

/// A resubmission's options: absent members keep the source job's; "scheme": null runs the
/// deck's own schemes.
std::optional<HttpResponse> read_resubmission(const HttpRequest& request, NewJob& job) {
  if (request.body.empty()) return std::nullopt;
  if (media_type_of(request) != "application/json")
    return problem(415, "unsupported_media_type", "send the options as application/json");
  const json j = json::parse(request.body, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return invalid_parameter("body", "not a JSON object");
  for (const auto& [field, value] : j.items()) {
    if (field == "scheme") {
      if (!value.is_null() && !value.is_string()) return invalid_parameter("scheme", "a string or null");
      job.scheme = value.is_null() ? std::nullopt : std::optional(value.get<std::string>());
    } else if (field == "name") {
      if (!value.is_string()) return invalid_parameter("name", "must be a string");
      job.name = value.get<std::string>();
    } else if (field == "labels") {
      job.labels.clear();  // they replace the source job's
      if (auto bad = read_labels(value, job.labels)) return bad;
    } else if (field == "resources") {
      job.resources = {};  // they replace the source job's
      if (!value.is_null())
        if (auto bad = read_resources_member(value, job.resources)) return bad;
    } else {
      return invalid_parameter(field, "unknown member (scheme, name, labels, resources)");
    }
  }
  return check_options(job.name, job.scheme, job.labels);
}

}  // namespace

HttpResponse key_reused() {
  return problem(422, "idempotency_key_reused",
                 "this Idempotency-Key was used for a different submission");
}

std::optional<HttpResponse> check_stored_deck(ApiContext& ctx, NewJob& job) {
  const fs::path input_dir = ctx.files.input_dir(job.id);
  if (const auto escape = find_escaping_include(input_dir, job.main_file))
    return deck_rejected(*escape, input_dir);
  const DeckCheckResult result = ctx.check_deck(input_dir / job.main_file, job.scheme);
  if (result.failure)
    return problem(422, "deck_check_failed", "the deck could not be checked: " + *result.failure);
  if (result.check.error) return deck_rejected(*result.check.error, input_dir);
  job.n_steps = result.check.n_steps;
  job.planned_time = result.check.total_time;
  return std::nullopt;
}

std::optional<HttpResponse> read_key(const HttpRequest& request, std::optional<std::string>& key) {
  key = request.header("idempotency-key");
  if (key && (key->empty() || key->size() > kMaxIdempotencyKey || has_control_chars(*key)))
    return invalid_parameter("Idempotency-Key", "1 to 255 printable characters");
  return std::nullopt;
}

HttpResponse submit_job(ApiContext& ctx, const HttpRequest& request) {
  Submission s;
  if (auto bad = read_submission(request, s)) return *bad;
  NewJob job;
  if (auto bad = read_key(request, job.idempotency_key)) return *bad;
  job.id = new_job_id();
  job.name = s.name.value_or("");
  job.scheme = s.scheme;
  job.labels = s.labels;
  job.resources = s.resources;
  job.fingerprint = fingerprint_of(s);
  return queue_new_job(ctx, std::move(job), [&](NewJob& j) { return store_upload(ctx, s, j); });
}

HttpResponse resubmit_job(ApiContext& ctx, const HttpRequest& request, const std::string& source_id) {
  const auto source = ctx.store.find_job(source_id);
  if (!source) return job_not_found(source_id);
  NewJob job;
  job.name = source->name;
  job.scheme = source->scheme;
  job.labels = source->labels;
  job.resources = source->resources;
  job.main_file = source->main_file;
  if (auto bad = read_resubmission(request, job)) return *bad;
  if (auto bad = read_key(request, job.idempotency_key)) return *bad;
  job.id = new_job_id();
  json options{{"resubmit_of", source_id}, {"name", job.name},
               {"scheme", job.scheme.value_or("")}, {"labels", job.labels}};
  if (const json r = to_json(job.resources); !r.empty()) options["resources"] = r;
  job.fingerprint = sha256_hex(options.dump());
  return queue_new_job(ctx, std::move(job), [&](NewJob& j) -> std::optional<HttpResponse> {
    std::error_code ec;
    fs::create_directories(ctx.files.job_dir(j.id), ec);
    if (!ec)
      fs::copy(ctx.files.input_dir(source_id), ctx.files.input_dir(j.id),
               fs::copy_options::recursive, ec);
    if (ec)
      return problem(409, "input_unavailable", "the input of job " + source_id +
                                                   " cannot be copied: " + ec.message());
    return std::nullopt;
  });
}

}  // namespace kontakt::server::handlers
