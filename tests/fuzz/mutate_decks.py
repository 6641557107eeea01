#!/usr/bin/python3
"""Mutation probe of `kontakt solve` (issue 10): small valid decks of our own, randomly
mutated (lines deleted, duplicated, truncated, swapped, numbers replaced by nan/inf/huge
values, keywords inserted), each solved in a fresh process with a time limit.

Every run must end with one of kontakt's exit codes (0 converged, 2 input error, 3 not
converged, 4 numerical error) within the limit; an input error must name the deck's file and
line. A signal (SIGSEGV, SIGABRT, ...), another exit code or a timeout is a finding: the deck is
kept in --keep for reproduction and the script exits 1.

  mutate_decks.py --kontakt build/solver/app/kontakt [--count 1500] [--seed 10] [--jobs 2]

The mutations are a pure function of (seed, index): a finding is reproduced with
`--seed S --only INDEX`.
"""
import argparse
import collections
import concurrent.futures
import os
import random
import re
import resource
import shutil
import signal
import subprocess
import sys
import tempfile

sys.dont_write_bytecode = True
HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(REPO, "tests", "server"))
import decks  # noqa: E402

KEYWORDS = ["*HEADING", "*", "*NODE", "*ELEMENT, TYPE=C3D8", "*ELEMENT, TYPE=C3D4", "*NSET, NSET=N",
            "*ELSET, ELSET=E", "*NSET, NSET=G, GENERATE", "*SURFACE, NAME=S", "*MATERIAL, NAME=M",
            "*ELASTIC", "*PLASTIC", "*EXPANSION", "*DENSITY", "*SOLID SECTION, ELSET=EALL, MATERIAL=M",
            "*BOUNDARY", "*CLOAD", "*DLOAD", "*TEMPERATURE", "*INITIAL CONDITIONS, TYPE=TEMPERATURE",
            "*EQUATION", "*AMPLITUDE, NAME=A", "*STEP", "*STEP, NLGEOM", "*STATIC", "*STATIC, DIRECT",
            "*END STEP", "*CONTROLS, PARAMETERS=TIME INCREMENTATION", "*NODE PRINT, NSET=NALL",
            "*EL PRINT, ELSET=EALL", "*NODE FILE", "*EL FILE", "*SURFACE INTERACTION, NAME=I",
            "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR", "*CONTACT PAIR, INTERACTION=I",
            "*INCLUDE, INPUT=missing.inp", "*INCLUDE, INPUT=/etc/passwd", "*ELEMENT, TYPE=C3D20R"]
ODD_NUMBERS = ["nan", "inf", "-inf", "1e308", "-1e308", "1e-320", "2147483648", "-2147483649",
               "99999999999999999999", "0", "-0", "1.d400", "", "NaN", "+", "1e", "0x10"]
NUMBER = re.compile(r"[-+]?(\d+\.?\d*|\.\d+)([eEdD][-+]?\d+)?")
KONTAKT_EXIT_CODES = {0, 2, 3, 4}


def feature_deck():
    """A small deck that touches many keywords: GENERATE sets, a face surface with a pressure,
    an amplitude, an equation, temperatures with expansion, prints and file output."""
    nodes = [f"{1 + i + 3 * j + 9 * k}, {0.5 * i}, {0.5 * j}, {0.5 * k}"
             for k in range(3) for j in range(3) for i in range(3)]
    def n(i, j, k):
        return 1 + i + 3 * j + 9 * k
    elements = []
    for k in range(2):
        for j in range(2):
            for i in range(2):
                c = [n(i, j, k), n(i + 1, j, k), n(i + 1, j + 1, k), n(i, j + 1, k),
                     n(i, j, k + 1), n(i + 1, j, k + 1), n(i + 1, j + 1, k + 1), n(i, j + 1, k + 1)]
                elements.append(f"{len(elements) + 1}, " + ", ".join(map(str, c)))
    return ("*HEADING\nfeature deck\n*NODE, NSET=NALL\n" + "\n".join(nodes) +
            "\n*ELEMENT, TYPE=C3D8, ELSET=EALL\n" + "\n".join(elements) +
            "\n*NSET, NSET=BOTTOM, GENERATE\n1, 9, 1\n*NSET, NSET=TOP, GENERATE\n19, 27, 1\n"
            "*ELSET, ELSET=UPPER, GENERATE\n5, 8\n*SURFACE, NAME=STOP\nUPPER, S2\n"
            "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n*EXPANSION\n1.2e-5\n"
            "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n*AMPLITUDE, NAME=RAMP\n0., 0., 1., 1.\n"
            "*EQUATION\n2\n27, 1, 1., 25, 1, -1.\n*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 20.\n"
            "*BOUNDARY\nBOTTOM, 1, 3\n*STEP\n*STATIC\n*DLOAD, AMPLITUDE=RAMP\nSTOP, P2, 10.\n"
            "*TEMPERATURE\nNALL, 70.\n*CLOAD\n27, 3, -5.\n*NODE PRINT, NSET=TOP\nU, RF\n"
            "*EL PRINT, ELSET=UPPER\nS\n*NODE FILE\nU\n*EL FILE\nS, E\n*END STEP\n")


def plastic_deck():
    """The NLGEOM beam with *PLASTIC: the finite-strain J2 path."""
    return decks.beam(2, nlgeom=True, increments=3, load=-40000.0).replace(
        "*ELASTIC\n210000, 0.3\n", "*ELASTIC\n210000, 0.3\n*PLASTIC\n200., 0.\n400., 0.1\n")


def contact_deck(work):
    """Two 2x2x2 C3D8 blocks in contact (tests/contact_models, our own generator)."""
    path = os.path.join(work, "cube.inp")
    subprocess.run([sys.executable, os.path.join(REPO, "tests", "contact_models", "generate.py"),
                    "cube", path, "--n", "2"], check=True, capture_output=True)
    with open(path) as f:
        return f.read()


