#include "server/include_check.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <set>
#include <vector>

namespace fs = std::filesystem;

namespace kontakt::server {

namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

/// INPUT= of a *INCLUDE keyword line, or nullopt when the line is something else.
std::optional<std::string> include_target(const std::string& line) {
  const std::string t = trim(line);
  if (t.size() < 2 || t[0] != '*' || t[1] == '*') return std::nullopt;
  const std::string keyword = upper(trim(t.substr(1, t.find(',') - 1)));
  if (keyword != "INCLUDE") return std::nullopt;
  std::size_t start = t.find(',');
  while (start != std::string::npos) {
    const std::size_t end = t.find(',', start + 1);
    const std::string param = trim(t.substr(start + 1, end == std::string::npos ? end : end - start - 1));
    const std::size_t eq = param.find('=');
    if (eq != std::string::npos && upper(trim(param.substr(0, eq))) == "INPUT") {
      std::string value = trim(param.substr(eq + 1));
      if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
        value = value.substr(1, value.size() - 2);
      return value;
    }
    start = end;
  }
  return std::string();
}

/// True when `target`, resolved against the including file's folder, stays in `root`.
bool stays_inside(const fs::path& root, const fs::path& including_dir, const std::string& target) {
  if (target.empty() || fs::path(target).is_absolute()) return false;
  const fs::path resolved = (including_dir / target).lexically_normal();
  const fs::path rel = resolved.lexically_relative(root);
  return !rel.empty() && *rel.begin() != ".." && !rel.is_absolute();
}

}  // namespace

std::optional<app::DeckError> find_escaping_include(const fs::path& input_dir,
                                                    const std::string& main_file) {
  const fs::path root = input_dir.lexically_normal();
  std::vector<fs::path> pending{root / main_file};
  std::set<fs::path> seen;
  while (!pending.empty()) {
    const fs::path file = pending.back().lexically_normal();
    pending.pop_back();
    if (!seen.insert(file).second) continue;
    std::ifstream in(file);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
      const auto target = include_target(line);
      if (!target) continue;
      const std::string shown = file.lexically_relative(root).string();
      if (!stays_inside(root, file.parent_path(), *target))
        return app::DeckError{.file = shown, .line = n, .keyword = "*INCLUDE",
                              .message = shown + ":" + std::to_string(n) +
                                         ": *INCLUDE: INPUT=" + *target +
                                         " must be a relative path inside the submitted files"};
      pending.push_back(file.parent_path() / *target);
    }
  }
  return std::nullopt;
}

}  // namespace kontakt::server
