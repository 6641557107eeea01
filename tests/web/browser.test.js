// The dashboard in a real browser: Debian's chromium, headless, driven by playwright-core,
// against the kontaktd daemons run_browser_tests.py started. Every page must load without a
// console error; screenshots go to $SCREENSHOT_DIR.
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import { createRequire } from "node:module";
import { dirname, join } from "node:path";
import { after, before, test } from "node:test";

const env = process.env;
const { chromium } = createRequire(join(dirname(env.NODE_MODULES), "index.js"))("playwright-core");
const OPEN = env.KONTAKTD_URL, LOCKED = env.KONTAKTD_TOKEN_URL, TOKEN = env.KONTAKTD_TOKEN;
const TIMEOUT = 60000;

// Debian's chromium without the background services it would otherwise try to reach.
const CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
  "--disable-background-networking", "--disable-component-update", "--disable-sync"];

let browser;
before(async () => {
  // playwright gives every launch a fresh, temporary --user-data-dir.
  browser = await chromium.launch({ executablePath: env.CHROMIUM, args: CHROMIUM_ARGS });
});
after(async () => browser && browser.close());

// ---- API helpers (node's fetch) ----------------------------------------------------------

async function api(base, path, { method = "GET", body, headers = {}, token } = {}) {
  if (token) headers.Authorization = "Bearer " + token;
  const r = await fetch(base + path, { method, body, headers });
  const text = await r.text();
  if (!r.ok) throw new Error(`${method} ${path}: ${r.status} ${text}`);
  return text ? JSON.parse(text) : null;
}

function submit(base, deck, query = "", token) {
  return api(base, "/v1/jobs" + (query ? "?" + query : ""), {
    method: "POST", body: readFileSync(join(env.DECK_DIR, deck), "utf8"),
    headers: { "Content-Type": "text/plain" }, token,
  });
}

async function wait_status(base, id, statuses, token, timeout = TIMEOUT) {
  const deadline = Date.now() + timeout;
  for (;;) {
    const job = await api(base, `/v1/jobs/${id}`, { token });
    if (statuses.includes(job.status)) return job;
    if (Date.now() > deadline) throw new Error(`job ${id} still ${job.status}`);
    await new Promise((r) => setTimeout(r, 100));
  }
}

/** Every row of /iterations or /increments, following the since cursor. */
async function table_rows(base, id, table) {
  const rows = [];
  let since = 0;
  for (;;) {
    const page = await api(base, `/v1/jobs/${id}/${table}?since=${since}&limit=10000`);
    rows.push(...page[table]);
    if (!page[table].length) return rows;
    since = page.next_since;
  }
}

// ---- browser helpers ---------------------------------------------------------------------

/** A fresh context and page that record console errors and uncaught exceptions. */
async function open_page(t) {
  const context = await browser.newContext({ viewport: { width: 1400, height: 1000 }, acceptDownloads: true });
  const page = await context.newPage();
  page.setDefaultTimeout(TIMEOUT);
  page.errors = [];
  page.on("console", (m) => { if (m.type() === "error") page.errors.push(m.text()); });
  page.on("pageerror", (e) => page.errors.push(String(e)));
  t.after(async () => {
    await context.close();
    assert.deepEqual(page.errors, [], "the page logged errors");
  });
  return page;
}

const shot = (page, name) => page.screenshot({ path: join(env.SCREENSHOT_DIR, name + ".png"), fullPage: true });
const points = async (page, box) => Number(await page.getAttribute(box, "data-points"));

// ---- scenarios ---------------------------------------------------------------------------

let contact_job;

