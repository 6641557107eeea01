// The Slurm executor's pure parts and its file tailing, without a Slurm: job resources and
// their checks, the batch script (run by sh here), sbatch's command line and answer, what
// squeue, scontrol and the jobcomp log say, the verdict on a job without an outcome, the
// --executor and --slurm-* settings, and an execution that reads events and outcome files.
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <fstream>
#include <sstream>

#include "server/command.hpp"
#include "server/job_outcome.hpp"
#include "server/settings.hpp"
#include "server/slurm_execution.hpp"
#include "server/slurm_protocol.hpp"
#include "server_test_util.hpp"

namespace kontakt::server {
namespace {

using testing::TempDir;

bool has(const std::vector<std::string>& argv, const std::string& arg) {
  return std::find(argv.begin(), argv.end(), arg) != argv.end();
}

TEST(JobResources, ChecksTakeSlurmsSpellings) {
  EXPECT_FALSE(check_partition("debug"));
  EXPECT_TRUE(check_partition(""));
  EXPECT_TRUE(check_partition("a b"));
  EXPECT_TRUE(check_partition("x;rm"));
  EXPECT_FALSE(check_cpus(1));
  EXPECT_TRUE(check_cpus(0));
  EXPECT_TRUE(check_cpus(1025));
  for (const char* ok : {"2000", "500M", "4G", "1t"}) EXPECT_FALSE(check_memory(ok)) << ok;
  for (const char* bad : {"", "G", "4GB", "-1", "0", "1.5G", "9999999999"})
    EXPECT_TRUE(check_memory(bad)) << bad;
  EXPECT_EQ(time_seconds("30"), 1800);
  EXPECT_EQ(time_seconds("1:30"), 90);
  EXPECT_EQ(time_seconds("1:00:00"), 3600);
  EXPECT_EQ(time_seconds("2-0"), 2 * 86400);
  EXPECT_EQ(time_seconds("1-2:03"), 86400 + 2 * 3600 + 180);
  EXPECT_EQ(time_seconds("1-2:03:04"), 86400 + 2 * 3600 + 184);
  for (const char* bad : {"", "0", "1:2:3:4", "a", "1-", "-1", "1:x", "UNLIMITED"})
    EXPECT_FALSE(time_seconds(bad)) << bad;
}

TEST(JobResources, ReadNamesTheBadMember) {
  JobResources r;
  EXPECT_FALSE(read_resources(nlohmann::json{{"partition", "p"}, {"cpus", 4}, {"memory", "4G"},
                                             {"time", "10"}},
                              r));
  EXPECT_EQ(to_json(r), (nlohmann::json{{"partition", "p"}, {"cpus", 4}, {"memory", "4G"},
                                        {"time", "10"}}));
  const auto field_of = [](const nlohmann::json& j) {
    JobResources x;
    const auto bad = read_resources(j, x);
    return bad ? bad->field : std::string("none");
  };
  EXPECT_EQ(field_of({{"cpus", 0}}), "resources.cpus");
  EXPECT_EQ(field_of({{"cpus", "2"}}), "resources.cpus");
  EXPECT_EQ(field_of({{"memory", 4}}), "resources.memory");
  EXPECT_EQ(field_of({{"time", "forever"}}), "resources.time");
  EXPECT_EQ(field_of({{"gpus", 1}}), "resources.gpus");
  EXPECT_EQ(field_of(nlohmann::json::array()), "resources");
  EXPECT_EQ(field_of({{"cpus", nullptr}}), "none");
}

TEST(JobResources, OverridesWinOverDefaults) {
  const JobResources r = merged({.partition = "batch", .cpus = 2, .memory = "1G", .time = "5"},
                                {.partition = std::nullopt, .cpus = 8, .memory = std::nullopt,
                                 .time = "60"});
  EXPECT_EQ(r.partition, "batch");
  EXPECT_EQ(r.cpus, 8);
  EXPECT_EQ(r.memory, "1G");
  EXPECT_EQ(r.time, "60");
}

TEST(SlurmProtocol, SbatchLineCarriesEverything) {
  const slurm::RunFiles files{"/data/jobs/abc/slurm"};
  const auto argv = slurm::sbatch_argv("0123456789abcdef", files, "/data/jobs/abc/work",
                                       {.partition = "debug", .cpus = 4, .memory = "2G",
                                        .time = "1:00:00"},
                                       90);
  EXPECT_EQ(argv.front(), "sbatch");
  EXPECT_EQ(argv.back(), "/data/jobs/abc/slurm/run.sh");
  for (const char* arg : {"--parsable", "--job-name=kontakt-0123456789ab",
                          "--chdir=/data/jobs/abc/work",
                          "--output=/data/jobs/abc/slurm/slurm-%j.out", "--signal=B:TERM@90",
                          "--comment=0123456789abcdef", "--partition=debug", "--cpus-per-task=4",
                          "--mem=2G", "--time=1:00:00"})
    EXPECT_TRUE(has(argv, arg)) << arg;
  const auto plain = slurm::sbatch_argv("id", files, "/w", {}, 60);
  EXPECT_TRUE(has(plain, "--cpus-per-task=1"));
  EXPECT_FALSE(std::any_of(plain.begin(), plain.end(), [](const std::string& a) {
    return a.rfind("--mem", 0) == 0 || a.rfind("--time", 0) == 0 || a.rfind("--partition", 0) == 0;
  }));
}

TEST(SlurmProtocol, SbatchAnswer) {
  EXPECT_EQ(slurm::parse_sbatch_id("123\n"), "123");
  EXPECT_EQ(slurm::parse_sbatch_id("77;cluster\n"), "77");
  EXPECT_FALSE(slurm::parse_sbatch_id(""));
  EXPECT_FALSE(slurm::parse_sbatch_id("Submitted batch job 5\n"));
}

/// The batch script, run by sh with a stand-in for kontaktd: it execs the program with every
/// argument intact (a quote in a path too) and its descriptor 3 appended to the events file.
TEST(SlurmProtocol, BatchScriptExecsTheWorkerWithItsReportInTheEventsFile) {
  TempDir dir;
  const std::filesystem::path odd = dir.path() / "it's here";
  std::filesystem::create_directories(odd);
  const std::filesystem::path exe = odd / "fake kontaktd";
  {
    std::ofstream f(exe);
    f << "#!/bin/sh\necho \"$OPENBLAS_NUM_THREADS $*\" >&3\n";
  }
  std::filesystem::permissions(exe, std::filesystem::perms::owner_all);
  const slurm::RunFiles files{odd};
  {
    std::ofstream(files.events()) << "{\"earlier\":1}\n";
  }
  const worker::Args args{.mode = worker::Mode::Run, .deck = odd / "deck.inp",
                          .out_dir = odd / "work", .job_name = "deck", .threads = 3,
                          .outcome_file = files.outcome()};
  {
    std::ofstream(files.script()) << slurm::batch_script(exe, args, files, "jobid");
  }
  const CommandResult r = run_command({"sh", files.script().string()}, std::chrono::seconds(10));
  ASSERT_TRUE(r.ok()) << r.err;
  std::ifstream in(files.events());
  std::string first, second;
  std::getline(in, first);
  std::getline(in, second);
  EXPECT_EQ(first, "{\"earlier\":1}");
  EXPECT_EQ(second, "3 job-worker run --deck " + (odd / "deck.inp").string() +
                        " --parent 0 --out " + (odd / "work").string() +
                        " --name deck --threads 3 --outcome " + files.outcome().string());
}

TEST(SlurmProtocol, QueueAndRecords) {
  const auto jobs = slurm::parse_squeue(
      "12|RUNNING|None|aaaa\n13|PENDING|Resources|bbbb\n14|FAILED|NonZeroExitCode|(null)\nbad\n");
  ASSERT_EQ(jobs.size(), 3u);
  EXPECT_EQ(jobs.at("12").state, "RUNNING");
  EXPECT_EQ(jobs.at("13").reason, "Resources");
  EXPECT_EQ(jobs.at("12").comment, "aaaa");
  const auto shown = slurm::parse_scontrol_job(
      "JobId=14 JobName=x\n   JobState=FAILED Reason=NonZeroExitCode Dependency=(null)\n"
      "   Requeue=1 Restarts=0 BatchFlag=1 Reboot=0 ExitCode=0:9\n");
  ASSERT_TRUE(shown);
  EXPECT_EQ(shown->state, "FAILED");
  EXPECT_EQ(shown->reason, "NonZeroExitCode");
  ASSERT_TRUE(shown->exit);
  EXPECT_TRUE(shown->exit->signaled);
  EXPECT_EQ(shown->exit->code, 9);
  EXPECT_FALSE(slurm::parse_scontrol_job("slurm_load_jobs error: Invalid job id specified\n"));
  const std::string log =
      "JobId=3 UserId=root(0) JobState=COMPLETED Partition=debug ExitCode=0:0 \n"
      "JobId=31 UserId=root(0) JobState=TIMEOUT ExitCode=0:15 \n"
      "JobId=3 UserId=root(0) JobState=NODE_FAIL Partition=debug ExitCode=0:0 \n";
  EXPECT_EQ(slurm::find_in_jobcomp(log, "3")->state, "NODE_FAIL");  // the last record
  EXPECT_EQ(slurm::find_in_jobcomp(log, "31")->state, "TIMEOUT");
  EXPECT_FALSE(slurm::find_in_jobcomp(log, "4"));
  EXPECT_EQ(slurm::jobcomp_file("JobCompLoc              = /var/log/comp.txt\n"
                                "JobCompType             = jobcomp/filetxt\n"),
            "/var/log/comp.txt");
  EXPECT_FALSE(slurm::jobcomp_file("JobCompLoc = /x\nJobCompType = jobcomp/none\n"));
  EXPECT_TRUE(slurm::is_finished("TIMEOUT"));
  EXPECT_FALSE(slurm::is_finished("COMPLETING"));
  EXPECT_FALSE(slurm::is_finished("PENDING"));
}

TEST(SlurmProtocol, ArraySbatchLineAndSpec) {
  EXPECT_EQ(slurm::array_spec({0, 1, 2, 3}, 2), "0-3%2");
  EXPECT_EQ(slurm::array_spec({0, 1, 3, 5, 6, 7}, 4), "0-1,3,5-7%4");
  EXPECT_EQ(slurm::array_spec({7}, 1), "7%1");
  const slurm::RunFiles files{"/data/sweeps/S/slurm"};
  const auto argv = slurm::sbatch_array_argv("0123456789abcdef", files, {0, 1, 2, 4}, 3,
                                             {.partition = "debug", .cpus = 2, .memory = "1G",
                                              .time = "10"},
                                             60);
  EXPECT_EQ(argv[0], "sbatch");
  EXPECT_TRUE(has(argv, "--parsable"));
  EXPECT_TRUE(has(argv, "--array=0-2,4%3"));
  EXPECT_TRUE(has(argv, "--job-name=kontakt-sweep-0123456789ab"));
  EXPECT_TRUE(has(argv, "--comment=0123456789abcdef"));
  EXPECT_TRUE(has(argv, "--output=/data/sweeps/S/slurm/slurm-%A_%a.out"));
  EXPECT_TRUE(has(argv, "--chdir=/data/sweeps/S/slurm"));
  EXPECT_TRUE(has(argv, "--signal=B:TERM@60"));
  EXPECT_TRUE(has(argv, "--no-requeue"));
  EXPECT_TRUE(has(argv, "--partition=debug"));
  EXPECT_TRUE(has(argv, "--cpus-per-task=2"));
  EXPECT_TRUE(has(argv, "--mem=1G"));
  EXPECT_TRUE(has(argv, "--time=10"));
  EXPECT_EQ(argv.back(), files.script().string());
  EXPECT_EQ(slurm::array_task_id("77", 12), "77_12");
}

TEST(SlurmProtocol, ArrayScriptRunsTheTasksRowWithItsOutputThere) {
  TempDir dir;
  std::map<std::size_t, std::filesystem::path> rows;
  for (std::size_t i : {0u, 2u}) {
    rows[i] = dir.path() / ("row '" + std::to_string(i) + "'") / "slurm";
    std::filesystem::create_directories(rows[i]);
    std::ofstream(rows[i] / "run.sh") << "#!/bin/sh\necho row " << i << " ran\necho oops >&2\n";
    std::filesystem::permissions(rows[i] / "run.sh", std::filesystem::perms::owner_all);
  }
  const std::filesystem::path script = dir.path() / "array.sh";
  std::ofstream(script) << slurm::array_script("S", rows);
  const auto task = [&](const std::string& id) {
    return run_command({"env", "SLURM_ARRAY_JOB_ID=41", "SLURM_ARRAY_TASK_ID=" + id, "sh",
                        script.string()},
                       std::chrono::seconds(10));
  };
  ASSERT_TRUE(task("2").ok());
  std::ifstream out(rows[2] / "slurm-41_2.out");
  std::stringstream text;
  text << out.rdbuf();
  EXPECT_EQ(text.str(), "row 2 ran\noops\n");
  EXPECT_FALSE(std::filesystem::exists(rows[0] / "slurm-41_0.out"));
  const CommandResult missing = task("1");  // a row left out of the array
  EXPECT_EQ(missing.exit.code, 2);
  EXPECT_NE(missing.err.find("kontaktd sweep S has no row 1"), std::string::npos);
}

TEST(SlurmProtocol, ArrayTasksInSqueueAndJobcomp) {
  // Without --array squeue lists an array's pending tasks as one line.
  const auto jobs = slurm::parse_squeue(
      "50_0|RUNNING|None|S\n50_[2-4,7%2]|PENDING|JobArrayTaskLimit|S\n50_1|COMPLETED|None|S\n"
      "51_[x-y]|PENDING|None|T\n");
  EXPECT_EQ(jobs.at("50_0").state, "RUNNING");
  EXPECT_EQ(jobs.at("50_1").state, "COMPLETED");
  for (const char* pending : {"50_2", "50_3", "50_4", "50_7"}) {
    ASSERT_TRUE(jobs.contains(pending)) << pending;
    EXPECT_EQ(jobs.at(pending).reason, "JobArrayTaskLimit");
    EXPECT_EQ(jobs.at(pending).comment, "S");
  }
  EXPECT_FALSE(jobs.contains("50_5"));
  EXPECT_TRUE(jobs.contains("51_[x-y]"));  // not understood: kept as it is
  const std::string log =
      "JobId=60 UserId=root(0) JobState=COMPLETED Partition=debug ArrayJobId=58 "
      "ArrayTaskId=1 ExitCode=0:0\n"
      "JobId=61 UserId=root(0) JobState=FAILED Partition=debug ArrayJobId=58 "
      "ArrayTaskId=2 ExitCode=3:0\n"
      "JobId=58 UserId=root(0) JobState=CANCELLED Partition=debug ArrayJobId=58 "
      "ArrayTaskId=0 ExitCode=0:15\n";
  EXPECT_EQ(slurm::find_in_jobcomp(log, "58_2")->state, "FAILED");
  EXPECT_EQ(slurm::find_in_jobcomp(log, "58_2")->exit->code, 3);
  EXPECT_EQ(slurm::find_in_jobcomp(log, "58_0")->state, "CANCELLED");
  EXPECT_EQ(slurm::find_in_jobcomp(log, "60")->state, "COMPLETED");
  EXPECT_FALSE(slurm::find_in_jobcomp(log, "58_3"));
  const auto shown = slurm::parse_scontrol_job(
      "JobId=61 ArrayJobId=58 ArrayTaskId=2 JobName=kontakt-sweep-x\n   JobState=PENDING "
      "Reason=JobArrayTaskLimit Dependency=(null)\n");
  EXPECT_EQ(shown->state, "PENDING");
}

TEST(SlurmProtocol, VerdictWithoutAnOutcome) {
  const auto of = [](slurm::JobState s) { return slurm::failure_from("7", s, "tail text"); };
  EXPECT_EQ(of({.state = "TIMEOUT", .reason = "TimeLimit"}).reason, "time_limit");
  EXPECT_EQ(of({.state = "OUT_OF_MEMORY"}).reason, "memory_limit");
  EXPECT_EQ(of({.state = "NODE_FAIL"}).reason, "worker_lost");
  EXPECT_EQ(of({.state = "FAILED", .exit = ExitStatus{.signaled = false, .code = 127}}).reason,
            "worker_lost");  // e.g. the program missing on the node: its output says so
  const ExecutorFailure crashed =
      of({.state = "FAILED", .reason = "NonZeroExitCode",
          .exit = ExitStatus{.signaled = true, .code = SIGSEGV}});
  EXPECT_EQ(crashed.reason, "solver_crashed");
  EXPECT_NE(crashed.message.find("Slurm job 7 ended FAILED (NonZeroExitCode) with signal 11"),
            std::string::npos)
      << crashed.message;
  EXPECT_NE(crashed.message.find("tail text"), std::string::npos);
}

TEST(Outcome, FileRoundTripAndWorkerArgument) {
  EXPECT_EQ(worker::parse_outcome(worker::outcome_text(worker::Exit::NotConverged)), 3);
  EXPECT_FALSE(worker::parse_outcome("{\"exit_co"));
  EXPECT_FALSE(worker::parse_outcome("{\"exit_code\":\"3\"}"));
  const worker::Args args{.mode = worker::Mode::Run, .deck = "d.inp", .out_dir = "w",
                          .job_name = "d", .outcome_file = "/x/outcome.json"};
  const auto parsed = worker::parse_args(worker::to_argv(args));
  ASSERT_TRUE(std::holds_alternative<worker::Args>(parsed));
  EXPECT_EQ(std::get<worker::Args>(parsed).outcome_file, "/x/outcome.json");
}

TEST(Outcome, ExecutorFailureIsTheVerdictUnlessTheDaemonStoppedTheRun) {
  ProcessEnd end;
  end.failure = ExecutorFailure{.reason = "worker_lost", .message = "Slurm job 3 ended NODE_FAIL"};
  const OutcomeContext context{};
  JobVerdict v = judge(end, context);
  EXPECT_EQ(v.status, JobStatus::Failed);
  EXPECT_EQ(v.reason, "worker_lost");
  EXPECT_EQ(v.message, "Slurm job 3 ended NODE_FAIL");
  end.cause = StopCause::Request;
  v = judge(end, context);
  EXPECT_EQ(v.status, JobStatus::Canceled);
}

TEST(Settings, ExecutorAndSlurmDefaults) {
  const auto no_env = [](const std::string&) -> std::optional<std::string> { return std::nullopt; };
  const auto s = std::get<Settings>(parse_settings(
      {"--executor", "slurm", "--slurm-partition", "batch", "--slurm-cpus", "4", "--slurm-mem",
       "8G", "--slurm-time", "2:00:00"},
      no_env));
  EXPECT_EQ(s.executor, "slurm");
  EXPECT_EQ(s.slurm.partition, "batch");
  EXPECT_EQ(s.slurm.cpus, 4);
  EXPECT_EQ(s.slurm.memory, "8G");
  EXPECT_EQ(s.slurm.time, "2:00:00");
  EXPECT_EQ(std::get<Settings>(parse_settings({}, no_env)).executor, "local");
  for (const std::vector<std::string>& bad :
       {std::vector<std::string>{"--executor", "k8s"}, {"--slurm-cpus", "0"},
        {"--slurm-mem", "lots"}, {"--slurm-time", "0"}, {"--slurm-partition", "a b"},
        {"--executor", "slurm", "--job-time-limit", "60"}}) {
    const auto r = parse_settings(bad, no_env);
    ASSERT_TRUE(std::holds_alternative<std::string>(r)) << bad[0];
    EXPECT_NE(std::get<std::string>(r).find(bad.size() == 4 ? "--job-time-limit" : bad[0]),
              std::string::npos)
        << std::get<std::string>(r);
  }
}

/// An execution whose files are written here by hand: events appended in pieces are relayed
/// whole and in order, the ones a previous daemon stored are skipped, and the outcome file
/// ends it without asking Slurm.
TEST(SlurmExecution, TailsEventsAndEndsWithTheOutcome) {
  TempDir dir;
  const slurm::RunFiles files{dir.path()};
  SlurmQueue queue(std::chrono::hours(1), [] { return std::optional<std::string>(); });
  SlurmExecution execution("5", files, queue,
                           [](const std::string&) { return std::optional<slurm::JobState>(); },
                           std::chrono::milliseconds(0), SlurmExecution::Clock::now(), 1);
  std::vector<std::string> lines;
  const LineHandler collect = [&](std::string_view l) { lines.emplace_back(l); };
  EXPECT_FALSE(execution.poll(std::chrono::milliseconds(0), collect, -1));  // no file yet
  std::ofstream events(files.events());
  events << "old\nfirst\nsec" << std::flush;
  EXPECT_FALSE(execution.poll(std::chrono::milliseconds(0), collect, -1));
  EXPECT_EQ(lines, (std::vector<std::string>{"first"}));
  events << "ond\nthird\n" << std::flush;
  std::ofstream(files.outcome()) << worker::outcome_text(worker::Exit::Converged);
  const auto end = execution.poll(std::chrono::milliseconds(0), collect, -1);
  ASSERT_TRUE(end);
  EXPECT_FALSE(end->signaled);
  EXPECT_EQ(end->code, 0);
  EXPECT_FALSE(execution.failure());
  EXPECT_EQ(lines, (std::vector<std::string>{"first", "second", "third"}));
}

TEST(SlurmExecution, ASigtermFromOutsideIsSlurmsAndSaysSo) {
  TempDir dir;
  const slurm::RunFiles files{dir.path()};
  SlurmQueue queue(std::chrono::hours(1), [] { return std::optional<std::string>(); });
  SlurmExecution execution("9", files, queue,
                           [](const std::string&) { return std::optional<slurm::JobState>(); },
                           std::chrono::milliseconds(0), SlurmExecution::Clock::now(), 0);
  std::ofstream(files.outcome()) << worker::outcome_text(worker::Exit::Cancelled);
  ASSERT_TRUE(execution.poll(std::chrono::milliseconds(0), [](std::string_view) {}, -1));
  ASSERT_TRUE(execution.failure());
  EXPECT_EQ(execution.failure()->reason, "time_limit");
  EXPECT_TRUE(execution.outlives_daemon());
}

/// Without an outcome file, Slurm's word ends the run: squeue's state, then scontrol's record
/// (with the exit signal) and the end of slurm-N.out in the message.
TEST(SlurmExecution, WithoutAnOutcomeSlurmsRecordIsTheFailure) {
  TempDir dir;
  const slurm::RunFiles files{dir.path()};
  std::ofstream(files.output("9")) << "line one\nkontaktd: something went wrong\n";
  SlurmQueue queue(std::chrono::milliseconds(0),
                   [] { return std::optional<std::string>("9|FAILED|NonZeroExitCode|id\n"); });
  SlurmExecution execution(
      "9", files, queue,
      [](const std::string& id) {
        EXPECT_EQ(id, "9");
        return std::optional(slurm::JobState{.state = "FAILED", .reason = "NonZeroExitCode",
                                             .exit = ExitStatus{.signaled = true, .code = 9}});
      },
      std::chrono::milliseconds(0), SlurmExecution::Clock::now(), 0);
  const auto end = execution.poll(std::chrono::milliseconds(0), [](std::string_view) {}, -1);
  ASSERT_TRUE(end);
  ASSERT_TRUE(execution.failure());
  EXPECT_EQ(execution.failure()->reason, "solver_crashed");
  EXPECT_NE(execution.failure()->message.find("Slurm job 9 ended FAILED (NonZeroExitCode) with "
                                              "signal 9 (SIGKILL"),
            std::string::npos)
      << execution.failure()->message;
  EXPECT_NE(execution.failure()->message.find("something went wrong"), std::string::npos);
}

/// squeue may miss a job it should list (it ran while sbatch was answering): when scontrol
/// then says the job is pending or running, the run is watched on, not failed.
TEST(SlurmExecution, AJobSqueueMissedButScontrolKnowsIsWatchedOn) {
  TempDir dir;
  const slurm::RunFiles files{dir.path()};
  SlurmQueue queue(std::chrono::milliseconds(0), [] { return std::optional<std::string>(""); });
  std::string scontrol_says = "PENDING";
  SlurmExecution execution(
      "4", files, queue,
      [&](const std::string&) { return std::optional(slurm::JobState{.state = scontrol_says}); },
      std::chrono::milliseconds(0), SlurmExecution::Clock::now(), 0);
  const LineHandler ignore = [](std::string_view) {};
  EXPECT_FALSE(execution.poll(std::chrono::milliseconds(0), ignore, -1));
  EXPECT_FALSE(execution.poll(std::chrono::milliseconds(0), ignore, -1));
  std::ofstream(files.outcome()) << worker::outcome_text(worker::Exit::NotConverged);
  const auto end = execution.poll(std::chrono::milliseconds(0), ignore, -1);
  ASSERT_TRUE(end);
  EXPECT_EQ(end->code, 3);
  EXPECT_FALSE(execution.failure());
}

/// Slurm forgot the job (past MinJobAge, no jobcomp log) and no outcome came: worker_lost.
TEST(SlurmExecution, AJobSlurmForgotIsLost) {
  TempDir dir;
  SlurmQueue queue(std::chrono::milliseconds(0), [] { return std::optional<std::string>(""); });
  SlurmExecution execution(
      "8", {dir.path()}, queue, [](const std::string&) { return std::optional<slurm::JobState>(); },
      std::chrono::milliseconds(0), SlurmExecution::Clock::now(), 0);
  ASSERT_TRUE(execution.poll(std::chrono::milliseconds(0), [](std::string_view) {}, -1));
  EXPECT_EQ(execution.failure()->reason, "worker_lost");
  EXPECT_NE(execution.failure()->message.find("no longer known to Slurm"), std::string::npos);
}

}  // namespace
}  // namespace kontakt::server
