// libFuzzer harness of the deck reader: bytes -> inp::read_deck. An input without NUL bytes is
// one deck read from memory; NUL bytes split it into a deck and up to kMaxIncludes files it may
// include (written to a scratch folder as main.inp, 1.inp, 2.inp, ...), read from disk.
//
// A model or an InputError naming a line is a pass. Anything else - another exception, a
// crash, a sanitizer report, a timeout, memory past -rss_limit_mb - is a finding.
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <unistd.h>

#include "core/error.hpp"
#include "inp/read_deck.hpp"

namespace fs = std::filesystem;

namespace {

/// More parts are appended to the last file: files cost time, not coverage.
constexpr int kMaxIncludes = 3;

const fs::path& scratch() {
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / ("fuzz_deck_text_" + std::to_string(getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

void read(std::string_view input) {
  if (input.find('\0') == std::string_view::npos) {
    kontakt::inp::read_deck_text(input, "fuzz.inp");
    return;
  }
  fs::remove_all(scratch());
  fs::create_directories(scratch());
  int index = 0;
  while (!input.empty()) {
    const std::size_t cut = index < kMaxIncludes ? input.find('\0') : std::string_view::npos;
    const std::string name = index == 0 ? "main.inp" : std::to_string(index) + ".inp";
    std::ofstream(scratch() / name, std::ios::binary) << input.substr(0, cut);
    input.remove_prefix(cut == std::string_view::npos ? input.size() : cut + 1);
    ++index;
  }
  kontakt::inp::read_deck(scratch() / "main.inp");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    read(std::string_view(reinterpret_cast<const char*>(data), size));
  } catch (const kontakt::InputError& e) {
    if (e.where().line <= 0) std::abort();  // every deck error names its line
  }
  return 0;
}
