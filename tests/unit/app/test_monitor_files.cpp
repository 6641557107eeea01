#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/monitor_files.hpp"

using namespace kontakt;
using Kind = analysis::Event::Kind;

namespace {
std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

TEST(MonitorFiles, StaAndCvgLinesHaveCcxColumns) {
  const auto dir = std::filesystem::temp_directory_path() / "kontakt_monitor_test";
  std::filesystem::create_directories(dir);
  {
    app::MonitorFiles files(dir, "job");
    files.on_event({.kind = Kind::Iteration, .step = 1, .increment = 1, .attempt = 1,
                    .iteration = 1, .residual = 500, .correction = 100});
    files.on_event({.kind = Kind::Cutback, .step = 2, .increment = 1, .attempt = 1,
                    .iteration = 8, .step_time = 0, .total_time = 1, .dt = 1});
    files.on_event({.kind = Kind::Increment, .step = 2, .increment = 1, .attempt = 2,
                    .iteration = 7, .step_time = 0.5, .total_time = 1.5, .dt = 0.5});
  }
  const std::string sta = slurp(dir / "job.sta"), cvg = slurp(dir / "job.cvg");
  EXPECT_NE(sta.find("\n     2          1     1U    8  0.100000E+01  0.000000E+00  0.100000E+01\n"),
            std::string::npos) << sta;
  EXPECT_NE(sta.find("\n     2          1     2     7  0.150000E+01  0.500000E+00  0.500000E+00\n"),
            std::string::npos) << sta;
  EXPECT_NE(cvg.find("\n     1     1     1     1        0  0.5000E+03  0.1000E+03  0.0000E+00  0.0000E+00\n"),
            std::string::npos) << cvg;
  EXPECT_EQ(cvg.rfind("SUMMARY OF C0NVERGENCE INFORMATION", 0), 0u);
  std::filesystem::remove_all(dir);
}
