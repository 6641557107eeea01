// The SQLite job store on a temporary database: inserts and idempotency, claiming, cancel,
// finishing, crash recovery, paging, events, migrations.
#include <gtest/gtest.h>

#include "server/digest.hpp"
#include "server/job_store.hpp"
#include "server/job_store_schema.hpp"
#include "server_test_util.hpp"

namespace kontakt::server {

namespace {

NewJob new_job(const std::string& name, std::optional<std::string> key = std::nullopt,
               const std::string& fingerprint = "f") {
  NewJob job;
  job.id = new_job_id();
  job.name = name;
  job.main_file = "deck.inp";
  job.labels = {{"sweep", "a"}};
  job.n_steps = 1;
  job.planned_time = 1;
  job.idempotency_key = std::move(key);
  job.fingerprint = fingerprint;
  return job;
}

}  // namespace

// Outside the anonymous namespace: the tests derived from it are not in it.
class JobStoreTest : public ::testing::Test {
 protected:
  testing::TempDir dir;
  JobStore store{dir.path() / "jobs.db"};
};

TEST_F(JobStoreTest, InsertedJobIsQueuedWithAStatusEvent) {
  const auto [result, job] = store.insert_job(new_job("a"));
  EXPECT_EQ(result, InsertResult::Created);
  EXPECT_EQ(job.status, JobStatus::Queued);
  EXPECT_EQ(job.labels.at("sweep"), "a");
  EXPECT_EQ(store.queue_position(job), 1);
  const auto events = store.events_since(job.id, 0, {}, 10);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, "status");
  EXPECT_EQ(events[0].seq, 1);
}

TEST_F(JobStoreTest, ClaimedJobHasNoQueuePositionEvenFromAStaleRecord) {
  const JobRecord first = store.insert_job(new_job("a")).second;
  const JobRecord second = store.insert_job(new_job("b")).second;
  EXPECT_EQ(store.queue_position(second), 2);
  ASSERT_TRUE(store.claim_next());  // a worker takes `first` after its record was read
  EXPECT_EQ(store.queue_position(first), std::nullopt);
  EXPECT_EQ(store.queue_position(second), 1);
}

TEST_F(JobStoreTest, IdempotencyKeyReplaysOrConflicts) {
  const auto first = store.insert_job(new_job("a", "key-1", "fp"));
  const auto again = store.insert_job(new_job("a", "key-1", "fp"));
  EXPECT_EQ(again.first, InsertResult::Replayed);
  EXPECT_EQ(again.second.id, first.second.id);
  const auto other = store.insert_job(new_job("b", "key-1", "other"));
  EXPECT_EQ(other.first, InsertResult::KeyConflict);
  EXPECT_EQ(store.list_jobs({}).jobs.size(), 1u);
}

TEST_F(JobStoreTest, ClaimTakesTheOldestAndCountsTheAttempt) {
  const auto a = store.insert_job(new_job("a")).second;
  store.insert_job(new_job("b"));
  const auto claimed = store.claim_next();
  ASSERT_TRUE(claimed);
  EXPECT_EQ(claimed->id, a.id);
  EXPECT_EQ(claimed->status, JobStatus::Running);
  EXPECT_EQ(claimed->attempts, 1);
  EXPECT_TRUE(claimed->started_ms);
  ASSERT_TRUE(store.claim_next());
  EXPECT_FALSE(store.claim_next());
}

TEST_F(JobStoreTest, CancelQueuedEndsItCancelRunningAsksTheSolver) {
  const auto queued = store.insert_job(new_job("q")).second;
  const auto running = store.insert_job(new_job("r")).second;
  ASSERT_EQ(store.claim_next()->id, queued.id);  // claim q, then cancel the still-queued r
  EXPECT_EQ(store.request_cancel(running.id)->status, JobStatus::Canceled);
  EXPECT_EQ(store.request_cancel(queued.id)->status, JobStatus::Canceling);
  EXPECT_EQ(store.request_cancel(queued.id)->status, JobStatus::Canceling);  // idempotent
  // However the run ends, a granted cancel ends canceled.
  EXPECT_TRUE(store.finish_job(queued.id, JobStatus::Succeeded, "", "", std::nullopt, {}));
  EXPECT_EQ(store.find_job(queued.id)->status, JobStatus::Canceled);
  EXPECT_FALSE(store.request_cancel("nope"));
}

