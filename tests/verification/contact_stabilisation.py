#!/usr/bin/python3
"""Contact stabilisation leaves the answer unchanged (issue 9, contact/README.md): every deck
that converges without it is solved twice, `--contact-stabilisation never` and `always` (the
springs engaged in every increment, then released), and the final displacements and nodal
contact pressures are compared.

Decks: the contact patch test variants (tests/contact_models/patch.py) with lgc7, gc7 and nts;
Hertz line contact (level 1, C3D8) with lgc7 and nts; the thesis cube (4^3) and a coarse
punch whose central points start in contact; the suite's frictionless contact decks
(tests/peer/select_decks.py --contact) with their own schemes.

Both runs solve every step to residuals of 1e-8 of the average force (the decks get
*CONTROLS, PARAMETERS=FIELD with R_n = R_p = 1e-8 in every step): with ccx's default 0.5 %, two
runs that converge along different paths may differ by up to the tolerance, which says nothing
about the stabilisation. Requirement: both runs converge, and max |U_always - U_never| <= 1e-6
max |U_never| and max |CPRESS_always - CPRESS_never| <= 1e-6 max |CPRESS_never| at the end of
the last step. The nonlinear variants (nts, gauss, gc*) fix their contact elements by the
pairing in the first evaluations of an increment, so their answer depends on the path a little
even without springs: for them the bound is the larger of 1e-6 and the difference between
two unstabilised runs with the first increment 1 and 0.5 (measured and printed; on Hertz with
nts 2e-5 in U and 0.6 % in CPRESS), and the stabilised run is compared with the nearer of the
two (on the gc7 patch test the stabilised pressure is 1 + 2.6e-7, the unstabilised ones
1 + 5.8e-6 and 1 + 2.8e-7).

And two punches that rock on their apex node with nts (tests/bench/README.md) must converge
without passing through the master: the 4^3 punch at x 0.05, y -0.03, 15 degrees, whose
release fails from the stiffer levels and converges only from the weakest one (before that
was tried it failed, "free to rock"), and the 4^3 punch at x 0.047, y -0.149, 50.2 degrees,
which once ended with ring nodes 9.7e-3 inside the lower block, carrying nothing, where the
apex pressed 3e-4 deep (their contact elements are decided at pairing, and the tilt came after
it). Converged, no node of the punch that carries no pressure may lie deeper below the lower
block's lowest top node than the deepest one that does. A fourth, at 6^3 (x -0.116, y 0.142,
23.9 degrees), tilts past a limit of its apex-only equilibrium, where smaller increments only
crawl towards the limit: it must converge (it does since a failed attempt is retried with
springs at its size before it is cut back). Two more snap past such a limit where the springs
find no way off (the 4^3 punch at x 0.004, y 0.162, 73.2 degrees and the 6^3 one at x 0.174,
y -0.168, 58.4 degrees): they must converge, held likewise (they do since pseudo-transient
continuation takes over from the last level the springs held; before, they ended on springs
they could not leave, after 858 and 758 iterations).

  contact_stabilisation.py --kontakt EXE [--work DIR] [--smoke] [--only NAME ...]
"""
import argparse
import os
import sys

sys.dont_write_bytecode = True  # keep the source tree clean

HERE = os.path.dirname(os.path.abspath(__file__))
for folder in ("../contact_models", "../peer"):
    sys.path.insert(0, os.path.join(HERE, folder))
import hertz  # noqa: E402
import patch  # noqa: E402
import run_peer  # noqa: E402
import select_decks  # noqa: E402
import solvers  # noqa: E402
import thesis_blocks  # noqa: E402

TOLERANCE = 1e-6
TIGHT_CONTROLS = "*CONTROLS, PARAMETERS=FIELD\n1e-8, 1e-8, , , 1e-8\n"


def tightened(text):
    """The deck with TIGHT_CONTROLS at the start of every step."""
    out = []
    for line in text.splitlines(keepends=True):
        out.append(line)
        if line.upper().replace(" ", "").startswith("*STEP"):
            out.append(TIGHT_CONTROLS)
    return "".join(out)


def tighten_file(path):
    with open(path) as f:
        text = f.read()
    with open(path, "w") as f:
        f.write(tightened(text))
    return path

