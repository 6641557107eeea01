#!/usr/bin/python3
"""Contact benchmark (issue 4): kontakt against ccx 2.20 in one run, side by side, on
  hueeber1  the suite's deck (read at run time from the installed calculix-ccx-test suite,
            never copied): two blocks, 8500 C3D8, surface to surface, K = 1e15;
  cube      the thesis cube (tests/contact_models/thesis_blocks.py, table 3) with 16 x 16 x 16
            C3D8 per body (--n; --element C3D20 for the quadratic one), centred, not rotated,
            surface to surface;
  sphere    the contact-heavy model (issue 9): Hertz point contact, a quarter sphere on a block
            (tests/contact_models/hertz_sphere.py), C3D8, a/h = 12 (--ratio): about 12,000
            active lgc7 points at the end of its 6 increments. Also reported: kontakt's wall
            time split (contact search and points, pattern and symbolic analysis, elements,
            contact forces, factorisation, solve), the first iteration of an increment against
            the later ones, and both solvers' peak nodal pressure against Hertz's p0 at the load
            each measured (4 x the quarter's top reaction);
  sliding   the frictional model (issue 11): the sliding block of friction.md 5.1
            (tests/contact_models/sliding_block.py) refined 6 times (--refine: lower 30 x 30 x
            12, upper 24 x 24 x 12 C3D8, about 61,000 dofs), mu = 0.3, pressed (step 1) then
            dragged by 0.02 in increments of 0.05 (step 2); also reported: each solver's
            pressed points at the end and how far their shear is from mu p.
For each: wall time, peak resident memory (ru_maxrss of the child, what /usr/bin/time -v
reports), converged increments and Newton iterations (from the .sta files, every attempt
counted), the ratios kontakt/ccx, and the agreement of the final displacements
(max |u_kontakt - u_ccx| / max |u_ccx| over the final displacement blocks of the .dat, the
peer contact measure); above 1e-2 the exit code is 1. kontakt runs its default scheme (lgc7
for surface to surface) unless --scheme is given.

Threads: both get --threads N (default 2): ccx through OMP_NUM_THREADS and
CCX_NPROC_EQUATION_SOLVER, kontakt through --threads. Machines are noisy: compare the ratios
of one run, not absolute times across runs.

  bench_contact.py --kontakt build/solver/app/kontakt [--n 16] [--element C3D8] [--work DIR]
  bench_contact.py --kontakt ... --smoke     # CI: hueeber1, a 6^3 cube, the sphere at a/h 4,
                                             # the sliding block unrefined
"""
import argparse
import os
import sys

sys.dont_write_bytecode = True  # keep the source tree clean

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "contact_models"))
sys.path.insert(0, os.path.join(HERE, "..", "verification"))
import contact_fields  # noqa: E402
import contact_friction  # noqa: E402
import datfile  # noqa: E402
import hertz_sphere  # noqa: E402
import sliding_block  # noqa: E402
import solvers  # noqa: E402
import thesis_blocks  # noqa: E402
from solvers import run_peer  # noqa: E402

SMOKE_N = 6
SMOKE_RATIO = 4
AGREEMENT = 1e-2


def sphere_load(run, name):
    """The load on the whole Hertz sphere a run measured: 4 x the quarter's top reaction."""
    blocks = datfile.parse(os.path.join(run.result_dir, name + ".dat"))
    return 4 * abs(sum(row[3] for row in datfile.find(blocks, "forces").rows))


def hertz_p0_error(run, name, nodal_path):
    """Peak nodal CPRESS against Hertz's p0 at the load the run measured (relative)."""
    _, p0 = hertz_sphere.closed_form(sphere_load(run, name))
    peak = max(p for _, p in contact_fields.nodal_contact(nodal_path).values())
    return peak / p0 - 1


def kontakt_timing(run, name):
    """(phase times of the done event, mean first iteration of an increment, mean later one), or
    None when the run wrote no event log (the ccx stand-in of the self-test writes none)."""
    import json
    first, later, previous, times = [], [], 0.0, {}
    path = os.path.join(run.result_dir, name + ".log.jsonl")
    stand_in = os.path.exists(os.path.join(run.result_dir, name + ".fake.log"))
    if not os.path.exists(path) and stand_in:
        return None
    with open(path) as f:
        for line in f:
            e = json.loads(line)
            if e["event"] == "iteration":
                (first if e["iteration"] == 1 else later).append(e["wall_time"] - previous)
            if e["event"] in ("iteration", "increment", "cutback"):
                previous = e["wall_time"]
            if e["event"] == "done":
                times = e.get("summary", {}).get("times", {})
    mean = lambda v: sum(v) / len(v) if v else float("nan")  # noqa: E731
    return times, mean(first), mean(later)


def displacement_agreement(ours_dat, ccx_dat):
    """Worst relative difference of the final displacement blocks (inf when not comparable)."""
    with open(ours_dat, errors="replace") as f, open(ccx_dat) as g:
        result, _ = run_peer.compare_contact(f.read(), g.read(), AGREEMENT)
    return result.worst