test("contact job page: plots hold every iteration, tables match the API", async (t) => {
  contact_job = await submit(OPEN, "hertz.inp", "name=hertz-line-contact&label=case=web&label=mesh=1");
  const done = await wait_status(OPEN, contact_job.id, ["succeeded", "failed"]);
  assert.equal(done.status, "succeeded");
  const page = await open_page(t);
  await page.goto(`${OPEN}/jobs/${contact_job.id}`);
  await page.waitForSelector("#job-header[data-history-loaded]");

  const iterations = await table_rows(OPEN, contact_job.id, "iterations");
  assert.ok(iterations.length > 10, `${iterations.length} iterations`);
  await page.waitForFunction((n) => Number(document.querySelector("#plot-residual").dataset.points) === n,
                             iterations.length);
  assert.equal(await points(page, "#plot-contact"), iterations.length);
  assert.ok(await page.locator("#plot-residual canvas").count() >= 1);

  const expected = (await table_rows(OPEN, contact_job.id, "increments"))
    .map((r) => [r.step, r.increment, r.attempt, r.iteration, r.converged].map(String));
  const shown = await page.$$eval("#increments tbody tr[data-step]", (rows) => rows.map((r) =>
    [r.dataset.step, r.dataset.increment, r.dataset.attempt, r.dataset.iterations, r.dataset.converged]));
  assert.deepEqual(shown, expected);
  // The default scheme's drift check froze the Hertz contact again at least once, and the page
  // says so (the rows of redone increments are marked: tests/web/unit/run_history.test.js).
  await page.waitForFunction(() =>
    /drift refreezes\s*[1-9]/.test(document.querySelector("#summary").textContent));

  const summary = await page.textContent("#summary");
  const s = await api(OPEN, `/v1/jobs/${contact_job.id}/summary`);
  assert.ok(s.max_contact_pressure > 0);
  assert.match(summary, /max CPRESS/);
  assert.ok(summary.includes(String(Number(s.max_contact_pressure.toPrecision(3)))) ||
            summary.includes(s.max_contact_pressure.toExponential(2)), summary);
  const { artifacts } = await api(OPEN, `/v1/jobs/${contact_job.id}/results`);
  const listed = await page.$$eval("#results tbody tr", (rows) => rows.map((r) => [r.dataset.name, r.querySelector(".sha").title]));
  assert.deepEqual(listed, artifacts.map((a) => [a.name, a.sha256]));
  assert.match(await page.textContent("#log"), /done converged/);
  assert.equal(await page.textContent("#job-status"), "succeeded");
  await shot(page, "job_contact");
});

test("a running job's page follows it live; cancel from the page", async (t) => {
  const job = await submit(OPEN, "long.inp", "name=long-beam");
  await wait_status(OPEN, job.id, ["running"]);
  const page = await open_page(t);
  await page.goto(`${OPEN}/jobs/${job.id}`);
  await page.waitForSelector("#stream-state[data-state=live]", { state: "attached" });
  await page.waitForFunction(() => Number(document.querySelector("#plot-residual").dataset.points) > 0);
  const before = await points(page, "#plot-residual");
  await page.waitForFunction((n) => Number(document.querySelector("#plot-residual").dataset.points) > n, before);
  await shot(page, "job_running");
  await page.click("#cancel");
  await page.waitForSelector("#job-status .chip[data-status=canceled]");
  assert.equal((await api(OPEN, `/v1/jobs/${job.id}`)).status, "canceled");
  await page.waitForSelector("#stream-state[data-state=ended]", { state: "attached" });
  assert.ok(await page.locator("#cancel").isHidden());
  // The page holds what the store holds: nothing was lost while it was live.
  const iterations = await table_rows(OPEN, job.id, "iterations");
  await page.waitForFunction((n) => Number(document.querySelector("#plot-residual").dataset.points) === n,
                             iterations.length);
  await shot(page, "job_canceled");
});

test("resubmit with another scheme opens the new job", async (t) => {
  const page = await open_page(t);
  await page.goto(`${OPEN}/jobs/${contact_job.id}`);
  await page.waitForSelector("#resubmit:not([disabled])");
  await page.selectOption("#resubmit-scheme", "gc3");
  await page.click("#resubmit");
  await page.waitForURL((url) => url.pathname.startsWith("/jobs/") && !url.pathname.endsWith(contact_job.id));
  const id = new URL(page.url()).pathname.split("/")[2];
  const job = await api(OPEN, `/v1/jobs/${id}`);
  assert.equal(job.scheme, "gc3");
  assert.deepEqual(job.labels, contact_job.labels);
  await page.waitForFunction(() => document.querySelector("#job-facts").textContent.includes("gc3"));
  await wait_status(OPEN, id, ["succeeded", "failed"]);
});

