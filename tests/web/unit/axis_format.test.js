// Tick labels and the choice of a log axis.
import assert from "node:assert/strict";
import { test } from "node:test";
import { fmt_legend, fmt_log_tick, fmt_tick, is_decade, prefers_log } from "../../../clients/dashboard/axis_format.js";

test("log ticks: decades short, exponents outside 0.01 ... 1000", () => {
  assert.deepEqual([1e-7, 0.01, 0.1, 1, 1000, 1e4, 3e-5, 0.3].map(fmt_log_tick),
                   ["1e-7", "0.01", "0.1", "1", "1000", "1e4", "3e-5", "0.3"]);
  assert.ok(is_decade(1e-6) && is_decade(100) && !is_decade(200));
});

test("linear ticks keep small measures readable", () => {
  assert.deepEqual([0, 0.0005, 0.25, 150, 2e6, null].map(fmt_tick), ["0", "5.0e-4", "0.25", "150", "2.0e6", null]);
});

test("a log axis for positive measures over two decades", () => {
  assert.ok(prefers_log([1e-3, null, 1e-5]));
  assert.ok(!prefers_log([1, 50]));
  assert.ok(!prefers_log([0, 1e-3, 1]));
  assert.ok(!prefers_log([null, null]));
});

test("legend values: 4 significant digits", () => {
  assert.deepEqual([0, 12.3456, 2.5e-4, 123456].map(fmt_legend), ["0", "12.35", "2.500e-4", "1.235e+5"]);
});
