// The job list's URL state: filters and cursor pages survive links, reloads and back/forward.
import assert from "node:assert/strict";
import { test } from "node:test";
import { api_url, first_page, next_page, parse_label_filter, previous_page, read_state,
         state_query } from "../../../clients/dashboard/list_query.js";

test("state round-trips through the page's query", () => {
  const s = { statuses: ["queued", "running"], labels: ["load=12", "case=a b"], limit: 100,
              page_token: "1700000000000.aa", back: ["", "1690000000000.bb"] };
  assert.deepEqual(read_state(state_query(s)), s);
  assert.equal(state_query(first_page([], [], 50)), "");
});

test("unknown statuses and sizes fall back; labels need key=value", () => {
  const s = read_state("?status=running,done&limit=7&label=novalue&label=k=v");
  assert.deepEqual(s.statuses, ["running"]);
  assert.equal(s.limit, 50);
  assert.deepEqual(s.labels, ["k=v"]);
});

test("next and previous walk the token stack back to the first page", () => {
  const p1 = first_page(["succeeded"], [], 50);
  const p2 = next_page(p1, "T2");
  const p3 = next_page(p2, "T3");
  assert.deepEqual(p3.back, ["", "T2"]);
  assert.equal(previous_page(p3).page_token, "T2");
  assert.equal(previous_page(previous_page(p3)).page_token, null);
  assert.deepEqual(read_state(state_query(p3)), p3);
});

test("the API request carries every filter", () => {
  const url = api_url({ statuses: ["failed", "canceled"], labels: ["load=1&2"], limit: 200, page_token: "T", back: [] });
  const q = new URL(url, "http://x").searchParams;
  assert.equal(new URL(url, "http://x").pathname, "/v1/jobs");
  assert.equal(q.get("status"), "failed,canceled");
  assert.deepEqual(q.getAll("label"), ["load=1&2"]);
  assert.equal(q.get("limit"), "200");
  assert.equal(q.get("page_token"), "T");
});

test("label filter text: entries, blanks and errors", () => {
  assert.deepEqual(parse_label_filter(" load=12 , case = a,, "), { labels: ["load=12", "case=a"] });
  assert.deepEqual(parse_label_filter(""), { labels: [] });
  assert.match(parse_label_filter("load").error, /"load": expected key=value/);
  assert.match(parse_label_filter("bad key=1").error, /bad key=1/);
});
