// Number, size, duration and event-line formatting.
import assert from "node:assert/strict";
import { test } from "node:test";
import { event_text } from "../../../clients/dashboard/event_text.js";
import { fmt_bytes, fmt_duration, fmt_number, seconds_between } from "../../../clients/dashboard/format.js";

test("numbers: 3 significant digits, exponent outside [1e-3, 1e5)", () => {
  assert.equal(fmt_number(0.123456), "0.123");
  assert.equal(fmt_number(12345.6), "12300");
  assert.equal(fmt_number(123456), "1.23e+5");
  assert.equal(fmt_number(0.0001234), "1.23e-4");
  assert.equal(fmt_number(-2.5), "-2.5");
  assert.equal(fmt_number(0), "0");
  assert.equal(fmt_number(null), "");
  assert.equal(fmt_number(undefined), "");
});

test("sizes and durations", () => {
  assert.equal(fmt_bytes(512), "512 B");
  assert.equal(fmt_bytes(1536), "1.5 KiB");
  assert.equal(fmt_bytes(3 * 1024 ** 3), "3 GiB");
  assert.equal(fmt_duration(0.0423), "0.042 s");
  assert.equal(fmt_duration(12.34), "12.3 s");
  assert.equal(fmt_duration(245), "4 min 05 s");
  assert.equal(fmt_duration(7380), "2 h 03 min");
  assert.equal(fmt_duration(null), "");
  assert.equal(seconds_between("2026-01-01T00:00:00.000Z", "2026-01-01T00:00:02.500Z"), 2.5);
  assert.equal(seconds_between(null, null, 0), null);
});

test("event lines name the place, the measures and any new numeric field", () => {
  assert.equal(event_text({ seq: 9, event: "iteration", step: 1, increment: 3, attempt: 2, iteration: 4,
                            residual: 0.0123, correction: 2e-5, contact_elements: 48, wall_time: 1.5, stick: 40, slip: 8 }),
               "#9 [1.5 s] step 1 inc 3 att 2 it 4  residual 0.0123 %  correction 2.00e-5 %  contact 48 stick 40 slip 8");
  assert.equal(event_text({ seq: 2, event: "status", status: "failed", reason: "not_converged", message: "too many cutbacks" }),
               "#2 status failed (not_converged): too many cutbacks");
  assert.match(event_text({ seq: 5, event: "done", status: "converged", wall_time: 2,
                            summary: { iterations: 7, max_displacement: 0.5, max_mises: 100, max_contact_pressure: 3, total_contact_force: 4, drift_refreezes: 2, drift_redos: 1 } }),
               /done converged: 7 iterations, max \|U\| 0.5, max Mises 100, max CPRESS 3, contact force 4, 2 drift refreezes, 1 drift redos/);
  assert.match(event_text({ seq: 6, event: "cutback", step: 1, increment: 2, attempt: 1, iteration: 16, message: "diverged" }),
               /inc 2 cut back after 16 it .*: diverged/);
});