def bench_case(name, deck, args):
    """Both solvers on one deck: (ccx Run, kontakt Run, agreement or None)."""
    ccx = solvers.run_ccx(deck, args.timeout, args.threads)
    ours = solvers.run_kontakt(args.kontakt, deck, args.scheme,
                               os.path.join(os.path.dirname(deck), "kontakt"), args.timeout,
                               args.threads)
    agreement = None
    if ccx.converged and ours.converged:
        agreement = displacement_agreement(os.path.join(ours.result_dir, name + ".dat"),
                                           os.path.join(ccx.result_dir, name + ".dat"))
    return ccx, ours, agreement


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--kontakt", required=True)
    p.add_argument("--scheme", choices=solvers.SCHEMES, help="default: kontakt's default")
    p.add_argument("--n", type=int, default=16, help="cube: elements per direction and body")
    p.add_argument("--element", default="C3D8", choices=("C3D8", "C3D20", "C3D20R"))
    p.add_argument("--ratio", type=float, default=12, help="sphere: a / h at the contact")
    p.add_argument("--refine", type=int, default=6, help="sliding: mesh refinement factor")
    p.add_argument("--cases", nargs="+", choices=("hueeber1", "cube", "sphere", "sliding"),
                   default=["hueeber1", "cube", "sphere", "sliding"], help="default: all four")
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--timeout", type=int, default=3600)
    p.add_argument("--suite", default=run_peer.DEFAULT_SUITE)
    p.add_argument("--smoke", action="store_true", help=f"CI size: cube {SMOKE_N}^3")
    p.add_argument("--work", default="bench_contact_work")
    args = p.parse_args()
    n = SMOKE_N if args.smoke else args.n
    ratio = SMOKE_RATIO if args.smoke else args.ratio
    refine = 1 if args.smoke else args.refine
    work = os.path.abspath(args.work)
    names = {"hueeber1": "hueeber1", "cube": f"cube_{args.element.lower()}_{n}",
             "sphere": f"sphere_{ratio:g}", "sliding": f"sliding_{refine}"}

    def write_case(case, name):
        """The case's deck in WORK/CASE/, its path."""
        if case == "hueeber1":
            run_peer.stage_deck(args.suite, name, os.path.join(work, name))
            return os.path.join(work, name, name + ".inp")
        if case == "cube":
            model = thesis_blocks.cube(args.element, n=n)
        elif case == "sphere":
            model = hertz_sphere.hertz_sphere(ratio=ratio)
        else:
            model = sliding_block.sliding_block(refine=refine)
            model.node_prints = [("UPPER", "ZMIN", "U"), ("UPPER", "ZMAX", "RF")]
        return solvers.write_deck(model, os.path.join(work, case), "SURFACE TO SURFACE", name)

    cases = [(case, names[case], write_case(case, names[case])) for case in args.cases]
    print(f"threads: {args.threads} for both; kontakt scheme: {args.scheme or 'default'}")
    print(f"{'case':18s} {'solver':8s} {'status':14s} {'wall s':>8s} {'cpu s':>8s} {'peak MiB':>9s} "
          f"{'increments':>10s} {'iterations':>10s}")
    ok = True
    for case, name, deck in cases:
        ccx, ours, agreement = bench_case(name, deck, args)
        for label, run in (("ccx", ccx), ("kontakt", ours)):
            print(f"{name:18s} {label:8s} {run.status:14s} {run.wall:8.2f} {run.cpu:8.2f} "
                  f"{run.peak_mib:9.0f} "
                  f"{run.increments:10d} {run.iterations:10d}")
        if agreement is None:
            print(f"{name:18s} not compared: a solver did not converge")
            ok = False
            continue
        print(f"{name:18s} ratios kontakt/ccx: wall {ours.wall / ccx.wall:.3f}, cpu "
              f"{ours.cpu / max(ccx.cpu, 1e-9):.3f}, memory "
              f"{ours.peak_mib / ccx.peak_mib:.3f}, iterations "
              f"{ours.iterations / max(ccx.iterations, 1):.3f}; final displacements differ by "
              f"{agreement:.2e}")
        ok &= agreement <= AGREEMENT
        if case == "sphere":
            ok &= report_sphere(name, ccx, ours)
        if case == "sliding":
            ok &= report_sliding(name, ccx, ours)
    return 0 if ok else 1


def report_sphere(name, ccx, ours):
    """Prints the contact-heavy model's figures; False when a figure cannot be read."""
    try:
        timing = kontakt_timing(ours, name)
        errors = {label: hertz_p0_error(run, name, contact_fields.result_file(run.result_dir, name))
                  for label, run in (("ccx", ccx), ("kontakt", ours))}
    except (OSError, KeyError, ValueError) as e:
        print(f"{name:18s} figures not read: {e}")
        return False
    if timing is None:
        print(f"{name:18s} no event log: a ccx stand-in ran as kontakt")
    else:
        times, first, later = timing
        split = ", ".join(f"{k} {v:.2f}" for k, v in times.items())
        print(f"{name:18s} kontakt time split (s): {split}")
        print(f"{name:18s} kontakt iterations: first of an increment {first:.2f} s, later ones "
              f"{later:.2f} s (ratio {first / later:.2f})")
    print(f"{name:18s} peak nodal pressure against Hertz p0: ccx {errors['ccx']:+.2%}, "
          f"kontakt {errors['kontakt']:+.2%}")
    return True


def report_sliding(name, ccx, ours):
    """Prints how far each solver's pressed points are from |q| = mu p at the end of the drag;
    False when kontakt's are not there within the print precision."""
    passed = True
    for label, run in (("ccx", ccx), ("kontakt", ours)):
        try:
            ok, detail = contact_friction.check_run(run, name, sliding_block.MU)
        except (OSError, KeyError, ValueError) as e:
            ok, detail = False, f"figures not read: {e}"
        print(f"{name:18s} {label:8s} {detail}")
        passed &= ok or label == "ccx"
    return passed


if __name__ == "__main__":
    sys.exit(main())
