// Error responses as RFC 9457 problem details (application/problem+json): one place decides
// their shape, so every handler fails the same way.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "server/http_types.hpp"

namespace kontakt::server {

/// {"type", "title", "status", "detail", "code"} plus the members of `extra`. `code` is a
/// stable snake_case name clients can branch on (not_found, invalid_parameter, ...).
HttpResponse problem(int status, const std::string& code, const std::string& detail,
                     const nlohmann::json& extra = nlohmann::json::object());

/// 400 naming the offending request field.
HttpResponse invalid_parameter(const std::string& field, const std::string& detail);

HttpResponse job_not_found(const std::string& id);

/// A JSON body with the given status.
HttpResponse json_response(int status, const nlohmann::json& body);

}  // namespace kontakt::server
