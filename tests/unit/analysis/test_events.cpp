// The event schema both ways: what a job process writes to its pipe is what the daemon reads.
#include <gtest/gtest.h>

#include "analysis/events.hpp"

namespace kontakt::analysis {
namespace {

using Kind = Event::Kind;

/// One event of every kind with the fields its emitters set.
std::vector<Event> sample_events() {
  return {
      {.kind = Kind::Step, .step = 2, .wall_time = 0.25},
      {.kind = Kind::Increment, .step = 1, .increment = 3, .attempt = 1, .iteration = 4,
       .step_time = 0.75, .total_time = 1.75, .dt = 0.25, .contact_elements = 12,
       .stabilisation_energy = 1e-6, .strain_energy = 2.5, .wall_time = 1.5},
      {.kind = Kind::Iteration, .step = 1, .increment = 3, .attempt = 2, .iteration = 1,
       .step_time = 0.5, .total_time = 1.5, .dt = 0.125, .residual = 3.5e-3,
       .correction = 1e-9, .contact_elements = 7, .stick = 4, .slip = 3,
       .stabilisation = 1e-3, .wall_time = 1.25},
      {.kind = Kind::Cutback, .step = 1, .increment = 2, .attempt = 1, .iteration = 9,
       .step_time = 0.5, .total_time = 0.5, .dt = 0.25, .wall_time = 0.5,
       .message = "divergence"},
      {.kind = Kind::Output, .step = 1, .increment = 1, .step_time = 1, .total_time = 1, .dt = 1},
      {.kind = Kind::Warning, .message = "deck.inp:3: *NODE: node 1 defined again"},
      {.kind = Kind::Done, .wall_time = 2, .status = "converged", .iterations = 17,
       .max_displacement = 0.125, .max_mises = 250.5, .has_contact = true,
       .max_contact_pressure = 12.5, .total_contact_force = 1e3, .drift_redos = 1,
       .drift_refreezes = 2,
       .times = {.contact_search = 0.5, .pattern = 0.25, .elements = 1, .contact = 0.125,
                 .factorisation = 0.75, .solve = 0.0625}},
      {.kind = Kind::Done, .status = "input_error", .message = "deck.inp:2: *: no keyword"},
      {.kind = Kind::Error, .message = "singular"},
  };
}

TEST(Events, EveryWrittenLineReadsBackToTheSameLine) {
  for (const Event& e : sample_events()) {
    const std::string line = to_json_line(e);
    const std::optional<Event> back = from_json_line(line);
    ASSERT_TRUE(back) << line;
    EXPECT_EQ(back->kind, e.kind) << line;
    EXPECT_EQ(to_json_line(*back), line);
  }
}

TEST(Events, CutbackCarriesWhereTheSolverWas) {
  const auto back = from_json_line(to_json_line(sample_events()[3]));
  ASSERT_TRUE(back);
  EXPECT_EQ(back->step_time, 0.5);
  EXPECT_EQ(back->total_time, 0.5);
  EXPECT_EQ(back->dt, 0.25);
  EXPECT_EQ(back->iteration, 9);
}

TEST(Events, AnythingElseIsRefused) {
  for (const char* line :
       {"", "not json", "[1,2]", "{}", R"({"event":"status"})", R"({"event":7})",
        R"({"event":"iteration","iteration":"3"})", R"({"event":"iteration","iteration":1.5})",
        R"({"event":"step","step":4294967296})", R"({"event":"done","summary":[1]})",
        R"({"event":"warning","message":5})", "{\"event\":\"step\"", R"({"event":"step"} x)"})
    EXPECT_FALSE(from_json_line(line)) << line;
}

TEST(Events, InvalidUtf8InAMessageIsReplacedNotThrown) {
  const Event e{.kind = Kind::Done, .status = "input_error", .message = "field 'a\xff\xfe'"};
  std::string line;
  ASSERT_NO_THROW(line = to_json_line(e));
  const auto back = from_json_line(line);
  ASSERT_TRUE(back);
  EXPECT_NE(back->message.find("\xEF\xBF\xBD"), std::string::npos);  // U+FFFD
}

}  // namespace
}  // namespace kontakt::analysis
