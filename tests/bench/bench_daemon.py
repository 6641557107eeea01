#!/usr/bin/python3
"""Benchmark of kontaktd (loopback only, bounded in time):

1. submit-to-done latency of a tiny deck through the daemon (POST, then the event stream
   until the job's terminal status) against `kontakt solve` of the same deck (process wall
   time); the difference is the daemon's overhead per job;
2. throughput of N tiny jobs (default 200) with 2 workers, submitted from 4 threads;
3. latency of GET /v1/jobs/{id} under load from a second process (wrk, 2 threads, 4 and
   16 connections, a few seconds each), with the p50/p99 wrk reports.

Goals (issue 5): overhead under 50 ms per job, p99 status latency under 10 ms.
"""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "server"))
import decks  # noqa: E402
import kontaktd_harness as harness  # noqa: E402


def cli_latency(kontakt, deck_path, work, runs):
    times = []
    for i in range(runs):
        t0 = time.perf_counter()
        subprocess.run([kontakt, "solve", deck_path, "-o", os.path.join(work, f"cli{i}"), "--quiet",
                        "--threads", "1"], check=True, timeout=60)
        times.append(time.perf_counter() - t0)
    return times


def run_seconds(job):
    """finished - started of a status document (millisecond timestamps)."""
    parse = lambda t: time.mktime(time.strptime(t[:19], "%Y-%m-%dT%H:%M:%S")) + float(t[19:-1])
    return parse(job["finished"]) - parse(job["started"])


def daemon_latency(d, deck, runs):
    """(submit-to-done seconds, the part of it outside the worker's run) per sample."""
    times, outside = [], []
    for _ in range(runs):
        t0 = time.perf_counter()
        status, _, job = d.submit(deck)
        assert status == 201, job
        events = d.sse(job["id"])
        times.append(time.perf_counter() - t0)
        assert events[-1][2]["status"] == "succeeded", events[-1]
        outside.append(times[-1] - run_seconds(d.json("GET", f"/v1/jobs/{job['id']}")[2]))
    return times, outside


def throughput(d, deck, n_jobs):
    ids, lock = [], threading.Lock()

    def submit(count):
        for _ in range(count):
            status, _, job = d.submit(deck, "label=bench%3Dthroughput")
            assert status == 201, job
            with lock:
                ids.append(job["id"])

    t0 = time.perf_counter()
    threads = [threading.Thread(target=submit, args=(n_jobs // 4 + (i < n_jobs % 4),)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    submitted = time.perf_counter() - t0
    for job_id in ids:
        assert d.wait(job_id, timeout=600)["status"] == "succeeded"
    return len(ids), submitted, time.perf_counter() - t0


def wrk_latency(wrk, url, seconds, connections):
    out = subprocess.run([wrk, "-t2", f"-c{connections}", f"-d{seconds}s", "--latency", url],
                         capture_output=True, text=True, timeout=seconds + 30, check=True).stdout
    def pct(p):
        m = re.search(rf"^\s+{p}%\s+([\d.]+)(us|ms|s)\s*$", out, re.M)
        value, unit = float(m.group(1)), m.group(2)
        return value * {"us": 1e-3, "ms": 1.0, "s": 1e3}[unit]
    rps = float(re.search(r"Requests/sec:\s+([\d.]+)", out).group(1))
    errors = re.search(r"Non-2xx or 3xx responses: (\d+)", out)
    return pct(50), pct(99), rps, int(errors.group(1)) if errors else 0


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--kontaktd", required=True)
    p.add_argument("--kontakt", required=True)
    p.add_argument("--wrk", default=shutil.which("wrk") or "/usr/bin/wrk")
    p.add_argument("--jobs", type=int, default=200)
    p.add_argument("--runs", type=int, default=20, help="latency samples of each kind")
    p.add_argument("--wrk-seconds", type=int, default=10)
    p.add_argument("--smoke", action="store_true", help="small sizes, for CI")
    args = p.parse_args()
    if args.smoke:
        args.jobs, args.runs, args.wrk_seconds = 20, 5, 2
    work = tempfile.mkdtemp(prefix="bench-daemon-")
    deck = decks.tiny()
    deck_path = os.path.join(work, "tiny.inp")
    with open(deck_path, "w") as f:
        f.write(deck)
    d = harness.Daemon(args.kontaktd, args=["--workers", "2", "--threads-per-job", "1"]).start()
    try:
        cli = cli_latency(args.kontakt, deck_path, work, args.runs)
        daemon, outside = daemon_latency(d, deck, args.runs)
        cli_ms, daemon_ms = 1e3 * statistics.median(cli), 1e3 * statistics.median(daemon)
        print(f"1. tiny deck, median of {args.runs}: kontakt solve {cli_ms:.1f} ms (process wall time), "
              f"daemon submit-to-done {daemon_ms:.1f} ms (p90 {1e3 * sorted(daemon)[int(0.9 * len(daemon))]:.1f} ms); "
              f"daemon time outside the run (submit, parse, queue, publish, event stream) "
              f"{1e3 * statistics.median(outside):.1f} ms median, {1e3 * max(outside):.1f} ms max (goal < 50 ms)")
        n, submitted, total = throughput(d, deck, args.jobs)
        print(f"2. {n} tiny jobs, 2 workers: submitted in {submitted:.2f} s, all done in {total:.2f} s "
              f"= {n / total:.1f} jobs/s")
        job_id = d.submit(deck)[2]["id"]
        d.wait(job_id)
        for connections in (4, 16):
            p50, p99, rps, errors = wrk_latency(args.wrk, f"{d.url}/v1/jobs/{job_id}", args.wrk_seconds,
                                                connections)
            print(f"3. GET /v1/jobs/{{id}} under wrk load ({args.wrk_seconds} s, {connections} connections): "
                  f"{rps:.0f} req/s, p50 {p50:.2f} ms, p99 {p99:.2f} ms (goal < 10 ms), non-2xx {errors}")
            if errors:
                return 1
    finally:
        d.stop()
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
