#include "server/result_publisher.hpp"

#include <algorithm>

#include "server/digest.hpp"

namespace fs = std::filesystem;

namespace kontakt::server {

std::string media_type_for(const fs::path& file) {
  const std::string name = file.filename().string();
  if (name.ends_with(".hdf") || name.ends_with(".h5")) return "application/x-hdf5";
  if (name.ends_with(".xdmf")) return "application/xml";
  if (name.ends_with(".jsonl")) return "application/x-ndjson";
  if (name.ends_with(".json")) return "application/json";
  return "text/plain; charset=utf-8";  // .dat, .frd, .sta, .cvg
}

std::vector<Artifact> publish_results(const fs::path& work, const fs::path& results) {
  std::vector<Artifact> artifacts;
  fs::create_directories(results);
  if (!fs::exists(work)) return artifacts;
  for (const auto& entry : fs::directory_iterator(work)) {
    if (!entry.is_regular_file() || entry.path().extension() == ".partial") continue;
    const fs::path& file = entry.path();
    artifacts.push_back({.name = file.filename().string(),
                         .media_type = media_type_for(file),
                         .size = static_cast<std::int64_t>(entry.file_size()),
                         .sha256 = sha256_file(file)});
    fs::rename(file, results / file.filename());
  }
  std::sort(artifacts.begin(), artifacts.end(),
            [](const Artifact& a, const Artifact& b) { return a.name < b.name; });
  return artifacts;
}

}  // namespace kontakt::server
