// The API's routes in-process (no sockets): HttpRequest in, HttpResponse out.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "server/handlers/routes.hpp"
#include "server_test_util.hpp"

using nlohmann::json;

namespace kontakt::server {

// Outside the anonymous namespace: the tests derived from it are not in it.
class HandlerTest : public ::testing::Test {
 protected:
  testing::TempDir dir;
  JobStore store{dir.path() / "jobs.db"};
  JobFiles files{dir.path()};
  testing::CountingControl control;
  handlers::ApiContext ctx{.store = store, .files = files, .control = control,
                           .check_deck = process_deck_checker(KONTAKTD_EXE, {},
                                                              std::chrono::seconds(60)),
                           .max_unpacked = 1 << 20};
  Router router = handlers::make_router(ctx);

  HttpResponse call(const std::string& method, const std::string& path, std::string body = {},
                    std::map<std::string, std::string> headers = {},
                    std::vector<std::pair<std::string, std::string>> query = {}) {
    HttpRequest r;
    r.method = method;
    r.path = path;
    r.body = std::move(body);
    r.headers = std::move(headers);
    r.query = std::move(query);
    return router.handle(r);
  }
  HttpResponse submit(const std::string& deck, std::vector<std::pair<std::string, std::string>> query = {},
                      std::map<std::string, std::string> headers = {{"content-type", "text/plain"}}) {
    return call("POST", "/v1/jobs", deck, std::move(headers), std::move(query));
  }
  static json body(const HttpResponse& r) { return json::parse(r.body); }
};

namespace {

/// The cube deck with line `line` (1-based) replaced.
std::string cube_with_line(int line, const std::string& text) {
  std::string deck = testing::cube_deck(), out;
  int n = 1;
  std::size_t start = 0;
  while (start < deck.size()) {
    const std::size_t end = deck.find('\n', start);
    out += (n == line ? text : deck.substr(start, end - start)) + "\n";
    start = end + 1;
    ++n;
  }
  return out;
}

}  // namespace

TEST_F(HandlerTest, SubmitQueuesAParsedDeck) {
  const auto r = submit(testing::cube_deck(), {{"name", "cube"}, {"label", "sweep=s1"}});
  ASSERT_EQ(r.status, 201) << r.body;
  const json job = body(r);
  EXPECT_EQ(job["status"], "queued");
  EXPECT_EQ(job["name"], "cube");
  EXPECT_EQ(job["labels"]["sweep"], "s1");
  EXPECT_EQ(job["progress"]["steps_total"], 1);
  EXPECT_EQ(job["queue_position"], 1);
  EXPECT_EQ(r.header("Location"), "/v1/jobs/" + job["id"].get<std::string>());
  EXPECT_EQ(control.queued, 1);
  EXPECT_TRUE(std::filesystem::exists(files.input_dir(job["id"]) / "deck.inp"));
  EXPECT_EQ(call("GET", "/v1/jobs/" + job["id"].get<std::string>()).status, 200);
}

TEST_F(HandlerTest, BadDecksAre422NamingFileLineAndKeyword) {
  struct Case { int line; std::string text; std::string keyword; };
  const std::vector<Case> cases{
      {10, "*ELEMENT, TYPE=C3D99, ELSET=EALL", "*ELEMENT"},   // unknown element type
      {2, "2,1,zero,0", "*NODE"},                            // not a number
      {11, "1,1,2,3,4,5,6,7,99", "*ELEMENT"},                // unknown node
      {23, "*CLOAD, AMPLITUDE=NOPE", "*CLOAD"},               // unknown amplitude
      {12, "*MATERIAL", "*MATERIAL"},                         // missing NAME=
      {3, "*", "*"},  // issue 10: a lone '*' crashed the reader and took the daemon with it
  };
  for (const Case& c : cases) {
    const auto r = submit(cube_with_line(c.line, c.text), {{"main", "bad.inp"}});
    ASSERT_EQ(r.status, 422) << c.text << ": " << r.body;
    EXPECT_EQ(r.content_type, "application/problem+json");
    const json problem = body(r);
    EXPECT_EQ(problem["code"], "input_error");
    ASSERT_EQ(problem["errors"].size(), 1u);
    const json& e = problem["errors"][0];
    EXPECT_EQ(e["file"], "bad.inp") << c.text;
    EXPECT_EQ(e["line"], c.line) << c.text << ": " << e["message"];
    EXPECT_EQ(e["keyword"], c.keyword) << c.text;
    EXPECT_EQ(e["message"].get<std::string>().find(dir.path().string()), std::string::npos)
        << "server paths leak: " << e["message"];
  }
  EXPECT_EQ(control.queued, 0);
  EXPECT_TRUE(files.folder_ids().empty()) << "refused uploads leave no folder";
}

TEST_F(HandlerTest, ADeckCheckThatDiesIs422AndLeavesNothingBehind) {
  ctx.check_deck = [](const std::filesystem::path&, const std::optional<std::string>&) {
    return DeckCheckResult{.check = {}, .failure = "the deck reader stopped with signal 11"};
  };
  const auto r = submit(testing::cube_deck());
  ASSERT_EQ(r.status, 422) << r.body;
  EXPECT_EQ(body(r)["code"], "deck_check_failed");
  EXPECT_NE(body(r)["detail"].get<std::string>().find("signal 11"), std::string::npos);
  EXPECT_EQ(control.queued, 0);
  EXPECT_TRUE(files.folder_ids().empty());
}

TEST_F(HandlerTest, BadOptionsAre400NamingTheField) {
  EXPECT_EQ(body(submit(testing::cube_deck(), {{"scheme", "gc5"}}))["field"], "scheme");
  EXPECT_EQ(body(submit(testing::cube_deck(), {{"label", "novalue"}}))["field"], "label");
  EXPECT_EQ(body(submit(testing::cube_deck(), {{"label", "bad key=v"}}))["field"], "labels");
  EXPECT_EQ(body(submit(testing::cube_deck(), {{"main", "../x.inp"}}))["field"], "main");
  EXPECT_EQ(body(submit(""))["field"], "body");
  EXPECT_EQ(submit(testing::cube_deck(), {}, {{"content-type", "image/png"}}).status, 415);
  EXPECT_EQ(call("GET", "/v1/jobs", "", {}, {{"limit", "0"}}).status, 400);
  EXPECT_EQ(call("GET", "/v1/jobs", "", {}, {{"status", "done"}}).status, 400);
  EXPECT_EQ(call("GET", "/v1/jobs", "", {}, {{"page_token", "x"}}).status, 400);
}

TEST_F(HandlerTest, AcceptedSchemeOverrideIsStored) {
  const auto r = submit(testing::cube_deck(), {{"scheme", "LGC7"}});
  ASSERT_EQ(r.status, 201);
  EXPECT_EQ(body(r)["scheme"], "LGC7");
}

TEST_F(HandlerTest, JsonSubmission) {
  const json request{{"deck", testing::cube_deck()}, {"name", "j"}, {"labels", {{"k", "v"}}}};
  const auto r = submit(request.dump(), {}, {{"content-type", "application/json"}});
  ASSERT_EQ(r.status, 201) << r.body;
  EXPECT_EQ(body(r)["labels"]["k"], "v");
  // Labels from the query and from the body add up.
  const auto both = submit(request.dump(), {{"label", "q=1"}}, {{"content-type", "application/json"}});
  EXPECT_EQ(body(both)["labels"], json({{"k", "v"}, {"q", "1"}}));
  EXPECT_EQ(submit("[1]", {}, {{"content-type", "application/json"}}).status, 400);
}

TEST_F(HandlerTest, ZipWithIncludesAndMain) {
  const std::string mesh = "*NODE, NSET=NALL\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n";
  std::string main = testing::cube_deck();
  main.replace(0, mesh.size(), "*INCLUDE, INPUT=mesh/nodes.inp\n");
  const std::string zip = testing::make_zip({{"model.inp", main}, {"mesh/nodes.inp", mesh}}, dir.path());
  const auto r = submit(zip, {}, {{"content-type", "application/zip"}});
  ASSERT_EQ(r.status, 201) << r.body;
  EXPECT_EQ(body(r)["main"], "model.inp");
  // Two decks at the top: ?main= decides.
  const std::string two = testing::make_zip({{"a.inp", testing::cube_deck()}, {"b.inp", "junk"}}, dir.path());
  EXPECT_EQ(body(submit(two, {}, {{"content-type", "application/zip"}}))["field"], "main");
  EXPECT_EQ(submit(two, {{"main", "a.inp"}}, {{"content-type", "application/zip"}}).status, 201);
}

TEST_F(HandlerTest, UnsafeZipsAreRefused) {
  const std::vector<std::vector<testing::ZipItem>> unsafe{
      {{"../evil.inp", "x"}},
      {{"/etc/evil.inp", "x"}},
      {{"a/../../evil.inp", "x"}},
      {{"deck.inp", testing::cube_deck()}, {"link.inp", "/etc/passwd", true}},
  };
  for (const auto& items : unsafe) {
    const auto r = submit(testing::make_zip(items, dir.path()), {{"main", "deck.inp"}},
                          {{"content-type", "application/zip"}});
    EXPECT_EQ(r.status, 400) << items.back().name << ": " << r.body;
  }
  EXPECT_EQ(submit("not a zip", {}, {{"content-type", "application/zip"}}).status, 400);
  EXPECT_TRUE(files.folder_ids().empty());
}

TEST_F(HandlerTest, IncludesMayNotLeaveTheUpload) {
  for (const char* target : {"/etc/passwd", "../other/deck.inp", "sub/../../x.inp"}) {
    const auto r = submit("*INCLUDE, INPUT=" + std::string(target) + "\n" + testing::cube_deck());
    ASSERT_EQ(r.status, 422) << target;
    EXPECT_EQ(body(r)["errors"][0]["line"], 1);
    EXPECT_EQ(body(r)["errors"][0]["keyword"], "*INCLUDE");
  }
}

TEST_F(HandlerTest, IdempotencyKey) {
  const std::map<std::string, std::string> h{{"content-type", "text/plain"}, {"idempotency-key", "k1"}};
  const auto first = submit(testing::cube_deck(), {}, h);
  const auto again = submit(testing::cube_deck(), {}, h);
  ASSERT_EQ(again.status, 201);
  EXPECT_EQ(body(again)["id"], body(first)["id"]);
  EXPECT_EQ(again.header("Idempotent-Replayed"), "true");
  const auto other = submit(testing::cube_deck() + "** changed\n", {}, h);
  EXPECT_EQ(other.status, 422);
  EXPECT_EQ(body(other)["code"], "idempotency_key_reused");
  EXPECT_EQ(control.queued, 1);
}

TEST_F(HandlerTest, UnknownJobsAndRoutes) {
  const std::string id(32, 'a');
  for (const std::string suffix : {"", "/events", "/iterations", "/increments", "/results",
                                   "/results/x.hdf", "/summary"})
    EXPECT_EQ(call("GET", "/v1/jobs/" + id + suffix).status, 404) << suffix;
  EXPECT_EQ(call("POST", "/v1/jobs/" + id + "/cancel").status, 404);
  EXPECT_EQ(call("DELETE", "/v1/jobs/" + id).status, 404);
  EXPECT_EQ(call("GET", "/v2/nothing").status, 404);
  const auto r = call("PUT", "/v1/jobs");
  EXPECT_EQ(r.status, 405);
  EXPECT_TRUE(r.header("Allow"));
}

TEST_F(HandlerTest, CancelIsIdempotentAndDeleteNeedsAFinishedJob) {
  const std::string id = body(submit(testing::cube_deck()))["id"];
  EXPECT_EQ(call("DELETE", "/v1/jobs/" + id).status, 409);
  const auto first = call("POST", "/v1/jobs/" + id + "/cancel");
  EXPECT_EQ(first.status, 200);
  EXPECT_EQ(body(first)["status"], "canceled");
  EXPECT_EQ(call("POST", "/v1/jobs/" + id + "/cancel").status, 200);
  EXPECT_EQ(call("DELETE", "/v1/jobs/" + id).status, 204);
  EXPECT_FALSE(std::filesystem::exists(files.job_dir(id)));
  EXPECT_EQ(call("GET", "/v1/jobs/" + id).status, 404);
}

TEST_F(HandlerTest, CancelOfARunningJobRaisesItsFlag) {
  const std::string id = body(submit(testing::cube_deck()))["id"];
  store.claim_next();
  // The flag goes up while the store still says running: no solver event can be stored
  // after `canceling` but the one of the iteration in flight.
  std::vector<JobStatus> seen;
  control.on_cancel = [&](const std::string& c) { seen.push_back(store.find_job(c)->status); };
  const auto r = call("POST", "/v1/jobs/" + id + "/cancel");
  EXPECT_EQ(r.status, 202);
  EXPECT_EQ(body(r)["status"], "canceling");
  ASSERT_FALSE(control.canceled.empty());
  EXPECT_EQ(control.canceled[0], id);
  EXPECT_EQ(seen.front(), JobStatus::Running);
}

TEST_F(HandlerTest, ListFiltersAndPages) {
  for (int i = 0; i < 5; ++i) submit(testing::cube_deck(), {{"label", i % 2 ? "odd=1" : "odd=0"}});
  const auto page1 = call("GET", "/v1/jobs", "", {}, {{"limit", "3"}});
  ASSERT_EQ(page1.status, 200);
  const json p1 = body(page1);
  EXPECT_EQ(p1["jobs"].size(), 3u);
  ASSERT_TRUE(p1["next_page_token"].is_string());
  EXPECT_NE(page1.header("Link")->find("rel=\"next\""), std::string::npos);
  const json p2 = body(call("GET", "/v1/jobs", "", {}, {{"limit", "3"}, {"page_token", p1["next_page_token"]}}));
  EXPECT_EQ(p2["jobs"].size(), 2u);
  EXPECT_TRUE(p2["next_page_token"].is_null());
  EXPECT_EQ(body(call("GET", "/v1/jobs", "", {}, {{"label", "odd=1"}}))["jobs"].size(), 2u);
  EXPECT_EQ(body(call("GET", "/v1/jobs", "", {}, {{"status", "running,failed"}}))["jobs"].size(), 0u);
  // Keys a submission cannot carry are a 400 naming the parameter (a NUL was a 500).
  for (const std::string& bad : {std::string("ko\0n=abc", 9), std::string("a\"b=1"), std::string("=1")}) {
    const auto r = call("GET", "/v1/jobs", "", {}, {{"label", bad}});
    EXPECT_EQ(r.status, 400);
    EXPECT_EQ(body(r)["field"], "label");
  }
}

TEST_F(HandlerTest, EventsTablesAndStream) {
  const std::string id = body(submit(testing::cube_deck()))["id"];
  store.claim_next();
  store.append_event(id, "iteration", R"({"event":"iteration","iteration":1})", std::nullopt);
  store.append_event(id, "increment", R"({"event":"increment","increment":1})", std::nullopt);
  const json its = body(call("GET", "/v1/jobs/" + id + "/iterations"));
  ASSERT_EQ(its["iterations"].size(), 1u);
  const int since = its["next_since"];
  EXPECT_EQ(body(call("GET", "/v1/jobs/" + id + "/iterations", "", {}, {{"since", std::to_string(since)}}))["iterations"].size(), 0u);
  const json incs = body(call("GET", "/v1/jobs/" + id + "/increments"));
  ASSERT_EQ(incs["increments"].size(), 1u);
  EXPECT_EQ(incs["increments"][0]["converged"], true);
  const auto stream = call("GET", "/v1/jobs/" + id + "/events", "", {{"last-event-id", "3"}});
  ASSERT_TRUE(stream.events);
  EXPECT_EQ(stream.events->after_seq, 3);
  EXPECT_EQ(stream.content_type, "text/event-stream");
  EXPECT_EQ(call("GET", "/v1/jobs/" + id + "/events", "", {{"last-event-id", "x"}}).status, 400);
}

TEST_F(HandlerTest, DownloadsWithEtagAndRange) {
  const std::string id = body(submit(testing::cube_deck()))["id"];
  store.claim_next();
  std::filesystem::create_directories(files.results_dir(id));
  std::ofstream(files.results_dir(id) / "deck.sta") << "0123456789";
  const std::string sha = "84d89877f0d4041efb6bf91a16f0248f2fd573e6af05c19f96bedb9f882f7882";
  store.finish_job(id, JobStatus::Succeeded, "", "", std::nullopt, {{"deck.sta", "text/plain", 10, sha}});
  const json list = body(call("GET", "/v1/jobs/" + id + "/results"));
  EXPECT_EQ(list["artifacts"][0]["sha256"], sha);
  const auto whole = call("GET", "/v1/jobs/" + id + "/results/deck.sta");
  ASSERT_TRUE(whole.file);
  EXPECT_EQ(whole.file->length, 10u);
  EXPECT_EQ(whole.header("ETag"), "\"" + sha + "\"");
  const auto part = call("GET", "/v1/jobs/" + id + "/results/deck.sta", "", {{"range", "bytes=2-4"}});
  EXPECT_EQ(part.status, 206);
  EXPECT_EQ(part.file->offset, 2u);
  EXPECT_EQ(part.file->length, 3u);
  EXPECT_EQ(part.header("Content-Range"), "bytes 2-4/10");
  EXPECT_EQ(call("GET", "/v1/jobs/" + id + "/results/deck.sta", "", {{"range", "bytes=20-"}}).status, 416);
  EXPECT_EQ(call("GET", "/v1/jobs/" + id + "/results/deck.sta", "", {{"if-none-match", "\"" + sha + "\""}}).status, 304);
  EXPECT_EQ(call("GET", "/v1/jobs/" + id + "/results/..%2Fjobs.db").status, 404);
  EXPECT_EQ(call("GET", "/v1/jobs/" + id + "/results/input").status, 404);
}

TEST_F(HandlerTest, BearerTokens) {
  router.require_tokens({"s3cret"});
  EXPECT_EQ(call("GET", "/v1/jobs").status, 401);
  EXPECT_TRUE(call("GET", "/v1/jobs").header("WWW-Authenticate"));
  EXPECT_EQ(call("GET", "/v1/jobs", "", {{"authorization", "Bearer wrong"}}).status, 401);
  EXPECT_EQ(call("GET", "/v1/jobs", "", {{"authorization", "Bearer s3cret"}}).status, 200);
  // Never from the URL: it would end up in logs, proxies and browser history.
  EXPECT_EQ(call("GET", "/v1/jobs", "", {}, {{"access_token", "s3cret"}}).status, 401);
  EXPECT_EQ(call("GET", "/v1/queue").status, 401);
  EXPECT_EQ(call("GET", "/v1/sweeps").status, 401);
  EXPECT_EQ(call("GET", "/v1/openapi.json").status, 401);
  EXPECT_EQ(call("GET", "/nothing/here").status, 401) << "unknown paths do not reveal themselves";
  // Liveness and the dashboard's pages and assets hold no data: open.
  for (const std::string& path : std::vector<std::string>{"/healthz", "/", "/jobs/" + std::string(32, 'a'),
                                                         "/sweeps", "/assets/job_page.js", "/assets/uPlot.esm.js"})
    EXPECT_EQ(call("GET", path).status, 200) << path;
  EXPECT_EQ(call("POST", "/").status, 405);
}

TEST_F(HandlerTest, DashboardPagesAndAssets) {
  for (const std::string& path : std::vector<std::string>{"/", "/jobs/" + std::string(32, 'b'), "/sweeps"}) {
    const auto page = call("GET", path);
    ASSERT_EQ(page.status, 200) << path;
    EXPECT_EQ(page.content_type, "text/html; charset=utf-8") << path;
    const auto csp = page.header("Content-Security-Policy");
    ASSERT_TRUE(csp) << path;
    EXPECT_NE(csp->find("default-src 'self'"), std::string::npos);
    EXPECT_NE(page.body.find("/assets/"), std::string::npos) << path;
  }
  EXPECT_NE(call("GET", "/").body.find("job_list.js"), std::string::npos);
  EXPECT_NE(call("GET", "/jobs/" + std::string(32, 'b')).body.find("job_page.js"), std::string::npos);
  EXPECT_NE(call("GET", "/sweeps").body.find("sweeps_page.js"), std::string::npos);
  const auto script = call("GET", "/assets/job_page.js");
  EXPECT_EQ(script.content_type, "text/javascript; charset=utf-8");
  const auto etag = script.header("ETag");
  ASSERT_TRUE(etag);
  EXPECT_EQ(script.header("Cache-Control"), "no-cache");
  EXPECT_EQ(call("GET", "/assets/job_page.js", "", {{"if-none-match", *etag}}).status, 304);
  EXPECT_EQ(call("GET", "/assets/job_page.js", "", {{"if-none-match", "\"old\""}}).status, 200);
  const auto uplot = call("GET", "/assets/uPlot.esm.js");
  EXPECT_EQ(uplot.status, 200);
  EXPECT_NE(uplot.body.find("export"), std::string::npos) << "uPlot's ES module, embedded";
  EXPECT_EQ(call("GET", "/assets/uPlot.min.css").content_type, "text/css; charset=utf-8");
  EXPECT_EQ(call("GET", "/assets/nothing.js").status, 404);
  EXPECT_EQ(call("GET", "/assets/v1/openapi.json").status, 404);
  EXPECT_EQ(call("GET", "/assets/..").status, 404);
}

TEST_F(HandlerTest, QueueCountsJobsAndWorkers) {
  const std::string a = body(submit(testing::cube_deck()))["id"];
  submit(testing::cube_deck());
  submit(testing::cube_deck());
  store.claim_next();
  call("POST", "/v1/jobs/" + a + "/cancel");  // a runs: canceling
  const std::string c = body(submit(testing::cube_deck()))["id"];
  call("POST", "/v1/jobs/" + c + "/cancel");  // queued: canceled at once
  const json q = body(call("GET", "/v1/queue"));
  EXPECT_EQ(q["queued"], 2);
  EXPECT_EQ(q["running"], 0);
  EXPECT_EQ(q["canceling"], 1);
  EXPECT_EQ(q["finished"], json({{"succeeded", 0}, {"failed", 0}, {"canceled", 1}}));
  EXPECT_EQ(q["workers"], 2);
  EXPECT_EQ(q["busy_workers"], 0);
}

TEST_F(HandlerTest, SweepsGroupJobsByLabelKey) {
  std::vector<std::string> ids;
  for (const char* load : {"1", "2.5", "10"})
    ids.push_back(body(submit(testing::cube_deck(), {{"label", std::string("load=") + load},
                                                     {"label", "case=beam"}}))["id"]);
  submit(testing::cube_deck(), {{"label", "case=other"}});
  submit(testing::cube_deck());
  const json list = body(call("GET", "/v1/sweeps"));
  ASSERT_EQ(list["sweeps"].size(), 2u);
  EXPECT_EQ(list["sweeps"][0]["key"], "case");  // its newest job is the newest labelled one
  EXPECT_EQ(list["sweeps"][0]["jobs"], 4);
  EXPECT_EQ(list["sweeps"][1]["key"], "load");
  EXPECT_EQ(list["sweeps"][1]["jobs"], 3);

  const json sweep = body(call("GET", "/v1/sweeps/load"));
  EXPECT_EQ(sweep["key"], "load");
  ASSERT_EQ(sweep["jobs"].size(), 3u);
  EXPECT_EQ(sweep["jobs"][0]["id"], ids[2]);  // newest first
  EXPECT_EQ(sweep["jobs"][0]["value"], "10");
  EXPECT_EQ(sweep["jobs"][2]["value"], "1");
  EXPECT_EQ(sweep["jobs"][0]["status"], "queued");
  EXPECT_TRUE(sweep["jobs"][0]["max_displacement"].is_null());
  EXPECT_TRUE(sweep["jobs"][0]["finished"].is_null());
  EXPECT_TRUE(sweep["next_page_token"].is_null());

  // A finished job's summary figures appear in its row.
  store.claim_next();
  JobSummary summary;
  summary.iterations = 3;
  summary.wall_time = 0.5;
  summary.max_displacement = 0.25;
  ASSERT_TRUE(store.finish_job(ids[0], JobStatus::Succeeded, "", "", summary, {}));
  const json rows = body(call("GET", "/v1/sweeps/load"))["jobs"];
  EXPECT_EQ(rows[2]["status"], "succeeded");
  EXPECT_EQ(rows[2]["iterations"], 3);
  EXPECT_EQ(rows[2]["max_displacement"], 0.25);
  EXPECT_TRUE(rows[2]["max_contact_pressure"].is_null());

  const json p1 = body(call("GET", "/v1/sweeps/load", "", {}, {{"limit", "2"}}));
  ASSERT_EQ(p1["jobs"].size(), 2u);
  ASSERT_TRUE(p1["next_page_token"].is_string());
  const json p2 = body(call("GET", "/v1/sweeps/load", "", {}, {{"page_token", p1["next_page_token"]}}));
  ASSERT_EQ(p2["jobs"].size(), 1u);
  EXPECT_EQ(p2["jobs"][0]["id"], ids[0]);

  // Narrowed by another label: one design loop's jobs among several.
  const json beams = body(call("GET", "/v1/sweeps/load", "", {}, {{"label", "case=beam"}}));
  EXPECT_EQ(beams["jobs"].size(), 3u);
  EXPECT_TRUE(body(call("GET", "/v1/sweeps/load", "", {}, {{"label", "case=other"}}))["jobs"].empty());
  EXPECT_EQ(body(call("GET", "/v1/sweeps/load", "", {}, {{"label", "case"}}))["field"], "label");

  EXPECT_TRUE(body(call("GET", "/v1/sweeps/nothing"))["jobs"].empty());
  EXPECT_EQ(body(call("GET", "/v1/sweeps/bad key"))["field"], "key");
  EXPECT_EQ(body(call("GET", "/v1/sweeps/load", "", {}, {{"limit", "1001"}}))["field"], "limit");
  EXPECT_EQ(body(call("GET", "/v1/sweeps/load", "", {}, {{"page_token", "1.x"}}))["field"], "page_token");
}

TEST_F(HandlerTest, PageTokensOutOfRangeAre400NotAnError) {
  EXPECT_EQ(call("GET", "/v1/jobs", "", {}, {{"page_token", std::string(19, '9') + "." + std::string(32, 'a')}}).status, 400);
  EXPECT_EQ(call("GET", "/v1/jobs", "", {}, {{"page_token", "12." + std::string(32, 'a')}}).status, 200);
}

TEST_F(HandlerTest, ResubmitCopiesTheInputWithOptions) {
  const std::string main = "*INCLUDE, INPUT=mesh/nodes.inp\n";
  const std::string deck = testing::cube_deck();
  const std::size_t nodes_end = deck.find("*ELEMENT");
  const std::string zip = testing::make_zip({{"model.inp", main + deck.substr(nodes_end)},
                                             {"mesh/nodes.inp", deck.substr(0, nodes_end)}}, dir.path());
  const auto first = submit(zip, {{"name", "cube"}, {"label", "load=3"}, {"scheme", "lgc3"}},
                            {{"content-type", "application/zip"}});
  ASSERT_EQ(first.status, 201) << first.body;
  const std::string source = body(first)["id"];

  const auto same = call("POST", "/v1/jobs/" + source + "/resubmit");
  ASSERT_EQ(same.status, 201) << same.body;
  const json copy = body(same);
  EXPECT_NE(copy["id"], source);
  EXPECT_EQ(copy["name"], "cube");
  EXPECT_EQ(copy["scheme"], "lgc3");
  EXPECT_EQ(copy["labels"]["load"], "3");
  EXPECT_EQ(copy["main"], "model.inp");
  EXPECT_EQ(copy["status"], "queued");
  EXPECT_EQ(same.header("Location"), "/v1/jobs/" + copy["id"].get<std::string>());
  EXPECT_TRUE(std::filesystem::exists(files.input_dir(copy["id"]) / "mesh" / "nodes.inp"));

  const auto other = call("POST", "/v1/jobs/" + source + "/resubmit",
                          R"({"scheme": "gc7", "name": "cube gc7", "labels": {"load": "4"}})",
                          {{"content-type", "application/json"}});
  ASSERT_EQ(other.status, 201) << other.body;
  EXPECT_EQ(body(other)["scheme"], "gc7");
  EXPECT_EQ(body(other)["name"], "cube gc7");
  EXPECT_EQ(body(other)["labels"], json({{"load", "4"}}));
  const auto own = call("POST", "/v1/jobs/" + source + "/resubmit", R"({"scheme": null})",
                        {{"content-type", "application/json"}});
  ASSERT_EQ(own.status, 201);
  EXPECT_TRUE(body(own)["scheme"].is_null());
  EXPECT_EQ(control.queued, 4);

  // The same key replays the job; another body under it is refused.
  const std::map<std::string, std::string> keyed{{"content-type", "application/json"},
                                                 {"idempotency-key", "r1"}};
  const auto k1 = call("POST", "/v1/jobs/" + source + "/resubmit", R"({"scheme": "nts"})", keyed);
  const auto k2 = call("POST", "/v1/jobs/" + source + "/resubmit", R"({"scheme": "nts"})", keyed);
  ASSERT_EQ(k2.status, 201);
  EXPECT_EQ(body(k2)["id"], body(k1)["id"]);
  EXPECT_EQ(k2.header("Idempotent-Replayed"), "true");
  EXPECT_EQ(call("POST", "/v1/jobs/" + source + "/resubmit", R"({"scheme": "gc1"})", keyed).status, 422);
  EXPECT_EQ(control.queued, 5);

  const auto post = [&](const std::string& text) {
    return call("POST", "/v1/jobs/" + source + "/resubmit", text, {{"content-type", "application/json"}});
  };
  EXPECT_EQ(body(post(R"({"scheme": "gc5"})"))["field"], "scheme");
  EXPECT_EQ(body(post(R"({"scheme": 7})"))["field"], "scheme");
  EXPECT_EQ(body(post(R"({"name": ""})"))["field"], "name");
  EXPECT_EQ(body(post(R"({"labels": {"bad key": "1"}})"))["field"], "labels");
  EXPECT_EQ(body(post(R"({"deck": "*NODE"})"))["field"], "deck");
  EXPECT_EQ(body(post("[1]"))["field"], "body");
  EXPECT_EQ(call("POST", "/v1/jobs/" + source + "/resubmit", "scheme=gc7",
                 {{"content-type", "text/plain"}}).status, 415);
  EXPECT_EQ(call("POST", "/v1/jobs/" + std::string(32, 'c') + "/resubmit").status, 404);
  EXPECT_EQ(control.queued, 5) << "refused resubmissions queue nothing";
  EXPECT_EQ(files.folder_ids().size(), 5u) << "and leave no folder";
}

TEST_F(HandlerTest, ResubmitReparsesTheDeck) {
  const std::string source = body(submit(testing::cube_deck()))["id"];
  // The input changed under the job (a disk fault, a hand edit): the copy is parsed again.
  std::ofstream(files.input_dir(source) / "deck.inp") << "*FROBNICATE\n";
  const auto r = call("POST", "/v1/jobs/" + source + "/resubmit");
  EXPECT_EQ(r.status, 422);
  EXPECT_EQ(body(r)["errors"][0]["keyword"], "*FROBNICATE");
  std::filesystem::remove_all(files.input_dir(source));
  EXPECT_EQ(call("POST", "/v1/jobs/" + source + "/resubmit").status, 409);
  EXPECT_EQ(files.folder_ids().size(), 1u);
}

TEST_F(HandlerTest, ServiceEndpoints) {
  const json health = body(call("GET", "/healthz"));
  EXPECT_EQ(health["status"], "ok");
  const auto metrics = call("GET", "/metrics");
  EXPECT_NE(metrics.body.find("kontakt_jobs_queued 0"), std::string::npos);
  EXPECT_NE(metrics.body.find("kontakt_job_duration_seconds_bucket{le=\"+Inf\"} 0"), std::string::npos);
  const json spec = body(call("GET", "/v1/openapi.json"));
  EXPECT_EQ(spec["openapi"], "3.1.0");
  EXPECT_TRUE(spec["components"]["schemas"].contains("Job"));
  const auto page = call("GET", "/");
  EXPECT_EQ(page.content_type.rfind("text/html", 0), 0u);
  EXPECT_EQ(call("GET", "/v1/openapi.json").header("ETag").has_value(), true);
}

}  // namespace kontakt::server
