// Entry point of the CalculiX/Abaqus .inp reader.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "model/model.hpp"

namespace kontakt::inp {

/// Reads and validates a deck (with its *INCLUDEs, relative to the including file).
/// Throws kontakt::InputError naming file:line and keyword for every user error.
model::Model read_deck(const std::filesystem::path& deck);

/// The same for deck text held in memory; includes are resolved relative to the current
/// directory. `file_name` is used in error locations.
model::Model read_deck_text(std::string_view text, const std::string& file_name = "<text>");

}  // namespace kontakt::inp
