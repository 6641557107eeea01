// One line of the event log tail per event, in the spirit of ccx's .sta/.msg (pure).
import { fmt_duration, fmt_number } from "./format.js";

const KNOWN = new Set(["event", "seq", "run", "step", "increment", "attempt", "iteration",
  "step_time", "total_time", "dt", "wall_time", "residual", "correction", "contact_elements",
  "status", "reason", "message", "summary"]);

function where(e) {
  const parts = [];
  if (e.step !== undefined) parts.push(`step ${e.step}`);
  if (e.increment !== undefined) parts.push(`inc ${e.increment}`);
  if (e.attempt !== undefined && e.attempt > 1) parts.push(`att ${e.attempt}`);
  return parts.join(" ");
}

/** The other numeric members ("stick 12 slip 3"), so new solver fields show up in the log. */
function extras(e) {
  return Object.entries(e)
    .filter(([k, v]) => !KNOWN.has(k) && typeof v === "number")
    .map(([k, v]) => ` ${k} ${fmt_number(v)}`).join("");
}

const SUMMARY_PARTS = [["max_displacement", "max |U|"], ["max_mises", "max Mises"],
  ["max_contact_pressure", "max CPRESS"], ["total_contact_force", "contact force"]];

function summary_text(s) {
  if (!s) return "";
  const parts = [`${s.iterations} iterations`];
  for (const [k, name] of SUMMARY_PARTS) if (typeof s[k] === "number") parts.push(`${name} ${fmt_number(s[k])}`);
  if (s.drift_refreezes) parts.push(`${s.drift_refreezes} drift refreezes`);
  if (s.drift_redos) parts.push(`${s.drift_redos} drift redos`);
  return ": " + parts.join(", ");
}

/** "#812 [1.4 s] step 1 inc 3 it 2  residual 0.12 %  correction 3.4e-3 %  contact 48" */
export function event_text(e) {
  const head = `#${e.seq}` + (e.wall_time !== undefined ? ` [${fmt_duration(e.wall_time)}]` : "");
  const contact = e.contact_elements !== undefined ? `  contact ${e.contact_elements}` : "";
  switch (e.event) {
    case "status":
      return `${head} status ${e.status}` + (e.reason ? ` (${e.reason})` : "") +
             (e.message ? `: ${e.message}` : "");
    case "step":
      return `${head} ${where(e)} begins`;
    case "iteration":
      return `${head} ${where(e)} it ${e.iteration}  residual ${fmt_number(e.residual)} %` +
             `  correction ${fmt_number(e.correction)} %${contact}${extras(e)}`;
    case "increment":
      return `${head} ${where(e)} converged in ${e.iteration} it  dt ${fmt_number(e.dt)}` +
             `  time ${fmt_number(e.total_time)}${contact}`;
    case "cutback":
      return `${head} ${where(e)} cut back after ${e.iteration} it  dt ${fmt_number(e.dt)}: ${e.message || ""}`;
    case "output":
      return `${head} ${where(e)} output at time ${fmt_number(e.total_time)}`;
    case "done":
      return `${head} done ${e.status}` + (e.status === "converged" ? summary_text(e.summary) : `: ${e.message || ""}`);
    default:
      return `${head} ${e.event}${e.message ? ": " + e.message : ""}${extras(e)}`;
  }
}