TEST_F(JobStoreTest, FinishStoresSummaryAndArtifactsOnce) {
  const auto job = store.insert_job(new_job("a")).second;
  store.claim_next();
  JobSummary summary{.iterations = 3, .wall_time = 0.5, .max_displacement = 2.0,
                     .max_mises = 7.0, .max_contact_pressure = std::nullopt,
                     .total_contact_force = std::nullopt};
  ASSERT_TRUE(store.finish_job(job.id, JobStatus::Succeeded, "", "", summary,
                               {{"a.hdf", "application/x-hdf5", 10, std::string(64, 'a')}}));
  const auto done = store.find_job(job.id);
  EXPECT_EQ(done->status, JobStatus::Succeeded);
  EXPECT_EQ(done->summary->iterations, 3);
  EXPECT_EQ(*done->summary->max_mises, 7.0);
  EXPECT_FALSE(done->summary->max_contact_pressure);
  EXPECT_TRUE(done->finished_ms);
  EXPECT_EQ(store.artifacts(job.id).size(), 1u);
  // A finished job cannot finish again.
  EXPECT_FALSE(store.finish_job(job.id, JobStatus::Failed, "x", "", std::nullopt, {}));
  EXPECT_EQ(store.counts().finished.at("succeeded"), 1);
  EXPECT_EQ(store.run_durations().size(), 1u);
}

TEST_F(JobStoreTest, RecoveryRequeuesThenFailsAfterMaxAttempts) {
  const auto job = store.insert_job(new_job("a")).second;
  for (int attempt = 1; attempt <= 2; ++attempt) {
    ASSERT_EQ(store.claim_next()->attempts, attempt);
    const RecoveryReport r = store.recover(2);
    if (attempt < 2) {
      EXPECT_EQ(r.requeued, 1);
      EXPECT_EQ(store.find_job(job.id)->status, JobStatus::Queued);
    } else {
      EXPECT_EQ(r.failed, 1);
      const auto failed = store.find_job(job.id);
      EXPECT_EQ(failed->status, JobStatus::Failed);
      EXPECT_EQ(failed->reason, "worker_lost");
    }
  }
}

TEST_F(JobStoreTest, RecoveryEndsCancelingJobsCanceled) {
  const auto job = store.insert_job(new_job("a")).second;
  store.claim_next();
  store.request_cancel(job.id);
  EXPECT_EQ(store.recover(3).canceled, 1);
  EXPECT_EQ(store.find_job(job.id)->status, JobStatus::Canceled);
}

TEST_F(JobStoreTest, DrainRequeueDoesNotCountTheAttempt) {
  const auto job = store.insert_job(new_job("a")).second;
  store.claim_next();
  ASSERT_TRUE(store.requeue(job.id));
  EXPECT_EQ(store.find_job(job.id)->attempts, 0);
  EXPECT_FALSE(store.requeue(job.id));  // queued -> queued is no transition
}

TEST_F(JobStoreTest, ListPagesNewestFirstWithFilters) {
  std::vector<std::string> ids;
  for (int i = 0; i < 5; ++i) ids.push_back(store.insert_job(new_job("j" + std::to_string(i))).second.id);
  JobQuery query;
  query.limit = 2;
  std::vector<std::string> seen;
  for (int page = 0; page < 5; ++page) {
    const JobPage p = store.list_jobs(query);
    for (const auto& j : p.jobs) seen.push_back(j.id);
    if (!p.more) break;
    query.after = std::pair{p.jobs.back().created_ms, p.jobs.back().id};
  }
  ASSERT_EQ(seen.size(), 5u);
  for (const auto& id : ids) EXPECT_NE(std::find(seen.begin(), seen.end(), id), seen.end());
  JobQuery running;
  running.statuses = {JobStatus::Running};
  EXPECT_TRUE(store.list_jobs(running).jobs.empty());
  JobQuery labelled;
  labelled.labels = {{"sweep", "a"}};
  EXPECT_EQ(store.list_jobs(labelled).jobs.size(), 5u);
  labelled.labels = {{"sweep", "b"}};
  EXPECT_TRUE(store.list_jobs(labelled).jobs.empty());
}

