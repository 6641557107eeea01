// A sweep's rows (GET /v1/sweeps/{key}) ordered by the label's value, and the series of one
// summary quantity against that value for the plot. Pure; tested under node.

export const QUANTITIES = [
  { key: "max_displacement", label: "max |U|" },
  { key: "max_mises", label: "max von Mises" },
  { key: "max_contact_pressure", label: "max CPRESS" },
  { key: "total_contact_force", label: "total contact force" },
  { key: "iterations", label: "iterations" },
  { key: "wall_time", label: "wall time (s)" },
];

const as_number = (v) => (typeof v === "string" && v.trim() !== "" ? Number(v) : NaN);

/** True when every value reads as a finite number ("0.5", "1e3", "-2"). */
export function values_are_numeric(rows) {
  return rows.length > 0 && rows.every((r) => Number.isFinite(as_number(r.value)));
}

function compare_values(numeric) {
  const collator = new Intl.Collator(undefined, { numeric: true });
  return numeric ? (a, b) => as_number(a) - as_number(b) : (a, b) => collator.compare(a, b);
}

/** Rows by value, then newest first for a repeated value. */
export function sort_rows(rows) {
  const by_value = compare_values(values_are_numeric(rows));
  return [...rows].sort((a, b) => by_value(a.value, b.value) || b.created.localeCompare(a.created));
}

/**
 * The plot of `field` against the value, from succeeded jobs only; a value run more than once
 * shows its newest job. Numeric values give x = the values; other values give x = 0, 1, ...
 * with `categories` naming them (every value of the sweep, so the axis is stable).
 * Returns {x, y, categories, repeated: jobs not shown because their value ran again}.
 */
export function sweep_series(rows, field) {
  const numeric = values_are_numeric(rows);
  const categories = numeric ? null : [...new Set(rows.map((r) => r.value))].sort(compare_values(false));
  const newest = new Map();
  let repeated = 0;
  for (const r of rows) {
    if (r.status !== "succeeded" || r[field] === null || r[field] === undefined) continue;
    const x = numeric ? as_number(r.value) : categories.indexOf(r.value);
    const seen = newest.get(x);
    if (seen) repeated += 1;
    if (!seen || r.created > seen.created) newest.set(x, r);
  }
  const xs = [...newest.keys()].sort((a, b) => a - b);
  return { x: xs, y: xs.map((x) => newest.get(x)[field]), categories, repeated };
}
