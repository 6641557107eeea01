// Job processes for real: `kontaktd job-worker` (KONTAKTD_EXE) checking and running decks,
// and stand-in workers (shell scripts) for the supervisor's signal handling.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <fstream>
#include <thread>

#include "server/deck_check.hpp"
#include "server/job_outcome.hpp"
#include "server/job_supervisor.hpp"
#include "server/worker_process.hpp"
#include "server_test_util.hpp"

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

namespace kontakt::server {
namespace {

const fs::path kWorkerExe = KONTAKTD_EXE;

/// Keeps every event it is given.
struct Events final : analysis::EventSink {
  std::vector<analysis::Event> seen;
  void on_event(const analysis::Event& e) override { seen.push_back(e); }
};

/// An NLGEOM beam with many fixed increments: runs for seconds, reporting all along.
std::string long_deck() {
  std::string nodes, elements;
  const int nx = 20;
  auto id = [&](int i, int j, int k) { return 1 + i + (nx + 1) * (j + 2 * k); };
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i <= nx; ++i)
        nodes += std::to_string(id(i, j, k)) + ", " + std::to_string(i) + ", " +
                 std::to_string(j) + ", " + std::to_string(k) + "\n";
  for (int i = 0; i < nx; ++i)
    elements += std::to_string(i + 1) + ", " + std::to_string(id(i, 0, 0)) + ", " +
                std::to_string(id(i + 1, 0, 0)) + ", " + std::to_string(id(i + 1, 1, 0)) + ", " +
                std::to_string(id(i, 1, 0)) + ", " + std::to_string(id(i, 0, 1)) + ", " +
                std::to_string(id(i + 1, 0, 1)) + ", " + std::to_string(id(i + 1, 1, 1)) + ", " +
                std::to_string(id(i, 1, 1)) + "\n";
  return "*NODE, NSET=NALL\n" + nodes + "*ELEMENT, TYPE=C3D8, ELSET=EALL\n" + elements +
         "*NSET, NSET=FIX\n1, 22, 43, 64\n*NSET, NSET=TIP\n21, 42, 63, 84\n"
         "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000, 0.3\n"
         "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n*BOUNDARY\nFIX, 1, 3\n"
         "*STEP, NLGEOM, INC=1000\n*STATIC, DIRECT\n0.0025, 1.0\n*CLOAD\nTIP, 3, -500.\n"
         "*NODE FILE\nU\n*END STEP\n";
}

/// Whether `pid` is a live process: an orphan's zombie waits for whoever reaps orphans here.
bool runs(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return false;
  const std::size_t close = line.rfind(')');
  return close != std::string::npos && close + 2 < line.size() && line[close + 2] != 'Z';
}

class JobProcessTest : public ::testing::Test {
 protected:
  testing::TempDir dir;
  fs::path write(const std::string& name, const std::string& text) {
    const fs::path p = dir.path() / name;
    std::ofstream(p) << text;
    return p;
  }
  worker::Args run_args(const fs::path& deck) {
    return {.mode = worker::Mode::Run, .deck = deck, .parent_pid = getpid(),
            .out_dir = dir.path() / "work", .job_name = "deck", .threads = 1};
  }
  /// A stand-in worker: a shell script run as `script job-worker run ...`.
  fs::path script(const std::string& body) {
    const fs::path p = write("worker.sh", "#!/bin/sh\n" + body + "\n");
    fs::permissions(p, fs::perms::owner_all);
    return p;
  }
};

TEST_F(JobProcessTest, ChildHasItsOwnGroupNoInheritedDescriptorsAndIsKilledWithItsGroupWhenDropped) {
  // No O_CLOEXEC: it would be inherited. Above 3, which the child's report pipe takes.
  const int null_fd = open("/dev/null", O_RDONLY);
  const int leak = fcntl(null_fd, F_DUPFD, 50);
  close(null_fd);
  const Pipe pipe = make_report_pipe();
  pid_t pid = 0, grandchild = 0;
  {
    ChildProcess child({"/bin/sh", "-c",
                        "test -e /proc/self/fd/" + std::to_string(leak) +
                            " && echo leaked >&3; sleep 30 & echo $! >&3; wait"},
                       pipe.write_end);
    close(pipe.write_end);
    pid = child.pid();
    std::string out;
    char buffer[256];
    const auto deadline = Clock::now() + 10s;
    while (out.find('\n') == std::string::npos && Clock::now() < deadline) {
      const ssize_t n = read(pipe.read_end, buffer, sizeof buffer);
      if (n > 0) out.append(buffer, static_cast<std::size_t>(n));
      else std::this_thread::sleep_for(10ms);
    }
    ASSERT_EQ(out.find("leaked"), std::string::npos) << "a descriptor without close-on-exec leaked";
    grandchild = std::stoi(out);
    EXPECT_EQ(getpgid(pid), pid) << "its own process group";
    EXPECT_FALSE(child.try_wait());
  }  // dropped while running: killed and reaped, with what it started
  EXPECT_NE(kill(pid, 0), 0);
  const auto deadline = Clock::now() + 5s;
  while (runs(grandchild) && Clock::now() < deadline) std::this_thread::sleep_for(10ms);
  EXPECT_FALSE(runs(grandchild)) << "a process the child started survived its kill";
  close(leak);
  close(pipe.read_end);
}

TEST_F(JobProcessTest, ExitCodesAndSignalsAreReported) {
  ChildProcess exits({"/bin/sh", "-c", "exit 3"}, -1);
  const auto a = exits.wait_for(10s);
  ASSERT_TRUE(a);
  EXPECT_FALSE(a->signaled);
  EXPECT_EQ(a->code, 3);
  ChildProcess crashes({"/bin/sh", "-c", "kill -SEGV $$"}, -1);
  const auto b = crashes.wait_for(10s);
  ASSERT_TRUE(b);
  EXPECT_TRUE(b->signaled);
  EXPECT_EQ(b->code, SIGSEGV);
  EXPECT_FALSE(crashes.send(SIGTERM)) << "ended: nothing to signal";
}

TEST_F(JobProcessTest, DeckCheckInAWorkerProcess) {
  const DeckChecker check = process_deck_checker(kWorkerExe, {}, 60s);
  const auto ok = check(write("ok.inp", testing::cube_deck()), std::nullopt);
  ASSERT_FALSE(ok.failure) << *ok.failure;
  EXPECT_FALSE(ok.check.error);
  EXPECT_EQ(ok.check.n_steps, 1);
  // Issue 10: a lone '*' crashed the reader (and the daemon with it).
  const auto bad = check(write("bad.inp", "*HEADING\n*\n*NODE\n1,0,0,0\n"), std::nullopt);
  ASSERT_FALSE(bad.failure) << *bad.failure;
  ASSERT_TRUE(bad.check.error);
  EXPECT_EQ(bad.check.error->line, 2);
  EXPECT_EQ(bad.check.error->keyword, "*");
}

TEST_F(JobProcessTest, DeckCheckOverTheMemoryLimitFailsTheCheckNotTheCaller) {
  // A million nodes: 13 MB of deck, about 330 MB to read.
  std::string text = "*NODE\n";
  for (int node = 1; node <= 1'000'000; ++node) text += std::to_string(node) + ",0,0,0\n";
  const fs::path deck = write("huge.inp", text);
  const auto r = process_deck_checker(kWorkerExe, {.memory_bytes = 256ull << 20}, 60s)(deck, {});
  ASSERT_TRUE(r.failure);
  EXPECT_NE(r.failure->find("memory limit of 256 MiB"), std::string::npos) << *r.failure;
}

TEST_F(JobProcessTest, RunRelaysEveryEventAndConverges) {
  WorkerProcess process(kWorkerExe, 1);
  ASSERT_TRUE(process.start(run_args(write("deck.inp", testing::cube_deck()))));
  Events events;
  StopSignal stop;
  const ProcessEnd end = supervise_job(process, events, stop, {}, dir.path() / "work");
  EXPECT_FALSE(end.exit.signaled);
  EXPECT_EQ(end.exit.code, static_cast<int>(worker::Exit::Converged));
  ASSERT_TRUE(end.done);
  EXPECT_EQ(end.done->status, "converged");
  EXPECT_EQ(end.n_events, events.seen.size());
  EXPECT_EQ(end.n_bad_reports, 0u);
  EXPECT_EQ(events.seen.back().kind, analysis::Event::Kind::Done);
  EXPECT_TRUE(fs::exists(dir.path() / "work" / "deck.hdf"));
}

TEST_F(JobProcessTest, CancelStopsTheRunAtAnIterationAndKeepsItsResults) {
  WorkerProcess process(kWorkerExe, 1);
  ASSERT_TRUE(process.start(run_args(write("deck.inp", long_deck()))));
  struct StopAfterIncrements final : analysis::EventSink {
    StopSignal* stop = nullptr;
    int increments = 0;
    void on_event(const analysis::Event& e) override {
      if (e.kind == analysis::Event::Kind::Increment && ++increments == 3)
        stop->request(StopCause::Request);
    }
  } sink;
  StopSignal stop;
  sink.stop = &stop;
  const ProcessEnd end = supervise_job(process, sink, stop, {}, dir.path() / "work");
  EXPECT_EQ(end.exit.code, static_cast<int>(worker::Exit::Cancelled)) << describe(end.exit);
  EXPECT_FALSE(end.killed);
  EXPECT_EQ(judge(end, {}).status, JobStatus::Canceled);
  EXPECT_TRUE(fs::exists(dir.path() / "work" / "deck.hdf"));
}

TEST_F(JobProcessTest, ACrashingProcessIsReportedWithItsSignal) {
  WorkerProcess process(kWorkerExe, 1);
  ASSERT_TRUE(process.start(run_args(write("deck.inp", long_deck()))));
  struct CrashAfterFirstEvent final : analysis::EventSink {
    WorkerProcess* process = nullptr;
    void on_event(const analysis::Event&) override { process->send(SIGSEGV); }
  } sink;
  sink.process = &process;
  StopSignal stop;
  const ProcessEnd end = supervise_job(process, sink, stop, {}, dir.path() / "work");
  ASSERT_TRUE(end.exit.signaled);
  EXPECT_EQ(end.exit.code, SIGSEGV);
  const JobVerdict v = judge(end, {});
  EXPECT_EQ(v.reason, "solver_crashed");
  EXPECT_NE(v.message.find("SIGSEGV"), std::string::npos);
}

TEST_F(JobProcessTest, AProcessIgnoringSigtermIsKilledAfterTheGrace) {
  WorkerProcess process(script("trap '' TERM; echo ready >&3; sleep 30"), 1);
  bool ready = false;
  while (!ready) ASSERT_FALSE(process.poll(10s, [&](std::string_view) { ready = true; }));
  Events events;
  StopSignal stop;
  stop.request(StopCause::Request);
  const auto t0 = Clock::now();
  const ProcessEnd end = supervise_job(process, events, stop, {.grace = 200ms}, dir.path());
  const auto took = Clock::now() - t0;
  EXPECT_TRUE(end.killed);
  EXPECT_TRUE(end.exit.signaled);
  EXPECT_EQ(end.exit.code, SIGKILL);
  EXPECT_GE(took, 200ms);
  EXPECT_LT(took, 5s);
}

TEST_F(JobProcessTest, TheKillWaitsForAResultFrameBeingWritten) {
  // The stand-in "writes a frame" (a .partial file) for 0.8 s while ignoring SIGTERM.
  WorkerProcess process(script("trap '' TERM; touch " + (dir.path() / "f.hdf.partial").string() +
                               "; sleep 0.8; rm " + (dir.path() / "f.hdf.partial").string() +
                               "; sleep 30"),
                        1);
  Events events;
  StopSignal stop;
  while (!writing_results(dir.path())) std::this_thread::sleep_for(5ms);
  const auto t0 = Clock::now();
  stop.request(StopCause::TimeLimit);
  const ProcessEnd end =
      supervise_job(process, events, stop, {.grace = 100ms, .max_frame_write = 10s}, dir.path());
  const auto took = Clock::now() - t0;
  EXPECT_TRUE(end.killed);
  EXPECT_EQ(end.cause, StopCause::TimeLimit);
  EXPECT_GE(took, 600ms) << "killed while the frame was being written";
  EXPECT_LT(took, 5s);
}

TEST_F(JobProcessTest, TheWallTimeLimitStopsTheRun) {
  WorkerProcess process(kWorkerExe, 1);
  ASSERT_TRUE(process.start(run_args(write("deck.inp", long_deck()))));
  Events events;
  StopSignal stop;
  const ProcessEnd end =
      supervise_job(process, events, stop, {.time_limit = 0.5}, dir.path() / "work");
  EXPECT_EQ(end.cause, StopCause::TimeLimit);
  EXPECT_EQ(judge(end, {.time_limit = 0.5}).reason, "time_limit");
  EXPECT_LT(end.seconds, 5.0);
}

}  // namespace
}  // namespace kontakt::server
