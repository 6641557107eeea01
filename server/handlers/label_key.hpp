// What a label key may be (submissions set them, sweeps look them up): 1 to 64 of
// A-Z a-z 0-9 _ - . -- safe in URLs, SQL JSON paths and file names alike.
#pragma once

#include <string>

namespace kontakt::server::handlers {

bool is_label_key(const std::string& key);

}  // namespace kontakt::server::handlers
