#include "output/time_stamp.hpp"

#include <gtest/gtest.h>

#include <regex>

namespace kontakt::output {

TEST(TimeStamp, FrdDateIsDayLowerCaseMonthYear) {
  const std::string d = frd_date_today();
  EXPECT_TRUE(std::regex_match(d, std::regex(R"(\d\d\.(january|february|march|april|may|june|)"
                                             R"(july|august|september|october|november|)"
                                             R"(december)\.\d{4})")))
      << d;
}

TEST(TimeStamp, Rfc3339InUtc) {
  const std::string t = time_stamp("%Y-%m-%dT%H:%M:%SZ", true);
  EXPECT_TRUE(std::regex_match(t, std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)"))) << t;
}

}  // namespace kontakt::output
