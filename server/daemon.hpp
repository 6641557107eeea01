// kontaktd assembled: the store and its recovery, the worker pool, the router, the HTTP
// listener on the I/O threads, and SIGINT/SIGTERM draining.
#pragma once

#include "server/settings.hpp"

namespace kontakt::server {

/// Runs the daemon until SIGINT or SIGTERM; returns the process exit code. Prints
/// "kontaktd: listening on http://ADDRESS:PORT" once requests are accepted.
int run_daemon(const Settings& settings);

}  // namespace kontakt::server
