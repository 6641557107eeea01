#!/usr/bin/python3
"""Peer test: every qualifying ccx test deck through ccx 2.20 and `kontakt solve`, .dat blocks
compared (select_decks.py holds the rule, compare_dat.py the measure).

For each deck the deck and its *INCLUDE files are written, decompressed, into a work folder;
`ccx -i NAME` there gives the reference NAME.dat (cached under WORK/ccx_cache by a hash of the
deck's and its includes' content, so reruns only run kontakt); `KONTAKT solve NAME.inp -o out`
in a second folder gives ours. The reference is ccx 2.20's own output (the suite's .dat.ref
files come from ccx 2.11). Decks that ask ccx for its iterative solver (*STATIC,
SOLVER=ITERATIVE ...) get their reference from ccx's default direct solver instead: the
iterative solver stops at a residual tolerance far looser than this comparison.

Prints one line per deck (deck, element types, status, worst block error, detail) and a last
line `N passed, M failed`; exits 0 only when every deck passed.
Statuses: PASS; FAIL (worst block error above the tolerance, or a structural mismatch);
ERROR (kontakt's exit code and the first line of its stderr, or no reference);
TIMEOUT (kontakt ran longer than --timeout).

--contact is the contact set, friction and tied contact included (select_decks.py's contact
rule, on the derived deck below): kontakt runs with its default scheme per pair type (nts for
node to surface, lgc7 for surface to surface); only the blocks of the last printed time are
compared, the displacement blocks decide (tolerance 1e-2) and the worst other final block
(stresses, forces, contact output) is reported in the detail; increments and iterations are
printed side by side with ccx's.

--tie is the *TIE set (select_decks.py's tie rule): the derived deck
select_decks.derived_deck() writes (perturbation steps dropped, prints added to decks that
print none; the contact set runs it too) runs through both solvers; a deck without NLGEOM is
compared like the linear set (every block, 1e-4), one with NLGEOM like the nonlinear set
(blocks at common times, 1e-3); increments and iterations are printed side by side with
ccx's.

--frd compares the .frd files instead of the .dat (compare_frd.py) on the decks of the chosen
set that request file output: the same nodes, elements and blocks, the values within the set's
tolerance and frames (linear: every frame, 1e-4; --nlgeom: frames at common times, the last
times equal, 1e-3; --contact: the same frames, the DISP blocks decide at 1e-2 and the other
blocks' worst is reported; --tie as its decks' .dat). Blocks Kontakt does not write (ERROR, MESTRAIN, ...) are
counted, not compared. The last lines count decks, blocks and values and give the worst
difference per field.

--reference-only runs no kontakt: it compares ccx 2.20's output with the suite's 2.11
.dat.ref files for the qualifying decks and counts agreement at 1e-4 and 1e-3 (a check of this
harness and of how stable ccx's own output is; exit code 0 unless a reference could not be
made).
"""
import argparse
import concurrent.futures
import hashlib
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_dat  # noqa: E402
import compare_frd  # noqa: E402
import frd_file  # noqa: E402
import select_decks  # noqa: E402

DEFAULT_SUITE = select_decks.DEFAULT_SUITE
CCX_TIMEOUT = 300
ITERATIVE_SOLVER = re.compile(r"(?im)^(\*STATIC[^\n]*?),\s*SOLVER\s*=\s*ITERATIVE[^,\n]*")


def direct_solver(text):
    """Deck text with SOLVER=ITERATIVE... removed from *STATIC (ccx's direct solver instead)."""
    return ITERATIVE_SOLVER.sub(r"\1", text)


def deck_text(source_dir, name, args):
    """The deck's text as this run's set uses it: the contact and tie sets' derived deck, else
    the deck's own."""
    deck_file = select_decks.deck_path(source_dir, name)
    if args.tie or args.contact:
        return select_decks.derived_deck(deck_file)
    return select_decks.read_text(deck_file)


def stage_deck(source_dir, name, dest, transform=None, text=None):
    """Writes NAME.inp (its own text, or `text` standing for it) and its includes,
    decompressed, into dest."""
    os.makedirs(dest, exist_ok=True)
    deck_file = select_decks.deck_path(source_dir, name)
    if text is None:
        text = select_decks.read_text(deck_file)
    with open(os.path.join(dest, name + ".inp"), "w") as f:
        f.write(transform(text) if transform else text)
    for inc in select_decks.included_files(deck_file):
        target = os.path.join(dest, inc)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        with open(target, "w") as f:
            f.write(select_decks.read_text(os.path.join(source_dir, inc)))


