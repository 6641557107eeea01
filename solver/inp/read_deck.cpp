#include "inp/read_deck.hpp"

#include "inp/deck_state.hpp"
#include "inp/inp_lexer.hpp"
#include "inp/keyword_registry.hpp"
#include "inp/model_builder.hpp"

namespace kontakt::inp {

namespace {
model::Model build(const std::vector<Record>& records, const std::string& source) {
  DeckState state;
  state.model.source_file = source;
  dispatch_records(records, state);
  return finish_model(state);
}
}  // namespace

model::Model read_deck(const std::filesystem::path& deck) {
  return build(lex_deck_file(deck), deck.string());
}

model::Model read_deck_text(std::string_view text, const std::string& file_name) {
  return build(lex_deck_text(text, file_name, std::filesystem::current_path()), file_name);
}

}  // namespace kontakt::inp
