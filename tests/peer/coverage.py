#!/usr/bin/python3
"""Coverage report: every deck of the ccx test suite whose only procedure is *STATIC
(select_decks.is_static_only) through `kontakt solve`, each with its outcome:

  matches  kontakt converges and its .dat agrees with ccx 2.20's at the peer tolerances;
  differs  kontakt converges, the .dat does not agree (the worst block or first mismatch);
  refused  kontakt refuses the deck (exit 2): its first refusal as kontakt prints it, grouped
           by REFUSAL_GROUPS (the rows of issue 15's table);
  failed   kontakt does not converge, crashes, times out, or ccx gives no reference: bugs or
           set-up problems, each listed.

Both solvers run the deck as select_decks.derived_deck() derives it (a deck that prints
nothing gets *NODE PRINT U and *EL PRINT S of everything). The comparison is the peer set's
that fits the deck (run_peer.py): with a *CONTACT PAIR the final displacement blocks at 1e-2;
with an NLGEOM step or a *PLASTIC material (ccx switches NLGEOM on for it) the blocks at
common times at 1e-3; otherwise every block at 1e-4. ccx runs only for decks kontakt solved,
its .dat cached in WORK/ccx_cache by content. One solver process at a time (OMP_NUM_THREADS=1,
kontakt --threads 1).

--out DIR writes coverage.csv and coverage.md (counts per outcome and per refusal group, then
every deck). --baseline FILE (deck names, one a line, `#` comments) makes the exit code 1
when a baseline deck does not match, and lists the decks that match but are not in it
(exit code unchanged); --write-baseline FILE writes today's matching decks.
"""
import argparse
import collections
import csv
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import types

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_dat  # noqa: E402
import run_peer  # noqa: E402
import select_decks  # noqa: E402

OUTCOMES = ("matches", "differs", "refused", "failed")

# Refusal groups, first match wins, on kontakt's message without its `file:line: ` prefix
# (`*KEYWORD: reason`). The labels are the rows of issue 15's table.
REFUSAL_GROUPS = [
    ("beam elements B31/B32(R)", r"element type B3"),
    ("shell and membrane elements S*, M3D*", r"element type (S\d|M3D)"),
    ("plane/axisymmetric elements CPE*, CPS*, CAX*", r"element type (CPE|CPS|CAX)"),
    ("springs, gaps, trusses, couplings (GAPUNI, SPRINGA, T3D2, DCOUP3D)",
     r"^\*ELEMENT: element type"),
    ("*TRANSFORM", r"^\*TRANSFORM\b"),
    ("*MPC", r"^\*MPC\b"),
    ("*NODE lines with an extra or empty field", r"^\*NODE:"),
    ("*TIE, *FRICTION, TIED",
     r"^\*(TIE|FRICTION|SURFACE BEHAVIOR|SURFACE INTERACTION|CONTACT PAIR)\b|TIED"),
    ("temperature-dependent *ELASTIC", r"^\*ELASTIC\b.*temperature"),
    ("*USER MATERIAL, *RIGID BODY", r"^\*(USER MATERIAL|RIGID ?BODY)\b"),
    ("*INITIAL CONDITIONS TYPE=STRESS, kinematic/combined hardening, ortho/aniso *ELASTIC",
     r"^\*(INITIAL CONDITIONS|PLASTIC|ELASTIC)\b"),
    ("*HYPERELASTIC, *ORIENTATION, *RESTART, *SUBMODEL",
     r"^\*(HYPERELASTIC|HYPERFOAM|ORIENTATION|RESTART|SUBMODEL)\b|ORIENTATION"),
    ("*DLOAD CENTRIF / GRAV, *PRE-TENSION SECTION, *MODEL CHANGE",
     r"^\*DLOAD\b.*(CENTRIF|GRAV)|^\*(PRE-TENSION SECTION|MODEL CHANGE)\b"),
]
OTHER_GROUP = "other"
_LOCATION = re.compile(r"^kontakt: error: [^:]*(:\d+)?: ")


def refusal_text(stderr):
    """kontakt's first error line without its `kontakt: error: FILE:LINE: ` prefix."""
    lines = [ln.strip() for ln in stderr.splitlines() if ln.strip()]
    first = next((ln for ln in lines if "error" in ln.lower()), lines[0] if lines else "")
    return _LOCATION.sub("", first) or "(no message)"


