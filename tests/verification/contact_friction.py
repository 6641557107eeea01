#!/usr/bin/python3
"""Coulomb friction on the sliding block (friction.md 5.1; tests/contact_models/sliding_block.py):
a block pressed onto another (step 1) and dragged across it by 0.02 (step 2, in increments of
0.05 of the step), non-matching meshes, mu = 0.3, stick slope 1e4, LINEAR K = 1e6.

What a correct solver shows, read from the *CONTACT PRINT blocks (CSTR: pressure, shear 1, 2):
- at the end of step 1 (pressure only) no point carries more shear than the Coulomb limit,
  |q| <= mu p;
- at the end of step 2 every pressed point slips: |q| = mu p within PRINT_TOLERANCE (the .dat
  carries 7 significant digits);
- the drag reaction on the upper top (RF x) is at most mu times the normal force the contact
  carries (the blocks are small-strain while the normal follows the deformed master, so it is
  not exactly mu: friction.md 5.1).
ccx 2.20 solves the same decks (--ccx: both pair types) as a reference column.

  contact_friction.py --kontakt EXE [--schemes lgc7 gc7 ...] [--slave upper lower] [--ccx]
"""
import argparse
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the source tree clean

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "contact_models"))
import datfile  # noqa: E402
import sliding_block  # noqa: E402
import solvers  # noqa: E402

PRINT_TOLERANCE = 1e-5
PRESSED = 1e-3  # points below this share of the largest pressure are at the edge of contact


def contact_stress_blocks(dat_path):
    """{time: rows (element, face, p, q1, q2) or (node, p, q1, q2)} of the CSTR blocks."""
    blocks = datfile.find(datfile.parse(dat_path), "contact stress", last=False)
    return {b.time: [r[-3:] for r in b.rows] for b in blocks}


def coulomb_figures(rows, mu):
    """(worst |q| / (mu p) over the pressed points, least of it, pressed points)."""
    p_max = max((p for p, _, _ in rows), default=0.0)
    ratios = [math.hypot(q1, q2) / (mu * p) for p, q1, q2 in rows if p > PRESSED * p_max]
    return (max(ratios, default=float("nan")), min(ratios, default=float("nan")), len(ratios))


def check_run(run, name, mu):
    """(passed, detail) of one converged run."""
    stresses = contact_stress_blocks(os.path.join(run.result_dir, name + ".dat"))
    end_1 = stresses.get(1.0)
    end_2 = stresses[max(stresses)]
    if end_1 is None:
        return False, "no contact stress block at the end of step 1"
    worst_1, _, n_1 = coulomb_figures(end_1, mu)
    worst_2, least_2, n_2 = coulomb_figures(end_2, mu)
    slip_error = max(abs(worst_2 - 1), abs(least_2 - 1))
    passed = (n_1 > 0 and n_2 > 0 and worst_1 <= 1 + PRINT_TOLERANCE
              and slip_error <= PRINT_TOLERANCE)
    return passed, (f"step 1: {n_1} pressed points, max |q|/(mu p) {worst_1:.6f}; step 2: "
                    f"{n_2} pressed points, |q|/(mu p) in [{least_2:.7f}, {worst_2:.7f}]")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    solvers.add_solver_options(p, ["lgc7", "gc7", "lgc3", "lgauss", "nts"])
    p.add_argument("--slave", nargs="+", default=["upper", "lower"], choices=("upper", "lower"))
    p.add_argument("--ccx", action="store_true", help="also ccx 2.20's two pair types")
    p.add_argument("--work", default="contact_friction_work")
    args = p.parse_args()
    passed = failed = 0

    def model_for(slave, contact_type):
        return sliding_block.sliding_block(slave=slave, contact_type=contact_type)

    for slave, label, run in solvers.runs_per_slave(model_for, "block", args):
        if run.converged:
            ok, detail = check_run(run, "block", sliding_block.MU)
        else:
            ok, detail = False, f"{run.status}: {run.message}"
        if label.startswith("ccx"):
            verdict = "reference"
        else:
            verdict = "PASS" if ok else "FAIL"
            passed, failed = passed + ok, failed + (not ok)
        print(f"slave {slave:5s} {label:24s} {verdict:9s} {run.iterations:4d} its  {detail}")
    print(f"{passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
