#include <cctype>

#include "model/contact.hpp"

namespace kontakt::model {

std::optional<ContactScheme> contact_scheme_from_name(const std::string& name) {
  std::string s;
  for (char c : name) s += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  using K = ContactScheme::Kind;
  if (s == "nts") return ContactScheme{K::NodeToSurface, false, 1};
  if (s == "gauss") return ContactScheme{K::Gauss, false, 0};
  if (s == "lgauss") return ContactScheme{K::Gauss, true, 0};
  const bool linear = s.rfind("lgc", 0) == 0;
  const std::string count = linear ? s.substr(3) : s.rfind("gc", 0) == 0 ? s.substr(2) : "";
  for (int n : {1, 3, 7, 12})
    if (count == std::to_string(n)) return ContactScheme{K::GaussCut, linear, n};
  return std::nullopt;
}

std::string contact_scheme_name(const ContactScheme& scheme) {
  switch (scheme.kind) {
    case ContactScheme::Kind::NodeToSurface: return "nts";
    case ContactScheme::Kind::Gauss: return scheme.linear ? "lgauss" : "gauss";
    case ContactScheme::Kind::GaussCut:
      return (scheme.linear ? "lgc" : "gc") + std::to_string(scheme.points);
  }
  return "?";
}

std::string contact_scheme_names() {
  std::string names;
  for (const char* n : {"nts", "gauss", "lgauss", "gc1", "gc3", "gc7", "gc12", "lgc1", "lgc3",
                        "lgc7", "lgc12"})
    names += (names.empty() ? "" : ", ") + std::string(n);
  return names;
}

}  // namespace kontakt::model
