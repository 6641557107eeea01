// The job page (/jobs/{id}): header, convergence plots, increments, event log tail, summary,
// results, cancel and resubmit. One event stream feeds everything: it replays the stored
// history (a finished job renders from it) and then follows the run live, resuming after a
// dropped connection with Last-Event-ID. Redraws are batched, at most five a second.
import { ApiError, download_with_token, get_json, post_json } from "./api.js";
import { stored_token } from "./auth.js";
import { prefers_log } from "./axis_format.js";
import { COLORS, make_chart, show_data } from "./charts.js";
import { el, fill, label_chips, status_chip } from "./dom.js";
import { EventLog } from "./event_log.js";
import { EventStream } from "./event_stream.js";
import { fmt_bytes, fmt_duration, fmt_number, fmt_time, seconds_between } from "./format.js";
import { start_header } from "./header.js";
import { RunHistory } from "./run_history.js";
import { VirtualRows } from "./virtual_rows.js";

const SCHEMES = ["nts", "gauss", "lgauss", "gc1", "gc3", "gc7", "gc12", "lgc1", "lgc3", "lgc7", "lgc12"];
const TERMINAL = new Set(["succeeded", "failed", "canceled"]);
const RENDER_MS = 200;
const POLL_MS = 2000;  // the status document (queue position, progress) while the job is live
const ROW_HEIGHT = 24;  // px, about what dashboard.css gives an .increments row

const id = location.pathname.split("/")[2] || "";
const runs = new RunHistory();
const log = new EventLog(document.getElementById("log"));
let job = null;
let charts = null;
let drawn_version = -1;
const increments = new VirtualRows(document.querySelector("#increments").parentElement,
                                   document.querySelector("#increments tbody"), ROW_HEIGHT,
                                   (i) => increment_row(runs.increments[i]));
let render_timer = null;
let finished_loaded = false;
const resubmit_key = random_key();

function random_key() {
  const bytes = crypto.getRandomValues(new Uint8Array(16));
  return [...bytes].map((b) => b.toString(16).padStart(2, "0")).join("");
}

function show_error(message) {
  let banner = document.getElementById("page-error");
  if (!banner) {
    banner = el("p", { id: "page-error", class: "error banner" });
    document.querySelector("main").prepend(banner);
  }
  banner.textContent = message;
}

// ---- header ------------------------------------------------------------------------------

function fact(name, ...value) {
  return [el("dt", {}, name), el("dd", {}, ...value)];
}

function render_header() {
  document.title = `${job.name} · kontaktd`;
  fill("job-name", job.name);
  fill("job-status", status_chip(job.status, job.reason));
  const reason = document.getElementById("job-reason");
  reason.textContent = job.reason ? `${job.reason.code}: ${job.reason.message}` : "";
  const now = Date.now();
  const waited = seconds_between(job.created, job.started, now);
  const ran = job.started ? seconds_between(job.started, job.finished, now) : null;
  fill("job-facts",
    ...fact("id", el("code", {}, job.id)),
    ...fact("deck", job.main),
    ...fact("scheme", job.scheme || "the deck's own"),
    ...fact("labels", label_chips(job.labels)),
    ...fact("queue position", job.queue_position ?? "–"),
    ...fact("attempts", job.attempts),
    ...fact("created", fmt_time(job.created)),
    ...fact("started", fmt_time(job.started) || "–"),
    ...fact("finished", fmt_time(job.finished) || "–"),
    ...fact("waited", fmt_duration(job.started ? waited : seconds_between(job.created, null, now))),
    ...fact("run time", ran === null ? "–" : fmt_duration(ran)),
    ...fact("progress", `${job.progress.percent.toFixed(1)} % · step ${job.progress.step}/${job.progress.steps_total}` +
                        ` · inc ${job.progress.increment} · it ${job.progress.iteration}`));
  document.getElementById("job-progress").style.width = `${job.progress.percent}%`;
  const cancel = document.getElementById("cancel");
  cancel.hidden = TERMINAL.has(job.status);
  cancel.disabled = job.status === "canceling";
  document.getElementById("resubmit").disabled = false;
  if (TERMINAL.has(job.status) && !finished_loaded) {
    finished_loaded = true;
    load_summary();
    load_results();
  }
}

let refresh_timer = null;
let latest_refresh = 0;
function refresh_job(delay = 100) {
  clearTimeout(refresh_timer);
  refresh_timer = setTimeout(async () => {
    const mine = ++latest_refresh;  // an older answer arriving late must not win
    try {
      const fresh = await get_json(`/v1/jobs/${id}`);
      if (mine !== latest_refresh) return;
      job = fresh;
      render_header();
    } catch (e) {
      show_error(e.message);
    }
  }, delay);
}

