#!/usr/bin/python3
"""Runs the libFuzzer harnesses of a KONTAKT_FUZZ build one after the other, each on its corpus
(seeded by make_corpus.py from the project's own decks, and grown by every run), and prints
executions, rate, corpus size, peak memory and findings per harness. Exit code 1 when any
harness found something: the input is kept as BUILD/fuzz/findings/HARNESS-crash-... (reproduce
with `BUILD/tests/fuzz/fuzz_HARNESS FILE`).

  run_fuzzers.py --build build-fuzz --seconds 25            # CI: a bounded time each
  run_fuzzers.py --build build-fuzz --runs 10000000         # the long run (tests/fuzz/README.md)
"""
import argparse
import concurrent.futures
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))

# harness -> (dictionary, -max_len). Small inputs: bugs need few lines, and small decks keep
# the executions per second high enough for the long runs.
HARNESSES = {
    "deck_text": ("inp.dict", 4096),
    "deck_zip": ("inp.dict", 4096),
    "submission": ("json.dict", 4096),
    "router": ("http.dict", 4096),
}


def scratch_root():
    """Scratch folders of the harnesses (stores, unpacked uploads) on tmpfs when there is one:
    SQLite's fsyncs would otherwise dominate the router harness."""
    return "/dev/shm" if os.path.isdir("/dev/shm") and os.access("/dev/shm", os.W_OK) else None


def stat(pattern, text, default=0):
    m = re.findall(pattern, text)
    return int(m[-1]) if m else default


def run(build, name, limit, seconds_budget):
    exe = os.path.join(build, "tests", "fuzz", f"fuzz_{name}")
    corpus = os.path.join(build, "fuzz", "corpus", name)
    findings = os.path.join(build, "fuzz", "findings")
    os.makedirs(findings, exist_ok=True)
    dictionary, max_len = HARNESSES[name]
    scratch = tempfile.mkdtemp(prefix=f"fuzz-{name}-", dir=scratch_root())
    # A 16 MiB quarantine, no fill of fresh blocks, short allocation stacks: 2.5x the
    # executions per second of ASan's defaults, leaks and use-after-free still caught.
    env = dict(os.environ, TMPDIR=scratch,
               ASAN_OPTIONS="detect_leaks=1:quarantine_size_mb=16:max_malloc_fill_size=0:"
                            "malloc_context_size=4",
               UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1")
    cmd = [exe, *limit, "-rss_limit_mb=2048", "-malloc_limit_mb=2048", "-timeout=30",
           f"-max_len={max_len}", f"-dict={os.path.join(HERE, dictionary)}",
           f"-artifact_prefix={os.path.join(findings, name)}-", "-print_final_stats=1",
           "-print_pcs=0", corpus]
    log_path = os.path.join(build, "fuzz", f"{name}.log")  # tail -f it during a long run
    t0 = time.monotonic()
    with open(log_path, "w") as log:
        r = subprocess.run(cmd, cwd=scratch, env=env, stdout=log, stderr=subprocess.STDOUT,
                           timeout=seconds_budget)
    elapsed = time.monotonic() - t0
    shutil.rmtree(scratch, ignore_errors=True)
    with open(log_path, errors="replace") as log:
        out = log.read()
    runs = stat(r"stat::number_of_executed_units:\s+(\d+)", out)
    result = {
        "name": name, "exit": r.returncode, "runs": runs, "seconds": elapsed,
        "corpus": len(os.listdir(corpus)), "rss": stat(r"stat::peak_rss_mb:\s+(\d+)", out),
        "coverage": stat(r"cov: (\d+)", out),
        "finding": None,
    }
    if r.returncode != 0:
        lines = [l for l in out.splitlines() if "ERROR" in l or "SUMMARY" in l or "Test unit written" in l]
        result["finding"] = "\n    ".join(lines[-6:]) or out[-2000:]
    return result


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--build", required=True, help="a build folder configured with KONTAKT_FUZZ=ON")
    g = p.add_mutually_exclusive_group(required=True)
    g.add_argument("--seconds", type=int, help="time per harness")
    g.add_argument("--runs", type=int, help="executions per harness")
    p.add_argument("--only", nargs="*", choices=sorted(HARNESSES), help="these harnesses only")
    p.add_argument("--parallel", type=int, default=2, help="harnesses run at once (default 2)")
    args = p.parse_args()
    build = os.path.abspath(args.build)
    seeds = os.path.join(build, "fuzz", "seeds")
    subprocess.run([sys.executable, os.path.join(HERE, "make_corpus.py"), seeds], check=True,
                   stdout=subprocess.DEVNULL)
    limit = [f"-max_total_time={args.seconds}"] if args.seconds else [f"-runs={args.runs}"]
    budget = args.seconds * 3 + 120 if args.seconds else None
    names = args.only or list(HARNESSES)
    for name in names:
        corpus = os.path.join(build, "fuzz", "corpus", name)
        os.makedirs(corpus, exist_ok=True)
        for seed in os.listdir(os.path.join(seeds, name)):
            shutil.copy(os.path.join(seeds, name, seed), os.path.join(corpus, "seed-" + seed))
    with concurrent.futures.ThreadPoolExecutor(args.parallel) as pool:
        results = list(pool.map(lambda name: run(build, name, limit, budget), names))
    for res in results:
        print(f"fuzz_{res['name']:<11} {res['runs']:>10} runs in {res['seconds']:7.0f} s "
              f"({res['runs'] / max(res['seconds'], 1e-9):7.0f}/s), corpus {res['corpus']:>5}, "
              f"coverage {res['coverage']:>5}, peak {res['rss']:>4} MB: "
              f"{'no finding' if res['exit'] == 0 else 'FINDING'}", flush=True)
        if res["finding"]:
            print("    " + res["finding"], flush=True)
    return 1 if any(r["exit"] != 0 for r in results) else 0


if __name__ == "__main__":
    sys.exit(main())
