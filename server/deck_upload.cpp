#include "server/deck_upload.hpp"

#include <fstream>

#include "server/zip_archive.hpp"

namespace fs = std::filesystem;

namespace kontakt::server {

namespace {

void write_file(const fs::path& path, const std::string& data) {
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out.write(data.data(), static_cast<std::streamsize>(data.size()));
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

bool is_top_level_deck(const std::string& name) {
  return name.find('/') == std::string::npos && name.size() > 4 &&
         (name.ends_with(".inp") || name.ends_with(".INP"));
}

}  // namespace

std::string write_raw_deck(const std::string& body, const std::optional<std::string>& file_name,
                           const fs::path& input_dir) {
  const std::string name = file_name.value_or("deck.inp");
  if (!is_safe_relative_path(name) || name.find('/') != std::string::npos)
    throw UploadError("main", "'" + name + "' is not a plain file name");
  if (body.empty()) throw UploadError("body", "the deck is empty");
  write_file(input_dir / name, body);
  return name;
}

std::string write_zip_deck(const std::string& body, const std::optional<std::string>& main,
                           const fs::path& input_dir, std::uint64_t max_unpacked) {
  std::vector<ZipEntry> entries;
  try {
    entries = read_zip(body, max_unpacked);
  } catch (const ZipError& e) {
    throw UploadError("body", e.what());
  }
  std::string main_file;
  if (main) {
    main_file = *main;
    bool found = false;
    for (const auto& e : entries) found = found || e.name == main_file;
    if (!found) throw UploadError("main", "the archive has no file '" + main_file + "'");
  } else {
    int n_decks = 0;
    for (const auto& e : entries)
      if (is_top_level_deck(e.name)) {
        main_file = e.name;
        ++n_decks;
      }
    if (n_decks != 1)
      throw UploadError("main", n_decks == 0
                                    ? "the archive has no .inp file at its top level"
                                    : "the archive has several .inp files: name one with ?main=");
  }
  for (const auto& e : entries) write_file(input_dir / e.name, e.data);
  return main_file;
}

}  // namespace kontakt::server