GENERATED = {  # name -> (model, schemes)
    "patch_thesis": (lambda: patch.patch(), ("lgc7", "gc7", "nts")),
    "patch_swapped": (lambda: patch.patch(slave="lower"), ("lgc7", "nts")),
    "patch_hex8": (lambda: patch.patch("C3D8", "C3D8", 3, 4), ("lgc7", "gc7", "nts")),
    "patch_distorted": (lambda: patch.patch(distortion=0.3), ("lgc7",)),
    "hertz_c3d8": (lambda: hertz.hertz("C3D8", 1), ("lgc7", "nts")),
    "cube_c3d8": (lambda: thesis_blocks.cube("C3D8", n=4, x=0.05, y=-0.1, rotation=20),
                  ("lgc7", "nts")),
    # central integration points in contact from the start: converges without springs
    "punch_c3d8": (lambda: thesis_blocks.punch("C3D8", n=4, x=0.1, y=0.05, z=-0.0023,
                                               rotation=66), ("lgc7", "gc7")),
}
SMOKE = ("patch_thesis", "cube_c3d8", "punch_c3d8", "contact3", "hueeber1", "rocking_punch",
         "unheld_punch", "snapping_punch", "snapping_punch_6", "thesis_punch_8", "limit_punch")


def final_fields(result_dir, name):
    """(U: n x 3, CPRESS: n or None) of the last frame of kontakt's HDF5 file."""
    import h5py
    with h5py.File(os.path.join(result_dir, name + ".hdf"), "r") as f:
        last = f["frames"][sorted(f["frames"])[-1]]
        cpress = last["CPRESS"][()] if "CPRESS" in last else None
        return last["U"][()], cpress


def relative_difference(a, b):
    import numpy as np
    scale = np.abs(a).max()
    return float(np.abs(a - b).max() / scale) if scale > 0 else float(np.abs(a - b).max())


def solved(exe, deck, scheme, out, mode, timeout):
    """(run, (U, CPRESS)) of one kontakt run; fields None when it did not converge."""
    run = solvers.run_kontakt(exe, deck, scheme, out, timeout,
                              extra_args=["--contact-stabilisation", mode])
    return run, final_fields(out, os.path.basename(deck)[:-4]) if run.converged else None


def differences(a, b):
    (u0, p0), (u1, p1) = a, b
    return relative_difference(u0, u1), relative_difference(p0, p1) if p0 is not None else 0.0


def halved_first_increment(deck):
    """A copy of a generated deck whose *STATIC takes increments of 0.5 (its line is 1, 1, ...)."""
    with open(deck) as f:
        text = f.read()
    lines = text.splitlines(keepends=True)
    for k, line in enumerate(lines[:-1]):
        if line.upper().startswith("*STATIC"):
            fields = lines[k + 1].split(",")
            lines[k + 1] = ", ".join(["0.5", fields[1].strip(), fields[2].strip(), "0.5"]) + "\n"
    path = deck[:-4] + "_half.inp"
    with open(path, "w") as f:
        f.write("".join(lines))
    return path


def compare(exe, deck, scheme, work, timeout):
    """(ok, text) for one deck and scheme."""
    runs = {}
    for mode in ("never", "always"):
        run, fields = solved(exe, deck, scheme, os.path.join(work, f"{scheme or 'deck'}_{mode}"),
                             mode, timeout)
        if fields is None:
            return False, f"{mode}: {run.status} {run.message}"
        runs[mode] = (run, fields)
    du, dp = differences(runs["never"][1], runs["always"][1])
    its = f"iterations {runs['never'][0].iterations} / {runs['always'][0].iterations}"
    bound_u = bound_p = TOLERANCE
    spread = ""
    if scheme and not model_scheme_linear(scheme):
        run, fields = solved(exe, halved_first_increment(deck), scheme,
                             os.path.join(work, f"{scheme}_never_half"), "never", timeout)
        if fields is None:
            return False, f"never, increments of 0.5: {run.status} {run.message}"
        su, sp = differences(runs["never"][1], fields)
        bound_u, bound_p = max(bound_u, su), max(bound_p, sp)
        # Either unstabilised path is the unstabilised answer: the nearer one is compared.
        hu, hp = differences(fields, runs["always"][1])
        du, dp = min(du, hu), min(dp, hp)
        spread = f"  (path spread without springs: U {su:.1e}  CPRESS {sp:.1e})"
    return du <= bound_u and dp <= bound_p, f"U {du:.1e}  CPRESS {dp:.1e}  {its}{spread}"


def model_scheme_linear(scheme):
    """The thesis' linear variants (lgauss, lgc*): frozen geometry, no re-pairing."""
    return scheme.startswith("l")


def cases(args):
    """[(label, deck path, scheme or None, work folder)] of the selected decks."""
    out = []
    for name, (make, schemes) in GENERATED.items():
        if args.only and name not in args.only:
            continue
        folder = os.path.join(args.work, name)
        os.makedirs(folder, exist_ok=True)
        model = make()
        for scheme in schemes:
            deck = tighten_file(
                solvers.write_deck(model, folder, solvers.contact_type_for(scheme), name))
            out.append((f"{name} {scheme}", deck, scheme, os.path.join(folder, scheme)))
    if os.path.isdir(args.suite):
        good, _ = select_decks.qualifying_decks(args.suite, contact=True)
        for name in good:
            if args.only and name not in args.only:
                continue
            folder = os.path.join(args.work, name)
            run_peer.stage_deck(args.suite, name, folder, transform=tightened)
            out.append((name, os.path.join(folder, name + ".inp"), None, folder))
    return out


