// Query parameters of the job lists (GET /v1/jobs, GET /v1/sweeps/{key}): label filters and
// cursor paging. The page token is the (created_ms, id) of the last row shown, "<ms>.<id>",
// opaque to clients.
#pragma once

#include <optional>

#include "server/http_types.hpp"
#include "server/job_store.hpp"

namespace kontakt::server::handlers {

/// The token that continues after `last`.
std::string page_token_after(const JobRecord& last);

/// Reads label=key=value (repeatable; every one must match) into `query`; a 400 naming it.
std::optional<HttpResponse> read_label_filters(const HttpRequest& request, JobQuery& query);

/// Reads limit= (1 to `max_limit`, else `default_limit`) and page_token= into `query`; a 400
/// naming the bad parameter.
std::optional<HttpResponse> read_page_parameters(const HttpRequest& request, int default_limit,
                                                 int max_limit, JobQuery& query);

}  // namespace kontakt::server::handlers
