#!/usr/bin/python3
"""Render times of the dashboard, measured in Debian's chromium (dashboard_render.js):

* job page of a job with ITERATIONS Newton iterations (an NLGEOM beam, one iteration per
  increment): time to the first plot, time until the residual plot holds every iteration
  (checked against /iterations), cursor response;
* job list with JOBS jobs at 200 per page: first page shown, paging through all of them.

Median of --runs page loads. Not a pass/fail timing test: it fails only when a page does not
show everything. --smoke (CI) uses 1000 iterations and 100 jobs.

usage: bench_dashboard.py --kontaktd PATH --node PATH --chromium PATH --node-modules DIR
                          [--smoke] [--iterations 10000] [--jobs 500] [--runs 3]
"""
import argparse
import json
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "server"))

import decks  # noqa: E402
import kontaktd_harness as harness  # noqa: E402


def count_rows(d, job_id, table):
    rows, since = 0, 0
    while True:
        _, _, page = d.json("GET", f"/v1/jobs/{job_id}/{table}?since={since}&limit=10000")
        if not page[table]:
            return rows
        rows += len(page[table])
        since = page["next_since"]


def main():
    p = argparse.ArgumentParser()
    for name in ("kontaktd", "node", "chromium", "node-modules"):
        p.add_argument("--" + name, required=True)
    p.add_argument("--smoke", action="store_true")
    p.add_argument("--iterations", type=int)
    p.add_argument("--jobs", type=int)
    p.add_argument("--runs", type=int, default=3)
    args = p.parse_args()
    iterations = args.iterations or (1000 if args.smoke else 10000)
    n_jobs = args.jobs or (100 if args.smoke else 500)

    d = harness.Daemon(args.kontaktd, args=["--workers", "2"]).start()
    try:
        start = time.monotonic()
        _, _, job = d.submit(decks.beam(1, nlgeom=True, increments=iterations, load=-2000.0),
                             "name=render-bench")
        d.wait(job["id"], until=("succeeded",), timeout=3600)
        n_iterations = count_rows(d, job["id"], "iterations")
        n_increments = count_rows(d, job["id"], "increments")
        print(f"job with {n_iterations} iterations, {n_increments} increments solved in "
              f"{time.monotonic() - start:.1f} s", flush=True)
        if n_iterations < iterations:
            raise SystemExit(f"the bench job has {n_iterations} iterations, wanted {iterations}")
        ids = [d.submit(decks.tiny(), f"name=list-{i}&label=bench%3Dlist")[2]["id"] for i in range(n_jobs)]
        for job_id in ids:
            d.wait(job_id, timeout=600)
        env = dict(os.environ, KONTAKTD_URL=d.url, JOB_ID=job["id"], ITERATIONS=str(n_iterations),
                   RUNS=str(args.runs), LIST_LABEL="bench=list", LIST_JOBS=str(n_jobs),
                   CHROMIUM=args.chromium, NODE_MODULES=os.path.abspath(args.node_modules))
        out = subprocess.run([args.node, os.path.join(HERE, "dashboard_render.js")], env=env,
                             capture_output=True, text=True, timeout=1800)
        if out.returncode != 0:
            raise SystemExit("dashboard_render.js failed:\n" + out.stdout + out.stderr)
        r = json.loads(out.stdout.strip().splitlines()[-1])
    finally:
        d.stop()

    print(f"job page, {r['iterations']} iterations (median of {r['runs']} loads, ms since navigation):")
    print(f"  page scripts ready    {r['scripts_ready_ms']:8.0f} ms")
    print(f"  first plot            {r['first_plot_ms']:8.0f} ms")
    print(f"  every iteration drawn {r['all_points_ms']:8.0f} ms")
    print(f"  whole history loaded  {r['history_loaded_ms']:8.0f} ms")
    print(f"  cursor response       {r['hover_ms']:8.0f} ms   JS heap {r['heap_mb']:.0f} MiB")
    print(f"job list, {r['jobs']} jobs, 200 per page:")
    print(f"  first page shown      {r['list_first_page_ms']:8.0f} ms")
    print(f"  paging through all    {r['list_paging_ms']:8.0f} ms ({r['list_rows']} rows)")
    ok = r["increments_rows"] == n_increments and r["list_rows"] == n_jobs
    if not ok:
        print(f"FAILED: increments table {r['increments_rows']} rows of {n_increments}, "
              f"list {r['list_rows']} rows of {n_jobs}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
