// The header every page shares: navigation, the queue depth and the workers' use, refreshed
// while the tab is visible.
import { get_json } from "./api.js";
import { el, fill } from "./dom.js";

const REFRESH_MS = 3000;

async function refresh() {
  if (document.visibilityState !== "visible") return;
  try {
    const q = await get_json("/v1/queue");
    fill("queue",
      el("span", { "data-queued": q.queued }, `${q.queued} queued`), " · ",
      el("span", { "data-running": q.running }, `${q.running} running`), " · ",
      el("span", { "data-busy": q.busy_workers, "data-workers": q.workers },
         `workers ${q.busy_workers}/${q.workers} busy`),
      el("span", { class: "meter", title: "worker use" },
         el("span", { style: { width: `${q.workers ? (100 * q.busy_workers) / q.workers : 0}%` } })));
  } catch (e) {
    fill("queue", el("span", { class: "error" }, "daemon unreachable: " + e.message));
  }
}

export function start_header() {
  refresh();
  setInterval(refresh, REFRESH_MS);
  document.addEventListener("visibilitychange", refresh);
}
