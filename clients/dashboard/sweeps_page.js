// Sweeps (/sweeps?label=KEY[&filter=k=v...]): the jobs sharing a label key as one table,
// ordered by the label's value, with a summary quantity plotted against it; refreshed while
// jobs still run. `filter` keeps the jobs with other labels too (one design loop among
// several: filter=sweep=load-sweep). Without ?label=, the label keys in use.
import { get_all_pages, get_json } from "./api.js";
import { make_chart, show_data } from "./charts.js";
import { el, fill, status_chip } from "./dom.js";
import { fmt_duration, fmt_number, fmt_time } from "./format.js";
import { start_header } from "./header.js";
import { QUANTITIES, sort_rows, sweep_series } from "./sweep_rows.js";

const REFRESH_MS = 3000;
const TERMINAL = new Set(["succeeded", "failed", "canceled"]);
const query = new URLSearchParams(location.search);
const key = query.get("label");
const filters = query.getAll("filter").filter((f) => f.includes("="));

let rows = [];
let chart = null;
let categories = null;

async function show_index() {
  document.getElementById("sweep-index").hidden = false;
  const { sweeps } = await get_json("/v1/sweeps");
  const trs = sweeps.map((s) => el("tr", {},
    el("td", {}, el("a", { href: `/sweeps?label=${encodeURIComponent(s.key)}` }, s.key)),
    el("td", { class: "num" }, s.jobs), el("td", { class: "time" }, fmt_time(s.latest))));
  if (!trs.length) trs.push(el("tr", {}, el("td", { colspan: 3, class: "empty" }, "no job has a label yet")));
  document.querySelector("#sweep-list tbody").replaceChildren(...trs);
}

/** This page with other filters. */
function sweep_url(with_filters) {
  const q = new URLSearchParams({ label: key });
  for (const f of with_filters) q.append("filter", f);
  return "/sweeps?" + q.toString();
}

/** The row's other labels; each narrows the sweep to the jobs that share it. */
function other_labels(r) {
  const span = el("span", { class: "labels" });
  for (const [k, v] of Object.entries(r.labels)) {
    if (k === key || filters.includes(`${k}=${v}`)) continue;
    span.append(el("a", { class: "label", href: sweep_url([...filters, `${k}=${v}`]),
                          title: `only the jobs with ${k}=${v}` }, `${k}=${v}`));
  }
  return span;
}

function show_filters() {
  if (!filters.length) return;
  fill("sweep-filter", "only jobs with ", ...filters.flatMap((f) => [
    el("span", { class: "label" }, f, " ",
       el("a", { href: sweep_url(filters.filter((g) => g !== f)), title: "remove this filter" }, "✕")), " "]));
}

function table_row(r) {
  return el("tr", { "data-id": r.id, "data-value": r.value },
    el("td", { class: "num" }, r.value),
    el("td", {}, el("a", { href: `/jobs/${r.id}` }, r.name), el("span", { class: "id" }, " " + r.id.slice(0, 8))),
    el("td", {}, status_chip(r.status, r.reason)),
    el("td", {}, r.scheme || ""),
    el("td", { class: "num" }, r.iterations ?? ""),
    el("td", { class: "num" }, r.wall_time === null ? "" : fmt_duration(r.wall_time)),
    el("td", { class: "num" }, fmt_number(r.max_displacement)),
    el("td", { class: "num" }, fmt_number(r.max_mises)),
    el("td", { class: "num" }, fmt_number(r.max_contact_pressure)),
    el("td", { class: "num" }, fmt_number(r.total_contact_force)),
    el("td", {}, other_labels(r)),
    el("td", { class: "time" }, fmt_time(r.created)));
}

function draw_plot() {
  const field = document.getElementById("quantity").value;
  const quantity = QUANTITIES.find((q) => q.key === field);
  const s = sweep_series(rows, field);
  categories = s.categories;
  const box = document.getElementById("plot-sweep");
  if (!chart || chart.categorical !== Boolean(categories) || chart.field !== field) {
    box.replaceChildren();
    chart = {
      categorical: Boolean(categories), field,
      u: make_chart(box, { x: { label: key, categories: categories ? () => categories : null },
                           y: { label: quantity.label }, series: [{ label: quantity.label, span_gaps: true, point_size: 7 }] }),
    };
  }
  show_data(chart.u, [s.x, s.y], box, s.x.length);
  fill("sweep-note", s.repeated ? `${s.repeated} older job(s) of a repeated value are in the table, not in the plot.` : "");
}

async function refresh() {
  try {
    const q = new URLSearchParams();
    for (const f of filters) q.append("label", f);
    rows = sort_rows(await get_all_pages(`/v1/sweeps/${encodeURIComponent(key)}?${q}`, "jobs"));
  } catch (e) {
    fill("sweep-counts", el("span", { class: "error" }, e.message));
    return true;  // try again
  }
  const done = rows.filter((r) => r.status === "succeeded").length;
  const live = rows.filter((r) => !TERMINAL.has(r.status)).length;
  fill("sweep-counts", `${rows.length} jobs: ${done} succeeded, ${live} queued or running, ` +
                       `${rows.length - done - live} failed or canceled`);
  document.querySelector("#sweep-table tbody").replaceChildren(...rows.map(table_row));
  draw_plot();
  return live > 0;
}

async function show_sweep() {
  document.getElementById("sweep").hidden = false;
  fill("sweep-title", `Sweep over `, el("code", {}, key));
  show_filters();
  document.title = `${key} · sweeps · kontaktd`;
  const select = document.getElementById("quantity");
  select.append(...QUANTITIES.map((q) => el("option", { value: q.key }, q.label)));
  select.addEventListener("change", draw_plot);
  const poll = async () => {
    if (document.visibilityState !== "visible" || await refresh()) setTimeout(poll, REFRESH_MS);
  };
  await refresh();
  performance.mark("kontakt:sweep-shown");
  if (rows.some((r) => !TERMINAL.has(r.status))) setTimeout(poll, REFRESH_MS);
}

start_header();
(key ? show_sweep() : show_index()).catch((e) => fill("sweep-counts", e.message));