def deck_digest(source_dir, name, text):
    """Hash of the deck as run (`text`) and its includes' content."""
    deck_file = select_decks.deck_path(source_dir, name)
    digest = hashlib.sha256(text.encode())
    for part in select_decks.included_files(deck_file):
        digest.update(select_decks.read_text(os.path.join(source_dir, part)).encode())
    return digest.hexdigest()[:16]


def work_root(work, source_dir):
    """Work subfolder of a deck folder: WORK for the suite, WORK/extra-<hash> for others."""
    if os.path.abspath(source_dir) == os.path.abspath(DEFAULT_SUITE):
        return work
    return os.path.join(work, "extra-" + hashlib.sha256(
        os.path.abspath(source_dir).encode()).hexdigest()[:8])


def ccx_reference(source_dir, name, args, text=None):
    """Path of ccx 2.20's .dat for the deck (or for `text`, standing for it), computed once
    per deck content (cached)."""
    work = work_root(args.work, source_dir)
    text = deck_text(source_dir, name, args) if text is None else text
    cached = os.path.join(work, "ccx_cache", f"{name}-{deck_digest(source_dir, name, text)}.dat")
    if os.path.exists(cached) and (not args.frd or os.path.exists(cached[:-4] + ".frd")):
        return cached
    run_dir = os.path.join(work, name, "ccx")
    shutil.rmtree(run_dir, ignore_errors=True)
    stage_deck(source_dir, name, run_dir, direct_solver, text)
    env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1")
    try:
        proc = run_killable(["ccx", "-i", name], run_dir, CCX_TIMEOUT, env)
    except subprocess.TimeoutExpired:
        raise RuntimeError(f"ccx ran longer than {CCX_TIMEOUT} s")
    produced = os.path.join(run_dir, name + ".dat")
    if proc.returncode != 0 or "Job finished" not in proc.stdout:
        lines = [ln for ln in proc.stdout.splitlines() if "ERROR" in ln] or ["no 'Job finished'"]
        raise RuntimeError(f"ccx exit {proc.returncode}: {lines[0].strip()}")
    if not os.path.exists(produced) or os.path.getsize(produced) == 0:
        raise RuntimeError("ccx produced no .dat")
    os.makedirs(os.path.dirname(cached), exist_ok=True)
    frd = os.path.join(run_dir, name + ".frd")
    if os.path.exists(frd):  # before the .dat: a cached .dat means both are there
        shutil.copy(frd, cached[:-4] + ".frd.part")
        os.replace(cached[:-4] + ".frd.part", cached[:-4] + ".frd")
    shutil.copy(produced, cached + ".part")
    os.replace(cached + ".part", cached)
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


def run_killable(cmd, cwd, timeout, env=None):
    """subprocess.run in a session of its own: on timeout the whole process group is killed
    (a wrapper script's children included) and TimeoutExpired raised."""
    with subprocess.Popen(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          text=True, errors="replace", start_new_session=True) as proc:
        try:
            out, err = proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.communicate()
            raise
    return subprocess.CompletedProcess(cmd, proc.returncode, out, err)


def describe(comparison):
    """Detail text of a failed comparison: the first problems, or the worst block."""
    if comparison.problems:
        return "; ".join(comparison.problems[:2])
    worst = comparison.worst_block()
    return f"worst block {worst.index}: {worst.header}" if worst else ""


def is_displacement_block(header):
    return header.startswith("displacements")


def compare_contact(ours_text, ref_text, tolerance):
    """(comparison of the final displacement blocks, detail text) for the contact set. The
    other final blocks (stresses, forces, contact output) are compared too and their worst
    error reported in the detail, but only the displacements decide."""
    gate = compare_dat.compare_blocks(ours_text, ref_text, tolerance, final_time_only=True,
                                      select=is_displacement_block)
    if not gate.blocks and not gate.problems:
        gate.problems.append("no final displacement block")
        gate.passed, gate.worst = False, float("inf")
    rest = compare_dat.compare_blocks(ours_text, ref_text, tolerance, final_time_only=True,
                                      select=lambda h: not is_displacement_block(h))
    detail = describe(gate) if not gate.passed else ""
    worst_other = rest.worst_block()
    if rest.problems:
        detail += f"; other blocks: {rest.problems[0]}"
    elif worst_other:
        detail += (f"; other blocks worst {worst_other.error:.2e} "
                   f"({worst_other.header.split(' for ')[0]})")
    return gate, detail.strip("; ")


