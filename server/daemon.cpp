#include "server/daemon.hpp"

#include <boost/asio/io_context.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/asio/thread_pool.hpp>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

#include "server/handlers/routes.hpp"
#include "server/job_files.hpp"
#include "server/job_store.hpp"
#include "server/listener.hpp"
#include "server/local_executor.hpp"
#include "server/slurm_executor.hpp"
#include "server/worker_pool.hpp"

namespace fs = std::filesystem;
namespace net = boost::asio;

namespace kontakt::server {

namespace {

/// Zip uploads may unpack to this multiple of the body limit (decks compress ~10x).
constexpr std::uint64_t kUnpackFactor = 16;
/// Workers are this program itself (`kontaktd job-worker`), whatever happens to its file.
const char* const kSelf = "/proc/self/exe";
/// A deck check that takes longer is refused (a 1 GiB upload reads in well under this).
constexpr auto kDeckCheckTimeLimit = std::chrono::seconds(120);

std::set<std::string> read_tokens(const std::string& file) {
  if (file.empty()) return {};
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read the token file " + file);
  std::stringstream text;
  text << in.rdbuf();
  const auto tokens = parse_token_file(text.str());
  if (tokens.empty()) throw std::runtime_error("the token file " + file + " has no token");
  return {tokens.begin(), tokens.end()};
}

/// Slurm's warning SIGTERM comes at least this long before the time limit (Slurm may send
/// it up to a minute early anyway), or --kill-grace if longer.
constexpr int kMinSlurmSignalGrace = 60;

std::unique_ptr<Executor> make_executor(const Settings& settings) {
  if (settings.executor == "slurm")
    return std::make_unique<SlurmExecutor>(SlurmSettings{
        .defaults = settings.slurm,
        .worker_exe = fs::read_symlink(kSelf),  // its path on the nodes too
        .signal_grace = std::max(kMinSlurmSignalGrace,
                                 static_cast<int>(std::ceil(settings.kill_grace))),
        .max_array_parallel = settings.workers});
  // Every worker thread finds a process waiting, and one more is loading.
  return std::make_unique<LocalExecutor>(kSelf, settings.threads_per_job,
                                         static_cast<std::size_t>(settings.workers) + 1);
}

/// Running and canceling jobs of the daemon before, for an executor whose runs went on.
std::vector<JobRecord> unfinished_runs(JobStore& store) {
  std::vector<JobRecord> jobs;
  JobQuery query;
  query.statuses = {JobStatus::Running, JobStatus::Canceling};
  query.limit = 1000;
  while (true) {
    JobPage page = store.list_jobs(query);
    for (JobRecord& job : page.jobs) jobs.push_back(std::move(job));
    if (!page.more || jobs.empty()) return jobs;
    query.after = std::pair{jobs.back().created_ms, jobs.back().id};
  }
}

/// Job folders without a record are uploads that a crash interrupted before their 201.
void remove_orphan_folders(JobStore& store, const JobFiles& files) {
  const auto ids = store.all_ids();
  const std::set<std::string> known(ids.begin(), ids.end());
  for (const std::string& id : files.folder_ids())
    if (!known.count(id)) files.remove(id);
}

}  // namespace

int run_daemon(const Settings& settings) {
  const std::set<std::string> tokens = read_tokens(settings.token_file);
  fs::create_directories(settings.data_dir);
  // Absolute: a Slurm job finds its folder by this path on its node.
  const fs::path data_dir = fs::absolute(settings.data_dir);
  JobStore store(data_dir / "kontakt.db");
  JobFiles files(data_dir);
  const std::unique_ptr<Executor> executor = make_executor(settings);
  std::vector<JobRecord> adopted;
  if (executor->outlives_daemon()) {
    adopted = unfinished_runs(store);
    if (!adopted.empty())
      std::printf("kontaktd: %zu jobs running or canceling in %s: watched again\n",
                  adopted.size(), settings.executor.c_str());
  } else {
    const RecoveryReport recovered = store.recover(settings.max_attempts);
    if (recovered.requeued + recovered.failed + recovered.canceled > 0)
      std::printf("kontaktd: recovered after a stop: %d requeued, %d failed (worker_lost), %d canceled\n",
                  recovered.requeued, recovered.failed, recovered.canceled);
  }
  remove_orphan_folders(store, files);

  const worker::Limits limits{.memory_bytes = settings.job_memory_limit,
                              .file_size_bytes = settings.job_file_size_limit};
  WorkerPool pool(store, files, *executor,
                  {.workers = settings.workers,
                   .threads_per_job = settings.threads_per_job,
                   .job_time_limit = settings.job_time_limit,
                   .max_attempts = settings.max_attempts,
                   .limits = limits,
                   .kill_grace = std::chrono::milliseconds(
                       static_cast<long long>(1000 * settings.kill_grace))});
  pool.adopt(std::move(adopted));
  handlers::ApiContext api{
      .store = store, .files = files, .control = pool,
      .check_deck = process_deck_checker(kSelf, {.memory_bytes = settings.job_memory_limit},
                                         kDeckCheckTimeLimit),
      .max_unpacked = kUnpackFactor * settings.max_body};
  Router router = handlers::make_router(api);
  router.require_tokens(tokens);

  net::io_context ioc(settings.io_threads);
  net::thread_pool handler_pool(static_cast<std::size_t>(settings.handler_threads));
  SessionContext sessions{.router = router, .store = store, .handler_pool = handler_pool,
                          .max_body = settings.max_body,
                          .request_timeout = std::chrono::seconds(settings.request_timeout)};
  const net::ip::tcp::endpoint endpoint(net::ip::make_address(settings.bind), settings.port);
  auto listener = std::make_shared<Listener>(ioc, endpoint, sessions);
  listener->start();
  pool.start();

  std::thread drainer;
  net::signal_set signals(ioc, SIGINT, SIGTERM);
  signals.async_wait([&](const boost::system::error_code& ec, int signal) {
    if (ec) return;
    std::printf("kontaktd: signal %d: draining (up to %g s)\n", signal, settings.drain_timeout);
    std::fflush(stdout);
    listener->stop();
    // Drain off the I/O threads: status requests keep being answered meanwhile.
    drainer = std::thread([&] {
      pool.drain(std::chrono::milliseconds(static_cast<long long>(1000 * settings.drain_timeout)));
      ioc.stop();
    });
  });
  std::printf("kontaktd: listening on http://%s:%u (data %s, %d workers, executor %s)\n",
              settings.bind.c_str(), listener->port(), settings.data_dir.c_str(), settings.workers,
              settings.executor.c_str());
  std::fflush(stdout);

  std::vector<std::thread> io_threads;
  for (int i = 1; i < settings.io_threads; ++i) io_threads.emplace_back([&ioc] { ioc.run(); });
  ioc.run();
  for (auto& t : io_threads) t.join();
  if (drainer.joinable()) drainer.join();
  handler_pool.join();
  std::printf("kontaktd: stopped\n");
  return 0;
}

}  // namespace kontakt::server
