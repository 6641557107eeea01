// The wall-clock time as result files stamp it: the .frd header (ccx writes local date and
// time) and the HDF5 `created` attribute (RFC 3339, UTC).
#pragma once

#include <string>

namespace kontakt::output {

/// The current time formatted by strftime `format`, in local time or UTC.
std::string time_stamp(const char* format, bool utc);

/// "02.december.2026": ccx's .frd date, lower-case month whatever the locale.
std::string frd_date_today();

}  // namespace kontakt::output
