#include "output/time_stamp.hpp"

#include <cstdio>
#include <ctime>

namespace kontakt::output {

namespace {

std::tm now_tm(bool utc) {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  if (utc) {
    gmtime_r(&t, &tm);
  } else {
    localtime_r(&t, &tm);
  }
  return tm;
}

}  // namespace

std::string time_stamp(const char* format, bool utc) {
  const std::tm tm = now_tm(utc);
  char b[64];
  const std::size_t n = std::strftime(b, sizeof b, format, &tm);
  return std::string(b, n);
}

std::string frd_date_today() {
  static constexpr const char* kMonths[] = {"january", "february", "march",     "april",
                                            "may",     "june",     "july",      "august",
                                            "september", "october", "november", "december"};
  const std::tm tm = now_tm(false);
  char b[48];
  std::snprintf(b, sizeof b, "%02d.%s.%04d", tm.tm_mday, kMonths[tm.tm_mon], tm.tm_year + 1900);
  return b;
}

}  // namespace kontakt::output
