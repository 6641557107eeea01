// The options and deck of POST /v1/jobs, read from the query and the body (text, zip or JSON),
// each checked before anything is stored. Pure: a request in, a Submission or a 400/415 out.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "server/http_types.hpp"
#include "server/job_resources.hpp"

namespace kontakt::server::handlers {

/// The most labels a job carries (a sweep's row: its sweep's label and parameters included).
inline constexpr std::size_t kMaxLabels = 32;

/// The submission's options and deck, from the query and (for JSON bodies) the body.
struct Submission {
  std::string media_type;  ///< text/plain, application/zip, ...
  std::string deck;        ///< raw .inp text or zip bytes
  std::optional<std::string> name, scheme, main;
  std::map<std::string, std::string> labels;
  JobResources resources;  ///< JSON bodies: "resources" for the executor (job_resources.hpp)
};

/// Reads and validates every option into `s`; a 400 (naming the field) or 415 response when
/// one is bad.
std::optional<HttpResponse> read_submission(const HttpRequest& request, Submission& s);

/// Name, scheme and labels of a submission or a resubmission; a 400 naming the bad one.
std::optional<HttpResponse> check_options(const std::optional<std::string>& name,
                                          const std::optional<std::string>& scheme,
                                          const std::map<std::string, std::string>& labels);

/// Adds the members of a JSON "labels" object (strings) to `labels`; a 400 when malformed.
std::optional<HttpResponse> read_labels(const nlohmann::json& j,
                                        std::map<std::string, std::string>& labels);

/// Reads a "resources" object into `r`; a 400 naming the bad member.
std::optional<HttpResponse> read_resources_member(const nlohmann::json& j, JobResources& r);

/// The request's media type: Content-Type without parameters, lower case; text/plain when
/// absent.
std::string media_type_of(const HttpRequest& request);

/// Names, labels and keys are printable: no C0 controls, no DEL.
bool has_control_chars(const std::string& s);

}  // namespace kontakt::server::handlers
