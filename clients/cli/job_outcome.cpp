#include "cli/job_outcome.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace kontakt::cli {

int exit_code_for_job(const nlohmann::json& job) {
  const std::string status = job.value("status", "");
  if (status == "succeeded") return kSucceeded;
  if (status == "canceled") return kCanceled;
  std::string reason;
  if (job.contains("reason") && job["reason"].is_object()) reason = job["reason"].value("code", "");
  if (reason == "input_error") return kInputError;
  if (reason == "not_converged") return kNotConverged;
  return kFailed;
}

std::string progress_line(const nlohmann::json& job, int width) {
  const nlohmann::json& p = job.at("progress");
  const double fraction = std::clamp(p.value("fraction", 0.0), 0.0, 1.0);
  const int filled = static_cast<int>(std::lround(fraction * width));
  std::string bar = "[" + std::string(static_cast<std::size_t>(filled), '#') +
                    std::string(static_cast<std::size_t>(width - filled), '-') + "]";
  char text[256];
  std::snprintf(text, sizeof text, "%-9s step %d/%d  inc %d  it %d  %s %3.0f%%",
                job.value("status", "?").c_str(), p.value("step", 0), p.value("steps_total", 0),
                p.value("increment", 0), p.value("iteration", 0), bar.c_str(), 100 * fraction);
  std::string line = text;
  if (p.contains("last_residual") && p["last_residual"].is_number()) {
    std::snprintf(text, sizeof text, "  res %.2e", p["last_residual"].get<double>());
    line += text;
  }
  if (p.contains("active_contact_elements") && p["active_contact_elements"].is_number())
    line += "  contact " + std::to_string(p["active_contact_elements"].get<int>());
  return line;
}

}  // namespace kontakt::cli
