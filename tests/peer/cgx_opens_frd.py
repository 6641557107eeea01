#!/usr/bin/python3
"""cgx (Debian calculix-cgx) opens Kontakt's .frd: CTest `frd_cgx_opens`.

Generates the contact patch deck (tests/contact_models: C3D15 on C3D20, so both reordered frd
element types are in it), adds file requests for every field the writer knows (U, RF, NT with
initial temperatures, S, E, PEEQ (elastic: no block), contact), runs `kontakt solve`, reads
the .frd with frd_file.py, then lets cgx read it in background mode (`cgx -bg FILE.fbd`: no
display needed) with a command file that prints the model summary and, for every dataset, its
name and the extremes of one component. Checks that cgx reports the file's node and element
counts, every block by name in order, and the same extremes (z components, CPRESS) as the
file holds.

    cgx_opens_frd.py --kontakt build/solver/app/kontakt --work DIR
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import frd_file  # noqa: E402

GENERATE = os.path.join(HERE, "..", "contact_models", "generate.py")
FILE_REQUESTS = "*NODE FILE\nU, RF, NT\n*EL FILE\nS, E, PEEQ\n"


def fail(message):
    print("FAIL:", message)
    return 1


def deck(work):
    path = os.path.join(work, "patch.inp")
    subprocess.run(["/usr/bin/python3", GENERATE, "patch", path, "--upper", "C3D15",
                    "--lower", "C3D20"], check=True, stdout=subprocess.DEVNULL)
    with open(path) as f:
        text = f.read()
    if "*NODE FILE\nU\n" not in text or "*STEP" not in text:
        raise SystemExit("the generated patch deck changed: no '*NODE FILE / U' lines")
    text = text.replace("*NODE FILE\nU\n", FILE_REQUESTS)
    # Initial temperatures (no change in the step): the NDTEMP block is written.
    if "*NODE, NSET=NALL\n" not in text:
        raise SystemExit("the generated patch deck changed: no node set NALL")
    text = text.replace("*STEP", "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 20.\n*STEP", 1)
    with open(path, "w") as f:
        f.write(text)
    return path


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--kontakt", required=True)
    p.add_argument("--work", required=True)
    args = p.parse_args()
    if shutil.which("cgx") is None:
        return fail("cgx not found -- install calculix-cgx (deploy/install-deps.sh)")
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    path = deck(args.work)
    run = subprocess.run([args.kontakt, "solve", path, "-o", args.work, "--quiet",
                          "--threads", "1"], capture_output=True, text=True, timeout=300)
    if run.returncode != 0:
        return fail(f"kontakt exit {run.returncode}: {run.stderr.strip()[:300]}")
    frd = frd_file.read(os.path.join(args.work, "patch.frd"))
    names = [b.name for b in frd.blocks]
    # PEEQ is requested too, but the patch is elastic: no PE block (as ccx).
    expected = ["DISP", "NDTEMP", "STRESS", "TOSTRAIN", "FORC", "CONTACT"]
    if names != expected:
        return fail(f"the .frd has blocks {names}, expected {expected}")

    # One dataset per block; `ds N e C` selects component C of dataset N and prints its name
    # and extremes: the z components (the patch is pressed along z) and CPRESS.
    shown_component = [4 if b.name == "CONTACT" else min(3, len(b.stored_components))
                       for b in frd.blocks]
    fbd = ["read patch.frd", "prnt info"] + [f"ds {k + 1} e {c}"
                                             for k, c in enumerate(shown_component)]
    with open(os.path.join(args.work, "open.fbd"), "w") as f:
        f.write("\n".join(fbd + ["quit"]) + "\n")
    try:
        cgx = subprocess.run(["cgx", "-bg", "open.fbd"], cwd=args.work, capture_output=True,
                             text=True, errors="replace", timeout=120)
    except subprocess.TimeoutExpired:
        return fail("cgx -bg did not finish in 120 s")
    out = cgx.stdout + cgx.stderr
    with open(os.path.join(args.work, "cgx.log"), "w") as f:
        f.write(out)
    summary = re.search(r"\bn:(\d+) e:(\d+)", out)
    if not summary:
        return fail("cgx printed no model summary (see cgx.log)")
    if (int(summary.group(1)), int(summary.group(2))) != (len(frd.nodes), len(frd.elements)):
        return fail(f"cgx read {summary.group(1)} nodes and {summary.group(2)} elements, the "
                    f"file has {len(frd.nodes)} and {len(frd.elements)}")
    shown = re.findall(r"^ *\d+ L .*$", out, re.MULTILINE)
    if [line.split()[4] for line in shown] != names:
        return fail(f"cgx named the datasets {[line.split()[4] for line in shown]}, the file "
                    f"has {names}")
    # cgx prints the name as it read it from its 8 columns: a shifted name shows.
    columns = {line.index(" " + name + " ") for line, name in zip(shown, names)}
    if len(columns) != 1:
        return fail(f"cgx shows the dataset names in different columns: {shown}")
    extremes = re.findall(r"max:(\S+) at node:(\d+)\s+min:(\S+) at node:(\d+)", out)
    if len(extremes) != len(names):
        return fail(f"cgx printed {len(extremes)} extremes for {len(names)} datasets")
    for block, c, (vmax, _, vmin, _) in zip(frd.blocks, shown_component, extremes):
        first = [v[c - 1] for v in block.values.values()]
        for got, want in ((float(vmax), max(first)), (float(vmin), min(first))):
            if abs(got - want) > 1e-5 * max(1e-30, abs(want), max(map(abs, first))):
                return fail(f"{block.name}: cgx extreme {got} against the file's {want}")
    print(f"cgx read {len(frd.nodes)} nodes, {len(frd.elements)} elements and the datasets "
          f"{', '.join(names)} with the file's extremes")
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
