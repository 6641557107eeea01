// Moving a finished run's files from its work folder to its results folder. Each file is
// hashed, then renamed (atomic on one file system): a download never sees half a file, and
// the store lists only what was renamed.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "server/job_record.hpp"

namespace kontakt::server {

/// Publishes every regular file of `work` (skipping *.partial leftovers) into `results`.
std::vector<Artifact> publish_results(const std::filesystem::path& work,
                                      const std::filesystem::path& results);

/// application/x-hdf5 for .hdf, application/xml for .xdmf, ...
std::string media_type_for(const std::filesystem::path& file);

}  // namespace kontakt::server
