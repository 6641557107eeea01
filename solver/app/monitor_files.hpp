// MODEL.sta and MODEL.cvg in ccx's layout, so existing CalculiX monitoring scripts keep
// working: one .sta line per attempted increment (a U marks an attempt that was cut back) and
// one .cvg line per Newton iteration. Both files are flushed line by line.
#pragma once

#include <filesystem>
#include <fstream>

#include "analysis/events.hpp"

namespace kontakt::app {

class MonitorFiles final : public analysis::EventSink {
 public:
  /// Creates DIR/JOB.sta and DIR/JOB.cvg with their headers.
  MonitorFiles(const std::filesystem::path& dir, const std::string& job);
  void on_event(const analysis::Event& event) override;

 private:
  void sta_line(const analysis::Event& e, bool cut_back);
  std::ofstream sta_, cvg_;
};

}  // namespace kontakt::app
