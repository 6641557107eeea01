#!/usr/bin/python3
"""Issue 10: one C3D8 with every degree of freedom prescribed (no free equation left), linear
and NLGEOM, a rigid translation (`*BOUNDARY NALL, 1, 3, 0.01`) and a uniaxial stretch. ccx 2.20
solves these and prints displacements and reactions; kontakt must too (it crashed with
SIGSEGV), with the same values: displacements to 1e-12, reactions to 1e-9 of the stretch's
reaction scale (the translation's reactions are round-off around zero in both programs).

  test_prescribed.py --kontakt build/solver/app/kontakt [--ccx /usr/bin/ccx] [--work DIR]
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "peer"))
import compare_dat  # noqa: E402

NODES = ["1, 0, 0, 0", "2, 1, 0, 0", "3, 1, 1, 0", "4, 0, 1, 0",
         "5, 0, 0, 1", "6, 1, 0, 1", "7, 1, 1, 1", "8, 0, 1, 1"]
BOUNDARIES = {
    "translation": "NALL, 1, 3, 0.01\n",
    "stretch": "BOTTOM, 1, 3\nTOP, 1, 2\nTOP, 3, 3, 0.01\n",
}
E = 210000.0
NU = 0.3
# Reaction per top node of the stretch: (lambda + 2 mu) * 0.01 / 4.
SCALE = E * (1 - NU) / ((1 + NU) * (1 - 2 * NU)) * 0.01 / 4


def deck(boundary, nlgeom):
    return ("*HEADING\none C3D8, every dof prescribed\n*NODE, NSET=NALL\n" + "\n".join(NODES) +
            "\n*ELEMENT, TYPE=C3D8, ELSET=EALL\n1, 1, 2, 3, 4, 5, 6, 7, 8\n"
            "*NSET, NSET=BOTTOM\n1, 2, 3, 4\n*NSET, NSET=TOP\n5, 6, 7, 8\n"
            f"*MATERIAL, NAME=STEEL\n*ELASTIC\n{E}, {NU}\n"
            "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n"
            + ("*STEP, NLGEOM\n*STATIC\n1., 1.\n" if nlgeom else "*STEP\n*STATIC\n")
            + "*BOUNDARY\n" + BOUNDARIES[boundary] + "*NODE PRINT, NSET=NALL\nU, RF\n*END STEP\n")


def blocks(path):
    with open(path) as f:
        return compare_dat.parse_blocks(f.read())


def compare(mine, ccx):
    """Largest difference of displacements and of reactions, and a structural problem if any."""
    a, b = blocks(mine), blocks(ccx)
    if [h for h, _ in a] != [h for h, _ in b]:
        return None, None, f"blocks differ: {[h for h, _ in a]} vs {[h for h, _ in b]}"
    worst = {"displacements": 0.0, "forces": 0.0}
    for (header, rows_a), (_, rows_b) in zip(a, b):
        kind = "displacements" if header.startswith("displacements") else "forces"
        for (key_a, va), (key_b, vb) in zip(rows_a, rows_b):
            if key_a != key_b or len(va) != len(vb):
                return None, None, f"rows differ in {header}"
            worst[kind] = max([worst[kind]] + [abs(x - y) for x, y in zip(va, vb)])
    return worst["displacements"], worst["forces"], None


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--kontakt", required=True)
    p.add_argument("--ccx", default=shutil.which("ccx") or "/usr/bin/ccx")
    p.add_argument("--work")
    args = p.parse_args()
    args.kontakt = os.path.abspath(args.kontakt)
    work = args.work or tempfile.mkdtemp(prefix="prescribed-")
    os.makedirs(work, exist_ok=True)
    failed = 0
    print(f"{'case':<24} {'kontakt':>8} {'max |dU|':>10} {'max |dRF|':>10}  (tolerances 1e-12, {1e-9 * SCALE:.1e})")
    for boundary in BOUNDARIES:
        for nlgeom in (False, True):
            name = f"{boundary}{'_nlgeom' if nlgeom else ''}"
            case = os.path.join(work, name)
            os.makedirs(case, exist_ok=True)
            for sub in ("kontakt", "ccx"):
                os.makedirs(os.path.join(case, sub), exist_ok=True)
                with open(os.path.join(case, sub, "deck.inp"), "w") as f:
                    f.write(deck(boundary, nlgeom))
            k = subprocess.run([args.kontakt, "solve", "deck.inp", "--quiet", "--threads", "1"],
                               cwd=os.path.join(case, "kontakt"), capture_output=True, text=True,
                               timeout=120)
            c = subprocess.run([args.ccx, "-i", "deck"], cwd=os.path.join(case, "ccx"),
                               capture_output=True, text=True, timeout=120)
            if k.returncode != 0 or c.returncode != 0:
                print(f"{name:<24} exit {k.returncode} (ccx {c.returncode}) FAIL {k.stderr.strip()}")
                failed += 1
                continue
            du, drf, problem = compare(os.path.join(case, "kontakt", "deck.dat"),
                                       os.path.join(case, "ccx", "deck.dat"))
            ok = problem is None and du <= 1e-12 and drf <= 1e-9 * SCALE
            failed += not ok
            print(f"{name:<24} {'exit 0':>8} {du if du is not None else float('nan'):10.2e} "
                  f"{drf if drf is not None else float('nan'):10.2e}  {'pass' if ok else 'FAIL ' + (problem or '')}")
    print(f"{4 - failed} passed, {failed} failed")
    if not args.work:
        shutil.rmtree(work, ignore_errors=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
