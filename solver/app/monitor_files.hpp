// MODEL.sta and MODEL.cvg in ccx's layout, so existing CalculiX monitoring scripts keep
// working: one .sta line per attempted increment (a U marks an attempt that was cut back) and
// one .cvg line per Newton iteration. Both files are flushed line by line. With contact, the
// .sta lines go on with two columns ccx does not have: the energy the contact stabilisation
// absorbed in the increment and the strain energy at its end (contact/README.md).
#pragma once

#include <filesystem>
#include <fstream>

#include "analysis/events.hpp"

namespace kontakt::app {

class MonitorFiles final : public analysis::EventSink {
 public:
  /// Creates DIR/JOB.sta and DIR/JOB.cvg with their headers (the .sta column line comes with
  /// the first increment, which tells whether the energy columns are there).
  MonitorFiles(const std::filesystem::path& dir, const std::string& job);
  void on_event(const analysis::Event& event) override;

 private:
  void sta_line(const analysis::Event& e, bool cut_back);
  std::ofstream sta_, cvg_;
  bool sta_columns_written_ = false;
};

}  // namespace kontakt::app