FRD_RESULTS = {}  # (folder, deck) -> compare_frd.Comparison, for the --frd summary


def decides(args):
    """The blocks whose error decides a deck in --frd mode: the DISP blocks in the contact set
    (as its .dat displacements), every block otherwise."""
    return (lambda block: block == "DISP") if args.contact else None


def compare_frd_files(ours_path, ref_path, nonlinear, args):
    """(compare_frd.Comparison, detail text) of our .frd against ccx's."""
    tolerance = args.tolerance or (1e-3 if nonlinear else 1e-4)
    result = compare_frd.Comparison(tolerance=tolerance)
    for path, who in ((ours_path, "ours"), (ref_path, "ccx's")):
        if not os.path.exists(path):
            result.problems.append(f"no .frd ({who})")
    if result.problems:
        return result, "; ".join(result.problems)
    try:
        ours, ref = frd_file.read(ours_path), frd_file.read(ref_path)
    except frd_file.FrdError as e:
        result.problems.append(str(e))
        return result, str(e)
    frames = "common" if args.contact or nonlinear else "all"
    result = compare_frd.compare(ours, ref, tolerance, frames)
    detail = "; ".join(result.problems[:2])
    if not result.problems:
        worst = result.worst_per_field()
        detail = " ".join(f"{k} {v:.1e}" for k, v in worst.items())
        detail += (f" ({result.frames} frames compared of {result.frame_counts[0]} "
                   f"(ccx {result.frame_counts[1]}), {len(result.blocks)} blocks, "
                   f"{result.values()} values)")
    return result, detail


def frd_summary(decks):
    """The --frd closing lines: decks, blocks, values, worst difference per field."""
    results = [FRD_RESULTS[d] for d in decks if d in FRD_RESULTS]
    worst, skipped = {}, {}
    for r in results:
        for k, v in r.worst_per_field().items():
            worst[k] = max(worst.get(k, 0.0), v)
        for k, v in r.skipped.items():
            skipped[k] = skipped.get(k, 0) + v
    print(f".frd compared: {len(results)} decks, {sum(r.frames for r in results)} frames, "
          f"{sum(len(r.blocks) for r in results)} blocks, "
          f"{sum(r.values() for r in results)} values; ccx blocks not written: "
          f"{skipped or 'none'}")
    print("worst relative difference per field: " +
          (", ".join(f"{k} {v:.2e}" for k, v in sorted(worst.items())) or "-"))


