#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "inp/inp_lexer.hpp"
#include "inp/read_deck.hpp"
#include "inp/record_access.hpp"
#include "deck_fixtures.hpp"

namespace kontakt::inp {
namespace {

namespace fs = std::filesystem;

TEST(inpLexer, SkipsCommentsAndBlankLinesAndNormalisesKeywords) {
  const auto records = lex_deck_text(
      "** a comment\n\n*node ,  nset = Nall\n1, 0.,0.,0.\r\n** inside\n  \n*Solid  Section, "
      "elset=E1, material=M\n",
      "t.inp", fs::current_path());
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[0].keyword, "*NODE");
  EXPECT_EQ(records[0].key, "NODE");
  ASSERT_EQ(records[0].params.size(), 1u);
  EXPECT_EQ(records[0].params[0].name, "NSET");
  EXPECT_EQ(records[0].params[0].value, "Nall");
  ASSERT_EQ(records[0].lines.size(), 1u);
  EXPECT_EQ(records[0].lines[0].fields.size(), 4u);
  EXPECT_EQ(records[0].lines[0].where.line, 4);
  EXPECT_EQ(records[1].keyword, "*SOLID SECTION");
  EXPECT_EQ(records[1].key, "SOLIDSECTION");
  EXPECT_EQ(records[1].where.line, 7);
  EXPECT_EQ(records[1].where.file, "t.inp");
}

TEST(inpLexer, TrailingCommaMarksContinuation) {
  const auto records = lex_deck_text("*ELEMENT, TYPE=C3D8\n1, 2, 3,\n4\n", "t", fs::current_path());
  ASSERT_EQ(records[0].lines.size(), 2u);
  EXPECT_TRUE(records[0].lines[0].ends_with_comma);
  EXPECT_EQ(records[0].lines[0].fields.size(), 3u);
  EXPECT_FALSE(records[0].lines[1].ends_with_comma);
}

TEST(inpLexer, ParsesFortranReals) {
  EXPECT_DOUBLE_EQ(*parse_real("1.d3"), 1000.0);
  EXPECT_DOUBLE_EQ(*parse_real("2.5E-1"), 0.25);
  EXPECT_DOUBLE_EQ(*parse_real("5."), 5.0);
  EXPECT_DOUBLE_EQ(*parse_real(".5"), 0.5);
  EXPECT_DOUBLE_EQ(*parse_real("+3"), 3.0);
  EXPECT_DOUBLE_EQ(*parse_real("-3"), -3.0);
  EXPECT_FALSE(parse_real("abc"));
  EXPECT_FALSE(parse_real("1.0x"));
  EXPECT_FALSE(parse_int("1.0"));
  EXPECT_EQ(*parse_int("-12"), -12);
}

class inpInclude : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("kontakt_inp_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_ / "sub");
  }
  void TearDown() override { fs::remove_all(dir_); }
  void write(const fs::path& rel, const std::string& text) {
    std::ofstream(dir_ / rel) << text;
  }
  fs::path dir_;
};

TEST_F(inpInclude, IncludesResolveRelativeToIncludingFile) {
  const std::string model = test::two_cubes_static();
  const auto split = model.find("*ELEMENT");
  write("main.inp", model.substr(0, split) + "*INCLUDE, INPUT=sub/elements.inp\n");
  // sub/elements.inp includes rest.inp from its own directory.
  write("sub/elements.inp", model.substr(split, model.find("*NSET") - split) +
                                "*include,input=rest.inp\n");
  write("sub/rest.inp", model.substr(model.find("*NSET")));
  const model::Model m = read_deck(dir_ / "main.inp");
  EXPECT_EQ(m.n_nodes(), 12);
  EXPECT_EQ(m.n_elements(), 2);
  ASSERT_EQ(m.steps.size(), 1u);
  EXPECT_EQ(m.source_file, (dir_ / "main.inp").string());
}

TEST_F(inpInclude, ErrorsInIncludedFileNameThatFile) {
  write("main.inp", "*INCLUDE, INPUT=bad.inp\n");
  write("bad.inp", "*NODE\n1, 0, 0, 0\n2, x, 0, 0\n");
  try {
    read_deck(dir_ / "main.inp");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, (dir_ / "bad.inp").string());
    EXPECT_EQ(e.where().line, 3);
    EXPECT_NE(std::string(e.what()).find("field 2 ('x')"), std::string::npos) << e.what();
  }
}

TEST_F(inpInclude, MissingIncludeFileIsAnInputError) {
  write("main.inp", "** x\n*INCLUDE, INPUT=nope.inp\n");
  try {
    read_deck(dir_ / "main.inp");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 2);
    EXPECT_EQ(e.keyword(), "*INCLUDE");
  }
}

TEST_F(inpInclude, IncludeCycleIsAnInputError) {
  write("main.inp", "*INCLUDE, INPUT=main.inp\n");
  EXPECT_THROW(read_deck(dir_ / "main.inp"), InputError);
}

TEST_F(inpInclude, IncludeOfADeviceOrFolderIsAnInputError) {
  for (const std::string& target :
       {std::string("/dev/zero"), std::string("/dev/stdin"), dir_.string()}) {
    try {
      lex_deck_text("*INCLUDE, INPUT=" + target + "\n", "main.inp", dir_);
      FAIL() << target;
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().line, 1);
      EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();
    }
  }
}

TEST(inpReader, MissingDeckIsAnInputError) {
  EXPECT_THROW(read_deck("/nonexistent/deck.inp"), InputError);
}

}  // namespace
}  // namespace kontakt::inp
