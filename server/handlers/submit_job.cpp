#include "server/handlers/submit_job.hpp"

#include <nlohmann/json.hpp>

#include "app/run_job.hpp"
#include "model/contact.hpp"
#include "server/deck_upload.hpp"
#include "server/digest.hpp"
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

bool is_label_key(const std::string& key) {
  if (key.empty() || key.size() > 64) return false;
  for (unsigned char c : key)
    if (!std::isalnum(c) && c != '_' && c != '-' && c != '.') return false;
  return true;
}

bool has_control_chars(const std::string& s) {
  for (unsigned char c : s)
    if (c < 0x20 || c == 0x7f) return true;
  return false;
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
  if (j.contains("labels")) {
    if (!j["labels"].is_object()) return invalid_parameter("labels", "must be an object");
    for (const auto& [k, v] : j["labels"].items()) {
      if (!v.is_string()) return invalid_parameter("labels", "values must be strings");
      s.labels[k] = v.get<std::string>();
    }
  }
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
  if (s.name && (s.name->empty() || s.name->size() > kMaxNameLength || has_control_chars(*s.name)))
    return invalid_parameter("name", "1 to 200 printable characters");
  if (s.scheme && !model::contact_scheme_from_name(*s.scheme))
    return invalid_parameter("scheme", "unknown contact scheme '" + *s.scheme + "' (" +
                                           model::contact_scheme_names() + ")");
  if (s.labels.size() > kMaxLabels) return invalid_parameter("labels", "at most 32 labels");
  for (const auto& [k, v] : s.labels) {
    if (!is_label_key(k)) return invalid_parameter("labels", "key '" + k + "': 1 to 64 of A-Z a-z 0-9 _ - .");
    if (v.size() > kMaxLabelValue || has_control_chars(v))
      return invalid_parameter("labels", "value of '" + k + "': at most 256 printable characters");
  }
  return std::nullopt;
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
  const app::DeckCheck check = app::check_deck(input_dir / job.main_file, s.scheme);
  if (check.error) return deck_rejected(*check.error, input_dir);
  job.n_steps = check.n_steps;
  job.planned_time = check.total_time;
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
