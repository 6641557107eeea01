#include "server/handlers/submission.hpp"

#include <cctype>
#include <nlohmann/json.hpp>

#include "model/contact.hpp"
#include "server/handlers/label_key.hpp"
#include "server/problem.hpp"

using nlohmann::json;

namespace kontakt::server::handlers {

namespace {

constexpr std::size_t kMaxNameLength = 200, kMaxLabelValue = 256;

}  // namespace

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

std::optional<HttpResponse> read_resources_member(const json& j, JobResources& r) {
  if (const auto bad = read_resources(j, r)) return invalid_parameter(bad->field, bad->message);
  return std::nullopt;
}

namespace {

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
  if (j.contains("resources") && !j["resources"].is_null())
    if (auto bad = read_resources_member(j["resources"], s.resources)) return bad;
  if (j.contains("labels")) return read_labels(j["labels"], s.labels);
  return std::nullopt;
}

}  // namespace

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

}  // namespace kontakt::server::handlers
