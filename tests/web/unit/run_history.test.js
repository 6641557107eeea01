// The job page's model of a run: iteration columns with gaps between attempts, markers,
// increment rows, the increment-size series, and fields the solver may add later.
import assert from "node:assert/strict";
import { test } from "node:test";
import { RunHistory, is_drift_redo, merge_xy } from "../../../clients/dashboard/run_history.js";

let seq = 0;
const it = (step, inc, att, n, extra = {}) => ({
  seq: ++seq, run: 1, event: "iteration", step, increment: inc, attempt: att, iteration: n,
  step_time: 0.5 * inc, total_time: 0.5 * inc, dt: 0.5 / att, residual: 10 / n, correction: 1 / n,
  contact_elements: 40 + n, wall_time: n, ...extra,
});
const ev = (event, fields) => ({ seq: ++seq, run: 1, event, ...fields });

function history(events) {
  const h = new RunHistory();
  for (const e of events) h.add(e);
  return h;
}

test("one x per iteration; a new attempt gets a boundary marker between two iterations", () => {
  seq = 0;
  const h = history([ev("step", { step: 1 }), it(1, 1, 1, 1), it(1, 1, 1, 2),
    ev("increment", { step: 1, increment: 1, attempt: 1, iteration: 2, total_time: 0.5, dt: 0.5 }),
    it(1, 2, 1, 1)]);
  assert.deepEqual(h.x, [1, 2, 3]);
  assert.deepEqual(h.residual, [10, 5, 10]);
  assert.equal(h.n_iterations, 3);
  assert.deepEqual(h.markers, [{ x: 2.5, kind: "increment", text: "step 1 inc 2" }]);
  assert.equal(h.where[2], "step 1 · inc 2 · att 1 · it 1");
  assert.ok(h.has_contact);
  assert.ok(!h.has_friction);
});

test("cutbacks and drift redos: marker on the failed attempt's last iteration, row, dt point", () => {
  seq = 0;
  const h = history([it(1, 1, 1, 1), it(1, 1, 1, 2),
    ev("cutback", { step: 1, increment: 1, attempt: 1, iteration: 2, message: "too many iterations" }),
    it(1, 1, 2, 1),
    ev("cutback", { step: 1, increment: 1, attempt: 2, iteration: 1,
                    message: "frozen contact geometry drifted: gaps off by 0.3 of the largest overclosure" }),
    it(1, 1, 3, 1),
    ev("increment", { step: 1, increment: 1, attempt: 3, iteration: 1, total_time: 0.5, dt: 0.5 / 3 })]);
  assert.deepEqual(h.markers.map((m) => [m.x, m.kind, m.text]),
                   [[2, "cutback", "cutback"], [2.5, "increment", "step 1 inc 1 att 2"],
                    [3, "drift", "drift redo"], [3.5, "increment", "step 1 inc 1 att 3"]]);
  assert.deepEqual(h.increments.map((r) => [r.attempt, r.converged, r.cause]),
                   [[1, false, "cutback"], [2, false, "drift"], [3, true, null]]);
  // The cutback event has no times of its own: the attempt's iterations supply them.
  assert.equal(h.increments[0].dt, 0.5);
  assert.equal(h.increments[0].total_time, 0.5);
  assert.deepEqual(h.dt_cutback, [[0.5, 0.5], [0.5, 0.25]]);
  assert.deepEqual(h.dt_converged, [[0.5, 0.5 / 3]]);
  // One x per time; the second cutback to the same time wins.
  assert.deepEqual(h.dt_columns(), [[0.5], [0.5 / 3], [0.25]]);
});

test("a step change and a new run (requeued job) are their own boundaries; dt restarts", () => {
  seq = 0;
  const h = history([it(1, 1, 1, 1), ev("increment", { step: 1, increment: 1, attempt: 1, iteration: 1, total_time: 1, dt: 1 }),
    it(2, 1, 1, 1), { ...it(1, 1, 1, 1), run: 2 }]);
  assert.deepEqual(h.markers.map((m) => m.kind), ["step", "run"]);
  assert.equal(h.markers[1].text, "run 2");
  assert.deepEqual(h.dt_converged, [], "the latest run's increments only");
  assert.equal(h.n_iterations, 3);
});

test("events seen twice (a resumed stream) are ignored", () => {
  seq = 0;
  const a = it(1, 1, 1, 1), b = it(1, 1, 1, 2);
  const h = history([a, b, a, b]);
  assert.equal(h.n_iterations, 2);
  const v = h.version;
  h.add(b);
  assert.equal(h.version, v);
});

test("stick/slip and unknown numeric fields get aligned columns", () => {
  seq = 0;
  const h = history([it(1, 1, 1, 1), it(1, 1, 1, 2, { stick: 30, slip: 12, stabilisation_energy: 1e-3, note: "x" }),
                     it(1, 2, 1, 1, { stick: 31, slip: 11 })]);
  assert.ok(h.has_friction);
  assert.deepEqual(h.stick, [null, 30, 31]);
  assert.deepEqual(h.slip, [null, 12, 11]);
  assert.deepEqual([...h.extra.keys()], ["stabilisation_energy"], "numbers only, known ones left out");
  assert.deepEqual(h.extra.get("stabilisation_energy"), [null, 1e-3, null]);
  for (const column of [h.residual, h.contact, h.stick, h.extra.get("stabilisation_energy")])
    assert.equal(column.length, h.x.length);
});

test("ratios that a log axis cannot show are null, the point still counts", () => {
  seq = 0;
  const h = history([it(1, 1, 1, 1, { residual: 0, correction: -1 })]);
  assert.deepEqual([h.residual[0], h.correction[0]], [null, null]);
  assert.equal(h.n_iterations, 1);
});

test("done event is kept; drift detection reads the solver's message", () => {
  seq = 0;
  const h = history([ev("done", { status: "converged", summary: { drift_redos: 2 } })]);
  assert.equal(h.done.summary.drift_redos, 2);
  assert.ok(is_drift_redo({ message: "frozen contact geometry drifted: gaps off by 1" }));
  assert.ok(!is_drift_redo({ message: "divergence" }));
  assert.ok(!is_drift_redo({}));
});

test("merge_xy aligns tables on sorted unique x", () => {
  assert.deepEqual(merge_xy([[[2, "b"], [1, "a"]], [[1.5, "c"], [2, "d"]]]),
                   [[1, 1.5, 2], ["a", null, "b"], [null, "c", "d"]]);
  assert.deepEqual(merge_xy([[], []]), [[], [], []]);
});