def refusal_group(reason):
    """The REFUSAL_GROUPS label of a refusal text, or OTHER_GROUP."""
    for label, pattern in REFUSAL_GROUPS:
        if re.search(pattern, reason, re.IGNORECASE):
            return label
    return OTHER_GROUP


def comparison_mode(path, text):
    """'contact', 'nonlinear' or 'linear': which peer comparison judges the deck."""
    recs = list(select_decks.records(path, text=text))
    if any(k == "CONTACT PAIR" for k, _, _ in recs):
        return "contact"
    if any(k == "PLASTIC" for k, _, _ in recs) or select_decks.has_nlgeom_step(path, text):
        return "nonlinear"
    return "linear"


def compare(mode, ours_text, ref_text):
    """(passed, worst error or None, detail) of our .dat against ccx's in the given mode."""
    if mode == "contact":
        result, detail = run_peer.compare_contact(ours_text, ref_text, 1e-2)
    else:
        nonlinear = mode == "nonlinear"
        result = compare_dat.compare_blocks(ours_text, ref_text, 1e-3 if nonlinear else 1e-4,
                                            common_times_only=nonlinear)
        detail = run_peer.describe(result) if not result.passed else ""
    return result.passed, result.worst, detail


def run_deck(suite, name, args):
    """{outcome, group, mode, worst, detail, seconds} of one deck."""
    path = select_decks.deck_path(suite, name)
    text = select_decks.derived_deck(path)
    mode = comparison_mode(path, text)
    row = {"deck": name, "elements": ",".join(select_decks.element_types(path)), "mode": mode,
           "group": "", "worst": "", "detail": "", "seconds": ""}
    run_dir = os.path.join(args.work, name, "kontakt")
    shutil.rmtree(run_dir, ignore_errors=True)
    run_peer.stage_deck(suite, name, run_dir, text=text)
    start = time.monotonic()
    try:
        proc = run_peer.run_killable([args.kontakt, "solve", name + ".inp", "-o", "out",
                                      "--quiet", "--threads", "1"], run_dir, args.timeout)
    except subprocess.TimeoutExpired:
        return dict(row, outcome="failed", detail=f"kontakt ran longer than {args.timeout} s")
    row["seconds"] = f"{time.monotonic() - start:.1f}"
    if proc.returncode == 2:
        reason = refusal_text(proc.stderr)
        return dict(row, outcome="refused", group=refusal_group(reason), detail=reason)
    if proc.returncode != 0:
        what = "not converged" if proc.returncode == 3 else f"exit {proc.returncode}"
        return dict(row, outcome="failed", detail=f"{what}: {refusal_text(proc.stderr)}")
    ours = os.path.join(run_dir, "out", name + ".dat")
    if not os.path.exists(ours):
        return dict(row, outcome="failed", detail=f"exit 0 but no out/{name}.dat")
    try:
        reference = run_peer.ccx_reference(suite, name, args, text)
    except Exception as e:  # no reference: the deck cannot be judged
        return dict(row, outcome="failed", detail=f"no ccx reference: {e}")
    with open(ours, errors="replace") as f, open(reference) as g:
        passed, worst, detail = compare(mode, f.read(), g.read())
    return dict(row, outcome="matches" if passed else "differs", detail=detail,
                worst="" if worst is None else f"{worst:.2e}")


def read_baseline(path):
    """Deck names of a baseline file (one a line; blank lines and `#` comments ignored)."""
    with open(path) as f:
        return {ln.split("#")[0].strip() for ln in f} - {""}


def markdown(rows, suite):
    """The report as markdown: counts per outcome, per refusal group, then every deck."""
    count = collections.Counter(r["outcome"] for r in rows)
    total = len(rows)
    out = [f"# Coverage of the *STATIC-only decks of {suite}", "",
           "| outcome | decks | share |", "|---|---|---|"]
    out += [f"| {o} | {count[o]} | {100 * count[o] / max(total, 1):.0f} % |" for o in OUTCOMES]
    out += [f"| total | {total} | |", "", "| refusal group (first refusal) | decks |", "|---|---|"]
    groups = collections.Counter(r["group"] for r in rows if r["outcome"] == "refused")
    out += [f"| {g} | {n} |" for g, n in groups.most_common()]
    out += ["", "| deck | elements | outcome | comparison | worst | detail |",
            "|---|---|---|---|---|---|"]
    for r in rows:
        detail = r["detail"].replace("|", "\\|")
        out.append(f"| {r['deck']} | {r['elements']} | {r['outcome']} | {r['mode']} | "
                   f"{r['worst']} | {detail} |")
    return "\n".join(out) + "\n"