def run_one(source_dir, name, args):
    """(status, worst error or None, detail) for one deck."""
    try:
        reference = ccx_reference(source_dir, name, args)
    except Exception as e:  # a broken reference is a setup failure of this deck
        return "ERROR", None, f"reference: {e}"
    run_dir = os.path.join(work_root(args.work, source_dir), name, "kontakt")
    shutil.rmtree(run_dir, ignore_errors=True)
    text = deck_text(source_dir, name, args)
    stage_deck(source_dir, name, run_dir, text=text)
    try:
        proc = run_killable([args.kontakt, "solve", name + ".inp", "-o", "out", "--quiet",
                             "--threads", "1"], run_dir, args.timeout)
    except subprocess.TimeoutExpired:
        return "TIMEOUT", None, f"> {args.timeout} s"
    if proc.returncode != 0:
        lines = [ln.strip() for ln in proc.stderr.splitlines() if ln.strip()]
        first = next((ln for ln in lines if "error" in ln.lower()),  # not a warning before it
                     lines[0] if lines else "(no message)")
        return "ERROR", None, f"exit {proc.returncode}: {first}"
    nonlinear = args.nlgeom or (args.tie and select_decks.has_nlgeom_step(
        select_decks.deck_path(source_dir, name), text))
    if args.frd:
        result, detail = compare_frd_files(os.path.join(run_dir, "out", name + ".frd"),
                                           reference[:-4] + ".frd", nonlinear, args)
        FRD_RESULTS[(source_dir, name)] = result
        worst = result.worst(decides(args)) if result.decided(decides(args)) else None
        if worst is None and not result.problems:
            detail = "no DISP block: structure only; " + detail
        return ("PASS" if result.passed(decides(args)) else "FAIL"), worst, detail
    ours_path = os.path.join(run_dir, "out", name + ".dat")
    if not os.path.exists(ours_path):
        return "ERROR", None, f"exit 0 but no out/{name}.dat"
    with open(ours_path, errors="replace") as f, open(reference) as g:
        ours_text, ref_text = f.read(), g.read()
    if args.contact:
        result, detail = compare_contact(ours_text, ref_text, args.tolerance)
    else:
        tolerance = args.tolerance or (1e-3 if nonlinear else 1e-4)
        result = compare_dat.compare_blocks(ours_text, ref_text, tolerance,
                                            common_times_only=nonlinear)
        detail = describe(result) if not result.passed else ""
    if args.nlgeom or args.contact or args.tie:  # incrementation side by side: ours vs ccx
        ours_sta = sta_counts(os.path.join(run_dir, "out", name + ".sta"))
        ccx_sta = sta_counts(os.path.join(work_root(args.work, source_dir), name, "ccx",
                                              name + ".sta"))
        if ours_sta and ccx_sta:
            detail = (f"increments/iterations {ours_sta[0]}/{ours_sta[1]} "
                      f"(ccx {ccx_sta[0]}/{ccx_sta[1]}) {detail}").strip()
    return ("PASS" if result.passed else "FAIL"), result.worst, detail


def reference_only(source_dir, name, args):
    """(status, worst error or None, detail): ccx 2.20 against the suite's 2.11 .dat.ref."""
    try:
        reference = ccx_reference(source_dir, name, args)
        old = select_decks.read_text(os.path.join(source_dir, name + ".dat.ref"))
    except Exception as e:
        return "ERROR", None, str(e)
    with open(reference) as f:
        new = f.read()
    if args.contact:
        result, detail = compare_contact(new, old, args.tolerance)
    else:
        result = compare_dat.compare_blocks(new, old, args.tolerance,
                                            common_times_only=args.nlgeom)
        detail = describe(result)
    return ("PASS" if result.passed else "FAIL"), result.worst, detail


