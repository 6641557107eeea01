#!/usr/bin/python3
"""Peer test: every qualifying ccx test deck through ccx 2.20 and `kontakt solve`, .dat blocks
compared (see deck_rule.py for the rule and compare_dat.py for the measure).

The reference is ccx 2.20's own output, regenerated here (the suite's .dat.ref files come from
ccx 2.11). Decks that ask ccx for its iterative solver (*STATIC, SOLVER=ITERATIVE ...) get their
reference from ccx's default direct solver instead: the iterative solver stops at a residual
tolerance far looser than this comparison. Prints one line per deck and `N passed, M failed`.
"""
import argparse
import concurrent.futures
import hashlib
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_dat  # noqa: E402
import deck_rule  # noqa: E402

DEFAULT_SUITE = "/usr/share/doc/calculix-ccx-test/examples/test"
ITERATIVE_SOLVER = re.compile(r"(?im)^(\*STATIC[^\n]*?),\s*SOLVER\s*=\s*ITERATIVE[^,\n]*")


def included_files(deck_file):
    """Relative names of every file the deck includes (recursively), in the deck's folder."""
    out, todo = [], [deck_file]
    while todo:
        text = deck_rule.read_text(todo.pop())
        for m in re.finditer(r"(?im)^\*INCLUDE\s*,\s*INPUT\s*=\s*([^\s,]+)", text):
            name = m.group(1)
            if name not in out:
                out.append(name)
                todo.append(os.path.join(os.path.dirname(deck_file), name))
    return out


def stage_deck(source_dir, name, dest, transform=None):
    """Writes NAME.inp and its includes, decompressed, into dest; returns the deck's text."""
    os.makedirs(dest, exist_ok=True)
    deck_file = os.path.join(source_dir, name + ".inp")
    text = deck_rule.read_text(deck_file)
    with open(os.path.join(dest, name + ".inp"), "w") as f:
        f.write(transform(text) if transform else text)
    for inc in included_files(deck_file):
        target = os.path.join(dest, inc)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        with open(target, "w") as f:
            f.write(deck_rule.read_text(os.path.join(source_dir, inc)))
    return text


def ccx_reference(source_dir, name, work):
    """Path of ccx 2.20's .dat for the deck, computed once per deck content (cached)."""
    deck_file = os.path.join(source_dir, name + ".inp")
    digest = hashlib.sha256()
    for part in [deck_file] + [os.path.join(source_dir, i) for i in included_files(deck_file)]:
        digest.update(deck_rule.read_text(part).encode())
    cached = os.path.join(work, "ccx_cache", f"{name}-{digest.hexdigest()[:16]}.dat")
    if os.path.exists(cached):
        return cached
    run_dir = os.path.join(work, name, "ccx")
    shutil.rmtree(run_dir, ignore_errors=True)
    stage_deck(source_dir, name, run_dir, lambda t: ITERATIVE_SOLVER.sub(r"\1", t))
    env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1")
    subprocess.run(["ccx", "-i", name], cwd=run_dir, env=env, capture_output=True, timeout=600)
    produced = os.path.join(run_dir, name + ".dat")
    if not os.path.exists(produced) or os.path.getsize(produced) == 0:
        raise RuntimeError("ccx produced no .dat")
    os.makedirs(os.path.dirname(cached), exist_ok=True)
    shutil.copy(produced, cached)
    return cached


def sta_counts(path):
    """(converged increments, Newton iterations of all attempts) from a .sta file, or None."""
    if not os.path.exists(path):
        return None
    increments = iterations = 0
    with open(path) as f:
        for line in f:
            fields = line.split()
            if len(fields) >= 7 and fields[0].isdigit():
                iterations += int(fields[3])
                increments += not fields[2].endswith("U")
    return increments, iterations


