// app::run_job and app::check_deck, the entry point `kontakt solve` and the daemon share.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>

#include "../analysis/cube_deck.hpp"
#include "../contact/two_blocks.hpp"
#include "../inp/deck_fixtures.hpp"
#include "app/run_job.hpp"

namespace fs = std::filesystem;

namespace kontakt::app {

namespace {

struct Recorder final : analysis::EventSink {
  std::vector<analysis::Event> events;
  void on_event(const analysis::Event& e) override { events.push_back(e); }
};

}  // namespace

// Outside the anonymous namespace: the tests derived from it are not in it.
class RunJobTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("kontakt-run-job-" + std::to_string(std::random_device{}()));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return dir / name;
  }
  static std::string cube(const std::string& step_head, const std::string& procedure) {
    return testing_decks::cube_model("*ELASTIC\n210000, 0.3\n") + testing_decks::kRollers +
           step_head + procedure + "*CLOAD\nX1, 1, 100\n*NODE FILE\nU\n*END STEP\n";
  }
  RunRequest request(const fs::path& deck) {
    return {.deck = deck, .out_dir = dir / "out", .job_name = "job", .threads = 1, .scheme = std::nullopt};
  }
  fs::path dir;
  std::atomic<bool> no_cancel{false};
};

TEST_F(RunJobTest, ConvergedRunWritesEveryResultFileAndEndsWithDone) {
  Recorder sink;
  const RunOutcome r = run_job(request(write("c.inp", cube("*STEP\n", "*STATIC\n"))), sink, no_cancel);
  EXPECT_EQ(r.status, RunStatus::Converged) << r.message;
  EXPECT_EQ(r.exit_code, 0);
  for (const char* ext : {".dat", ".hdf", ".xdmf", ".log.jsonl", ".sta", ".cvg"})
    EXPECT_TRUE(fs::exists(dir / "out" / (std::string("job") + ext))) << ext;
  ASSERT_FALSE(sink.events.empty());
  EXPECT_EQ(sink.events.back().kind, analysis::Event::Kind::Done);
  EXPECT_EQ(sink.events.back().status, "converged");
}

TEST_F(RunJobTest, InputErrorNamesFileLineAndKeyword) {
  Recorder sink;
  const fs::path deck = write("bad.inp", "*NODE\n1, 0, 0, 0\n*FROBNICATE\n");
  const RunOutcome r = run_job(request(deck), sink, no_cancel);
  EXPECT_EQ(r.status, RunStatus::InputError);
  EXPECT_EQ(r.exit_code, 2);
  ASSERT_TRUE(r.deck_error);
  EXPECT_EQ(r.deck_error->line, 3);
  EXPECT_EQ(r.deck_error->keyword, "*FROBNICATE");
  EXPECT_EQ(fs::path(r.deck_error->file).filename(), "bad.inp");
  ASSERT_FALSE(sink.events.empty());
  EXPECT_EQ(sink.events.back().status, "input_error");
  const DeckCheck check = check_deck(deck, std::nullopt);
  ASSERT_TRUE(check.error);
  EXPECT_EQ(check.error->line, 3);
}

TEST_F(RunJobTest, CheckDeckReportsStepsAndTotalTime) {
  const fs::path deck = write("c.inp", cube("*STEP\n", "*STATIC\n") + "*STEP\n*STATIC\n0.5, 2.0\n*END STEP\n");
  const DeckCheck check = check_deck(deck, std::nullopt);
  ASSERT_FALSE(check.error) << check.error->message;
  EXPECT_EQ(check.n_steps, 2);
  EXPECT_DOUBLE_EQ(check.total_time, 3.0);
}

TEST_F(RunJobTest, UnknownSchemeIsAnInputError) {
  const DeckCheck check = check_deck(write("c.inp", cube("*STEP\n", "*STATIC\n")), "gc5");
  ASSERT_TRUE(check.error);
  EXPECT_NE(check.error->message.find("gc5"), std::string::npos);
  EXPECT_FALSE(check_deck(dir / "c.inp", "lgc12").error);
}

