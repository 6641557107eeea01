// Parses the ccx example decks (Debian package calculix-ccx-test) that use only what the
// reader supports. Qualification is decided by scanning keyword lines, independently of the
// reader. Skipped when the examples are not installed.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

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
      "ELPRINT", "NODEFILE", "NODEOUTPUT", "ELFILE", "ELEMENTOUTPUT", "OUTPUT", "FILEFORMAT",
      "PLASTIC", "CONTROLS", "SURFACEINTERACTION", "SURFACEBEHAVIOR", "FRICTION",
      "CHANGEFRICTION", "CONTACTPAIR", "CONTACTPRINT", "CONTACTFILE", "CONTACTOUTPUT", "TIE",
      "ORIENTATION", "CYCLICSYMMETRYMODEL"};
  static const std::set<std::string> types = {"C3D4",  "C3D6",  "C3D8",  "C3D8R", "C3D8I",
                                              "C3D10", "C3D15", "C3D20", "C3D20R"};
  if (!keywords.contains(keyword)) return false;
  for (const char* option : {",USER", ",TIMEDELAY", ",FIXED", ",SUBMODEL"}) {
    if (card.find(option) != std::string::npos) return false;
  }
  if (keyword == "ELASTIC" && card.find("TYPE=") != std::string::npos &&
      card.find("TYPE=ISO") == std::string::npos && card.find("TYPE=ORTHO") == std::string::npos &&
      card.find("TYPE=ENGINEERINGCONSTANTS") == std::string::npos &&
      card.find("TYPE=ANISO") == std::string::npos) {
    return false;
  }
  if (keyword == "INITIALCONDITIONS" && card.find("TYPE=TEMPERATURE") == std::string::npos) {
    return false;
  }
  if (keyword == "CONTACTPAIR" && card.find("TYPE=NODETOSURFACE") == std::string::npos &&
      card.find("TYPE=SURFACETOSURFACE") == std::string::npos) {
    return false;  // mortar and massless contact
  }
  if (keyword == "TIE" && card.find(",MULTISTAGE") != std::string::npos) {
    return false;  // ties of another analysis
  }
  if (keyword == "CYCLICSYMMETRYMODEL" && card.find("NGRAPH=") != std::string::npos &&
      card.find("NGRAPH=1,") == std::string::npos && !card.ends_with("NGRAPH=1")) {
    return false;  // expanded output
  }
  if (keyword == "PLASTIC" && card.find("HARDENING=") != std::string::npos &&
      card.find("HARDENING=ISOTROPIC") == std::string::npos) {
    return false;
  }
  if (keyword == "ELEMENT") {
    const auto at = card.find("TYPE=");
    if (at == std::string::npos) return false;
    if (!types.contains(card.substr(at + 5, card.find(',', at) - at - 5))) return false;
  }
  return true;
}

/// Data lines the reader rejects on purpose: DLOADs other than pressures and GRAV/CENTRIF.
bool supported_data(const std::string& keyword, const std::string& data) {
  if (keyword == "DLOAD") {
    const auto comma = data.find(',');
    const std::string label = data.substr(comma + 1, data.find(',', comma + 1) - comma - 1);
    return label == "P" || label == "GRAV" || label == "CENTRIF" ||
           (label.size() == 2 && label[0] == 'P' && label[1] >= '1' && label[1] <= '6');
  }
  return true;
}

