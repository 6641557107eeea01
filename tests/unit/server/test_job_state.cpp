// The job state machine: exactly the transitions of the table, nothing else.
#include <gtest/gtest.h>

#include <set>
#include <utility>

#include "server/job_state.hpp"

namespace kontakt::server {

namespace {
using S = JobStatus;
const S kAll[] = {S::Queued, S::Running, S::Canceling, S::Succeeded, S::Failed, S::Canceled};
}  // namespace

TEST(JobState, AllowsExactlyTheDocumentedTransitions) {
  const std::set<std::pair<S, S>> expected{
      {S::Queued, S::Running},    {S::Queued, S::Canceled},  {S::Running, S::Succeeded},
      {S::Running, S::Failed},    {S::Running, S::Canceling}, {S::Running, S::Queued},
      {S::Canceling, S::Canceled}};
  for (S from : kAll)
    for (S to : kAll)
      EXPECT_EQ(transition_allowed(from, to), expected.count({from, to}) == 1)
          << status_name(from) << " -> " << status_name(to);
}

TEST(JobState, TerminalStatesHaveNoWayOut) {
  for (S from : kAll) {
    if (!is_terminal(from)) continue;
    for (S to : kAll) EXPECT_FALSE(transition_allowed(from, to)) << status_name(from);
  }
  EXPECT_FALSE(is_terminal(S::Queued));
  EXPECT_FALSE(is_terminal(S::Running));
  EXPECT_FALSE(is_terminal(S::Canceling));
}

TEST(JobState, EveryStateCanReachATerminalState) {
  for (S from : kAll) {
    std::set<S> reached{from}, frontier{from};
    while (!frontier.empty()) {
      std::set<S> next;
      for (S a : frontier)
        for (S b : kAll)
          if (transition_allowed(a, b) && reached.insert(b).second) next.insert(b);
      frontier = next;
    }
    bool terminal = false;
    for (S s : reached) terminal = terminal || is_terminal(s);
    EXPECT_TRUE(terminal) << status_name(from);
  }
}

TEST(JobState, NamesRoundTrip) {
  for (S s : kAll) EXPECT_EQ(status_from_name(status_name(s)), s);
  EXPECT_FALSE(status_from_name("done"));
  EXPECT_FALSE(status_from_name("Queued"));
}

}  // namespace kontakt::server
