#include "server/handlers/submit_job.hpp"

#include <nlohmann/json.hpp>

#include "app/run_job.hpp"
#include "model/contact.hpp"
#include "server/deck_upload.hpp"
#include "server/digest.hpp"
#include "server/handlers/label_key.hpp"
#include "server/include_check.hpp"
#include "server/job_json.hpp"
#include "server/problem.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace kontakt::server::handlers {

namespace {

constexpr std::size_t kMaxNameLength = 200, kMaxLabels = 32, kMaxLabelValue = 256,
                      kMaxIdempotencyKey = 255;

/// The submission's options and deck, from the query and (for JSON bodies) the body.
struct Submission {
  std::string media_type;  ///< text/plain, application/zip, ...
  std::string deck;        ///< raw .inp text or zip bytes
  std::optional<std::string> name, scheme, main;
  std::map<std::string, std::string> labels;
};

std::string media_type_of(const HttpRequest& request) {
  std::string type = request.header("content-type").value_or("text/plain");
  type = type.substr(0, type.find(';'));
  while (!type.empty() && type.back() == ' ') type.pop_back();
  for (char& c : type) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return type;
}

bool has_control_chars(const std::string& s) {
  for (unsigned char c : s)
    if (c < 0x20 || c == 0x7f) return true;
  return false;
}

/// Name, scheme and labels of a submission or a resubmission; a 400 naming the bad one.
std::optional<HttpResponse> check_options(const std::optional<std::string>& name,
                                          const std::optional<std::string>& scheme,
                                          const std::map<std::string, std::string>& labels) {
  if (name && (name->empty() || name->size() > kMaxNameLength || has_control_chars(*name)))
    return invalid_parameter("name", "1 to 200 printable characters");
  if (scheme && !model::contact_scheme_from_name(*scheme))
    return invalid_parameter("scheme", "unknown contact scheme '" + *scheme + "' (" +
                                           model::contact_scheme_names() + ")");
  if (labels.size() > kMaxLabels) return invalid_parameter("labels", "at most 32 labels");
  for (const auto& [k, v] : labels) {
    if (!is_label_key(k)) return invalid_parameter("labels", "key '" + k + "': 1 to 64 of A-Z a-z 0-9 _ - .");
    if (v.size() > kMaxLabelValue || has_control_chars(v))
      return invalid_parameter("labels", "value of '" + k + "': at most 256 printable characters");
  }
  return std::nullopt;
}

/// Adds a "labels" member (an object of strings) to `labels`.
std::optional<HttpResponse> read_labels(const json& j, std::map<std::string, std::string>& labels) {
  if (!j.is_object()) return invalid_parameter("labels", "must be an object");
  for (const auto& [k, v] : j.items()) {
    if (!v.is_string()) return invalid_parameter("labels", "values must be strings");
    labels[k] = v.get<std::string>();
  }
  return std::nullopt;
}

/// Fills `s` from a JSON body; returns a 400 when it is malformed.
std::optional<HttpResponse> read_json_body(const std::string& body, Submission& s) {
  const json j = json::parse(body, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return invalid_parameter("body", "not a JSON object");
  if (!j.contains("deck") || !j["deck"].is_string())
    return invalid_parameter("deck", "a JSON submission needs \"deck\": the .inp text");
  s.deck = j["deck"].get<std::string>();
  s.media_type = "text/plain";
  for (const char* field : {"name", "scheme", "main"}) {
    if (!j.contains(field) || j[field].is_null()) continue;
    if (!j[field].is_string()) return invalid_parameter(field, "must be a string");
    const std::string v = j[field].get<std::string>();
    if (std::string(field) == "name") s.name = v;
    else if (std::string(field) == "scheme") s.scheme = v;
    else s.main = v;
  }
  if (j.contains("labels")) return read_labels(j["labels"], s.labels);
  return std::nullopt;
}

/// Reads and validates every option; a 400/415 response when one is bad.
std::optional<HttpResponse> read_submission(const HttpRequest& request, Submission& s) {
  s.media_type = media_type_of(request);
  s.name = request.param("name");
  s.scheme = request.param("scheme");
  s.main = request.param("main");
  for (const std::string& label : request.params("label")) {
    const std::size_t eq = label.find('=');
    if (eq == std::string::npos) return invalid_parameter("label", "expected key=value, got '" + label + "'");
    s.labels[label.substr(0, eq)] = label.substr(eq + 1);
  }
  if (s.media_type == "application/json") {
    if (auto bad = read_json_body(request.body, s)) return bad;
  } else if (s.media_type == "text/plain" || s.media_type == "application/octet-stream" ||
             s.media_type == "application/x-www-form-urlencoded" /* curl --data-binary */ ||
             s.media_type == "application/zip") {
    s.deck = request.body;
  } else {
    return problem(415, "unsupported_media_type",
                   "send the deck as text/plain, application/zip or application/json, not " +
                       s.media_type);
  }
  return check_options(s.name, s.scheme, s.labels);
}

/// Same key, same submission <=> same fingerprint.
std::string fingerprint_of(const Submission& s) {
  const json options{{"media_type", s.media_type}, {"name", s.name.value_or("")},
                     {"scheme", s.scheme.value_or("")}, {"main", s.main.value_or("")},
                     {"labels", s.labels}};
  return sha256_hex(options.dump() + '\n' + sha256_hex(s.deck));
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

/// Parses the deck in place in the job's input folder; a 422 when the reader refuses it.
std::optional<HttpResponse> check_stored_deck(ApiContext& ctx, NewJob& job) {
  const fs::path input_dir = ctx.files.input_dir(job.id);
  if (const auto escape = find_escaping_include(input_dir, job.main_file))
    return deck_rejected(*escape, input_dir);
  const app::DeckCheck check = app::check_deck(input_dir / job.main_file, job.scheme);
  if (check.error) return deck_rejected(*check.error, input_dir);
  job.n_steps = check.n_steps;
  job.planned_time = check.total_time;
  return std::nullopt;
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

/// The Idempotency-Key header: nullopt when absent; a 400 when malformed.
std::optional<HttpResponse> read_key(const HttpRequest& request, std::optional<std::string>& key) {
  key = request.header("idempotency-key");
  if (key && (key->empty() || key->size() > kMaxIdempotencyKey || has_control_chars(*key)))
    return invalid_parameter("Idempotency-Key", "1 to 255 printable characters");
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
    } else {
      return invalid_parameter(field, "unknown member (scheme, name, labels)");
    }
  }
  return check_options(job.name, job.scheme, job.labels);
}

}  // namespace

HttpResponse submit_job(ApiContext& ctx, const HttpRequest& request) {
  Submission s;
  if (auto bad = read_submission(request, s)) return *bad;
  NewJob job;
  if (auto bad = read_key(request, job.idempotency_key)) return *bad;
  job.id = new_job_id();
  job.name = s.name.value_or("");
  job.scheme = s.scheme;
  job.labels = s.labels;
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
  job.main_file = source->main_file;
  if (auto bad = read_resubmission(request, job)) return *bad;
  if (auto bad = read_key(request, job.idempotency_key)) return *bad;
  job.id = new_job_id();
  const json options{{"resubmit_of", source_id}, {"name", job.name},
                     {"scheme", job.scheme.value_or("")}, {"labels", job.labels}};
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
