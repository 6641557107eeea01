#!/usr/bin/python3
"""Kontakt's own decks for the step set-up and loading cards, run through ccx 2.20 and
`kontakt solve` and compared strictly: every .dat block (same headers, times included, in the
same order: an output written at a time ccx skips, or missing, fails) within the tolerance, and
the same converged increments (step, increment, step time) in the .sta files (tolerance 1e-3,
the nonlinear peer measure).

Decks (a C3D8 cantilever bar 4 x 1 x 1, 4 x 1 x 1 elements, E = 210000, nu = 0.3, clamped at
x = 0, pushed down at its free end under NLGEOM):
  time_points  *TIME POINTS on step time (three points, step 1), on total time with GENERATE
               (step 2, named on *EL PRINT: it replaces the first for all outputs), then
               FREQUENCY=2 (step 3): the points cut increments, output only there and at the
               step ends, the size the increments grow from is not cut.
  network_pressure  *DLOAD P5NP: the pressure on the top faces is the prescribed dof 2 of a
               node without elements, with its amplitude, changed in step 2, replaced by a
               plain P5 in step 3 (OP=NEW).
  amplitude_steps, amplitude_steps_small  a pressure with an amplitude in step 1 (ending at
               0.6 of its value), a new value in step 2: it goes over from its end value
               (step 2 with NLGEOM and with NLGEOM=NO).
  set_print_order  sets printed as ccx prints them: unsorted labels, a set made of two
               overlapping sets (duplicates kept, counted twice in TOTALS=), a GENERATE range
               naming labels without a node (zero rows up to the largest label, none beyond),
               element sets in deck order.
  change_solid_section  linear steps: the bar under its own weight and a tip load, the
               elements of its outer half given a softer and denser material in step 2
               (*CHANGE SOLID SECTION), all four the original one again in step 3.
  contact_pair_change  not the bar: a 2 x 2 block pressed onto a 3 x 3 one (C3D8, rollers,
               surface-to-surface), its contact pair taken out by *MODEL CHANGE, REMOVE (the
               top block pushed on through the lower one, then lifted off) and put back by ADD
               (pressed again), both blocks pulled along x throughout: the contact stresses
               vanish and come back as ccx's.

Usage: check_setup_decks.py --kontakt PATH [--work DIR] [--only NAME...]
Exit code 0 when every deck agrees with ccx.
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "verification"))
import compare_dat  # noqa: E402
import meshgen  # noqa: E402

TOLERANCE = 1e-3  # the nonlinear peer measure: iterates stop within the residual tolerance


def bar(nx=4, length=4.0):
    """Nodes and C3D8 elements of a bar [0, length] x [0, 1] x [0, 1] with nx elements."""
    nodes, elements = {}, {}
    node_id = lambda i, j, k: 1 + i + (nx + 1) * (j + 2 * k)  # noqa: E731
    for k in range(2):
        for j in range(2):
            for i in range(nx + 1):
                nodes[node_id(i, j, k)] = (length * i / nx, float(j), float(k))
    for i in range(nx):
        c = [node_id(i, 0, 0), node_id(i + 1, 0, 0), node_id(i + 1, 1, 0), node_id(i, 1, 0)]
        elements[i + 1] = c + [n + 2 * (nx + 1) for n in c]
    clamped = sorted(node_id(0, j, k) for j in range(2) for k in range(2))
    tip = sorted(node_id(nx, j, k) for j in range(2) for k in range(2))
    return nodes, elements, clamped, tip


def model_lines(nx=4, extra_nodes=()):
    nodes, elements, clamped, tip = bar(nx)
    lines = ["*HEADING", "Kontakt step set-up check", "*NODE"]
    lines += [f"{n}, {x:.6g}, {y:.6g}, {z:.6g}" for n, (x, y, z) in nodes.items()]
    lines += [f"{n}, 9., 9., 9." for n in extra_nodes]  # no element: network nodes
    lines.append("*ELEMENT, TYPE=C3D8, ELSET=EALL")
    lines += [f"{e}, " + ", ".join(map(str, c)) for e, c in elements.items()]
    lines += ["*NSET, NSET=FIX", ", ".join(map(str, clamped)),
              "*NSET, NSET=TIP", ", ".join(map(str, tip)),
              "*NSET, NSET=NALL, GENERATE", f"1, {len(nodes)}",
              "*MATERIAL, NAME=EL", "*ELASTIC", "210000., 0.3",
              "*SOLID SECTION, ELSET=EALL, MATERIAL=EL",
              "*BOUNDARY", "FIX, 1, 3"]
    return lines


def time_points_deck():
    lines = model_lines()
    lines += ["*TIME POINTS, NAME=T1", ".25, .5, .8",
              "*TIME POINTS, NAME=TT, TIME=TOTAL TIME, GENERATE", "1.5, 2.6, .5",
              "*STEP, NLGEOM", "*STATIC", ".1, 1.",
              "*CLOAD", "TIP, 2, -500.",
              "*NODE PRINT, NSET=TIP, TIME POINTS=T1", "U",
              "*EL PRINT, ELSET=EALL", "S",
              "*END STEP",
              # the total-time points 1.5, 2.0, 2.5 and 2.6 fall in this step (1 ... 3)
              "*STEP", "*STATIC", ".3, 2.",
              "*CLOAD", "TIP, 2, -1200.",
              "*EL PRINT, ELSET=EALL, TIME POINTS=TT", "S",
              "*END STEP",
              "*STEP", "*STATIC", ".2, 1.",
              "*CLOAD", "TIP, 2, -600.",
              "*NODE PRINT, NSET=TIP, FREQUENCY=2", "U",
              "*END STEP"]
    return "\n".join(lines) + "\n"


def network_pressure_deck():
    # Node 100 carries the pressure on the top faces (S5) of elements 3 and 4 as its prescribed
    # dof 2: with an amplitude in step 1 (the *BOUNDARY after the *DLOAD), changed to a pull
    # in step 2 (the load follows the boundary), replaced by a plain pressure in step 3.
    lines = model_lines(extra_nodes=[100])
    lines += ["*ELSET, ELSET=TOP", "3, 4",
              "*AMPLITUDE, NAME=A1", "0., 0., .5, .8, 1., 1.",
              "*STEP, NLGEOM", "*STATIC", ".25, 1.",
              "*DLOAD", "TOP, P5NP, 100",
              "*BOUNDARY, AMPLITUDE=A1", "100, 2, 2, 30.",
              "*NODE PRINT, NSET=TIP", "U",
              "*EL PRINT, ELSET=EALL", "S",
              "*END STEP",
              "*STEP, NLGEOM", "*STATIC", ".5, 1.",
              "*BOUNDARY", "100, 2, 2, -10.",
              "*END STEP",
              "*STEP, NLGEOM", "*STATIC", ".5, 1.",
              "*DLOAD, OP=NEW", "4, P5, 5.",
              "*END STEP"]
    return "\n".join(lines) + "\n"


def pressure_amplitude_deck(nlgeom):
    # A pressure with an amplitude in step 1, given a new value in step 2: it goes from its
    # end value in step 1 to the new one (the amplitude does not outlive its step).
    # Without NLGEOM the step runs in the nonlinear driver all the same (the first is NLGEOM).
    step = "*STEP, NLGEOM" if nlgeom else "*STEP, NLGEOM=NO"
    lines = model_lines()
    lines += ["*ELSET, ELSET=TOP", "3, 4",
              "*AMPLITUDE, NAME=A1", "0., 0., .5, .8, 1., .6",
              "*STEP, NLGEOM", "*STATIC", ".25, 1.",
              "*DLOAD, AMPLITUDE=A1", "TOP, P5, 30.",
              "*NODE PRINT, NSET=TIP", "U",
              "*EL PRINT, ELSET=EALL", "S",
              "*END STEP",
              step, "*STATIC", ".5, 1.",
              "*DLOAD", "TOP, P5, -10.",
              "*END STEP"]
    return "\n".join(lines) + "\n"


def set_print_order_deck():
    # Node 100 (no element) makes 100 the largest label: the range's 24, 31, 38 print as zero
    # rows, 45 and beyond not at all.
    lines = model_lines(extra_nodes=[100])
    lines += ["*NSET, NSET=UNSORTED", "20, 5, 15, 1, 5",
              "*NSET, NSET=GEN, GENERATE", "3, 200, 7",
              "*NSET, NSET=BOTH", "TIP, UNSORTED",
              "*NSET, NSET=BOTH", "GEN",
              "*ELSET, ELSET=EUNSORTED", "3, 1, 3",
              "*ELSET, ELSET=EBOTH", "EUNSORTED, EALL",
              "*STEP, NLGEOM", "*STATIC", ".5, 1.",
              "*CLOAD", "TIP, 2, -500.",
              "*NODE PRINT, NSET=UNSORTED", "U",
              "*NODE PRINT, NSET=BOTH, TOTALS=YES", "RF",
              "*NODE PRINT, NSET=GEN", "U",
              "*EL PRINT, ELSET=EBOTH, TOTALS=YES", "EVOL",
              "*EL PRINT, ELSET=EUNSORTED", "S",
              "*END STEP"]
    return "\n".join(lines) + "\n"


def change_solid_section_deck():
    lines = model_lines()
    elastic = lines.index("210000., 0.3")
    lines[elastic + 1:elastic + 1] = ["*DENSITY", "7.8e-9"]
    lines += ["*MATERIAL, NAME=SOFT", "*ELASTIC", "70000., 0.33", "*DENSITY", "2.7e-9",
              "*ELSET, ELSET=OUTER", "3, 4",
              "*STEP", "*STATIC",
              "*CLOAD", "TIP, 2, -500.",
              "*DLOAD", "EALL, GRAV, 9810., 0., -1., 0.",
              "*NODE PRINT, NSET=NALL", "U, RF",
              "*EL PRINT, ELSET=EALL", "S, E",
              "*END STEP",
              "*STEP", "*STATIC",
              "*CHANGE SOLID SECTION, ELSET=OUTER, MATERIAL=SOFT",
              "*END STEP",
              "*STEP", "*STATIC",
              "*CHANGE SOLID SECTION, ELSET=EALL, MATERIAL=EL",
              "*END STEP"]
    return "\n".join(lines) + "\n"


def contact_pair_change_deck():
    # Upper block (nodes and elements from 1001) on the lower one; rollers on the x = 0 and
    # y = 0 faces and under the lower block, the upper top moved in z step by step.
    lower = meshgen.box_mesh("C3D8", (3, 3, 1), size=(1.0, 1.0, 0.5))
    upper = meshgen.box_mesh("C3D8", (2, 2, 1), size=(1.0, 1.0, 0.5), origin=(0.0, 0.0, 0.5))
    lines = ["*HEADING", "Kontakt *MODEL CHANGE check", "*NODE, NSET=NALL"]
    for offset, mesh in ((0, lower), (1000, upper)):
        lines += [f"{offset + n}, {x:.6g}, {y:.6g}, {z:.6g}" for n, (x, y, z) in mesh.nodes.items()]
    for offset, mesh, name in ((0, lower, "LOWER"), (1000, upper, "UPPER")):
        lines.append(f"*ELEMENT, TYPE=C3D8, ELSET={name}")
        lines += [f"{offset + e}, " + ", ".join(str(offset + n) for n in c)
                  for e, c in mesh.elements.items()]
        for nset in ("XMIN", "XMAX", "YMIN", "ZMIN", "ZMAX"):
            lines += [f"*NSET, NSET={name}_{nset}",
                      ", ".join(str(offset + n) for n in mesh.nsets[nset])]
    lines.append("*SURFACE, NAME=SLAVE")
    lines += [f"{1000 + e}, S{f}" for e, f in upper.faces_on("ZMIN")]
    lines.append("*SURFACE, NAME=MASTER")
    lines += [f"{e}, S{f}" for e, f in lower.faces_on("ZMAX")]
    lines += ["*ELSET, ELSET=EALL", "LOWER, UPPER",
              "*MATERIAL, NAME=EL", "*ELASTIC", "210000., 0.3",
              "*SOLID SECTION, ELSET=EALL, MATERIAL=EL",
              "*SURFACE INTERACTION, NAME=SI", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR",
              "1e7, 1.",
              "*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE", "SLAVE, MASTER",
              "*BOUNDARY", "LOWER_ZMIN, 3, 3", "LOWER_XMIN, 1, 1", "LOWER_YMIN, 2, 2",
              "UPPER_XMIN, 1, 1", "UPPER_YMIN, 2, 2"]
    steps = [("", -0.01), ("*MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE", -0.03),
             ("", 0.005), ("*MODEL CHANGE, TYPE=CONTACT PAIR, ADD", -0.01)]
    for k, (change, top) in enumerate(steps):
        lines += ["*STEP, NLGEOM", "*STATIC, DIRECT", ".5, 1."]
        lines += [change, "SLAVE, MASTER"] if change else []
        lines += ["*BOUNDARY", f"UPPER_ZMAX, 3, 3, {top}"]
        if k == 0:  # a pull along x keeps both blocks stressed while the pair is out
            lines += ["*CLOAD", "UPPER_XMAX, 1, 10.", "LOWER_XMAX, 1, 10.",
                      "*NODE PRINT, NSET=NALL", "U", "*NODE PRINT, NSET=UPPER_XMIN", "RF",
                      "*EL PRINT, ELSET=EALL", "S"]
        lines.append("*END STEP")
    return "\n".join(lines) + "\n"


DECKS = {
    "set_print_order": set_print_order_deck,
    "change_solid_section": change_solid_section_deck,
    "contact_pair_change": contact_pair_change_deck,
    "time_points": time_points_deck,
    "network_pressure": network_pressure_deck,
    "amplitude_steps": lambda: pressure_amplitude_deck(True),
    "amplitude_steps_small": lambda: pressure_amplitude_deck(False),
}


def sta_increments(path):
    """(step, increment, step time) of every converged increment in a .sta file."""
    rows = []
    with open(path) as f:
        for line in f:
            fields = line.split()
            if len(fields) >= 7 and fields[0].isdigit() and not fields[2].endswith("U"):
                rows.append((int(fields[0]), int(fields[1]), round(float(fields[5]), 5)))
    return rows


def check(name, text, args):
    """Runs both solvers on the deck; returns a list of problems (empty: agrees)."""
    folder = os.path.join(args.work, name)
    shutil.rmtree(folder, ignore_errors=True)
    for side in ("ccx", "kontakt"):
        os.makedirs(os.path.join(folder, side))
        with open(os.path.join(folder, side, name + ".inp"), "w") as f:
            f.write(text)
    env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1")
    ccx = subprocess.run(["ccx", "-i", name], cwd=os.path.join(folder, "ccx"), env=env,
                         capture_output=True, text=True, timeout=300)
    if ccx.returncode != 0 or "Job finished" not in ccx.stdout:
        print(f"{name:14s} ERROR ccx failed (exit {ccx.returncode})")
        return ["ccx failed"]
    ours = subprocess.run([args.kontakt, "solve", name + ".inp", "-o", "out", "--threads", "1",
                           "--quiet"], cwd=os.path.join(folder, "kontakt"), capture_output=True,
                          text=True, timeout=300)
    if ours.returncode != 0:
        print(f"{name:14s} ERROR kontakt exit {ours.returncode}: {ours.stderr.strip()[:300]}")
        return ["kontakt failed"]
    out = os.path.join(folder, "kontakt", "out")
    with open(os.path.join(out, name + ".dat")) as f_o, \
            open(os.path.join(folder, "ccx", name + ".dat")) as f_r:
        result = compare_dat.compare_blocks(f_o.read(), f_r.read(), tolerance=TOLERANCE)
    problems = list(result.problems)
    problems += [f"block {b.index} ({b.header}): {b.error:.2e}" for b in result.blocks
                 if not b.passed]
    inc_o = sta_increments(os.path.join(out, name + ".sta"))
    inc_r = sta_increments(os.path.join(folder, "ccx", name + ".sta"))
    if inc_o != inc_r:
        problems.append(f"increments {inc_o} where ccx has {inc_r}")
    if problems:
        print(f"{name:14s} FAIL  " + "; ".join(problems))
    else:
        print(f"{name:14s} PASS  worst block {result.worst:.2e} of {len(result.blocks)}, "
              f"{len(inc_r)} increments as ccx")
    return problems


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--kontakt", required=True)
    p.add_argument("--work", help="scratch folder (default: a new temporary one)")
    p.add_argument("--only", nargs="+", choices=sorted(DECKS))
    args = p.parse_args()
    args.kontakt = os.path.abspath(args.kontakt)
    args.work = os.path.abspath(args.work or tempfile.mkdtemp(prefix="setup_decks_"))
    failed = [name for name in (args.only or DECKS) if check(name, DECKS[name](), args)]
    print(f"{len(args.only or DECKS) - len(failed)} passed, {len(failed)} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
