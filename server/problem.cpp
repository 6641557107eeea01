#include "server/problem.hpp"

#include "server/job_json.hpp"

namespace kontakt::server {

namespace {

const char* title_of(int status) {
  switch (status) {
    case 400: return "Bad Request";
    case 401: return "Unauthorized";
    case 404: return "Not Found";
    case 405: return "Method Not Allowed";
    case 409: return "Conflict";
    case 413: return "Content Too Large";
    case 415: return "Unsupported Media Type";
    case 416: return "Range Not Satisfiable";
    case 422: return "Unprocessable Content";
    case 500: return "Internal Server Error";
    case 503: return "Service Unavailable";
    default: return "Error";
  }
}

}  // namespace

HttpResponse problem(int status, const std::string& code, const std::string& detail,
                     const nlohmann::json& extra) {
  nlohmann::json body = extra;
  body["type"] = "urn:kontakt:problem:" + code;
  body["title"] = title_of(status);
  body["status"] = status;
  body["detail"] = detail;
  body["code"] = code;
  HttpResponse r;
  r.status = status;
  r.content_type = "application/problem+json";
  r.body = json_text(body);
  return r;
}

HttpResponse invalid_parameter(const std::string& field, const std::string& detail) {
  return problem(400, "invalid_parameter", field + ": " + detail, {{"field", field}});
}

HttpResponse job_not_found(const std::string& id) {
  return problem(404, "not_found", "no job " + id);
}

HttpResponse json_response(int status, const nlohmann::json& body) {
  HttpResponse r;
  r.status = status;
  r.body = json_text(body);
  return r;
}

}  // namespace kontakt::server
