#include "server/zip_archive.hpp"

#include <zip.h>

#include <memory>
#include <sys/stat.h>

namespace kontakt::server {

namespace {

using ZipHandle = std::unique_ptr<zip_t, decltype(&zip_discard)>;

ZipHandle open_archive(const std::string& bytes) {
  zip_error_t error;
  zip_error_init(&error);
  zip_source_t* source = zip_source_buffer_create(bytes.data(), bytes.size(), 0, &error);
  if (!source) throw ZipError("cannot read the zip: " + std::string(zip_error_strerror(&error)));
  zip_t* archive = zip_open_from_source(source, ZIP_RDONLY | ZIP_CHECKCONS, &error);
  if (!archive) {
    zip_source_free(source);
    const std::string why = zip_error_strerror(&error);
    zip_error_fini(&error);
    throw ZipError("not a valid zip archive: " + why);
  }
  zip_error_fini(&error);
  return ZipHandle(archive, zip_discard);
}

/// Unix file type of an entry made on Unix (links and devices are refused); 0 otherwise.
unsigned unix_file_type(zip_t* archive, zip_uint64_t index) {
  zip_uint8_t opsys = 0;
  zip_uint32_t attributes = 0;
  if (zip_file_get_external_attributes(archive, index, 0, &opsys, &attributes) != 0) return 0;
  if (opsys != ZIP_OPSYS_UNIX) return 0;
  return (attributes >> 16) & S_IFMT;
}

std::string read_entry(zip_t* archive, zip_uint64_t index, zip_uint64_t size,
                       const std::string& name) {
  std::unique_ptr<zip_file_t, decltype(&zip_fclose)> file(zip_fopen_index(archive, index, 0),
                                                          zip_fclose);
  if (!file) throw ZipError(name + ": cannot unpack: " + zip_strerror(archive));
  std::string data(size, '\0');
  zip_uint64_t done = 0;
  while (done < size) {
    const zip_int64_t n = zip_fread(file.get(), data.data() + done, size - done);
    if (n <= 0) throw ZipError(name + ": truncated or corrupt entry");
    done += static_cast<zip_uint64_t>(n);
  }
  return data;
}

}  // namespace

bool is_safe_relative_path(const std::string& name) {
  if (name.empty() || name.front() == '/' || name.size() > 1024) return false;
  std::size_t start = 0;
  while (start <= name.size()) {
    const std::size_t end = std::min(name.find('/', start), name.size());
    const std::string segment = name.substr(start, end - start);
    if (segment.empty() || segment == "." || segment == "..") return false;
    for (unsigned char c : segment)
      if (c < 0x20 || c == 0x7f || c == '\\' || c == ':') return false;
    start = end + 1;
  }
  return true;
}

std::vector<ZipEntry> read_zip(const std::string& bytes, std::uint64_t max_unpacked) {
  const ZipHandle archive = open_archive(bytes);
  const zip_int64_t n = zip_get_num_entries(archive.get(), 0);
  std::vector<ZipEntry> entries;
  std::uint64_t unpacked = 0;
  for (zip_int64_t i = 0; i < n; ++i) {
    const auto index = static_cast<zip_uint64_t>(i);
    zip_stat_t st;
    if (zip_stat_index(archive.get(), index, 0, &st) != 0 || !(st.valid & ZIP_STAT_NAME))
      throw ZipError("entry " + std::to_string(i) + ": unreadable");
    std::string name = st.name;
    const bool is_folder = !name.empty() && name.back() == '/';
    if (is_folder) name.pop_back();
    if (!is_safe_relative_path(name))
      throw ZipError("unsafe entry name '" + std::string(st.name) +
                     "' (absolute paths, '..' and empty segments are refused)");
    const unsigned type = unix_file_type(archive.get(), index);
    if (type == S_IFLNK) throw ZipError(name + ": symbolic links are refused");
    if (type != 0 && type != S_IFREG && type != S_IFDIR)
      throw ZipError(name + ": only regular files and folders are accepted");
    if (is_folder || type == S_IFDIR) continue;
    unpacked += st.size;
    if (unpacked > max_unpacked)
      throw ZipError("the archive unpacks to more than " + std::to_string(max_unpacked) + " bytes");
    entries.push_back({name, read_entry(archive.get(), index, st.size, name)});
  }
  return entries;
}

}  // namespace kontakt::server