def base_decks(work):
    return {"beam": decks.beam(2), "nlgeom": decks.beam(2, nlgeom=True, increments=3),
            "plastic": plastic_deck(), "feature": feature_deck(), "contact": contact_deck(work)}


def mutate(text, rng):
    """One to three random edits of the deck's lines."""
    lines = text.splitlines()
    for _ in range(rng.randint(1, 3)):
        if not lines:
            lines = [rng.choice(KEYWORDS)]
        i = rng.randrange(len(lines))
        op = rng.choice(["delete", "duplicate", "truncate", "swap", "number", "number",
                         "keyword", "empty_field", "split"])
        if op == "delete":
            del lines[i]
        elif op == "duplicate":
            lines.insert(i, lines[i])
        elif op == "truncate":
            lines[i] = lines[i][:rng.randrange(len(lines[i]) + 1)]
        elif op == "swap":
            j = rng.randrange(len(lines))
            lines[i], lines[j] = lines[j], lines[i]
        elif op == "number":
            matches = list(NUMBER.finditer(lines[i]))
            if matches:
                m = rng.choice(matches)
                lines[i] = lines[i][:m.start()] + rng.choice(ODD_NUMBERS) + lines[i][m.end():]
        elif op == "keyword":
            lines.insert(i, rng.choice(KEYWORDS))
        elif op == "empty_field":
            lines[i] += "," * rng.randint(1, 3)
        elif op == "split":
            cut = rng.randrange(len(lines[i]) + 1)
            lines[i:i + 1] = [lines[i][:cut], lines[i][cut:]]
    return "\n".join(lines) + "\n"


def make_case(bases, seed, index):
    rng = random.Random(seed * 1_000_003 + index)
    name = rng.choice(sorted(bases))
    return name, mutate(bases[name], rng)


LOCATED = re.compile(r"\S+:[1-9]\d*: ")  # the deck or a file it includes


def limit_memory(megabytes):
    """preexec_fn: a mutated GENERATE range must not take the machine's memory."""
    def apply():
        limit = megabytes << 20
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    return apply


def run_case(kontakt, work, index, name, text, timeout, memory_mb):
    """(index, base name, verdict, detail). Verdicts: exit0..exit4, crash, hang, unlocated."""
    case_dir = os.path.join(work, f"case{index}")
    os.makedirs(case_dir, exist_ok=True)
    deck = os.path.join(case_dir, "deck.inp")
    with open(deck, "w") as f:
        f.write(text)
    try:
        r = subprocess.run([kontakt, "solve", deck, "--quiet", "--threads", "1"],
                           capture_output=True, text=True, errors="replace", timeout=timeout,
                           preexec_fn=limit_memory(memory_mb))
    except subprocess.TimeoutExpired:
        return index, name, "hang", f"no exit after {timeout} s"
    detail = r.stderr.strip().splitlines()[-1] if r.stderr.strip() else ""
    if r.returncode < 0:
        verdict = "crash"
        detail = f"signal {signal.Signals(-r.returncode).name}: {detail}"
    elif r.returncode not in KONTAKT_EXIT_CODES:
        verdict = "crash"
        detail = f"exit code {r.returncode}: {detail}"
    elif r.returncode == 2 and not LOCATED.search(r.stderr):
        verdict = "unlocated"
    else:
        verdict = f"exit{r.returncode}"
    if verdict not in ("crash", "hang", "unlocated"):
        shutil.rmtree(case_dir, ignore_errors=True)
    return index, name, verdict, detail


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--kontakt", required=True)
    p.add_argument("--count", type=int, default=1500)
    p.add_argument("--seed", type=int, default=10)
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--timeout", type=float, default=60.0, help="seconds per solve")
    p.add_argument("--memory-limit", type=int, default=4096, help="MiB of address space per solve")
    p.add_argument("--only", type=int, nargs="*", help="run only these case indices")
    p.add_argument("--keep", help="folder for the decks of findings (default: a temporary one)")
    p.add_argument("--print-deck", type=int, help="print the mutated deck of this index and exit")
    args = p.parse_args()

    work = tempfile.mkdtemp(prefix="mutate-decks-")
    try:
        bases = base_decks(work)
        if args.print_deck is not None:
            sys.stdout.write(make_case(bases, args.seed, args.print_deck)[1])
            return 0
        indices = args.only if args.only else range(args.count)
        verdicts = collections.Counter()
        findings = []
        with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
            futures = [pool.submit(run_case, args.kontakt, work, i,
                                   *make_case(bases, args.seed, i), args.timeout, args.memory_limit)
                       for i in indices]
            for future in concurrent.futures.as_completed(futures):
                index, name, verdict, detail = future.result()
                verdicts[verdict] += 1
                if verdict in ("crash", "hang", "unlocated"):
                    findings.append((index, name, verdict, detail))
        keep = args.keep or os.path.join(tempfile.gettempdir(), f"mutate-decks-findings-{args.seed}")
        for index, name, verdict, detail in sorted(findings):
            os.makedirs(keep, exist_ok=True)
            shutil.copy(os.path.join(work, f"case{index}", "deck.inp"),
                        os.path.join(keep, f"case{index}.inp"))
            print(f"  case {index} ({name}): {verdict}: {detail}")
        n = sum(verdicts.values())
        print(f"{n} mutated decks (seed {args.seed}): " +
              ", ".join(f"{k} {v}" for k, v in sorted(verdicts.items())))
        bad = verdicts["crash"] + verdicts["hang"] + verdicts["unlocated"]
        print(f"findings: {bad}" + (f" (decks in {keep})" if bad else ""))
        return 1 if bad else 0
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
