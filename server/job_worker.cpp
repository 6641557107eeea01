#include "server/job_worker.hpp"

#include <malloc.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <new>
#include <nlohmann/json.hpp>
#include <variant>

#include "app/run_job.hpp"
#include "output/hdf5_writer.hpp"
#include "server/deck_check.hpp"
#include "server/worker_protocol.hpp"

namespace fs = std::filesystem;
using kontakt::server::worker::Exit;

namespace kontakt::server {

namespace {

/// Raised by SIGTERM/SIGINT; the solver polls it once per iteration and stops cleanly.
std::atomic<bool> g_cancel{false};
/// Raised by SIGXFSZ: a write went past RLIMIT_FSIZE (and failed with EFBIG).
std::atomic<bool> g_file_size_exceeded{false};
static_assert(std::atomic<bool>::is_always_lock_free, "used in signal handlers");

extern "C" void on_stop_signal(int) { g_cancel.store(true); }
extern "C" void on_file_size_signal(int) { g_file_size_exceeded.store(true); }

/// Below this much free space, a failed write is taken for a full disk.
constexpr unsigned long long kDiskFullBytes = 1ull << 20;
/// A request line is a few hundred bytes (paths and numbers).
constexpr std::size_t kMaxRequest = 1u << 16;
/// Freed heap kept rather than trimmed; allocations served from the heap rather than mmap.
constexpr int kKeptHeap = 256 << 20, kHeapAllocationMax = 32 << 20;

void handle(int signal, void (*handler)(int)) {
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(signal, &action, nullptr);
}

/// Ties the process to the daemon: killed when the daemon dies; gone at once if it already is.
bool follow_parent(long parent_pid) {
  if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0) return false;
  return parent_pid == 0 || getppid() == parent_pid;
}

/// Resource limits, no core files, and first in line for the kernel's OOM killer.
void apply_limits(const worker::Limits& limits) {
  const auto set = [](int resource, rlim_t value) {
    const rlimit limit{value, value};
    setrlimit(resource, &limit);
  };
  set(RLIMIT_CORE, 0);
  if (limits.memory_bytes) set(RLIMIT_AS, limits.memory_bytes);
  if (limits.file_size_bytes) set(RLIMIT_FSIZE, limits.file_size_bytes);
  std::ofstream("/proc/self/oom_score_adj") << 1000;
}

/// Writes all of `text` to `fd`; false once the reader is gone.
bool write_all(int fd, std::string_view text) {
  while (!text.empty()) {
    const ssize_t n = write(fd, text.data(), text.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    text.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

/// Every event to the daemon as one JSON line; a daemon that went away ends the reporting.
class ReportSink final : public analysis::EventSink {
 public:
  void on_event(const analysis::Event& event) override {
    if (open_) open_ = write_all(worker::kReportFd, analysis::to_json_line(event) + '\n');
  }

 private:
  bool open_ = true;
};

bool disk_full(const fs::path& dir) {
  struct statvfs fs {};
  if (statvfs(dir.c_str(), &fs) != 0) return false;
  return static_cast<unsigned long long>(fs.f_bavail) * fs.f_frsize < kDiskFullBytes;
}

/// Works in the job's folder: `ls -l /proc/PID/cwd` tells which job a process runs.
void enter(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  fs::current_path(dir, ec);
}

Exit check(const worker::Args& args) {
  try {
    const app::DeckCheck result = app::check_deck(args.deck, args.scheme);
    write_all(worker::kReportFd, deck_check_to_json(result) + '\n');
    return result.error ? Exit::InputError : Exit::Converged;
  } catch (const std::bad_alloc&) {
    return Exit::OutOfMemory;
  }
}

Exit run(const worker::Args& args) {
  handle(SIGTERM, on_stop_signal);
  handle(SIGINT, on_stop_signal);
  handle(SIGXFSZ, on_file_size_signal);
  const fs::path deck = fs::absolute(args.deck), out_dir = fs::absolute(args.out_dir);
  enter(out_dir);
  ReportSink sink;
  const app::RunOutcome outcome = app::run_job({.deck = deck,
                                                .out_dir = out_dir,
                                                .job_name = args.job_name,
                                                .threads = args.threads,
                                                .scheme = args.scheme},
                                               sink, g_cancel);
  switch (outcome.status) {
    case app::RunStatus::Converged: return Exit::Converged;
    case app::RunStatus::InputError: return Exit::InputError;
    case app::RunStatus::NotConverged: return Exit::NotConverged;
    case app::RunStatus::Cancelled: return Exit::Cancelled;
    case app::RunStatus::Error: break;
  }
  if (outcome.out_of_memory) return Exit::OutOfMemory;
  if (g_file_size_exceeded.load()) return Exit::FileSizeLimit;
  if (disk_full(out_dir)) return Exit::DiskFull;
  return Exit::SolverError;
}

/// The run's end for an executor that is not the process's parent: written whole, then
/// renamed, so a reader never sees half of it.
void write_outcome(const fs::path& file, Exit exit) {
  const fs::path partial = file.string() + ".tmp";
  {
    std::ofstream out(partial, std::ios::trunc);
    out << worker::outcome_text(exit);
    out.flush();
    if (!out) return;  // the executor's fallback (Slurm's job state) says how it ended
  }
  std::error_code ec;
  fs::rename(partial, file, ec);
}

/// The requests of a standby process: JSON lines on stdin (WorkerProcess::start), read a
/// block at a time (a byte at a time costs a system call per byte of every request).
class RequestReader {
 public:
  /// The next request's arguments; empty when the daemon closed the channel (no more work)
  /// or sent something else than a JSON array.
  std::vector<std::string> next() {
    std::size_t end;
    while ((end = buffered_.find('\n')) == std::string::npos && buffered_.size() < kMaxRequest) {
      char block[4096];
      const ssize_t n = read(0, block, sizeof block);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      buffered_.append(block, static_cast<std::size_t>(n));
    }
    const std::string line = buffered_.substr(0, end);
    buffered_.erase(0, end == std::string::npos ? end : end + 1);
    const auto j = nlohmann::json::parse(line, nullptr, false);
    std::vector<std::string> argv;
    if (!j.is_array()) return argv;
    for (const auto& a : j)
      if (a.is_string()) argv.push_back(a.get<std::string>());
    return argv;
  }

 private:
  std::string buffered_;
};

/// Parses and prepares one piece of work; the exit code for a bad one.
std::variant<worker::Args, Exit> prepare(const std::vector<std::string>& argv) {
  const auto parsed = worker::parse_args(argv);
  if (const auto* error = std::get_if<std::string>(&parsed)) {
    std::fprintf(stderr, "kontaktd job-worker: %s\n", error->c_str());
    return Exit::Usage;
  }
  const worker::Args& args = std::get<worker::Args>(parsed);
  if (!follow_parent(args.parent_pid)) return Exit::Usage;
  signal(SIGPIPE, SIG_IGN);  // a daemon gone mid-report: write() fails instead
  apply_limits(args.limits);
  return args;
}

}  // namespace

int job_worker_main(std::vector<std::string> argv) {
  // The process lives for its work only: it keeps freed memory instead of returning it piece by
  // piece (every trim or munmap is a TLB flush, tens of ms over a small job in a VM).
  mallopt(M_TRIM_THRESHOLD, kKeptHeap);
  mallopt(M_MMAP_THRESHOLD, kHeapAllocationMax);
  if (argv.size() != 2 || argv[0] != worker::kStandby) {  // the work on the command line
    const auto work = prepare(argv);
    if (const auto* exit = std::get_if<Exit>(&work)) return static_cast<int>(*exit);
    const auto& args = std::get<worker::Args>(work);
    if (args.mode == worker::Mode::Check) return static_cast<int>(check(args));
    const Exit ran = run(args);
    if (!args.outcome_file.empty()) write_outcome(args.outcome_file, ran);
    return static_cast<int>(ran);
  }
  long parent = 0;
  std::from_chars(argv[1].data(), argv[1].data() + argv[1].size(), parent);
  if (!follow_parent(parent)) return static_cast<int>(Exit::Usage);  // tied before it waits
  try {
    output::warm_up_hdf5();
  } catch (const std::exception&) {  // the job will meet the same trouble and report it
  }
  // Checks one deck after the other until a run, a failed check or the end of the requests.
  RequestReader requests;
  while (true) {
    const std::vector<std::string> request = requests.next();
    if (request.empty()) return static_cast<int>(Exit::Converged);  // not needed any more
    const auto work = prepare(request);
    if (const auto* exit = std::get_if<Exit>(&work)) return static_cast<int>(*exit);
    const auto& args = std::get<worker::Args>(work);
    if (args.mode == worker::Mode::Run) {
      // Its files are closed and its events written: the process ends here, without the
      // libraries' exit clean-up (HDF5's alone costs milliseconds of every job's latency).
      const Exit ran = run(args);
      std::fflush(nullptr);
      _exit(static_cast<int>(ran));
    }
    const Exit checked = check(args);
    if (checked != Exit::Converged && checked != Exit::InputError) return static_cast<int>(checked);
  }
}

}  // namespace kontakt::server
