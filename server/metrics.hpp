// GET /metrics in the Prometheus text exposition format (version 0.0.4).
#pragma once

#include <string>
#include <vector>

#include "server/job_store.hpp"

namespace kontakt::server {

/// Queue depth, running jobs, busy workers, finished jobs by status and a histogram of run times.
std::string prometheus_text(const StoreCounts& counts, const std::vector<double>& run_seconds,
                            int n_workers, int n_busy);

}  // namespace kontakt::server
