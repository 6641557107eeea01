// The pure parts of the job processes: report lines, the worker command line, the deck check
// report, signal names.
#include <gtest/gtest.h>

#include <csignal>

#include "server/child_process.hpp"
#include "server/deck_check.hpp"
#include "server/line_splitter.hpp"
#include "server/worker_protocol.hpp"

namespace kontakt::server {
namespace {

std::vector<std::string> split(LineSplitter& s, std::initializer_list<std::string_view> chunks) {
  std::vector<std::string> lines;
  for (std::string_view chunk : chunks)
    s.feed(chunk, [&](std::string_view line) { lines.emplace_back(line); });
  return lines;
}

TEST(LineSplitter, JoinsChunksAndDropsOverlongLines) {
  LineSplitter s(8);
  EXPECT_EQ(split(s, {"ab", "c\nde", "f\n\n", "g"}),
            (std::vector<std::string>{"abc", "def", ""}));
  EXPECT_EQ(s.n_dropped(), 0u);
  // "g" + a 12-byte rest: over the limit, dropped up to its newline; the next line is whole.
  EXPECT_EQ(split(s, {"123456", "789012\nok\n"}), (std::vector<std::string>{"ok"}));
  EXPECT_EQ(s.n_dropped(), 1u);
  EXPECT_EQ(split(s, {"cut off"}), (std::vector<std::string>{}));
  s.finish();  // a writer that died mid-line
  EXPECT_EQ(s.n_dropped(), 2u);
}

TEST(WorkerProtocol, CommandLineRoundTrips) {
  const worker::Args run{.mode = worker::Mode::Run, .deck = "/d/in/deck.inp", .scheme = "lgc7",
                         .limits = {.memory_bytes = 1ull << 30, .file_size_bytes = 4096},
                         .parent_pid = 42, .out_dir = "/d/work", .job_name = "deck",
                         .threads = 2};
  const auto back = std::get<worker::Args>(worker::parse_args(worker::to_argv(run)));
  EXPECT_EQ(back.mode, worker::Mode::Run);
  EXPECT_EQ(back.deck, run.deck);
  EXPECT_EQ(back.scheme, run.scheme);
  EXPECT_EQ(back.limits.memory_bytes, run.limits.memory_bytes);
  EXPECT_EQ(back.limits.file_size_bytes, run.limits.file_size_bytes);
  EXPECT_EQ(back.parent_pid, 42);
  EXPECT_EQ(back.out_dir, run.out_dir);
  EXPECT_EQ(back.job_name, "deck");
  EXPECT_EQ(back.threads, 2);
  const worker::Args check{.mode = worker::Mode::Check, .deck = "x.inp"};
  EXPECT_EQ(std::get<worker::Args>(worker::parse_args(worker::to_argv(check))).mode,
            worker::Mode::Check);
  for (const std::vector<std::string>& bad :
       {std::vector<std::string>{}, {"solve"}, {"run", "--deck", "a"}, {"check"},
        {"check", "--deck"}, {"check", "--deck", "a", "--parent", "-1"},
        {"check", "--deck", "a", "--bogus", "1"}})
    EXPECT_TRUE(std::holds_alternative<std::string>(worker::parse_args(bad)));
}

TEST(WorkerProtocol, LimitsInWords) {
  EXPECT_EQ(worker::byte_size(256u << 10), "256 KiB");
  EXPECT_EQ(worker::byte_size(400u << 20), "400 MiB");
  EXPECT_EQ(worker::byte_size(8ull << 30), "8 GiB");
  EXPECT_EQ(worker::byte_size(1536u << 10), "1536 KiB");
  EXPECT_EQ(worker::byte_size(4097), "4097 bytes");
}

TEST(DeckCheckReport, RoundTripsErrorAndFigures) {
  app::DeckCheck ok;
  ok.n_steps = 2;
  ok.total_time = 1.5;
  const auto a = deck_check_from_json(deck_check_to_json(ok));
  ASSERT_TRUE(a);
  EXPECT_FALSE(a->error);
  EXPECT_EQ(a->n_steps, 2);
  EXPECT_EQ(a->total_time, 1.5);
  app::DeckCheck bad;
  bad.error = app::DeckError{.file = "deck.inp", .line = 2, .keyword = "*", .message = "m\xff"};
  const auto b = deck_check_from_json(deck_check_to_json(bad));
  ASSERT_TRUE(b && b->error);
  EXPECT_EQ(b->error->line, 2);
  EXPECT_EQ(b->error->keyword, "*");
  for (const char* line : {"", "{}", "[]", R"({"n_steps":"2","total_time":1})", R"({"error":3})"})
    EXPECT_FALSE(deck_check_from_json(line)) << line;
}

TEST(ExitStatus, NamesSignals) {
  EXPECT_EQ(describe({.signaled = false, .code = 3}), "exit code 3");
  EXPECT_EQ(describe({.signaled = true, .code = SIGSEGV}),
            "signal 11 (SIGSEGV: Segmentation fault)");
  EXPECT_EQ(signal_name(SIGKILL), "SIGKILL");
}

}  // namespace
}  // namespace kontakt::server
