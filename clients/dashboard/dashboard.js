// kontaktd dashboard: the job list with status chips and progress, kept live by one SSE
// stream per running job (closed by the server when the job ends). Plain JS, no build step.
"use strict";

const token = new URLSearchParams(location.search).get("access_token");
const auth = token ? { Authorization: "Bearer " + token } : {};
const withToken = (url) => (token ? url + (url.includes("?") ? "&" : "?") + "access_token=" + encodeURIComponent(token) : url);
const streams = new Map();  // job id -> EventSource
const rows = new Map();     // job id -> <tr>

async function getJson(url) {
  const r = await fetch(url, { headers: auth });
  if (!r.ok) throw new Error(url + ": HTTP " + r.status);
  return r.json();
}

function cell(text) {
  const td = document.createElement("td");
  td.textContent = text;
  return td;
}

function render(job) {
  let tr = rows.get(job.id);
  if (!tr) {
    tr = document.createElement("tr");
    tr.dataset.id = job.id;
    rows.set(job.id, tr);
    document.querySelector("#jobs tbody").prepend(tr);
  }
  const p = job.progress;
  tr.replaceChildren();
  tr.append(cell(job.name + " (" + job.id.slice(0, 8) + ")"));
  const chip = document.createElement("span");
  chip.className = "chip " + job.status;
  chip.textContent = job.reason && job.reason.code !== job.status ? job.status + ": " + job.reason.code : job.status;
  const status = document.createElement("td");
  status.append(chip);
  tr.append(status);
  const bar = document.createElement("div");
  bar.className = "bar";
  bar.innerHTML = "<div></div>";
  bar.firstChild.style.width = p.percent.toFixed(0) + "%";
  const progress = document.createElement("td");
  progress.append(bar);
  tr.append(progress);
  tr.append(cell(p.step + "/" + p.steps_total + " · " + p.increment + " · " + p.iteration));
  tr.append(cell(p.last_residual === null ? "" : p.last_residual.toExponential(2)));
  tr.append(cell(job.created.replace("T", " ").slice(0, 19)));
  const action = document.createElement("td");
  if (job.status === "queued" || job.status === "running") {
    const b = document.createElement("button");
    b.textContent = "cancel";
    b.onclick = () => fetch("/v1/jobs/" + job.id + "/cancel", { method: "POST", headers: auth });
    action.append(b);
  }
  tr.append(action);
  if (job.status === "queued" || job.status === "running" || job.status === "canceling") follow(job.id);
}

// On each event, re-read the status document (progress, status) of that job.
function follow(id) {
  if (streams.has(id)) return;
  const es = new EventSource(withToken("/v1/jobs/" + id + "/events"));
  streams.set(id, es);
  let pending = false;
  const refresh = () => {
    if (pending) return;
    pending = true;
    setTimeout(async () => {
      pending = false;
      try { render(await getJson("/v1/jobs/" + id)); } catch (e) { /* next event retries */ }
    }, 250);
  };
  for (const kind of ["status", "step", "increment", "iteration", "done"]) es.addEventListener(kind, refresh);
  es.onerror = () => { es.close(); streams.delete(id); refresh(); };
}

async function poll() {
  try {
    const health = await getJson("/healthz");
    document.getElementById("health").textContent =
      "v" + health.version + " · " + health.busy_workers + "/" + health.workers + " workers busy · " + health.queued + " queued";
    const page = await getJson("/v1/jobs?limit=50");
    for (const job of page.jobs.reverse()) render(job);
  } catch (e) {
    document.getElementById("health").textContent = String(e);
  }
}

poll();
setInterval(poll, 5000);  // picks up jobs submitted elsewhere