def write_reports(rows, out_dir, suite):
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, "coverage.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=["deck", "elements", "outcome", "group", "mode",
                                               "worst", "seconds", "detail"])
        writer.writeheader()
        writer.writerows(rows)
    with open(os.path.join(out_dir, "coverage.md"), "w") as f:
        f.write(markdown(rows, suite))


def baseline_verdict(rows, baseline):
    """(lost: baseline decks not matching with their outcome, gained: matching decks not in
    the baseline)."""
    by_name = {r["deck"]: r for r in rows}
    lost = [(n, by_name[n]["outcome"] if n in by_name else "not in the population")
            for n in sorted(baseline) if by_name.get(n, {}).get("outcome") != "matches"]
    gained = sorted(n for n, r in by_name.items() if r["outcome"] == "matches"
                    and n not in baseline)
    return lost, gained


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--kontakt", required=True, help="path of the kontakt executable")
    p.add_argument("--suite", default=select_decks.DEFAULT_SUITE, help="ccx test deck folder")
    p.add_argument("--work", help="scratch folder, ccx results cached in it (default: a new "
                                  "temporary folder)")
    p.add_argument("--out", help="folder for coverage.csv and coverage.md")
    p.add_argument("--only", nargs="+", metavar="NAME", help="just these decks")
    p.add_argument("--baseline", help="fail when a deck named in this file does not match")
    p.add_argument("--write-baseline", metavar="FILE", help="write the matching decks here")
    p.add_argument("--timeout", type=int, default=300, help="kontakt time limit per deck (s)")
    args = p.parse_args()
    if not os.path.isdir(args.suite):
        print(f"deck folder not found: {args.suite} -- this is a setup error: install "
              "calculix-ccx-test (deploy/install-deps.sh)")
        return 1
    if shutil.which("ccx") is None:
        print("ccx not found -- install calculix-ccx (deploy/install-deps.sh)")
        return 1
    names = [n for n in select_decks.deck_names(args.suite)
             if select_decks.is_static_only(select_decks.deck_path(args.suite, n))]
    if args.only:
        unknown = set(args.only) - set(names)
        if unknown:
            print(f"not *STATIC-only decks (or unknown): {' '.join(sorted(unknown))}")
            return 1
        names = [n for n in names if n in args.only]
    args.kontakt = os.path.abspath(args.kontakt)
    args.work = os.path.abspath(args.work or tempfile.mkdtemp(prefix="kontakt_coverage_"))
    args = types.SimpleNamespace(**vars(args), frd=False)  # what run_peer.ccx_reference reads

    rows = []
    for name in names:
        row = run_deck(args.suite, name, args)
        rows.append(row)
        print(f"{name:20s} {row['outcome']:8s} {row['worst']:>9s}  "
              f"{row['group'] + ': ' if row['group'] else ''}{row['detail']}", flush=True)
    count = collections.Counter(r["outcome"] for r in rows)
    print(f"{len(rows)} decks: " + ", ".join(f"{count[o]} {o}" for o in OUTCOMES)
          + f"; work folder {args.work}")
    if args.out:
        write_reports(rows, args.out, args.suite)
        print(f"report: {os.path.join(args.out, 'coverage.md')}, coverage.csv")
    if args.write_baseline:
        with open(args.write_baseline, "w") as f:
            f.write("# *STATIC-only suite decks that match ccx 2.20 (tests/peer/coverage.py)\n")
            f.write("".join(r["deck"] + "\n" for r in rows if r["outcome"] == "matches"))
    if not args.baseline:
        return 0
    lost, gained = baseline_verdict(rows, read_baseline(args.baseline))
    if args.only:
        lost = [(n, o) for n, o in lost if n in args.only]
    for name, outcome in lost:
        print(f"REGRESSION: {name} is in the baseline but {outcome}")
    if gained:
        print(f"now matching, not in the baseline (add them): {' '.join(gained)}")
    return 1 if lost else 0


if __name__ == "__main__":
    sys.exit(main())