def label(folder, name, args):
    """Deck name as shown: bare for the suite, FOLDER/NAME for --extra-decks folders."""
    if os.path.abspath(folder) == os.path.abspath(args.suite):
        return name
    return f"{os.path.basename(os.path.normpath(folder))}/{name}"


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--kontakt", help="path of the kontakt executable")
    p.add_argument("--suite", default=DEFAULT_SUITE, help="ccx test deck folder")
    p.add_argument("--extra-decks", action="append", default=[], metavar="DIR",
                   help="a further folder of decks (e.g. hidden ones), run through the same "
                        "rule; repeatable")
    p.add_argument("--work", help="scratch folder, ccx results cached in it (default: a new "
                                  "temporary folder)")
    p.add_argument("--only", nargs="+", metavar="NAME", help="run just these decks")
    p.add_argument("--nlgeom", action="store_true",
                   help="the nonlinear set: decks with NLGEOM steps, final blocks compared")
    p.add_argument("--contact", action="store_true",
                   help="the frictionless contact set: final displacement blocks compared")
    p.add_argument("--tie", action="store_true",
                   help="the *TIE set: derived decks, linear or nonlinear comparison per deck")
    p.add_argument("--tolerance", type=float, default=None,
                   help="largest block error (default 1e-4, --nlgeom 1e-3, --contact 1e-2, "
                        "--tie 1e-4 or with NLGEOM 1e-3)")
    p.add_argument("--timeout", type=int, default=300, help="kontakt time limit per deck (s)")
    p.add_argument("--jobs", type=int, default=2, help="decks run in parallel")
    p.add_argument("--list", action="store_true", help="print the rule's verdict per deck and exit")
    p.add_argument("--reference-only", action="store_true",
                   help="no kontakt: compare ccx 2.20 with the suite's 2.11 .dat.ref files")
    p.add_argument("--frd", action="store_true",
                   help="compare the .frd files of the set's decks that request file output")
    args = p.parse_args()
    if args.nlgeom + args.contact + args.tie > 1:
        p.error("--nlgeom, --contact and --tie are separate sets")
    if args.tie and args.reference_only:
        p.error("--reference-only compares the suite's decks as they are; --tie derives them")
    if args.frd and args.reference_only:
        p.error("--reference-only compares .dat files; --frd compares kontakt's .frd with ccx's")
    if args.tolerance is None and not args.tie:  # the tie set's default depends on the deck
        args.tolerance = 1e-3 if args.nlgeom else 1e-2 if args.contact else 1e-4

    folders = [args.suite] + args.extra_decks
    missing = [d for d in folders if not os.path.isdir(d)]
    if missing:
        print(f"deck folder(s) not found: {', '.join(missing)} -- this is a setup error: "
              "install calculix-ccx-test (deploy/install-deps.sh)")
        return 1
    decks = []
    for folder in folders:
        good, excluded = select_decks.qualifying_decks(folder, args.nlgeom, args.contact,
                                                       args.tie)
        if args.list:
            for name in sorted(set(good) | set(excluded)):
                print(f"{name:24s} {'qualifies' if name in good else 'excluded: ' + excluded[name]}")
            print(f"{folder}: {len(good)} qualify, {len(excluded)} excluded")
        if args.frd and not args.list:  # only the decks that request file output
            good = [n for n in good if select_decks.has_file_requests(
                select_decks.deck_path(folder, n), deck_text(folder, n, args))]
        decks += [(folder, n) for n in good if not args.only or n in args.only]
    if args.list:
        return 0
    if args.only:
        unknown = set(args.only) - {n for _, n in decks}
        if unknown:
            print(f"not qualifying decks (or unknown): {' '.join(sorted(unknown))}")
            return 1
    if not args.kontakt and not args.reference_only:
        p.error("--kontakt is required (or --reference-only)")
    if shutil.which("ccx") is None:
        print("ccx not found -- install calculix-ccx (deploy/install-deps.sh)")
        return 1
    args.work = os.path.abspath(args.work or tempfile.mkdtemp(prefix="kontakt_peer_"))
    os.makedirs(args.work, exist_ok=True)
    if args.kontakt:
        args.kontakt = os.path.abspath(args.kontakt)

    if args.reference_only:
        return main_reference_only(decks, args)
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        results = list(pool.map(lambda d: run_one(d[0], d[1], args), decks))
    passed = 0
    print(f"{'deck':20s} {'elements':16s} {'status':8s} {'worst error':>11s}  detail")
    for (folder, name), (status, worst, detail) in zip(decks, results):
        passed += status == "PASS"
        types = ",".join(select_decks.element_types(select_decks.deck_path(folder, name)))
        shown = "-" if worst is None else f"{worst:.2e}"
        print(f"{label(folder, name, args):20s} {types:16s} {status:8s} {shown:>11s}  {detail}", flush=True)
    tolerance = f"{args.tolerance:g}" if args.tolerance else "1e-4 (NLGEOM: 1e-3)"
    print(f"work folder {args.work}; tolerance {tolerance} on "
          f"max|ours - ccx| / max|ccx| per {'.frd' if args.frd else '.dat'} block")
    if args.frd:
        frd_summary(decks)
    print(f"{passed} passed, {len(decks) - passed} failed")
    return 0 if passed == len(decks) else 1


def main_reference_only(decks, args):
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        results = list(pool.map(lambda d: reference_only(d[0], d[1], args), decks))
    print("ccx 2.20 (reference, direct solver) against the suite's ccx 2.11 .dat.ref")
    print(f"{'deck':20s} {'elements':16s} {'2.20 vs 2.11':>12s}  detail")
    counts = {1e-4: 0, 1e-3: 0}
    errors = 0
    for (folder, name), (status, worst, detail) in zip(decks, results):
        types = ",".join(select_decks.element_types(select_decks.deck_path(folder, name)))
        if status == "ERROR":
            errors += 1
            shown = "ERROR"
        else:
            shown = f"{worst:.2e}"
            for tol in counts:
                counts[tol] += worst <= tol
            detail = detail if worst > 1e-4 else ""
        print(f"{label(folder, name, args):20s} {types:16s} {shown:>12s}  {detail}")
    for tol, n in counts.items():
        print(f"agree at {tol:g}: {n} of {len(decks)}")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
