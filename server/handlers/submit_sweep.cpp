#include "server/handlers/submit_sweep.hpp"

#include <fstream>
#include <nlohmann/json.hpp>

#include "server/deck_upload.hpp"
#include "server/digest.hpp"
#include "server/handlers/submission.hpp"
#include "server/handlers/submit_job.hpp"
#include "server/job_json.hpp"
#include "server/problem.hpp"
#include "server/sweep_template.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace kontakt::server::handlers {

namespace {

/// The label every row carries: sweep=<sweep id>.
constexpr const char* kSweepLabel = "sweep";

/// The request, read and checked.
struct SweepRequest {
  std::vector<std::string> decks;           ///< one per row, expanded
  std::vector<SweepRow> rows;               ///< the parameter values (empty with "decks")
  std::optional<std::string> name, scheme;
  std::map<std::string, std::string> labels;
  JobResources resources;
  int max_parallel = 0;
};

/// A table cell: a string as it is, a number as JSON writes it.
std::optional<std::string> cell_text(const json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number()) return v.dump();
  return std::nullopt;
}

std::optional<HttpResponse> read_rows(const json& j, std::vector<SweepRow>& rows) {
  if (!j.is_array()) return invalid_parameter("rows", "an array of objects (name -> value)");
  if (j.size() > kMaxSweepRows)
    return invalid_parameter("rows", std::to_string(j.size()) + " rows: a sweep has at most " +
                                         std::to_string(kMaxSweepRows));
  for (std::size_t i = 0; i < j.size(); ++i) {
    if (!j[i].is_object()) return invalid_parameter("rows", "row " + std::to_string(i) + " is not an object");
    SweepRow row;
    for (const auto& [name, value] : j[i].items()) {
      const auto text = cell_text(value);
      if (!text)
        return invalid_parameter("rows", "row " + std::to_string(i) + ", '" + name +
                                             "': a string or a number");
      row[name] = *text;
    }
    rows.push_back(std::move(row));
  }
  return std::nullopt;
}

std::optional<HttpResponse> read_decks(const json& j, std::vector<std::string>& decks) {
  if (!j.is_array()) return invalid_parameter("decks", "an array of .inp texts");
  if (j.empty()) return invalid_parameter("decks", "no deck");
  if (j.size() > kMaxSweepRows)
    return invalid_parameter("decks", std::to_string(j.size()) + " decks: a sweep has at most " +
                                          std::to_string(kMaxSweepRows));
  for (std::size_t i = 0; i < j.size(); ++i) {
    if (!j[i].is_string()) return invalid_parameter("decks", "deck " + std::to_string(i) + " is not a string");
    decks.push_back(j[i].get<std::string>());
  }
  return std::nullopt;
}

std::optional<HttpResponse> read_max_parallel(const json& j, int& max_parallel) {
  if (!j.is_number_integer() || j.get<long long>() < 1 ||
      j.get<long long>() > static_cast<long long>(kMaxSweepRows))
    return invalid_parameter("max_parallel", "an integer from 1 to 1000: rows running at once");
  max_parallel = j.get<int>();
  return std::nullopt;
}

/// Reads every member; a 400 naming the bad one.
std::optional<HttpResponse> read_sweep(const json& j, SweepRequest& s) {
  if (!j.is_object()) return invalid_parameter("body", "not a JSON object");
  std::optional<std::string> deck_template;
  bool has_rows = false;
  for (const auto& [field, value] : j.items()) {
    std::optional<HttpResponse> bad;
    if (field == "template") {
      if (!value.is_string()) return invalid_parameter("template", "the deck text with <name> placeholders");
      deck_template = value.get<std::string>();
    } else if (field == "rows") {
      has_rows = true;
      bad = read_rows(value, s.rows);
    } else if (field == "decks") {
      bad = read_decks(value, s.decks);
    } else if (field == "name" || field == "scheme") {
      if (value.is_null()) continue;
      if (!value.is_string()) return invalid_parameter(field, "must be a string");
      (field == "name" ? s.name : s.scheme) = value.get<std::string>();
    } else if (field == "labels") {
      bad = read_labels(value, s.labels);
    } else if (field == "resources") {
      if (!value.is_null()) bad = read_resources_member(value, s.resources);
    } else if (field == "max_parallel") {
      bad = read_max_parallel(value, s.max_parallel);
    } else {
      return invalid_parameter(field, "unknown member (template, rows, decks, name, labels, "
                                      "scheme, resources, max_parallel)");
    }
    if (bad) return bad;
  }
  if (deck_template && !s.decks.empty())
    return invalid_parameter("decks", "give either \"template\" and \"rows\", or \"decks\"");
  if (!deck_template && s.decks.empty())
    return invalid_parameter("template", "a sweep needs \"template\" and \"rows\", or \"decks\"");
  if (deck_template) {
    if (!has_rows) return invalid_parameter("rows", "a template needs its parameter table");
    auto expanded = expand_sweep(*deck_template, s.rows);
    if (const auto* error = std::get_if<SweepError>(&expanded)) {
      json extra{{"field", error->field}};
      if (error->row) extra["row"] = *error->row;
      return problem(400, "invalid_parameter", error->field + ": " + error->message, extra);
    }
    s.decks = std::move(std::get<std::vector<std::string>>(expanded));
  } else if (has_rows) {
    return invalid_parameter("rows", "rows go with a template; \"decks\" are complete");
  }
  if (auto bad = check_options(s.name, s.scheme, s.labels)) return bad;
  // Every row's labels: the sweep's own, sweep=<id> and its parameters.
  if (s.labels.contains(kSweepLabel))
    return invalid_parameter("labels", "'sweep' is set by the sweep (sweep=<its id>)");
  if (!s.rows.empty()) {
    for (const auto& [column, value] : s.rows.front())
      if (column == kSweepLabel || s.labels.contains(column))
        return invalid_parameter("rows", "parameter '" + column +
                                             "' is also a label of the sweep; rename one");
    if (s.labels.size() + 1 + s.rows.front().size() > kMaxLabels)
      return invalid_parameter("rows", "labels and parameters together: at most 31");
  }
  if (s.max_parallel == 0) s.max_parallel = static_cast<int>(s.decks.size());
  return std::nullopt;
}