TEST_F(JobStoreTest, LabelKeysFindSweeps) {
  NewJob a = new_job("a"), b = new_job("b"), c = new_job("c");
  a.labels = {{"load", "1"}, {"mesh", "fine"}};
  b.labels = {{"load", "2"}};
  c.labels = {};
  for (const NewJob& j : {a, b, c}) store.insert_job(j);
  JobQuery with_load;
  with_load.label_keys = {"load"};
  const JobPage page = store.list_jobs(with_load);
  ASSERT_EQ(page.jobs.size(), 2u);
  EXPECT_EQ(page.jobs[0].id, b.id);  // newest first
  EXPECT_EQ(page.jobs[1].id, a.id);
  with_load.label_keys = {"load", "mesh"};
  ASSERT_EQ(store.list_jobs(with_load).jobs.size(), 1u);
  with_load.label_keys = {"lo"};  // a key, not a prefix
  EXPECT_TRUE(store.list_jobs(with_load).jobs.empty());
  const auto keys = store.label_keys();
  ASSERT_EQ(keys.size(), 2u);
  EXPECT_EQ(keys[0].key, "load");  // its newest job is newer than mesh's
  EXPECT_EQ(keys[0].jobs, 2);
  EXPECT_EQ(keys[0].latest_ms, store.find_job(b.id)->created_ms);
  EXPECT_EQ(keys[1].key, "mesh");
  EXPECT_EQ(keys[1].jobs, 1);
}

TEST_F(JobStoreTest, EventsCarrySequenceRunAndProgress) {
  const auto job = store.insert_job(new_job("a")).second;
  store.claim_next();
  JobProgress p;
  p.step = 1;
  p.increment = 2;
  p.total_time = 0.5;
  p.residual = 0.1;
  const auto before = store.generation();
  const auto seq = store.append_event(job.id, "increment", R"({"event":"increment"})", p);
  EXPECT_GT(store.generation(), before);
  const auto events = store.events_since(job.id, seq - 1, {"increment"}, 10);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].run, 1);
  const auto now = store.find_job(job.id);
  EXPECT_EQ(now->progress.increment, 2);
  EXPECT_EQ(*now->progress.residual, 0.1);
  EXPECT_TRUE(store.events_since(job.id, seq, {}, 10).empty());
}

TEST_F(JobStoreTest, DeleteOnlyFinishedJobs) {
  const auto job = store.insert_job(new_job("a")).second;
  EXPECT_EQ(store.delete_job(job.id), JobStore::DeleteResult::NotFinished);
  store.request_cancel(job.id);
  EXPECT_EQ(store.delete_job(job.id), JobStore::DeleteResult::Deleted);
  EXPECT_EQ(store.delete_job(job.id), JobStore::DeleteResult::NotFound);
  EXPECT_TRUE(store.events_since(job.id, 0, {}, 10).empty());  // cascaded
}

TEST_F(JobStoreTest, SchemaVersionIsRecordedAndReopenKeepsJobs) {
  const auto id = store.insert_job(new_job("a")).second.id;
  JobStore reopened(dir.path() / "jobs.db");
  EXPECT_TRUE(reopened.find_job(id));
  SqliteDb db(dir.path() / "jobs.db");
  Statement st(db, "PRAGMA user_version");
  ASSERT_TRUE(st.step());
  EXPECT_EQ(st.integer(0), schema_version());
}

TEST(JobStoreSchema, RefusesADatabaseFromANewerBuild) {
  testing::TempDir dir;
  {
    SqliteDb db(dir.path() / "new.db");
    db.exec("PRAGMA user_version = 99");
  }
  EXPECT_THROW(JobStore(dir.path() / "new.db"), StoreError);
}

TEST_F(JobStoreTest, AChangeWakesItsWaitersOnceAndOnlyThoseStillThere) {
  const auto owner = std::make_shared<int>(0);
  auto gone = std::make_shared<int>(0);
  int woken = 0, woken_gone = 0, woken_late = 0;
  store.on_next_change(store.generation(), owner, [&] { ++woken; });
  store.on_next_change(store.generation(), std::weak_ptr<int>(gone), [&] { ++woken_gone; });
  const std::uint64_t seen = store.generation();
  EXPECT_EQ(woken, 0);
  gone.reset();  // its stream closed before the change
  store.insert_job(new_job("a"));
  EXPECT_EQ(woken, 1);
  EXPECT_EQ(woken_gone, 0);
  store.insert_job(new_job("b"));
  EXPECT_EQ(woken, 1);  // once: a stream waits again after it has read
  // A waiter that saw an older generation missed a change already: woken at once.
  store.on_next_change(seen, owner, [&] { ++woken_late; });
  EXPECT_EQ(woken_late, 1);
}

}  // namespace kontakt::server