def run_one(source_dir, name, args):
    """(status, detail, worst error) for one deck."""
    try:
        reference = ccx_reference(source_dir, name, args.work)
    except Exception as e:  # a broken reference is a setup failure of this deck
        return "ERROR", f"reference: {e}", None
    run_dir = os.path.join(args.work, name, "kontakt")
    shutil.rmtree(run_dir, ignore_errors=True)
    stage_deck(source_dir, name, run_dir)
    try:
        proc = subprocess.run([args.kontakt, "solve", name + ".inp", "-o", "out", "--quiet",
                               "--threads", "1"], cwd=run_dir, capture_output=True, text=True,
                              timeout=args.timeout)
    except subprocess.TimeoutExpired:
        return "TIMEOUT", f"> {args.timeout} s", None
    if proc.returncode != 0:
        first = (proc.stderr.strip().splitlines() or ["(no message)"])[-1]
        return "ERROR", f"exit {proc.returncode}: {first}", None
    with open(os.path.join(run_dir, "out", name + ".dat")) as f:
        ours = f.read()
    with open(reference) as f:
        worst, problems = compare_dat.compare(ours, f.read(), common_times_only=args.nlgeom)
    detail = ""
    if args.nlgeom:  # incrementation side by side: increments/iterations, ours vs ccx
        ours_sta = sta_counts(os.path.join(run_dir, "out", name + ".sta"))
        ccx_sta = sta_counts(os.path.join(args.work, name, "ccx", name + ".sta"))
        if ours_sta and ccx_sta:
            detail = f"increments/iterations {ours_sta[0]}/{ours_sta[1]} (ccx {ccx_sta[0]}/{ccx_sta[1]})"
    if problems:
        return "FAIL", "; ".join(problems[:2]), worst
    return ("PASS" if worst <= args.tolerance else "FAIL"), detail, worst


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--kontakt", help="path of the kontakt executable")
    p.add_argument("--suite", default=DEFAULT_SUITE, help="ccx test deck folder")
    p.add_argument("--extra-decks", action="append", default=[],
                   help="further folders of decks, run through the same rule")
    p.add_argument("--work", default="peer_work", help="scratch folder (ccx results are cached)")
    p.add_argument("--only", nargs="+", help="run just these decks")
    p.add_argument("--nlgeom", action="store_true",
                   help="the nonlinear set: decks with NLGEOM steps, final blocks compared")
    p.add_argument("--tolerance", type=float, default=None,
                   help="largest block error (default 1e-4, with --nlgeom 1e-3)")
    p.add_argument("--timeout", type=int, default=300)
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--list", action="store_true", help="print the rule's verdict per deck and exit")
    args = p.parse_args()
    if args.tolerance is None:
        args.tolerance = 1e-3 if args.nlgeom else 1e-4

    folders = [args.suite] + args.extra_decks
    missing = [d for d in folders if not os.path.isdir(d)]
    if missing:
        print(f"deck folder(s) not found: {', '.join(missing)} "
              "(install calculix-ccx-test: deploy/install-deps.sh)")
        return 1
    decks = []
    for folder in folders:
        good, excluded = deck_rule.qualifying_decks(folder, args.nlgeom)
        if args.list:
            for name in sorted(set(good) | set(excluded)):
                print(f"{name:24s} {'qualifies' if name in good else 'excluded: ' + excluded[name]}")
            print(f"{folder}: {len(good)} qualify, {len(excluded)} excluded")
        decks += [(folder, n) for n in good if not args.only or n in args.only]
    if args.list:
        return 0
    if not args.kontakt:
        p.error("--kontakt is required")
    args.kontakt = os.path.abspath(args.kontakt)
    args.work = os.path.abspath(args.work)
    if shutil.which("ccx") is None:
        print("ccx not found (install calculix-ccx: deploy/install-deps.sh)")
        return 1

    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        results = list(pool.map(lambda d: run_one(d[0], d[1], args), decks))
    passed = 0
    print(f"{'deck':24s} {'status':8s} {'worst error':>12s}  detail")
    for (folder, name), (status, detail, worst) in zip(decks, results):
        passed += status == "PASS"
        shown = "-" if worst is None else f"{worst:.2e}"
        print(f"{name:24s} {status:8s} {shown:>12s}  {detail}")
    print(f"tolerance {args.tolerance:g} on max|ours - ccx| / max|ccx| per .dat block")
    print(f"{passed} passed, {len(decks) - passed} failed")
    return 0 if passed == len(decks) else 1


if __name__ == "__main__":
    sys.exit(main())