TEST_F(RunJobTest, FrictionAndTiedContactAreCheckedAsCcxDoes) {
  // Friction and *CHANGE FRICTION are solved; a TIED card needs its stiffness and a *FRICTION
  // (its stick slope). Lines 33-35 hold SI.
  const std::string pair = "*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE\nSLAVE, MASTER\n";
  const std::string step = "*STEP\n*STATIC\n*END STEP\n";
  const std::string base = inp::test::two_cubes_surfaces() + inp::test::linear_interaction();
  EXPECT_FALSE(check_deck(write("free.inp", base + pair + step), std::nullopt).error);
  EXPECT_FALSE(check_deck(write("f.inp", base + "*FRICTION\n0.3, 1e5\n" + pair + step), std::nullopt).error);
  EXPECT_FALSE(check_deck(
      write("c.inp", base + pair + step + "*STEP\n*STATIC\n*CHANGE FRICTION, INTERACTION=SI\n*FRICTION\n0.1\n*END STEP\n"),
      std::nullopt).error);

  const std::string tied = "*SURFACE INTERACTION, NAME=SI\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TIED\n";
  const DeckCheck no_stiffness = check_deck(
      write("k.inp", inp::test::two_cubes_surfaces() + tied + "*FRICTION\n0.3, 1e5\n" + pair + step), std::nullopt);
  ASSERT_TRUE(no_stiffness.error);
  EXPECT_EQ(no_stiffness.error->line, 34);
  EXPECT_EQ(no_stiffness.error->keyword, "*SURFACE BEHAVIOR");

  Recorder sink;
  const RunOutcome r = run_job(request(write("t.inp", inp::test::two_cubes_surfaces() + tied + "1e7\n" + pair + step)), sink, no_cancel);
  EXPECT_EQ(r.exit_code, 2);
  ASSERT_TRUE(r.deck_error);
  EXPECT_EQ(r.deck_error->line, 34);
  EXPECT_EQ(r.deck_error->keyword, "*SURFACE BEHAVIOR");
  EXPECT_NE(r.deck_error->message.find("*FRICTION"), std::string::npos) << r.deck_error->message;
}

TEST_F(RunJobTest, RaisedCancelFlagStopsANonlinearRun) {
  std::atomic<bool> cancel{true};
  Recorder sink;
  const RunOutcome r =
      run_job(request(write("n.inp", cube("*STEP, NLGEOM\n", "*STATIC\n0.1, 1.0\n"))), sink, cancel);
  EXPECT_EQ(r.status, RunStatus::Cancelled);
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_EQ(sink.events.back().status, "cancelled");
  EXPECT_TRUE(fs::exists(dir / "out" / "job.hdf")) << "results are completed on cancel";
}

TEST_F(RunJobTest, CancelStopsALinearRunBeforeItsNextStep) {
  // The flag goes up when step 1 is solved: step 2 is neither assembled nor solved.
  std::atomic<bool> cancel{false};
  struct CancelAfterFirstIncrement final : analysis::EventSink {
    std::atomic<bool>* flag;
    std::vector<analysis::Event> events;
    void on_event(const analysis::Event& e) override {
      events.push_back(e);
      if (e.kind == analysis::Event::Kind::Increment) flag->store(true);
    }
  } sink;
  sink.flag = &cancel;
  const RunOutcome r = run_job(
      request(write("l.inp", cube("*STEP\n", "*STATIC\n") + "*STEP\n*STATIC\n*END STEP\n")), sink,
      cancel);
  EXPECT_EQ(r.status, RunStatus::Cancelled);
  EXPECT_EQ(r.exit_code, 3);
  int increments = 0;
  for (const auto& e : sink.events) increments += e.kind == analysis::Event::Kind::Increment;
  EXPECT_EQ(increments, 1);
  EXPECT_EQ(sink.events.back().status, "cancelled");
  EXPECT_TRUE(fs::exists(dir / "out" / "job.hdf"));
}

TEST_F(RunJobTest, UnwritableOutputIsAnError) {
  Recorder sink;
  RunRequest req = request(write("c.inp", cube("*STEP\n", "*STATIC\n")));
  write("file", "x");
  req.out_dir = dir / "file" / "sub";
  const RunOutcome r = run_job(req, sink, no_cancel);
  EXPECT_EQ(r.status, RunStatus::Error);
  EXPECT_EQ(r.exit_code, 4);
}

TEST_F(RunJobTest, TiesAreSetUpBeforeALinearSolveAndTheirWarningsReported) {
  // The upper block hangs over the lower one: its slave nodes beyond x = 1 stay free.
  contact::fixtures::TwoBlocks t;
  t.offset_x = 0.75;
  std::string text = contact::fixtures::two_blocks_deck(t);
  text.insert(text.find("*STEP"), "*TIE, NAME=BOND\nSLAVE, MASTER\n");
  const fs::path deck = write("tie.inp", text);
  Recorder sink;
  const RunOutcome r = run_job(request(deck), sink, no_cancel);
  ASSERT_EQ(r.status, RunStatus::Converged) << r.message;
  const auto free_nodes = [](const std::string& w) {
    return w.find("tie BOND: 6 slave node(s) of SLAVE have no master face") != std::string::npos;
  };
  EXPECT_TRUE(std::any_of(sink.events.begin(), sink.events.end(), [&](const analysis::Event& e) {
    return e.kind == analysis::Event::Kind::Warning && free_nodes(e.message);
  }));
  EXPECT_TRUE(std::none_of(sink.events.begin(), sink.events.end(), [](const analysis::Event& e) {
    return e.kind == analysis::Event::Kind::Iteration;  // linear: no Newton iterations
  }));
  const DeckCheck check = check_deck(deck, std::nullopt);
  EXPECT_TRUE(std::any_of(check.warnings.begin(), check.warnings.end(), free_nodes));
}

}  // namespace kontakt::app
