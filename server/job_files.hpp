// The folders of a job under the data directory:
//   DATA/jobs/ID/input/    the submitted deck and its *INCLUDE files
//   DATA/jobs/ID/work/     the solver writes here while it runs
//   DATA/jobs/ID/results/  finished files, moved in by rename: a download never sees half a file
// and of a sweep (POST /v1/sweeps), for what its executor keeps of it (the Slurm array):
//   DATA/sweeps/ID/
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace kontakt::server {

class JobFiles {
 public:
  explicit JobFiles(std::filesystem::path data_dir);
  std::filesystem::path job_dir(const std::string& id) const;
  std::filesystem::path input_dir(const std::string& id) const { return job_dir(id) / "input"; }
  std::filesystem::path work_dir(const std::string& id) const { return job_dir(id) / "work"; }
  std::filesystem::path results_dir(const std::string& id) const { return job_dir(id) / "results"; }
  std::filesystem::path sweep_dir(const std::string& sweep_id) const;
  /// Removes the job's folders; no error when they are gone already.
  void remove(const std::string& id) const;
  /// Ids of every job folder present.
  std::vector<std::string> folder_ids() const;

 private:
  std::filesystem::path jobs_, sweeps_;
};

}  // namespace kontakt::server
