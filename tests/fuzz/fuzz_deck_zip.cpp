// libFuzzer harness of a zip submission as the daemon takes it: unpacked into a scratch input
// folder (deck_upload), its *INCLUDEs confined to it (include_check), then read by the reader
// with its include files. A refused upload (UploadError), an escaping include or an InputError
// are passes; anything else is a finding.
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>

#include "core/error.hpp"
#include "inp/read_deck.hpp"
#include "server/deck_upload.hpp"
#include "server/include_check.hpp"

namespace fs = std::filesystem;

namespace {

/// The daemon allows 16 x the body limit; the fuzzer's inputs are small.
constexpr std::uint64_t kMaxUnpacked = 1u << 20;

const fs::path& scratch() {
  static const fs::path dir =
      fs::temp_directory_path() / ("fuzz_deck_zip_" + std::to_string(getpid()));
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace kontakt;
  fs::remove_all(scratch());
  const fs::path input = scratch() / "input";
  try {
    const std::string main = server::write_zip_deck(
        std::string(reinterpret_cast<const char*>(data), size), std::nullopt, input, kMaxUnpacked);
    if (server::find_escaping_include(input, main)) return 0;
    inp::read_deck(input / main);
  } catch (const server::UploadError&) {
  } catch (const InputError& e) {
    if (e.where().line <= 0 && e.where().file.empty()) std::abort();
  }
  return 0;
}
