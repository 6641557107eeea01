// The daemon's small pure pieces: query and range parsing, SSE framing, settings, tokens, zip
// entry names, progress from events, metrics text, times.
#include <gtest/gtest.h>

#include "server/byte_range.hpp"
#include "server/digest.hpp"
#include "server/http_types.hpp"
#include "server/job_json.hpp"
#include "server/metrics.hpp"
#include "server/settings.hpp"
#include "server/sse_format.hpp"
#include "server/store_event_sink.hpp"
#include "server/zip_archive.hpp"
#include "server_test_util.hpp"

namespace kontakt::server {

TEST(Query, DecodesPairsInOrderAndRefusesBadEscapes) {
  const auto q = parse_query("a=1&label=x%3Dy&label=k+v&flag");
  ASSERT_TRUE(q);
  ASSERT_EQ(q->size(), 4u);
  EXPECT_EQ((*q)[1].second, "x=y");
  EXPECT_EQ((*q)[2].second, "k v");
  EXPECT_EQ((*q)[3].first, "flag");
  EXPECT_FALSE(parse_query("a=%4"));
  EXPECT_FALSE(parse_query("a=%zz"));
  EXPECT_EQ(percent_encode("a b/c"), "a%20b%2Fc");
}

TEST(ByteRange, HonoursOneRangeOfEachForm) {
  ByteRange r;
  EXPECT_EQ(parse_byte_range(std::nullopt, 100, r), RangeResult::Whole);
  EXPECT_EQ(parse_byte_range("bytes=10-19", 100, r), RangeResult::Partial);
  EXPECT_EQ(r.offset, 10u);
  EXPECT_EQ(r.length, 10u);
  EXPECT_EQ(parse_byte_range("bytes=90-", 100, r), RangeResult::Partial);
  EXPECT_EQ(r.length, 10u);
  EXPECT_EQ(parse_byte_range("bytes=-5", 100, r), RangeResult::Partial);
  EXPECT_EQ(r.offset, 95u);
  EXPECT_EQ(parse_byte_range("bytes=50-500", 100, r), RangeResult::Partial);
  EXPECT_EQ(r.length, 50u);
  EXPECT_EQ(parse_byte_range("bytes=100-", 100, r), RangeResult::Unsatisfiable);
  EXPECT_EQ(parse_byte_range("bytes=0-1,5-6", 100, r), RangeResult::Whole);
  EXPECT_EQ(parse_byte_range("items=0-1", 100, r), RangeResult::Whole);
  EXPECT_EQ(parse_byte_range("bytes=9-2", 100, r), RangeResult::Whole);
}

TEST(Sse, FramesCarryIdKindAndPosition) {
  const std::string frame = sse_frame({7, 2, "iteration", R"({"event":"iteration","iteration":3})"});
  EXPECT_EQ(frame.rfind("id: 7\nevent: iteration\ndata: {", 0), 0u);
  EXPECT_NE(frame.find("\"seq\":7"), std::string::npos);
  EXPECT_NE(frame.find("\"run\":2"), std::string::npos);
  EXPECT_EQ(frame.substr(frame.size() - 2), "\n\n");
  EXPECT_EQ(std::count(frame.begin(), frame.end(), '\n'), 4);
  EXPECT_EQ(sse_resume_point(std::nullopt, std::nullopt), 0);
  EXPECT_EQ(sse_resume_point("12", "3"), 12);
  EXPECT_EQ(sse_resume_point(std::nullopt, "3"), 3);
  EXPECT_FALSE(sse_resume_point("-1", std::nullopt));
}

TEST(Settings, DefaultsEnvironmentThenFlags) {
  auto no_env = [](const std::string&) -> std::optional<std::string> { return std::nullopt; };
  const auto defaults = std::get<Settings>(parse_settings({}, no_env));
  EXPECT_EQ(defaults.port, 8080);
  EXPECT_EQ(defaults.bind, "127.0.0.1");
  auto env = [](const std::string& name) -> std::optional<std::string> {
    if (name == "KONTAKTD_WORKERS") return "3";
    if (name == "KONTAKTD_MAX_BODY") return "2M";
    return std::nullopt;
  };
  const auto s = std::get<Settings>(parse_settings({"--workers", "5", "--port=0"}, env));
  EXPECT_EQ(s.workers, 5);
  EXPECT_EQ(s.max_body, 2u << 20);
  EXPECT_EQ(s.port, 0);
  EXPECT_NE(std::get<std::string>(parse_settings({"--workers", "0"}, no_env)).find("--workers"), std::string::npos);
  EXPECT_NE(std::get<std::string>(parse_settings({"--frobnicate"}, no_env)).find("unknown"), std::string::npos);
  EXPECT_NE(std::get<std::string>(parse_settings({"--port"}, no_env)).find("needs a value"), std::string::npos);
  auto bad_env = [](const std::string& name) -> std::optional<std::string> {
    return name == "KONTAKTD_PORT" ? std::optional<std::string>("http") : std::nullopt;
  };
  EXPECT_NE(std::get<std::string>(parse_settings({}, bad_env)).find("KONTAKTD_PORT"), std::string::npos);
  EXPECT_EQ(std::get<std::string>(parse_settings({"--help"}, no_env)), "help");
  EXPECT_NE(settings_usage().find("KONTAKTD_TOKEN_FILE"), std::string::npos);
}

TEST(Settings, JobLimits) {
  auto no_env = [](const std::string&) -> std::optional<std::string> { return std::nullopt; };
  const auto defaults = std::get<Settings>(parse_settings({}, no_env));
  EXPECT_EQ(defaults.job_memory_limit, 0u);
  EXPECT_EQ(defaults.job_file_size_limit, 0u);
  EXPECT_EQ(defaults.kill_grace, 2.0);
  const auto s = std::get<Settings>(parse_settings(
      {"--job-memory-limit", "8G", "--job-file-size-limit=10M", "--kill-grace", "0.5"}, no_env));
  EXPECT_EQ(s.job_memory_limit, 8ull << 30);
  EXPECT_EQ(s.job_file_size_limit, 10ull << 20);
  EXPECT_EQ(s.kill_grace, 0.5);
  EXPECT_EQ(std::get<Settings>(parse_settings({"--job-memory-limit", "0"}, no_env)).job_memory_limit, 0u);
  // A limit the worker could not even start under, or nonsense, is refused with its name.
  for (const char* bad : {"1K", "63M", "-1", "lots", "2P"})
    EXPECT_NE(std::get<std::string>(parse_settings({"--job-memory-limit", bad}, no_env))
                  .find("--job-memory-limit"),
              std::string::npos)
        << bad;
  EXPECT_TRUE(std::holds_alternative<std::string>(parse_settings({"--kill-grace", "-1"}, no_env)));
  EXPECT_TRUE(std::holds_alternative<std::string>(parse_settings({"--max-body", "0"}, no_env)));
}

TEST(Settings, TokenFileSkipsBlanksAndComments) {
  EXPECT_EQ(parse_token_file("# team tokens\nabc\n\n  def  \r\n"), (std::vector<std::string>{"abc", "def"}));
}

TEST(ZipNames, OnlyPlainRelativePaths) {
  for (const char* ok : {"a.inp", "mesh/part1.inp", "x-y_z.inp"}) EXPECT_TRUE(is_safe_relative_path(ok)) << ok;
  for (const char* bad : {"", "/abs.inp", "../up.inp", "a/../../b", "a//b", "./a", "a\\b", "c:x", "a/\n"})
    EXPECT_FALSE(is_safe_relative_path(bad)) << bad;
}

TEST(ZipArchive, RefusesBombsBeyondTheCap) {
  testing::TempDir dir;
  const std::string zip = testing::make_zip({{"big.inp", std::string(10000, 'x')}}, dir.path());
  EXPECT_NO_THROW(read_zip(zip, 10000));
  EXPECT_THROW(read_zip(zip, 9999), ZipError);
}

TEST(Progress, FollowsStepIncrementAndIterationEvents) {
  using analysis::Event;
  JobProgress p;
  p = advance_progress(p, {.kind = Event::Kind::Step, .step = 2});
  EXPECT_EQ(p.step, 2);
  Event it;
  it.kind = Event::Kind::Iteration;
  it.step = 2;
  it.increment = 3;
  it.iteration = 4;
  it.total_time = 1.5;
  it.residual = 0.02;
  it.contact_elements = 17;
  p = advance_progress(p, it);
  EXPECT_EQ(p.iteration, 4);
  EXPECT_EQ(*p.residual, 0.02);
  EXPECT_EQ(*p.contact_elements, 17);
  EXPECT_EQ(p.total_time, 1.5);
  Event warning;
  warning.kind = Event::Kind::Warning;
  EXPECT_EQ(advance_progress(p, warning).iteration, 4);
}

TEST(Metrics, PrometheusTextCountsAndHistogram) {
  StoreCounts c;
  c.queued = 3;
  c.running = 1;
  c.finished["succeeded"] = 2;
  const std::string text = prometheus_text(c, {0.05, 2.0, 100.0}, 2, 1);
  EXPECT_NE(text.find("kontakt_jobs_queued 3\n"), std::string::npos);
  EXPECT_NE(text.find("kontakt_jobs_finished_total{status=\"succeeded\"} 2\n"), std::string::npos);
  EXPECT_NE(text.find("kontakt_jobs_finished_total{status=\"failed\"} 0\n"), std::string::npos);
  EXPECT_NE(text.find("kontakt_job_duration_seconds_bucket{le=\"0.1\"} 1\n"), std::string::npos);
  EXPECT_NE(text.find("kontakt_job_duration_seconds_bucket{le=\"5\"} 2\n"), std::string::npos);
  EXPECT_NE(text.find("kontakt_job_duration_seconds_count 3\n"), std::string::npos);
}

TEST(Digest, Sha256AndIds) {
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  const std::string a = new_job_id(), b = new_job_id();
  EXPECT_TRUE(is_job_id(a));
  EXPECT_NE(a, b);
  EXPECT_FALSE(is_job_id("ABC"));
}

TEST(Times, Rfc3339InUtcWithMilliseconds) {
  EXPECT_EQ(rfc3339(0), "1970-01-01T00:00:00.000Z");
  EXPECT_EQ(rfc3339(1764000000123), "2025-11-24T16:00:00.123Z");
}

}  // namespace kontakt::server
