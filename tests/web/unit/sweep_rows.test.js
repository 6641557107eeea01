// A sweep's table order and plotted series.
import assert from "node:assert/strict";
import { test } from "node:test";
import { sort_rows, sweep_series, values_are_numeric } from "../../../clients/dashboard/sweep_rows.js";

const row = (value, status, u, created) => ({ value, status, max_displacement: u, created });

test("numeric values sort as numbers and plot against their value", () => {
  const rows = [row("10", "succeeded", 1.0, "2026-01-01T00:00:03.000Z"), row("2.5", "succeeded", 0.25, "2026-01-01T00:00:02.000Z"),
                row("-1", "failed", null, "2026-01-01T00:00:01.000Z"), row("1e-1", "running", null, "2026-01-01T00:00:04.000Z")];
  assert.ok(values_are_numeric(rows));
  assert.deepEqual(sort_rows(rows).map((r) => r.value), ["-1", "1e-1", "2.5", "10"]);
  const s = sweep_series(rows, "max_displacement");
  assert.deepEqual([s.x, s.y, s.categories, s.repeated], [[2.5, 10], [0.25, 1.0], null, 0]);
});

test("a repeated value plots its newest succeeded job; the table keeps both, newest first", () => {
  const old = row("2", "succeeded", 5, "2026-01-01T00:00:01.000Z");
  const fresh = row("2", "succeeded", 6, "2026-01-01T00:00:09.000Z");
  const s = sweep_series([fresh, old], "max_displacement");
  assert.deepEqual([s.x, s.y, s.repeated], [[2], [6], 1]);
  assert.deepEqual(sort_rows([old, fresh]), [fresh, old]);
});

test("other values are categories in natural order", () => {
  const rows = [row("mesh10", "succeeded", 3, "a"), row("mesh2", "succeeded", 2, "b"), row("coarse", "queued", null, "c")];
  assert.ok(!values_are_numeric(rows));
  assert.deepEqual(sort_rows(rows).map((r) => r.value), ["coarse", "mesh2", "mesh10"]);
  const s = sweep_series(rows, "max_displacement");
  assert.deepEqual(s.categories, ["coarse", "mesh2", "mesh10"]);
  assert.deepEqual([s.x, s.y], [[1, 2], [2, 3]]);
});

test("blank values are not numbers; an empty sweep plots nothing", () => {
  assert.ok(!values_are_numeric([row(" ", "succeeded", 1, "a")]));
  assert.deepEqual(sweep_series([], "max_displacement").x, []);
});
