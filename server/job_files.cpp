#include "server/job_files.hpp"

namespace fs = std::filesystem;

namespace kontakt::server {

JobFiles::JobFiles(fs::path data_dir) : jobs_(data_dir / "jobs"), sweeps_(data_dir / "sweeps") {
  fs::create_directories(jobs_);
}

fs::path JobFiles::job_dir(const std::string& id) const { return jobs_ / id; }

fs::path JobFiles::sweep_dir(const std::string& sweep_id) const { return sweeps_ / sweep_id; }

void JobFiles::remove(const std::string& id) const {
  std::error_code ec;
  fs::remove_all(job_dir(id), ec);
}

std::vector<std::string> JobFiles::folder_ids() const {
  std::vector<std::string> ids;
  for (const auto& entry : fs::directory_iterator(jobs_))
    if (entry.is_directory()) ids.push_back(entry.path().filename().string());
  return ids;
}

}  // namespace kontakt::server
