// The table of keywords the reader understands: where each may appear and who handles it.
// A keyword missing from the table is an input error ("keyword not supported").
#pragma once

#include <string_view>

#include "inp/deck_state.hpp"

namespace kontakt::inp {

enum class Placement {
  Model,     ///< model definition: before the first *STEP
  Step,      ///< between *STEP and *END STEP
  Anywhere,  ///< both (e.g. *BOUNDARY, *AMPLITUDE)
};

/// The data block (*MATERIAL or *SURFACE INTERACTION and the cards below it) a keyword
/// belongs to. Any keyword outside a block closes the open block, as in ccx.
enum class Block { None, Material, Interaction };

using KeywordHandler = void (*)(const Record&, DeckState&);

struct KeywordSpec {
  std::string_view key;  ///< blank-free upper case, as Record::key
  Placement placement;
  Block block;
  KeywordHandler handler;
};

/// nullptr when the keyword is not supported.
const KeywordSpec* find_keyword(std::string_view key);

/// Runs every record through its handler, enforcing placement.
void dispatch_records(const std::vector<Record>& records, DeckState& state);

}  // namespace kontakt::inp
