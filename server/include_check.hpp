// Keeps a submitted deck inside its job folder: every *INCLUDE, INPUT= of the deck and of the
// files it includes must name a relative path that stays under the input folder. The reader
// would otherwise open any file the daemon can read (/etc/..., another job's deck).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "app/run_job.hpp"

namespace kontakt::server {

/// The first *INCLUDE that leaves `input_dir`, as a deck error with file (relative), line and
/// keyword; nullopt when every include stays inside. Missing files are left to the reader.
std::optional<app::DeckError> find_escaping_include(const std::filesystem::path& input_dir,
                                                    const std::string& main_file);

}  // namespace kontakt::server