test("job list: filters, pages, links, queue depth and worker use", async (t) => {
  const ids = [];
  for (let i = 0; i < 56; i += 1) ids.push((await submit(OPEN, "tiny.inp", `name=tiny-${i}&label=batch=list`)).id);
  for (const id of ids) await wait_status(OPEN, id, ["succeeded"]);
  const page = await open_page(t);
  await page.goto(`${OPEN}/?label=batch=list`);
  await page.waitForSelector("#queue [data-workers='2']");
  await page.waitForFunction(() => document.querySelectorAll("#jobs tbody tr[data-id]").length === 50);
  await shot(page, "job_list");
  const first_page = await page.$$eval("#jobs tbody tr[data-id]", (rows) => rows.map((r) => r.dataset.id));
  assert.deepEqual(first_page, ids.slice(-50).reverse(), "newest first");
  await page.click("#next-page");
  await page.waitForFunction(() => document.querySelectorAll("#jobs tbody tr[data-id]").length === 6);
  assert.match(page.url(), /page_token=/);
  assert.doesNotMatch(page.url(), /access_token/);
  await page.click("#previous-page");
  await page.waitForFunction(() => document.querySelectorAll("#jobs tbody tr[data-id]").length === 50);
  await page.goBack();
  await page.waitForFunction(() => document.querySelectorAll("#jobs tbody tr[data-id]").length === 6);

  await page.goto(`${OPEN}/`);
  await page.check("#status-filter input[value=failed]");
  await page.waitForSelector("#jobs td.empty");
  assert.match(page.url(), /status=failed/);
  await page.uncheck("#status-filter input[value=failed]");
  await page.fill("#label-filter", "case=web");
  await page.press("#label-filter", "Enter");
  await page.waitForFunction(() => [...document.querySelectorAll("#jobs tbody tr[data-id]")].length === 2);
  await page.fill("#label-filter", "not a label");
  await page.press("#label-filter", "Enter");
  assert.match(await page.textContent("#filter-error"), /expected key=value/);
  await page.click(`#jobs tr[data-id='${contact_job.id}'] a.job-link`);
  await page.waitForURL(`${OPEN}/jobs/${contact_job.id}`);
});

test("sweep: one row per job by label value, a summary value plotted against it", async (t) => {
  const loads = [5, 1, 8, 2, 3];
  for (const k of loads) await submit(OPEN, `sweep_${k}.inp`, `name=sweep-${k}&label=load=${k}&label=series=a`);
  await submit(OPEN, "sweep_2.inp", "name=other-series&label=load=4&label=series=b");  // another loop
  const page = await open_page(t);
  await page.goto(`${OPEN}/sweeps?label=load`);
  // Live: the page refreshes until every job has finished.
  await page.waitForFunction(() => document.querySelectorAll("#sweep-table .chip[data-status=succeeded]").length === 6);
  await page.click("#sweep-table a.label:text-is('series=a')");  // narrow to one design loop
  await page.waitForURL(/filter=series%3Da/);
  await page.waitForFunction(() => document.querySelectorAll("#sweep-table .chip[data-status=succeeded]").length === 5);
  await page.waitForFunction(() => Number(document.querySelector("#plot-sweep").dataset.points) === 5);
  const values = await page.$$eval("#sweep-table tbody tr", (rows) => rows.map((r) => r.dataset.value));
  assert.deepEqual(values, ["1", "2", "3", "5", "8"]);
  assert.match(await page.textContent("#sweep-filter"), /only jobs with series=a/);
  const sweep = await api(OPEN, "/v1/sweeps/load");
  const u = Object.fromEntries(sweep.jobs.map((r) => [r.value, r.max_displacement]));
  assert.ok(Math.abs(u["8"] / u["1"] - 8) < 1e-6, "linear: |U| scales with the load");
  await shot(page, "sweep");
  await page.selectOption("#quantity", "wall_time");
  await page.waitForFunction(() => Number(document.querySelector("#plot-sweep").dataset.points) === 5);
  await page.goto(`${OPEN}/sweeps`);
  await page.waitForSelector("#sweep-list a[href='/sweeps?label=load']");
  await shot(page, "sweeps_index");
});

