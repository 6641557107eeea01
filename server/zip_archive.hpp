// Reading an uploaded zip (libzip) and checking its entry names before anything is written:
// no absolute paths, no `..`, no links, no special files, and a cap on the unpacked size
// (a zip bomb is refused, not unpacked).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace kontakt::server {

/// A refused archive; the message names the entry.
class ZipError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ZipEntry {
  std::string name;  ///< relative path with '/' separators, checked by is_safe_relative_path
  std::string data;
};

/// The regular files of the archive (folders are implied by the names). Throws ZipError for a
/// corrupt archive, an unsafe name, a link or special file, or more than `max_unpacked` bytes.
std::vector<ZipEntry> read_zip(const std::string& bytes, std::uint64_t max_unpacked);

/// True for "a/b.inp": no leading '/', no '\\', no empty, '.' or '..' segment, no control chars.
bool is_safe_relative_path(const std::string& name);

}  // namespace kontakt::server
