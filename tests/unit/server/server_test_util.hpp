// Shared pieces of the server tests: a temporary data folder, a JobControl that only counts,
// decks, and a zip writer (libzip) for upload tests.
#pragma once

#include <zip.h>

#include <atomic>
#include <filesystem>
#include <functional>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <utility>
#include <vector>

#include "server/handlers/api_context.hpp"

namespace kontakt::server::testing {

/// A fresh folder under the system temp dir, removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() / ("kontakt-server-test-" + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

class CountingControl final : public handlers::JobControl {
 public:
  void job_queued() override { ++queued; }
  void cancel_running(const std::string& id) override {
    canceled.push_back(id);
    if (on_cancel) on_cancel(id);
  }
  int n_workers() const override { return 2; }
  int n_busy() const override { return 0; }
  std::atomic<int> queued{0};
  std::vector<std::string> canceled;
  std::function<void(const std::string&)> on_cancel;  ///< observes the store at each call
};

/// One linear C3D8 cube under a tip load: parses and solves in milliseconds.
inline std::string cube_deck() {
  return "*NODE, NSET=NALL\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
         "*ELEMENT, TYPE=C3D8, ELSET=EALL\n1,1,2,3,4,5,6,7,8\n"
         "*MATERIAL, NAME=M\n*ELASTIC\n210000, 0.3\n*SOLID SECTION, ELSET=EALL, MATERIAL=M\n"
         "*BOUNDARY\n1,1,3\n4,1,3\n5,1,3\n8,1,3\n*STEP\n*STATIC\n*CLOAD\n2,3,-1\n3,3,-1\n"
         "*NODE FILE\nU\n*END STEP\n";
}

struct ZipItem {
  std::string name, data;
  bool symlink = false;
};

/// The bytes of a zip holding `items` (a symlink item stores its data as the link target).
inline std::string make_zip(const std::vector<ZipItem>& items, const std::filesystem::path& scratch) {
  const auto file = scratch / "upload.zip";
  std::filesystem::remove(file);
  int error = 0;
  zip_t* z = zip_open(file.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  for (const auto& item : items) {
    zip_source_t* src = zip_source_buffer(z, item.data.data(), item.data.size(), 0);
    const zip_int64_t index = zip_file_add(z, item.name.c_str(), src, ZIP_FL_ENC_UTF_8);
    if (item.symlink)
      zip_file_set_external_attributes(z, static_cast<zip_uint64_t>(index), 0, ZIP_OPSYS_UNIX,
                                       (S_IFLNK | 0777u) << 16);
  }
  zip_close(z);
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace kontakt::server::testing
