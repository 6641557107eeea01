// A job's event log turned into what the job page draws: per-iteration columns for uPlot
// (residual, correction, active contact elements, stick/slip, and any other numeric field the
// solver adds), attempt/step/run boundaries and cutback markers, the increments table, and the
// increment size over time. Pure (no DOM): events go in in seq order as they arrive.

// The solver's message for an increment redone because frozen contact projections drifted
// (solver/analysis/nonlinear_static.cpp); every other cutback is a convergence cutback.
const DRIFT_MESSAGE = "frozen contact geometry drifted";

// Iteration-event members that locate or time an iteration (or have their own plot), so the
// generic "other measures" plot leaves them out.
const NOT_EXTRA = new Set(["event", "seq", "run", "step", "increment", "attempt", "iteration",
  "step_time", "total_time", "dt", "wall_time", "residual", "correction", "contact_elements",
  "stick", "slip"]);

const number_or_null = (v) => (typeof v === "number" && Number.isFinite(v) ? v : null);
// Log-scale columns: a ratio of 0 (or a missing one) cannot be drawn.
const positive_or_null = (v) => (typeof v === "number" && v > 0 && Number.isFinite(v) ? v : null);

export function is_drift_redo(cutback) {
  return typeof cutback.message === "string" && cutback.message.startsWith(DRIFT_MESSAGE);
}

export class RunHistory {
  constructor() {
    // Iteration columns, aligned: x is the iteration's ordinal over the whole job (1, 2, ...).
    // The lines run on across attempts (a saw-tooth, as in ccx's .cvg); markers between two
    // ordinals show where an attempt, a step or a run begins.
    this.x = [];
    this.where = [];        // "step 1 · inc 3 · att 1 · it 2"
    this.residual = [];
    this.correction = [];
    this.contact = [];
    this.stick = [];
    this.slip = [];
    this.extra = new Map(); // other numeric field -> its column
    this.n_iterations = 0;
    this.markers = [];      // {x, kind: increment|step|run|cutback|drift, text}
    this.increments = [];   // rows of the .sta-like table, converged or not
    this.dt_converged = []; // [total time reached, increment size] of the latest run
    this.dt_cutback = [];   // [total time the attempt tried to reach, increment size]
    this.has_contact = false;
    this.has_friction = false;
    this.done = null;       // the solver's done event
    this.last_seq = 0;
    this.version = 0;       // grows with every change, so views redraw only when it moved
    this.attempt_key_ = null;  // run/step/increment/attempt of the latest iteration
    this.last_run_ = null;     // ... and its run and step
    this.last_iteration_ = {};
    this.step_ = null;
    this.run_ = null;          // the run of the latest solver event
  }

  /** Adds one event; an event already seen (same or lower seq) is ignored. */
  add(e) {
    if (typeof e.seq !== "number" || e.seq <= this.last_seq) return;
    this.last_seq = e.seq;
    if (e.run !== undefined && e.run !== this.run_ && e.event !== "status") this.start_run_(e.run);
    switch (e.event) {
      case "iteration": this.add_iteration_(e); break;
      case "increment": this.add_increment_(e, null); break;
      case "cutback": this.add_increment_(e, is_drift_redo(e) ? "drift" : "cutback"); break;
      case "done": this.done = e; break;
      default: return;
    }
    this.version += 1;
  }

  /** The columns the dt plot draws: [x, converged dt, cutback dt], x sorted and unique. */
  dt_columns() {
    return merge_xy([this.dt_converged, this.dt_cutback]);
  }

  start_run_(run) {
    if (this.run_ !== null) {
      this.dt_converged = [];
      this.dt_cutback = [];
    }
    this.run_ = run;
  }

  add_iteration_(e) {
    const key = `${e.run}/${e.step}/${e.increment}/${e.attempt}`;
    if (key !== this.attempt_key_) {
      if (this.n_iterations > 0) this.add_boundary_(e);
      this.attempt_key_ = key;
      this.step_ = e.step;
      this.last_run_ = e.run;
    }
    this.n_iterations += 1;
    this.last_iteration_ = e;
    this.x.push(this.n_iterations);
    this.where.push(`step ${e.step} · inc ${e.increment} · att ${e.attempt} · it ${e.iteration}`);
    this.residual.push(positive_or_null(e.residual));
    this.correction.push(positive_or_null(e.correction));
    this.contact.push(number_or_null(e.contact_elements));
    this.stick.push(number_or_null(e.stick));
    this.slip.push(number_or_null(e.slip));
    if (e.contact_elements !== undefined) this.has_contact = true;
    if (e.stick !== undefined || e.slip !== undefined) this.has_friction = true;
    for (const [k, v] of Object.entries(e)) {
      if (typeof v === "number" && !NOT_EXTRA.has(k) && !this.extra.has(k))
        this.extra.set(k, new Array(this.x.length - 1).fill(null));
    }
    for (const [k, column] of this.extra) column.push(number_or_null(e[k]));
  }

  /** The marker between the previous attempt's last iteration and this one's first. */
  add_boundary_(e) {
    let kind = "increment", text = `step ${e.step} inc ${e.increment}`;
    if (e.attempt > 1) text += ` att ${e.attempt}`;
    if (e.run !== this.last_run_) {
      kind = "run";
      text = `run ${e.run}`;
    } else if (e.step !== this.step_) {
      kind = "step";
      text = `step ${e.step}`;
    }
    this.markers.push({ x: this.n_iterations + 0.5, kind, text });
  }

  add_increment_(e, cause) {
    const converged = cause === null;
    // A cutback event does not repeat the attempt's times: its iterations carry them (the
    // time the attempt tried to reach and its increment size).
    const same_attempt = this.attempt_key_ === `${e.run}/${e.step}/${e.increment}/${e.attempt}`;
    const tried = !converged && same_attempt ? this.last_iteration_ : {};
    const step_time = number_or_null(e.step_time ?? tried.step_time);
    const total_time = number_or_null(e.total_time ?? tried.total_time);
    const dt = number_or_null(e.dt ?? tried.dt);
    this.increments.push({
      seq: e.seq, run: e.run, step: e.step, increment: e.increment, attempt: e.attempt,
      iterations: number_or_null(e.iteration), step_time, total_time, dt,
      contact_elements: number_or_null(e.contact_elements ?? tried.contact_elements),
      wall_time: number_or_null(e.wall_time), converged, cause, message: e.message || "",
    });
    if (total_time !== null && dt !== null) (converged ? this.dt_converged : this.dt_cutback).push([total_time, dt]);
    // The marker sits on the attempt's last iteration (a cutback before any iteration, e.g.
    // a singular first tangent, has nothing to sit on).
    if (!converged && same_attempt)
      this.markers.push({ x: this.n_iterations, kind: cause,
                          text: cause === "drift" ? "drift redo" : "cutback" });
  }
}

/**
 * Aligns several [[x, y], ...] tables on one sorted x column (uPlot's data layout): one
 * column per table, null where a table has no point at that x; for a repeated x within a
 * table the last point wins.
 */
export function merge_xy(tables) {
  const xs = [...new Set(tables.flatMap((t) => t.map((p) => p[0])))].sort((a, b) => a - b);
  const index = new Map(xs.map((x, i) => [x, i]));
  const columns = tables.map((t) => {
    const column = new Array(xs.length).fill(null);
    for (const [x, y] of t) column[index.get(x)] = y;
    return column;
  });
  return [xs, ...columns];
}
