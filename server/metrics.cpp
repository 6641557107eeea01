#include "server/metrics.hpp"

#include <array>
#include <cstdio>

namespace kontakt::server {

namespace {

constexpr std::array<double, 10> kBuckets{0.1, 0.5, 1, 5, 10, 30, 60, 300, 1800, 7200};

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string gauge(const char* name, const char* help, double value) {
  return std::string("# HELP ") + name + " " + help + "\n# TYPE " + name + " gauge\n" + name +
         " " + number(value) + "\n";
}

}  // namespace

std::string prometheus_text(const StoreCounts& counts, const std::vector<double>& run_seconds,
                            int n_workers, int n_busy) {
  std::string out;
  out += gauge("kontakt_jobs_queued", "Jobs waiting for a worker.", counts.queued);
  out += gauge("kontakt_jobs_running", "Jobs running or stopping after a cancel request.",
               counts.running + counts.canceling);
  out += gauge("kontakt_workers", "Worker slots.", n_workers);
  out += gauge("kontakt_workers_busy", "Worker slots running a job.", n_busy);
  out += "# HELP kontakt_jobs_finished_total Finished jobs by final status.\n"
         "# TYPE kontakt_jobs_finished_total counter\n";
  for (const char* status : {"succeeded", "failed", "canceled"}) {
    const auto it = counts.finished.find(status);
    out += std::string("kontakt_jobs_finished_total{status=\"") + status + "\"} " +
           std::to_string(it == counts.finished.end() ? 0 : it->second) + "\n";
  }
  out += "# HELP kontakt_job_duration_seconds Run time of finished jobs.\n"
         "# TYPE kontakt_job_duration_seconds histogram\n";
  double sum = 0;
  for (double s : run_seconds) sum += s;
  for (double le : kBuckets) {
    std::size_t n = 0;
    for (double s : run_seconds) n += s <= le;
    out += "kontakt_job_duration_seconds_bucket{le=\"" + number(le) + "\"} " + std::to_string(n) + "\n";
  }
  out += "kontakt_job_duration_seconds_bucket{le=\"+Inf\"} " + std::to_string(run_seconds.size()) + "\n";
  out += "kontakt_job_duration_seconds_sum " + number(sum) + "\n";
  out += "kontakt_job_duration_seconds_count " + std::to_string(run_seconds.size()) + "\n";
  return out;
}

}  // namespace kontakt::server