function build_actions() {
  const select = document.getElementById("resubmit-scheme");
  select.append(el("option", { value: "same" }, "same as this job"),
                el("option", { value: "deck" }, "the deck's own"),
                ...SCHEMES.map((s) => el("option", { value: s }, s)));
  document.getElementById("cancel").addEventListener("click", async (e) => {
    e.target.disabled = true;
    try {
      job = await post_json(`/v1/jobs/${id}/cancel`);
      render_header();
    } catch (err) {
      show_error(err.message);
      e.target.disabled = false;
    }
  });
  document.getElementById("resubmit").addEventListener("click", async (e) => {
    const choice = select.value;
    const body = choice === "same" ? {} : { scheme: choice === "deck" ? null : choice };
    e.target.disabled = true;
    try {
      const created = await post_json(`/v1/jobs/${id}/resubmit`, body,
                                      { "Idempotency-Key": `${resubmit_key}-${choice}` });
      location.assign(`/jobs/${created.id}`);
    } catch (err) {
      show_error("resubmit: " + err.message);
      e.target.disabled = false;
    }
  });
}

// ---- summary and results -----------------------------------------------------------------

async function load_summary() {
  try {
    const s = await get_json(`/v1/jobs/${id}/summary`);
    const { drift_refreezes: refreezes, drift_redos: drift } = runs.done?.summary ?? {};
    fill("summary",
      ...fact("status", status_chip(s.status, s.reason)),
      ...fact("iterations", s.iterations ?? "–"),
      ...fact("wall time", s.wall_time === null ? "–" : fmt_duration(s.wall_time)),
      ...fact("max |U|", fmt_number(s.max_displacement) || "–"),
      ...fact("max von Mises", fmt_number(s.max_mises) || "–"),
      ...fact("max CPRESS", fmt_number(s.max_contact_pressure) || "–"),
      ...fact("total contact force", fmt_number(s.total_contact_force) || "–"),
      ...(refreezes !== undefined ? fact("drift refreezes", refreezes) : []),
      ...(drift !== undefined ? fact("drift redos", drift) : []));
  } catch (e) {
    show_error("summary: " + e.message);
  }
}

async function load_results() {
  try {
    const { artifacts } = await get_json(`/v1/jobs/${id}/results`);
    const rows = artifacts.map((a) => {
      const url = `/v1/jobs/${id}/results/${encodeURIComponent(a.name)}`;
      const link = el("a", { href: url, download: a.name }, a.name);
      link.addEventListener("click", (e) => {
        if (!stored_token()) return;  // the browser follows the link itself
        e.preventDefault();
        download_with_token(url, a.name).catch((err) => show_error(err.message));
      });
      return el("tr", { "data-name": a.name }, el("td", {}, link), el("td", { class: "num" }, fmt_bytes(a.size)),
                el("td", {}, el("code", { class: "sha", title: a.sha256 }, a.sha256)));
    });
    if (!rows.length) rows.push(el("tr", {}, el("td", { colspan: 3, class: "empty" }, "no result files")));
    document.querySelector("#results tbody").replaceChildren(...rows);
  } catch (e) {
    show_error("results: " + e.message);
  }
}

// ---- plots, increments, log --------------------------------------------------------------

function iteration_x() {
  return { label: "iteration", value: (u, v, s, idx) => (idx === null ? "" : runs.where[idx] ?? "") };
}

function make_contact_chart() {
  const series = [{ label: "active" }];
  if (runs.has_friction) series.push({ label: "stick", stroke: COLORS[1] }, { label: "slip", stroke: COLORS[4] });
  const box = document.getElementById("plot-contact");
  box.replaceChildren();
  document.getElementById("contact-title").textContent =
    runs.has_friction ? "Contact elements per iteration: active, stick, slip" : "Active contact elements per iteration";
  return { u: make_chart(box, { x: iteration_x(), y: { label: "elements" }, series, markers: () => runs.markers, sync: "it" }),
           friction: runs.has_friction };
}

function make_charts() {
  charts = {
    residual: make_chart(document.getElementById("plot-residual"), {
      x: iteration_x(), y: { label: "%", log: true },
      series: [{ label: "residual", span_gaps: true }, { label: "correction", span_gaps: true }],
      markers: () => runs.markers, sync: "it",
      on_first_draw: () => performance.mark("kontakt:first-plot"),
    }),
    dt: make_chart(document.getElementById("plot-dt"), {
      x: { label: "total time" }, y: { label: "increment", log: true },
      series: [{ label: "converged", span_gaps: true }, { label: "cut back", points_only: true, stroke: "#c62828" }],
    }),
    contact: null,
    extra: new Map(),
  };
}

function draw_extra(name, column) {
  let chart = charts.extra.get(name);
  if (!chart) {
    document.getElementById("extra-card").hidden = false;
    const box = el("div", { class: "plot", "data-field": name });
    document.getElementById("plot-extra").append(el("div", {}, el("h3", {}, name), box));
    chart = { box, u: make_chart(box, { x: iteration_x(), y: { label: name, log: prefers_log(column) },
                                        series: [{ label: name, span_gaps: true }],
                                        markers: () => runs.markers, sync: "it" }) };
    charts.extra.set(name, chart);
  }
  show_data(chart.u, [runs.x, column], chart.box, column.reduce((n, v) => n + (v !== null), 0));
}

