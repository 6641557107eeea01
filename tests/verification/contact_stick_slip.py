#!/usr/bin/python3
"""Stick slope and slip onset (friction.md 5.1, fricloop-style) on the drag block of
tests/contact_models/drag_block.py: stiff blocks (E = 1e9), the upper one pressed down by a
prescribed approach (p ~ 100, uniform) and dragged by 4.4e-3 in 20 increments; K = 1e6,
mu = 0.3, lambda = 1e4, contact area A_c = 1.

Closed form (drag_block.py): F_t = k delta while sticking, 1 / k = 1 / (lambda A_c) + c_block;
at every point q = lambda t until lambda |t| = mu p, then |q| = mu p; the drag at slip onset is
delta_onset = mu F_n / k; afterwards F_t = mu F_n.

Checked on every increment of the drag, from the .dat (CSTR, CDIS per contact point; RF of the
upper top summed for F_t, F_n), the same for kontakt and ccx:
  point law     every active point: |q - q_closed| <= POINT_TOLERANCE mu p, q_closed =
                t min(lambda, mu p / |t|) (the vector law of monotonic loading; print precision)
  stick slope   F_t / delta of every sticking increment within SLOPE_TOLERANCE of k: c_block is
                a simple-shear upper bound, 2.6e-5 of 1 / k; its error (a fraction of itself)
                and the print precision (1e-6) are far below 1e-3 -- a lost or miscounted
                contact area (1e-2 per face row) or a stick slope off lambda is not
  slip onset    no point slips before delta_onset, every point slips from the increment that
                contains it on; the relative slip at the onset: max |t| of the last sticking
                increment < mu p / lambda <= min |t| of the first slipping one
  slip force    F_t / F_n = mu within SLIP_TOLERANCE after the onset (stiff blocks: the normal of
                the deformed master tilts by ~1e-6)
ccx 2.20 solves the same decks (--ccx: both pair types) as reference columns.

  contact_stick_slip.py --kontakt EXE [--schemes lgc7 nts ...] [--slave upper lower] [--ccx]
"""
import argparse
import os
import sys

sys.dont_write_bytecode = True  # keep the source tree clean

import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "contact_models"))
import datfile  # noqa: E402
import drag_block  # noqa: E402
import solvers  # noqa: E402

POINT_TOLERANCE = 1e-5
SLOPE_TOLERANCE = 1e-3
SLIP_TOLERANCE = 1e-5


def increments(dat_path):
    """[(time, |F| per direction on the upper top, rows (p, q1, q2, t1, t2) of the active
    points)] of every printed increment, in time order."""
    blocks = datfile.parse(dat_path)
    forces = {b.time: np.abs(np.sum([r[-3:] for r in b.rows], axis=0))
              for b in blocks if b.kind.startswith("forces")}
    stresses = {b.time: [r[-3:] for r in b.rows]
                for b in blocks if b.kind.startswith("contact stress")}
    slips = {b.time: [r[-2:] for r in b.rows]
             for b in blocks if b.kind.startswith("relative contact displacement")}
    return [(t, forces[t], np.hstack([np.asarray(stresses[t], float).reshape(-1, 3),
                                      np.asarray(slips[t], float).reshape(-1, 2)]))
            for t in sorted(forces) if t in stresses and t in slips]


def closed_form_shear(points):
    """q_closed per point: t min(lambda, mu p / |t|)."""
    p, t = points[:, 0], points[:, 3:5]
    size = np.maximum(np.linalg.norm(t, axis=1), 1e-300)
    return t * np.minimum(drag_block.STICK_SLOPE, drag_block.MU * p / size)[:, None]


def slipping(points):
    """Per point: lambda |t| >= mu p (on the slip branch of the law)."""
    size = np.linalg.norm(points[:, 3:5], axis=1)
    return drag_block.STICK_SLOPE * size >= drag_block.MU * points[:, 0] * (1 - POINT_TOLERANCE)


def stick_stiffness():
    return 1.0 / (1.0 / (drag_block.STICK_SLOPE * drag_block.AREA) + drag_block.block_compliance())