test("token: asked once, kept in session storage, never in a URL", async (t) => {
  const job = await submit(LOCKED, "beam.inp", "name=locked-beam&main=beam.inp", TOKEN);
  await wait_status(LOCKED, job.id, ["succeeded"], TOKEN);
  const page = await open_page(t);
  const urls = [];
  page.on("request", (r) => urls.push(r.url()));
  // The refused API calls before the token is entered log 401s: expected here.
  const expected_401 = () => { page.errors = page.errors.filter((e) => !/401/.test(e)); };
  await page.goto(`${LOCKED}/`);
  await page.waitForSelector(".token-form");
  await shot(page, "token_prompt");
  await page.fill(".token-form input", "wrong");
  await page.click(".token-form button");
  await page.waitForFunction(() => /not accepted/.test(document.querySelector(".token-form .hint")?.textContent || ""));
  await page.fill(".token-form input", TOKEN);
  await page.click(".token-form button");
  await page.waitForSelector(`#jobs tr[data-id='${job.id}']`);
  assert.equal(await page.evaluate(() => sessionStorage.getItem("kontaktd.token")), TOKEN);

  await page.goto(`${LOCKED}/jobs/${job.id}`);  // same tab: no second prompt
  await page.waitForSelector("#job-header[data-history-loaded]");
  assert.equal(await page.locator(".token-form").count(), 0);
  await page.waitForSelector("#results tr[data-name='beam.dat']");
  const { artifacts } = await api(LOCKED, `/v1/jobs/${job.id}/results`, { token: TOKEN });
  const dat = artifacts.find((a) => a.name === "beam.dat");
  const [download] = await Promise.all([page.waitForEvent("download"), page.click("#results a[download='beam.dat']")]);
  assert.equal(download.suggestedFilename(), "beam.dat");
  const saved = readFileSync(await download.path());
  assert.equal(saved.length, dat.size);
  expected_401();
  assert.ok(urls.length > 5);
  for (const url of urls) assert.ok(!url.includes(TOKEN) && !url.includes("access_token"), url);
});

/** SSE frames of synthetic events numbered from `first_seq`. */
const sse_frames = (events, first_seq = 1) => events.map((e, i) =>
  `id: ${first_seq + i}\nevent: ${e.event}\ndata: ${JSON.stringify({ ...e, seq: first_seq + i, run: 1 })}\n\n`).join("");