HttpResponse row_refused(const HttpResponse& refused, std::size_t row) {
  json body = json::parse(refused.body, nullptr, false);
  if (!body.is_object()) return refused;
  const std::string detail = "row " + std::to_string(row) + ": " + body.value("detail", "");
  body["detail"] = detail;
  body["row"] = row;
  if (body.contains("errors") && body["errors"].is_array())
    for (json& e : body["errors"]) e["row"] = row;
  HttpResponse r = refused;
  r.body = json_text(body);
  return r;
}

HttpResponse created(ApiContext& ctx, const SweepRecord& sweep, bool replayed) {
  HttpResponse r = json_response(201, sweep_document_of(ctx, sweep));
  r.headers.emplace_back("Location", "/v1/sweeps/id/" + sweep.id);
  if (replayed) r.headers.emplace_back("Idempotent-Replayed", "true");
  return r;
}

/// The rows' jobs: input folders written and decks checked; a 422 naming the first refused
/// row. The caller removes the folders of `jobs` when it does not store them.
std::optional<HttpResponse> prepare_rows(ApiContext& ctx, const SweepRequest& s,
                                         const std::string& sweep_id, const std::string& name,
                                         std::vector<NewJob>& jobs) {
  for (std::size_t i = 0; i < s.decks.size(); ++i) {
    NewJob& job = jobs.emplace_back();
    job.id = new_job_id();
    job.name = name + "-" + std::to_string(i);
    job.scheme = s.scheme;
    job.labels = s.labels;
    job.labels[kSweepLabel] = sweep_id;
    if (!s.rows.empty())
      for (const auto& [column, value] : s.rows[i]) job.labels[column] = value;
    job.resources = s.resources;
    try {
      job.main_file = write_raw_deck(s.decks[i], "row-" + std::to_string(i) + ".inp",
                                     ctx.files.input_dir(job.id));
    } catch (const UploadError& e) {  // an empty deck
      return problem(400, "invalid_upload", "row " + std::to_string(i) + ": " + e.what(),
                     {{"field", "decks"}, {"row", i}});
    }
    if (auto refused = check_stored_deck(ctx, job)) return row_refused(*refused, i);
  }
  return std::nullopt;
}

}  // namespace

json sweep_document_of(ApiContext& ctx, const SweepRecord& sweep) {
  std::optional<std::string> array_id;
  std::ifstream in(ctx.files.sweep_dir(sweep.id) / "slurm" / "array_id");
  if (std::string line; std::getline(in, line) && !line.empty()) array_id = line;
  return sweep_document(sweep, ctx.store.sweep_counts(sweep.id), array_id);
}

HttpResponse submit_sweep(ApiContext& ctx, const HttpRequest& request) {
  if (media_type_of(request) != "application/json")
    return problem(415, "unsupported_media_type", "send the sweep as application/json");
  const json body = json::parse(request.body, nullptr, false);
  if (body.is_discarded()) return invalid_parameter("body", "not a JSON object");
  SweepRequest s;
  if (auto bad = read_sweep(body, s)) return *bad;
  SweepRecord sweep;
  sweep.id = new_job_id();
  sweep.name = s.name.value_or("sweep");
  sweep.max_parallel = s.max_parallel;
  if (auto bad = read_key(request, sweep.idempotency_key)) return *bad;
  sweep.fingerprint = sha256_hex(json_text(body));  // nlohmann orders members: canonical
  if (sweep.idempotency_key)
    if (const auto existing = ctx.store.find_sweep_by_key(*sweep.idempotency_key))
      return existing->fingerprint == sweep.fingerprint ? created(ctx, *existing, true)
                                                        : key_reused();
  std::vector<NewJob> jobs;
  const auto remove_rows = [&] {
    for (const NewJob& job : jobs) ctx.files.remove(job.id);
  };
  try {
    if (auto refused = prepare_rows(ctx, s, sweep.id, sweep.name, jobs)) {
      remove_rows();
      return *refused;
    }
    const auto [result, record] = ctx.store.insert_sweep(sweep, jobs);
    if (result != InsertResult::Created) remove_rows();  // lost a race on the key
    if (result == InsertResult::KeyConflict) return key_reused();
    if (result == InsertResult::Created)
      for (std::size_t i = 0; i < jobs.size(); ++i) ctx.control.job_queued();
    return created(ctx, record, result == InsertResult::Replayed);
  } catch (...) {
    remove_rows();
    throw;
  }
}

}  // namespace kontakt::server::handlers
