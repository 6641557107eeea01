// The job list: status and label filters, cursor pages, links to the job pages; the visible
// page is re-read every few seconds and only the rows that changed are redrawn.
import { get_json, post_json } from "./api.js";
import { el, label_chips, status_chip } from "./dom.js";
import { fmt_duration, fmt_number, fmt_time, seconds_between } from "./format.js";
import { start_header } from "./header.js";
import { PAGE_SIZES, STATUSES, api_url, first_page, next_page, parse_label_filter,
         previous_page, read_state, state_query } from "./list_query.js";

const REFRESH_MS = 2000;

let state = read_state(location.search);
let next_token = null;
const rows = new Map();  // job id -> {tr, key}

function progress_cell(job) {
  const bar = el("div", { class: "bar" }, el("div", { style: { width: `${job.progress.percent.toFixed(1)}%` } }));
  return el("td", { class: "progress", title: `${job.progress.percent.toFixed(1)} %` }, bar);
}

function run_time(job) {
  return fmt_duration(seconds_between(job.started, job.finished, Date.now()));
}

function cancel_button(job) {
  if (job.status !== "queued" && job.status !== "running") return null;
  return el("button", {
    type: "button", class: "small",
    onclick: async (e) => {
      e.target.disabled = true;
      try { update_row(await post_json(`/v1/jobs/${job.id}/cancel`)); } catch (err) { alert(err.message); }
    },
  }, "cancel");
}

function row_cells(job) {
  const p = job.progress;
  const position = job.queue_position ? ` #${job.queue_position}` : "";
  return [
    el("td", {}, el("a", { href: `/jobs/${job.id}`, class: "job-link" }, job.name),
       el("span", { class: "id" }, " " + job.id.slice(0, 8))),
    el("td", {}, status_chip(job.status, job.reason), position),
    progress_cell(job),
    el("td", { class: "num" }, `${p.step}/${p.steps_total} · ${p.increment} · ${p.iteration}`),
    el("td", { class: "num" }, fmt_number(p.last_residual)),
    el("td", { class: "num" }, p.active_contact_elements ?? ""),
    el("td", {}, label_chips(job.labels)),
    el("td", {}, job.scheme || ""),
    el("td", { class: "time" }, fmt_time(job.created)),
    el("td", { class: "num" }, run_time(job)),
    el("td", {}, cancel_button(job)),
  ];
}

/** Redraws a row only when the job changed (or its run time keeps moving). */
function update_row(job) {
  const key = `${job.updated}|${job.status}|${job.queue_position}`;
  let row = rows.get(job.id);
  if (!row) {
    row = { tr: el("tr", { "data-id": job.id }), key: null };
    rows.set(job.id, row);
  }
  if (row.key !== key || job.status === "running") {
    row.tr.dataset.status = job.status;
    row.tr.replaceChildren(...row_cells(job));
    row.key = key;
  }
  return row.tr;
}

let latest_load = 0;

async function load() {
  // A refresh still in flight when the reader pages on must not draw the old page over it.
  const mine = ++latest_load;
  let page;
  try {
    page = await get_json(api_url(state));
  } catch (e) {
    if (mine === latest_load) document.getElementById("page-info").textContent = e.message;
    return;
  }
  if (mine !== latest_load) return;
  const tbody = document.querySelector("#jobs tbody");
  const shown = new Set(page.jobs.map((j) => j.id));
  for (const id of rows.keys()) if (!shown.has(id)) rows.delete(id);
  const trs = page.jobs.map(update_row);
  // Reorder only when the page's rows changed, so a refresh does not touch the DOM otherwise.
  const same = trs.length === tbody.children.length && trs.every((tr, i) => tbody.children[i] === tr);
  if (!same) tbody.replaceChildren(...trs);
  if (!page.jobs.length)
    tbody.replaceChildren(el("tr", {}, el("td", { colspan: 11, class: "empty" }, "no jobs match")));
  next_token = page.next_page_token;
  const first = state.back.length * state.limit;
  document.getElementById("page-info").textContent =
    page.jobs.length ? `jobs ${first + 1}–${first + page.jobs.length}` : "";
  document.getElementById("next-page").disabled = !next_token;
  document.getElementById("previous-page").disabled = !state.page_token;
  document.getElementById("first-page").disabled = !state.page_token;
}

function go(new_state) {
  state = new_state;
  history.pushState(null, "", "/" + state_query(state));
  show_filters();
  load();
}

function show_filters() {
  for (const box of document.querySelectorAll("#status-filter input"))
    box.checked = state.statuses.includes(box.value);
  document.getElementById("label-filter").value = state.labels.join(", ");
  document.getElementById("page-size").value = String(state.limit);
}

function build_filters() {
  const statuses = document.getElementById("status-filter");
  for (const s of STATUSES)
    statuses.append(el("label", { class: "check" }, el("input", { type: "checkbox", value: s }), s));
  const size = document.getElementById("page-size");
  for (const n of PAGE_SIZES) size.append(el("option", { value: n }, n));
  document.getElementById("filters").addEventListener("submit", (e) => {
    e.preventDefault();
    const parsed = parse_label_filter(document.getElementById("label-filter").value);
    document.getElementById("filter-error").textContent = parsed.error || "";
    if (parsed.error) return;
    const checked = [...document.querySelectorAll("#status-filter input:checked")].map((b) => b.value);
    go(first_page(checked, parsed.labels, Number(size.value)));
  });
  for (const input of document.querySelectorAll("#status-filter input, #page-size"))
    input.addEventListener("change", () => document.getElementById("filters").requestSubmit());
  document.getElementById("next-page").addEventListener("click", () => go(next_page(state, next_token)));
  document.getElementById("previous-page").addEventListener("click", () => go(previous_page(state)));
  document.getElementById("first-page").addEventListener("click",
    () => go(first_page(state.statuses, state.labels, state.limit)));
  window.addEventListener("popstate", () => {
    state = read_state(location.search);
    show_filters();
    load();
  });
}

start_header();
build_filters();
show_filters();
load().then(() => performance.mark("kontakt:list-shown"));
setInterval(() => {
  if (document.visibilityState === "visible") load();
}, REFRESH_MS);