/// True when the deck uses only keywords, element types and options the reader supports.
bool qualifies(const std::string& text) {
  std::istringstream lines(text);
  std::string line, keyword;
  while (std::getline(lines, line)) {
    const std::string compact = upper_no_blanks(line);
    if (compact.empty() || compact.starts_with("**")) continue;
    if (compact[0] != '*') {
      if (!supported_data(keyword, compact)) return false;
      continue;
    }
    const std::string card = compact.substr(1);
    keyword = card.substr(0, card.find(','));
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

fs::path example(const std::string& name) {
  const fs::path plain = kExamples / (name + ".inp");
  return fs::exists(plain) ? plain : kExamples / (name + ".inp.gz");
}

/// The frictionless and frictional contact decks of issue 4 parse into what they say.
TEST(inpCcxExamples, ContactDecksParse) {
  if (!fs::is_directory(kExamples)) GTEST_SKIP() << kExamples << " not installed";
  using Type = model::ContactPair::Type;
  using Law = model::SurfaceBehavior::Law;
  const std::vector<std::pair<std::string, Type>> decks = {
      {"contact1", Type::NodeToSurface},      {"contact3", Type::NodeToSurface},
      {"contact4", Type::SurfaceToSurface},   {"contact6", Type::NodeToSurface},
      {"contactenergy", Type::SurfaceToSurface}, {"cubespring", Type::NodeToSurface},
      {"punch1", Type::SurfaceToSurface},     {"punch2", Type::SurfaceToSurface},
      {"hueeber1", Type::SurfaceToSurface},   {"hueeber2", Type::SurfaceToSurface},
      {"hueeber3", Type::SurfaceToSurface},   {"hueeber4", Type::SurfaceToSurface},
      {"friction1", Type::NodeToSurface},     {"friction2", Type::NodeToSurface}};
  std::map<std::string, model::Model> models;
  for (const auto& [name, type] : decks) {
    const fs::path path = example(name);
    ASSERT_TRUE(fs::exists(path)) << path;
    try {
      models.emplace(name, read_deck_text(read_text(path), name + ".inp"));
    } catch (const std::exception& e) {
      ADD_FAILURE() << e.what();
      continue;
    }
    const model::Model& m = models.at(name);
    ASSERT_EQ(m.contact_pairs.size(), 1u) << name;
    EXPECT_EQ(m.contact_pairs[0].type, type) << name;
    EXPECT_EQ(model::contact_scheme_name(m.contact_pairs[0].scheme),
              type == Type::NodeToSurface ? "nts" : "lgc7")
        << name;
  }
  if (::testing::Test::HasFailure()) return;
  const auto& behavior = [&](const std::string& name) -> const model::SurfaceBehavior& {
    const model::Model& m = models.at(name);
    return m.interactions[static_cast<std::size_t>(m.contact_pairs[0].interaction)].behavior;
  };
  EXPECT_EQ(behavior("contact1").law, Law::Exponential);
  EXPECT_DOUBLE_EQ(behavior("contact1").exp_c0, 1.5351e-7);
  EXPECT_DOUBLE_EQ(behavior("contact3").tension_limit, 3.);
  EXPECT_DOUBLE_EQ(behavior("hueeber1").stiffness, 1e15);
  // contactenergy gives K only: sigma_inf = E / 70000 with E = 210000.
  EXPECT_DOUBLE_EQ(behavior("contactenergy").tension_limit, 3.);
  const auto& energy = models.at("contactenergy").steps[0];
  ASSERT_EQ(energy.contact_prints.size(), 1u);
  EXPECT_EQ(energy.contact_prints[0].variables, std::vector<std::string>{"CELS"});
  EXPECT_TRUE(energy.contact_prints[0].totals);
  EXPECT_EQ(energy.contact_prints[0].after_prints, 2u);  // after *NODE PRINT and *EL PRINT
  EXPECT_EQ(models.at("cubespring").steps[0].contact_files[0].variables,
            (std::vector<std::string>{"CDIS", "CSTR"}));
  EXPECT_EQ(models.at("contact1").surfaces.at("SSLAV").kind, model::Surface::Kind::Nodes);
  EXPECT_DOUBLE_EQ(*models.at("punch1").contact_pairs[0].adjust_distance, 0.005);
  EXPECT_FALSE(models.at("punch1").contact_pairs[0].small_sliding);  // ignored for F2F
  EXPECT_EQ(models.at("punch2").contact_pairs[0].adjust_set, "CONTACT");
  const auto& sticking = models.at("friction1").steps[0].interaction_friction[0];
  ASSERT_TRUE(sticking.has_value());
  EXPECT_DOUBLE_EQ(sticking->mu, 0.2);
  EXPECT_DOUBLE_EQ(sticking->stick_slope, 47000.);
  // friction2: *CHANGE FRICTION in step 4 lowers mu from 0.2 to 0.1.
  const auto& steps = models.at("friction2").steps;
  ASSERT_EQ(steps.size(), 4u);
  EXPECT_DOUBLE_EQ(steps[2].interaction_friction[0]->mu, 0.2);
  EXPECT_DOUBLE_EQ(steps[3].interaction_friction[0]->mu, 0.1);
  EXPECT_DOUBLE_EQ(steps[3].interaction_friction[0]->stick_slope, 80.);
  EXPECT_EQ(steps[3].contact_prints[0].frequency, 100);
}

/// The suite's *TIE decks (tied contact, not cyclic symmetry) parse into their ties.
TEST(inpCcxExamples, TieDecksParse) {
  if (!fs::is_directory(kExamples)) GTEST_SKIP() << kExamples << " not installed";
  using Kind = model::Surface::Kind;
  const std::vector<std::tuple<std::string, std::string, std::string, Kind>> decks = {
      {"cubef2f3", "SLAVE", "MASTER", Kind::ElementFaces},
      {"beamptied1", "NDEP", "INDF", Kind::Nodes},
      {"beamptied2", "DEPF", "INDF", Kind::ElementFaces}};
  for (const auto& [name, slave, master, kind] : decks) {
    const model::Model m = read_deck_text(read_text(example(name)), name + ".inp");
    ASSERT_EQ(m.ties.size(), 1u) << name;
    const model::Tie& tie = m.ties[0];
    EXPECT_EQ(tie.name, "T1") << name;
    EXPECT_EQ(tie.slave, slave) << name;
    EXPECT_EQ(tie.master, master) << name;
    EXPECT_FALSE(tie.position_tolerance.has_value()) << name;
    EXPECT_TRUE(tie.adjust) << name;
    EXPECT_EQ(m.surfaces.at(slave).kind, kind) << name;
    EXPECT_TRUE(m.contact_pairs.empty()) << name;  // cubef2f3's TIED interaction is unused
  }
}

}  // namespace
}  // namespace kontakt::inp
