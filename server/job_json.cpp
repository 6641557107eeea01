#include "server/job_json.hpp"

#include <algorithm>
#include <ctime>

namespace kontakt::server {

std::string json_text(const nlohmann::json& j) {
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

using nlohmann::json;

namespace {

json optional_time(const std::optional<std::int64_t>& ms) {
  return ms ? json(rfc3339(*ms)) : json(nullptr);
}

template <class T>
json or_null(const std::optional<T>& v) {
  return v ? json(*v) : json(nullptr);
}

json progress_document(const JobRecord& job) {
  const JobProgress& p = job.progress;
  double fraction = 0;
  if (job.status == JobStatus::Succeeded) fraction = 1;
  else if (job.planned_time > 0) fraction = std::clamp(p.total_time / job.planned_time, 0.0, 1.0);
  return {{"fraction", fraction},
          {"percent", 100 * fraction},
          {"step", p.step},
          {"steps_total", job.n_steps},
          {"increment", p.increment},
          {"attempt", p.attempt},
          {"iteration", p.iteration},
          {"step_time", p.step_time},
          {"total_time", p.total_time},
          {"dt", p.dt},
          {"last_residual", or_null(p.residual)},
          {"active_contact_elements", or_null(p.contact_elements)}};
}

}  // namespace

std::string rfc3339(std::int64_t unix_ms) {
  const std::time_t seconds = static_cast<std::time_t>(unix_ms / 1000);
  std::tm tm{};
  gmtime_r(&seconds, &tm);
  char buf[40];
  const std::size_t n = std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &tm);
  char ms[8];
  std::snprintf(ms, sizeof ms, ".%03dZ", static_cast<int>(unix_ms % 1000));
  return std::string(buf, n) + ms;
}

json job_document(const JobRecord& job, std::optional<int> queue_position, bool results_available) {
  const std::string self = "/v1/jobs/" + job.id;
  json reason = nullptr;
  if (!job.reason.empty()) reason = {{"code", job.reason}, {"message", job.message}};
  return {{"id", job.id},
          {"name", job.name},
          {"status", status_name(job.status)},
          {"reason", reason},
          {"main", job.main_file},
          {"scheme", or_null(job.scheme)},
          {"labels", job.labels},
          {"resources", to_json(job.resources)},
          {"created", rfc3339(job.created_ms)},
          {"started", optional_time(job.started_ms)},
          {"finished", optional_time(job.finished_ms)},
          {"updated", rfc3339(job.updated_ms)},
          {"attempts", job.attempts},
          {"queue_position", or_null(queue_position)},
          {"progress", progress_document(job)},
          {"results_available", results_available},
          {"links",
           {{"self", self},
            {"events", self + "/events"},
            {"iterations", self + "/iterations"},
            {"increments", self + "/increments"},
            {"results", self + "/results"},
            {"summary", self + "/summary"}}}};
}

json summary_document(const JobRecord& job) {
  json reason = job.reason.empty() ? json(nullptr) : json(job.reason);
  json doc{{"id", job.id},
           {"name", job.name},
           {"status", status_name(job.status)},
           {"reason", reason},
           {"labels", job.labels},
           {"iterations", nullptr},
           {"wall_time", nullptr},
           {"max_displacement", nullptr},
           {"max_mises", nullptr},
           {"max_contact_pressure", nullptr},
           {"total_contact_force", nullptr}};
  if (job.summary) {
    const JobSummary& s = *job.summary;
    doc["iterations"] = s.iterations;
    doc["wall_time"] = s.wall_time;
    doc["max_displacement"] = or_null(s.max_displacement);
    doc["max_mises"] = or_null(s.max_mises);
    doc["max_contact_pressure"] = or_null(s.max_contact_pressure);
    doc["total_contact_force"] = or_null(s.total_contact_force);
  }
  return doc;
}

json artifacts_document(const std::vector<Artifact>& artifacts) {
  json list = json::array();
  for (const Artifact& a : artifacts)
    list.push_back({{"name", a.name}, {"media_type", a.media_type}, {"size", a.size},
                    {"sha256", a.sha256}});
  return {{"artifacts", list}};
}

json queue_document(const StoreCounts& counts, int workers, int busy_workers) {
  json finished = json::object();
  for (JobStatus s : {JobStatus::Succeeded, JobStatus::Failed, JobStatus::Canceled}) {
    const auto it = counts.finished.find(status_name(s));
    finished[status_name(s)] = it == counts.finished.end() ? 0 : it->second;
  }
  return {{"queued", counts.queued},       {"running", counts.running},
          {"canceling", counts.canceling}, {"finished", finished},
          {"workers", workers},            {"busy_workers", busy_workers}};
}

json sweep_list_document(const std::vector<LabelKeyCount>& keys) {
  json list = json::array();
  for (const LabelKeyCount& k : keys)
    list.push_back({{"key", k.key}, {"jobs", k.jobs}, {"latest", rfc3339(k.latest_ms)}});
  return {{"sweeps", list}};
}

json sweep_row_document(const JobRecord& job, const std::string& key) {
  json row = summary_document(job);
  const auto value = job.labels.find(key);
  row["value"] = value == job.labels.end() ? json(nullptr) : json(value->second);
  row["scheme"] = or_null(job.scheme);
  row["created"] = rfc3339(job.created_ms);
  row["finished"] = optional_time(job.finished_ms);
  return row;
}

json sweep_document(const SweepRecord& sweep, const std::map<std::string, int>& counts,
                    const std::optional<std::string>& slurm_array_id) {
  const std::string self = "/v1/sweeps/id/" + sweep.id;
  json by_status = json::object();
  int finished = 0, queued = 0;
  for (JobStatus s : {JobStatus::Queued, JobStatus::Running, JobStatus::Canceling,
                      JobStatus::Succeeded, JobStatus::Failed, JobStatus::Canceled}) {
    const auto it = counts.find(status_name(s));
    const int n = it == counts.end() ? 0 : it->second;
    by_status[status_name(s)] = n;
    if (is_terminal(s)) finished += n;
    if (s == JobStatus::Queued) queued = n;
  }
  int jobs = 0;
  for (const auto& [status, n] : counts) jobs += n;
  // Jobs deleted one by one leave the sweep: it is over when the rest is.
  const char* status = finished == jobs ? "finished" : queued == jobs ? "queued" : "running";
  return {{"id", sweep.id},
          {"name", sweep.name},
          {"status", status},
          {"rows", sweep.n_rows},
          {"max_parallel", sweep.max_parallel},
          {"jobs", by_status},
          {"created", rfc3339(sweep.created_ms)},
          {"slurm_array_id", or_null(slurm_array_id)},
          {"links",
           {{"self", self},
            {"jobs", self + "/jobs"},
            {"cancel", self + "/cancel"},
            {"by_label", "/v1/sweeps/sweep?label=sweep=" + sweep.id}}}};
}

json sweep_job_document(const JobRecord& job) {
  json row = summary_document(job);
  row["row"] = job.sweep_row;
  row["created"] = rfc3339(job.created_ms);
  row["finished"] = optional_time(job.finished_ms);
  return row;
}

}  // namespace kontakt::server