test("a dropped stream resumes from Last-Event-ID: nothing lost, nothing twice", async (t) => {
  // The job's API is served by the test, so the connection can be dropped at a known event.
  const id = "e".repeat(32);
  const job = { ...(await api(OPEN, `/v1/jobs/${contact_job.id}`)), id, name: "dropped-stream", status: "running",
                finished: null };
  const n = 40;
  const events = [{ event: "status", status: "running" }];
  for (let i = 1; i <= n; i += 1)
    events.push({ event: "iteration", step: 1, increment: i, attempt: 1, iteration: 1, step_time: i / n,
                  total_time: i / n, dt: 1 / n, residual: 1 / i, correction: 0.1 / i, wall_time: i / 10 });
  events.push({ event: "status", status: "succeeded" });
  const cut = 25;  // the first connection ends after event 25, without the terminal status
  const requests = [];
  const page = await open_page(t);
  const json = (data) => ({ status: 200, contentType: "application/json", body: JSON.stringify(data) });
  await page.route(`**/v1/jobs/${id}`, (r) => r.fulfill(json(job)));
  await page.route(`**/v1/jobs/${id}/events`, (r) => {
    const last = r.request().headers()["last-event-id"];
    requests.push(last ?? null);
    const after = last === undefined ? 0 : Number(last);
    const upto = requests.length === 1 ? cut : events.length;
    r.fulfill({ status: 200, contentType: "text/event-stream",
                body: sse_frames(events.slice(after, upto), after + 1) });
  });
  for (const part of ["summary", "results"])
    await page.route(`**/v1/jobs/${id}/${part}`, (r) => r.fulfill(json(part === "results" ? { artifacts: [] } : {
      id, name: job.name, status: "succeeded", reason: null, labels: {}, iterations: n, wall_time: 4,
      max_displacement: 1, max_mises: 1, max_contact_pressure: null, total_contact_force: null })));
  await page.goto(`${OPEN}/jobs/${id}`);
  await page.waitForSelector("#job-header[data-history-loaded]");
  assert.deepEqual(requests, [null, String(cut)], "one reconnect, resuming after the last event seen");
  assert.equal(await points(page, "#plot-residual"), n);
  const seqs = await page.$$eval("#log li", (lines) => lines.map((l) => Number(l.textContent.match(/^#(\d+)/)[1])));
  assert.deepEqual(seqs, events.map((_, i) => i + 1));
});

test("fields the solver will add: stick/slip series and other numeric measures are plotted", async (t) => {
  // The solver does not report friction yet: the page gets a job whose API answers are
  // served by the test (playwright routes), the rest is the real page.
  const id = "f".repeat(32);
  const job = await api(OPEN, `/v1/jobs/${contact_job.id}`);
  Object.assign(job, { id, name: "friction-preview", status: "succeeded" });
  const n = 60;
  const events = [{ event: "status", status: "running" }, { event: "step", step: 1 }];
  for (let i = 1; i <= n; i += 1) {
    const inc = Math.ceil(i / 4), it = ((i - 1) % 4) + 1;
    events.push({ event: "iteration", step: 1, increment: inc, attempt: 1, iteration: it, step_time: inc / 15,
                  total_time: inc / 15, dt: 1 / 15, residual: 10 ** (2 - it), correction: 10 ** (1 - it),
                  contact_elements: 100 + i, stick: 60 + (i % 7), slip: 40 - (i % 7), stabilisation_energy: 1e-3 / i,
                  wall_time: i / 10 });
    if (it === 4) events.push({ event: "increment", step: 1, increment: inc, attempt: 1, iteration: 4,
                                step_time: inc / 15, total_time: inc / 15, dt: 1 / 15, contact_elements: 100 + i, wall_time: i / 10 });
  }
  events.push({ event: "done", status: "converged", summary: { iterations: n } }, { event: "status", status: "succeeded" });
  const body = sse_frames(events);
  const page = await open_page(t);
  const json = (data) => ({ status: 200, contentType: "application/json", body: JSON.stringify(data) });
  await page.route(`**/v1/jobs/${id}`, (r) => r.fulfill(json(job)));
  await page.route(`**/v1/jobs/${id}/events`, (r) => r.fulfill({ status: 200, contentType: "text/event-stream", body }));
  await page.route(`**/v1/jobs/${id}/summary`, (r) => r.fulfill(json({ id, name: job.name, status: "succeeded", reason: null,
    labels: {}, iterations: n, wall_time: 6, max_displacement: 1, max_mises: 2, max_contact_pressure: 3, total_contact_force: 4 })));
  await page.route(`**/v1/jobs/${id}/results`, (r) => r.fulfill(json({ artifacts: [] })));
  await page.goto(`${OPEN}/jobs/${id}`);
  await page.waitForSelector("#job-header[data-history-loaded]");
  assert.equal(await points(page, "#plot-residual"), n);
  assert.equal(await points(page, "#plot-contact"), n);
  assert.match(await page.textContent("#contact-title"), /stick, slip/);
  const legend = await page.textContent("#plot-contact .u-legend");
  assert.match(legend, /stick/);
  assert.match(legend, /slip/);
  assert.ok(await page.isVisible("#extra-card"));
  assert.equal(await points(page, "#plot-extra [data-field=stabilisation_energy]"), n);
  assert.equal(await page.locator("#plot-extra .plot").count(), 1, "only the unknown numeric field");
  assert.match(await page.textContent("#log"), /stick 66 slip 34 stabilisation_energy/);
  await shot(page, "job_friction_fields");
});

test("unknown job: a clear message, no crash", async (t) => {
  const page = await open_page(t);
  await page.goto(`${OPEN}/jobs/${"0".repeat(32)}`);
  await page.waitForSelector("#page-error");
  assert.match(await page.textContent("#page-error"), /no job 0{32}/);
  page.errors = page.errors.filter((e) => !/404/.test(e));  // the refused lookup itself
  await page.goto(`${OPEN}/jobs/nonsense`);
  await page.waitForSelector("#page-error");
  assert.match(await page.textContent("#page-error"), /not a job id/);
});
