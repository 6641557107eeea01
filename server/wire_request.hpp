// A request off the wire (Beast) as the plain HttpRequest the router sees: the target split
// into the decoded path and query, header names in lower case.
#pragma once

#include <boost/beast/http/message.hpp>
#include <boost/beast/http/string_body.hpp>
#include <optional>

#include "server/http_types.hpp"

namespace kontakt::server {

/// nullopt when the target's path or query has a malformed percent escape.
std::optional<HttpRequest> to_plain_request(
    boost::beast::http::request<boost::beast::http::string_body>&& request);

}  // namespace kontakt::server
