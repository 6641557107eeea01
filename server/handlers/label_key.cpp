#include "server/handlers/label_key.hpp"

#include <cctype>

namespace kontakt::server::handlers {

bool is_label_key(const std::string& key) {
  if (key.empty() || key.size() > 64) return false;
  for (unsigned char c : key)
    if (!std::isalnum(c) && c != '_' && c != '-' && c != '.') return false;
  return true;
}

}  // namespace kontakt::server::handlers