function increment_row(r) {
  const outcome = r.converged ? "converged" : r.cause === "drift" ? "drift redo" : "cutback";
  return el("tr", {
    class: r.converged ? "" : `row-${r.cause}`, title: r.message || null,
    "data-step": r.step, "data-increment": r.increment, "data-attempt": r.attempt,
    "data-iterations": r.iterations, "data-converged": String(r.converged),
  },
  el("td", { class: "num" }, r.step), el("td", { class: "num" }, r.increment),
  el("td", { class: "num" }, r.attempt), el("td", { class: "num" }, r.iterations ?? ""),
  el("td", { class: "num" }, fmt_number(r.step_time)), el("td", { class: "num" }, fmt_number(r.total_time)),
  el("td", { class: "num" }, fmt_number(r.dt)), el("td", { class: "num" }, r.contact_elements ?? ""),
  el("td", { class: "num" }, fmt_duration(r.wall_time)), el("td", {}, outcome));
}

function render() {
  render_timer = null;
  if (runs.version !== drawn_version) {
    drawn_version = runs.version;
    if (!charts) make_charts();
    show_data(charts.residual, [runs.x, runs.residual, runs.correction],
              document.getElementById("plot-residual"), runs.n_iterations);
    const dt = runs.dt_columns();
    show_data(charts.dt, dt, document.getElementById("plot-dt"), dt[0].length);
    if (!runs.has_contact && runs.n_iterations > 0)
      fill("plot-contact", el("p", { class: "empty" }, "No contact in this model."));
    if (runs.has_contact) {
      if (!charts.contact || charts.contact.friction !== runs.has_friction) charts.contact = make_contact_chart();
      const columns = [runs.x, runs.contact];
      if (runs.has_friction) columns.push(runs.stick, runs.slip);
      show_data(charts.contact.u, columns, document.getElementById("plot-contact"), runs.n_iterations);
    }
    for (const [name, column] of runs.extra) draw_extra(name, column);
    increments.set_count(runs.increments.length);
    const cut = runs.increments.filter((r) => !r.converged).length;
    fill("increment-count", `(${runs.increments.length - cut} converged, ${cut} cut back)`);
  }
  log.flush();
}

let render_ms = 0;  // how long the last redraw took

/** The first redraw at once; then at most every RENDER_MS, and rendering never takes more
 *  than about a quarter of the time while a long history streams in. */
function schedule_render() {
  if (render_timer) return;
  const delay = drawn_version < 0 ? 0 : Math.max(RENDER_MS, 3 * render_ms);
  render_timer = setTimeout(() => {
    const start = performance.now();
    render();
    render_ms = performance.now() - start;
  }, delay);
}

/** Notes for plots that stay empty once the stream has ended. */
function explain_empty_plots() {
  if (!runs.n_iterations)
    fill("plot-residual", el("p", { class: "empty" }, "No Newton iterations: linear steps are solved directly."));
  if (!runs.has_contact)
    fill("plot-contact", el("p", { class: "empty" }, "No contact in this model."));
}

function on_stream_state(state) {
  const text = state === "live" ? "● live" : state === "reconnecting" ? "○ reconnecting…" : state === "ended" ? "" : state;
  fill("stream-state", text);
  document.getElementById("stream-state").dataset.state = state;
  if (state === "ended") {
    load_summary();  // again: the drift counts come from the done event just replayed
    render();
    explain_empty_plots();
    document.getElementById("job-header").dataset.historyLoaded = "true";
    performance.mark("kontakt:history-loaded");
  }
}

// ---- start -------------------------------------------------------------------------------

async function main() {
  start_header();
  build_actions();
  if (!/^[0-9a-f]{32}$/.test(id)) {
    show_error(`"${id}" is not a job id`);
    return;
  }
  // The stream opens at once, beside the job document: the plots need not wait for it.
  const stream = new EventStream(`/v1/jobs/${id}/events`, {
    on_events(events) {
      for (const e of events) runs.add(e);
      log.add(events);
      if (job && events.some((e) => e.event === "status")) refresh_job();
      schedule_render();
    },
    on_state: on_stream_state,
    is_last: (e) => e.event === "status" && TERMINAL.has(e.status),
  });
  const streaming = stream.run();
  try {
    job = await get_json(`/v1/jobs/${id}`);
  } catch (e) {
    stream.close();
    show_error(e instanceof ApiError && e.status === 404 ? `There is no job ${id}.` : e.message);
    return;
  }
  render_header();
  setInterval(() => {
    if (!TERMINAL.has(job.status)) refresh_job(0);
  }, POLL_MS);
  await streaming;
}

main();