def unheld_depths(result_dir, name):
    """(deepest pressing, deepest non-pressing) slave node below the lowest node of the lower
    block's top in the last frame (the upper block's nodes are the slave side)."""
    import h5py
    import numpy as np
    with h5py.File(os.path.join(result_dir, name + ".hdf"), "r") as f:
        last = f["frames"][sorted(f["frames"])[-1]]
        x = f["VTKHDF/Points"][()] + last["U"][()]
        upper_elements = set(f["mesh/sets/elsets/UPPER"][()].tolist())
        upper = np.zeros(len(x), bool)
        for element, nodes in zip(f["mesh/element_ids"][()], f["mesh/xdmf_topology"][()]):
            if element in upper_elements:
                upper[nodes] = True
        lower_z = f["VTKHDF/Points"][()][~upper, 2]
        lower_top = (~upper) & (f["VTKHDF/Points"][()][:, 2] > lower_z.max() - 1e-9)
        depth = x[lower_top, 2].min() - x[:, 2]
        pressing = last["CPRESS"][()] > 0
        return (float(depth[upper & pressing].max(initial=0)),
                float(depth[upper & ~pressing].max(initial=0)))


# name: (placement, elements per edge). thesis_punch_8: the 4^3 rocking_punch placement at
# 8^3, where ccx 2.20's node to surface fails; kontakt's did too (272 iterations) until points
# that arrive after the pairing evaluations got their elements. limit_punch: tilts past a limit
# of its apex-only equilibrium; it failed (326 iterations) until a failed attempt was retried
# with springs at its size before cutting back. snapping_punch (the former stuck_punch, seed
# 77's placement rounded) and snapping_punch_6 (seed 5's) of the coarse punches
# (tests/bench/README.md) failed until pseudo-transient continuation.
ROCKING_PUNCHES = {"rocking_punch": (dict(x=0.05, y=-0.03, rotation=15.0), 4),
                   "unheld_punch": (dict(x=0.047, y=-0.149, rotation=50.2), 4),
                   "snapping_punch": (dict(x=0.004, y=0.162, rotation=73.2), 4),
                   "snapping_punch_6": (dict(x=0.173858, y=-0.167741, rotation=58.408), 6),
                   "thesis_punch_8": (dict(x=0.05, y=-0.03, rotation=15.0), 8),
                   "limit_punch": (dict(x=-0.116, y=0.142, rotation=23.9), 6)}


def rocking_punch(exe, work, timeout, name):
    """(ok, text): a coarse punch of ROCKING_PUNCHES that rocks on its apex node with nts
    converges without passing through the master."""
    placement, n = ROCKING_PUNCHES[name]
    model = thesis_blocks.punch("C3D8", n=n, **placement)
    folder = os.path.join(work, name)
    deck = solvers.write_deck(model, folder, "NODE TO SURFACE", "punch")
    out = os.path.join(folder, "kontakt_nts")
    run = solvers.run_kontakt(exe, deck, "nts", out, timeout)
    if not run.converged:
        return False, run.status + ": " + run.message[-160:]
    held, unheld = unheld_depths(out, "punch")
    return unheld <= held, f"converged; deepest node without pressure {unheld:.3g}, with {held:.3g}"


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--kontakt", required=True, help="the kontakt executable")
    p.add_argument("--work", default="contact_stabilisation_work")
    p.add_argument("--suite", default=select_decks.DEFAULT_SUITE)
    p.add_argument("--only", nargs="+", help="deck names (generated or suite)")
    p.add_argument("--smoke", action="store_true", help="CI size: " + ", ".join(SMOKE))
    p.add_argument("--timeout", type=int, default=600)
    args = p.parse_args()
    args.work = os.path.abspath(args.work)
    if args.smoke and not args.only:
        args.only = list(SMOKE)
    failed = 0
    print(f"{'deck':28s} {'result':6s} never vs always (relative), iterations never / always")
    for label, deck, scheme, work in cases(args):
        ok, text = compare(args.kontakt, deck, scheme, work, args.timeout)
        failed += not ok
        print(f"{label:28s} {'ok' if ok else 'FAIL':6s} {text}", flush=True)
    print(f"requirement (both converge, U and CPRESS within {TOLERANCE:g}): "
          f"{'met' if failed == 0 else f'NOT met on {failed} decks'}")
    for name in ROCKING_PUNCHES:
        if not args.only or name in args.only:
            ok, text = rocking_punch(args.kontakt, args.work, args.timeout, name)
            failed += not ok
            print(f"{name + ' nts':28s} {'ok' if ok else 'FAIL':6s} {text}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
