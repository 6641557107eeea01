// Parses the ccx example decks (Debian package calculix-ccx-test) that use only what the
// reader supports. Qualification is decided by scanning keyword lines, independently of the
// reader. Skipped when the examples are not installed.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "inp/read_deck.hpp"

namespace kontakt::inp {
namespace {

namespace fs = std::filesystem;

const fs::path kExamples = "/usr/share/doc/calculix-ccx-test/examples/test";

std::string read_text(const fs::path& path) {
  if (path.extension() != ".gz") {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  std::string text;
  const std::string command = "gzip -dc '" + path.string() + "'";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return text;
  std::array<char, 65536> buffer{};
  std::size_t n = 0;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) text.append(buffer.data(), n);
  pclose(pipe);
  return text;
}

std::string upper_no_blanks(std::string_view s) {
  std::string out;
  for (char c : s) {
    if (c == ' ' || c == '\t' || c == '\r') continue;
    out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return out;
}

bool supported_card(const std::string& keyword, const std::string& card) {
  static const std::set<std::string> keywords = {
      "HEADING", "NODE", "ELEMENT", "NSET", "ELSET", "SURFACE", "MATERIAL", "ELASTIC",
      "DENSITY", "EXPANSION", "SOLIDSECTION", "INITIALCONDITIONS", "EQUATION", "AMPLITUDE",
      "BOUNDARY", "STEP", "STATIC", "ENDSTEP", "CLOAD", "DLOAD", "TEMPERATURE", "NODEPRINT",
      "ELPRINT", "NODEFILE", "NODEOUTPUT", "ELFILE", "ELEMENTOUTPUT", "OUTPUT", "FILEFORMAT"};
  static const std::set<std::string> types = {"C3D4",  "C3D6",  "C3D8",  "C3D8R", "C3D8I",
                                              "C3D10", "C3D15", "C3D20", "C3D20R"};
  if (!keywords.contains(keyword)) return false;
  for (const char* option : {",USER", ",TIMEDELAY", ",FIXED", ",ORIENTATION", ",SUBMODEL"}) {
    if (card.find(option) != std::string::npos) return false;
  }
  if (keyword == "ELASTIC" && card.find("TYPE=") != std::string::npos &&
      card.find("TYPE=ISO") == std::string::npos) {
    return false;
  }
  if (keyword == "INITIALCONDITIONS" && card.find("TYPE=TEMPERATURE") == std::string::npos) {
    return false;
  }
  if (keyword == "ELEMENT") {
    const auto at = card.find("TYPE=");
    if (at == std::string::npos) return false;
    if (!types.contains(card.substr(at + 5, card.find(',', at) - at - 5))) return false;
  }
  return true;
}

/// Data lines the reader rejects on purpose: temperature tables, non-pressure DLOADs.
bool supported_data(const std::string& keyword, const std::string& data, int& lines_in_card) {
  ++lines_in_card;
  if ((keyword == "ELASTIC" || keyword == "DENSITY" || keyword == "EXPANSION") &&
      lines_in_card > 1) {
    return false;
  }
  if (keyword == "DLOAD") {
    const auto comma = data.find(',');
    const std::string label = data.substr(comma + 1, data.find(',', comma + 1) - comma - 1);
    return label == "P" || (label.size() == 2 && label[0] == 'P' && label[1] >= '1' &&
                            label[1] <= '6');
  }
  return true;
}

/// True when the deck uses only keywords, element types and options the reader supports.
bool qualifies(const std::string& text) {
  std::istringstream lines(text);
  std::string line, keyword;
  int lines_in_card = 0;
  while (std::getline(lines, line)) {
    const std::string compact = upper_no_blanks(line);
    if (compact.empty() || compact.starts_with("**")) continue;
    if (compact[0] != '*') {
      if (!supported_data(keyword, compact, lines_in_card)) return false;
      continue;
    }
    const std::string card = compact.substr(1);
    keyword = card.substr(0, card.find(','));
    lines_in_card = 0;
    if (!supported_card(keyword, card)) return false;
  }
  return true;
}

TEST(inpCcxExamples, QualifyingDecksParse) {
  if (!fs::is_directory(kExamples)) GTEST_SKIP() << kExamples << " not installed";
  int parsed = 0, skipped = 0;
  std::vector<std::string> failures;
  for (const auto& entry : fs::directory_iterator(kExamples)) {
    const std::string name = entry.path().filename().string();
    if (!name.ends_with(".inp") && !name.ends_with(".inp.gz")) continue;
    const std::string text = read_text(entry.path());
    if (!qualifies(text)) {
      ++skipped;
      continue;
    }
    try {
      const model::Model m = read_deck_text(text, name);
      EXPECT_GT(m.n_elements(), 0) << name;
      ++parsed;
    } catch (const std::exception& e) {
      failures.push_back(e.what());
    }
  }
  for (const std::string& f : failures) ADD_FAILURE() << f;
  std::printf("[ ccx examples ] %d qualifying decks parsed, %zu failed, %d skipped\n", parsed,
              failures.size(), skipped);
  EXPECT_GT(parsed, 0);
}

}  // namespace
}  // namespace kontakt::inp