namespace kontakt::server {

TEST_F(JobStoreTest, ResourcesAreKeptWithTheJob) {
  NewJob job = new_job("r");
  job.resources = {.partition = "debug", .cpus = 4, .memory = "2G", .time = "10"};
  store.insert_job(job);
  const auto found = store.find_job(job.id);
  ASSERT_TRUE(found);
  EXPECT_EQ(to_json(found->resources), to_json(job.resources));
  const auto plain = store.insert_job(new_job("p")).second;
  EXPECT_EQ(to_json(plain.resources), nlohmann::json::object());
}

/// A daemon that adopts a run after a restart skips the events the store has of that run:
/// only the current run's solver events count, not its status changes or an earlier run's.
TEST_F(JobStoreTest, CountsTheCurrentRunsSolverEvents) {
  const auto job = store.insert_job(new_job("c")).second;
  store.claim_next();
  store.append_event(job.id, "iteration", "{}", std::nullopt);
  store.append_event(job.id, "iteration", "{}", std::nullopt);
  EXPECT_EQ(store.count_run_events(job.id), 2);
  store.retry(job.id, "killed");
  store.claim_next();
  EXPECT_EQ(store.count_run_events(job.id), 0);
  store.append_event(job.id, "step", "{}", std::nullopt);
  EXPECT_EQ(store.count_run_events(job.id), 1);
}

}  // namespace kontakt::server

namespace kontakt::server {

namespace {

SweepRecord new_sweep(int max_parallel, std::optional<std::string> key = std::nullopt,
                      const std::string& fingerprint = "s") {
  SweepRecord sweep;
  sweep.id = new_job_id();
  sweep.name = "study";
  sweep.max_parallel = max_parallel;
  sweep.idempotency_key = std::move(key);
  sweep.fingerprint = fingerprint;
  return sweep;
}

}  // namespace

TEST_F(JobStoreTest, SweepRowsAreJobsInRowOrder) {
  const auto [result, sweep] =
      store.insert_sweep(new_sweep(2), {new_job("r0"), new_job("r1"), new_job("r2")});
  EXPECT_EQ(result, InsertResult::Created);
  EXPECT_EQ(sweep.n_rows, 3);
  EXPECT_EQ(sweep.max_parallel, 2);
  const auto jobs = store.sweep_jobs(sweep.id);
  ASSERT_EQ(jobs.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(jobs[i].sweep_row, i);
    EXPECT_EQ(jobs[i].sweep_id, sweep.id);
    EXPECT_EQ(jobs[i].name, "r" + std::to_string(i));
  }
  EXPECT_EQ(store.sweep_counts(sweep.id), (std::map<std::string, int>{{"queued", 3}}));
  EXPECT_EQ(store.find_sweep(sweep.id)->name, "study");
  EXPECT_FALSE(store.find_sweep("nope"));
}

TEST_F(JobStoreTest, ClaimsKeepASweepWithinItsMaxParallelAndPassItForOthers) {
  const auto sweep = store.insert_sweep(new_sweep(2), {new_job("r0"), new_job("r1"), new_job("r2")}).second;
  const auto other = store.insert_job(new_job("other")).second;
  const auto first = store.claim_next(), second = store.claim_next();
  EXPECT_EQ(first->sweep_row, 0);
  EXPECT_EQ(second->sweep_row, 1);
  // Two rows run: the third waits, the job queued after the sweep goes ahead of it.
  EXPECT_EQ(store.claim_next()->id, other.id);
  EXPECT_FALSE(store.claim_next());
  // A canceling row still counts; a finished one frees its place.
  store.request_cancel(first->id);
  EXPECT_FALSE(store.claim_next());
  store.finish_job(first->id, JobStatus::Canceled, "", "", std::nullopt, {});
  const auto third = store.claim_next();
  ASSERT_TRUE(third);
  EXPECT_EQ(third->sweep_row, 2);
  EXPECT_EQ(store.sweep_counts(sweep.id),
            (std::map<std::string, int>{{"canceled", 1}, {"running", 2}}));
}

TEST_F(JobStoreTest, SweepIdempotencyKeyReplaysOrConflicts) {
  const auto created = store.insert_sweep(new_sweep(1, "k", "f1"), {new_job("a")}).second;
  const auto [replayed, same] = store.insert_sweep(new_sweep(1, "k", "f1"), {new_job("b")});
  EXPECT_EQ(replayed, InsertResult::Replayed);
  EXPECT_EQ(same.id, created.id);
  EXPECT_EQ(store.insert_sweep(new_sweep(1, "k", "f2"), {new_job("c")}).first,
            InsertResult::KeyConflict);
  EXPECT_EQ(store.sweep_jobs(created.id).size(), 1u);
  EXPECT_EQ(store.find_sweep_by_key("k")->id, created.id);
}

}  // namespace kontakt::server
