// Writing a submitted deck into a job's input folder: a raw .inp, or a zip of a deck with its
// *INCLUDE files whose main file is named by ?main= (or is the only .inp at the top).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

namespace kontakt::server {

/// A refused upload; `field` names the request part at fault (body, main).
class UploadError : public std::runtime_error {
 public:
  UploadError(std::string field, const std::string& message)
      : std::runtime_error(message), field_(std::move(field)) {}
  const std::string& field() const { return field_; }

 private:
  std::string field_;
};

/// Writes `body` as INPUT_DIR/FILE_NAME; returns FILE_NAME (default "deck.inp").
std::string write_raw_deck(const std::string& body, const std::optional<std::string>& file_name,
                           const std::filesystem::path& input_dir);

/// Unpacks the zip into INPUT_DIR and returns the main deck's relative path.
std::string write_zip_deck(const std::string& body, const std::optional<std::string>& main,
                           const std::filesystem::path& input_dir, std::uint64_t max_unpacked);

}  // namespace kontakt::server