def evaluate(history):
    """[(check, passed, detail)] of one converged run's increments."""
    drag = [(t, f, pts) for t, f, pts in history if t > 1.0 + 1e-9]
    if not drag:
        return [("drag increments printed", False, "none")]
    k = stick_stiffness()
    mu, lam = drag_block.MU, drag_block.STICK_SLOPE
    delta = [(t - 1.0) * drag_block.DRAG for t, _, _ in drag]
    point_error = max(float(np.max(np.linalg.norm(pts[:, 1:3] - closed_form_shear(pts), axis=1)
                                   / (mu * pts[:, 0]))) for _, _, pts in drag)
    states = [slipping(pts) for _, _, pts in drag]
    stick = [i for i, s in enumerate(states) if not s.any()]
    slip = [i for i, s in enumerate(states) if s.all()]
    mixed = [i for i, s in enumerate(states) if s.any() and not s.all()]
    f_n = drag[0][1][2]
    onset = mu * f_n / k
    expected = next(i for i, d in enumerate(delta) if d >= onset)
    slopes = [drag[i][1][0] / delta[i] for i in stick]
    slope_error = max((abs(s / k - 1) for s in slopes), default=float("inf"))
    checks = [("point law q = t min(lambda, mu p/|t|)", point_error <= POINT_TOLERANCE,
               f"max |q - q_closed| / (mu p) {point_error:.1e}"),
              ("stick slope F_t/delta = k", slope_error <= SLOPE_TOLERANCE,
               f"k = {k:.2f}, measured {min(slopes, default=0):.2f} .. "
               f"{max(slopes, default=0):.2f} ({slope_error:.1e})")]
    onset_ok = (not mixed and stick == list(range(expected))
                and slip == list(range(expected, len(drag))))
    detail = f"predicted in increment {expected + 1} (delta {onset:.4e}), first slip " + (
        f"{slip[0] + 1}" if slip else "none") + (f", mixed {[i + 1 for i in mixed]}" if mixed
                                                 else "")
    if onset_ok and expected > 0:
        last_stick, first_slip = drag[expected - 1][2], drag[expected][2]
        limit = mu * first_slip[:, 0] / lam
        before = float(np.max(np.linalg.norm(last_stick[:, 3:5], axis=1) / limit))
        after = float(np.min(np.linalg.norm(first_slip[:, 3:5], axis=1) / limit))
        onset_ok = before < 1.0 <= after
        detail += f"; |t| / (mu p / lambda): {before:.4f} before, {after:.4f} after"
    checks.append(("slip onset at delta = mu F_n / k", onset_ok, detail))
    ratios = [f[0] / f[2] for i, (_, f, _) in enumerate(drag) if i in slip]
    ratio_error = max((abs(r / mu - 1) for r in ratios), default=float("inf"))
    checks.append(("slip force F_t/F_n = mu", ratio_error <= SLIP_TOLERANCE,
                   f"{min(ratios, default=0):.7f} .. {max(ratios, default=0):.7f}"))
    return checks


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    solvers.add_solver_options(p, ["lgc7", "gc7", "lgc3", "lgauss", "nts"])
    p.add_argument("--slave", nargs="+", default=["upper", "lower"], choices=("upper", "lower"))
    p.add_argument("--ccx", action="store_true", help="also ccx 2.20's two pair types")
    p.add_argument("--work", default="contact_stick_slip_work")
    args = p.parse_args()
    passed = failed = 0

    def model_for(slave, contact_type):
        return drag_block.drag_block(slave=slave, contact_type=contact_type)

    for slave, label, run in solvers.runs_per_slave(model_for, "drag", args):
        checks = (evaluate(increments(os.path.join(run.result_dir, "drag.dat")))
                  if run.converged else [("converges", False, f"{run.status}: {run.message}")])
        reference = label.startswith("ccx")
        for check, ok, detail in checks:
            verdict = "reference" if reference else "PASS" if ok else "FAIL"
            if not reference:
                passed, failed = passed + ok, failed + (not ok)
            print(f"slave {slave:5s} {label:24s} {verdict:9s} {run.increments:3d} inc "
                  f"{run.iterations:4d} its  {check}: {detail}")
    print(f"{passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
