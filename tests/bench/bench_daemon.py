#!/usr/bin/python3
"""Benchmark of kontaktd (loopback only, bounded in time):

1. submit-to-done latency of a tiny deck through the daemon (POST, then the event stream
   until the job's terminal status) against `kontakt solve` of the same deck (process wall
   time). The daemon's overhead per job is submit-to-done minus the solver's own time (the
   `done` event's wall_time): the request, the deck check, the queue, the job's process (start,
   libraries, exit), publishing and the event stream. With --baseline-kontaktd (another
   build: one from before issue 10 ran jobs in its own threads; one from before a change to
   measure) both are measured side by side, alternating, in the same run;
2. throughput of N tiny jobs (default 200) with 2 workers, submitted from 4 threads;
3. latency of GET /v1/jobs/{id} under load from a second process (wrk, 2 threads, 4 and
   16 connections, a few seconds each), with the p50/p99 wrk reports;
4. cancel latency in the middle of a factorisation: a linear block (--cancel-dofs) is solved
   once to time its factorisation, then canceled half way through it; the latency is from the
   cancel request to the job's terminal status event (with the baseline too: a build that
   runs jobs in threads lets the factorisation run to its end).

With --executor slurm, a second daemon of this build runs its jobs through a private Slurm
started here (tests/slurm/slurm_cluster.py: munged, slurmctld, slurmd on this host, needs root)
and is measured in parts 1 and 2 side by side with the local executor, in the same run.

--sweep measures only sweeps (POST /v1/sweeps): throughput in jobs/s, from the POST to the
last job's end, of sweeps of tiny decks (--sweep-rows, default 20 and 100 rows) through the
local executor and, with --executor slurm, through a Slurm job array, against the same number
of separately submitted Slurm jobs, side by side in one run.

Goals (issues 5 and 10): overhead under 50 ms per job, p99 status latency under 10 ms, cancel
within the kill grace (default 2 s) however long the factorisation.
"""
import http.client
import json
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
sys.path.insert(0, os.path.join(HERE, "..", "slurm"))
import decks  # noqa: E402
import kontaktd_harness as harness  # noqa: E402
import make_block  # noqa: E402


def cli_latency(kontakt, deck_path, work, runs):
    times = []
    for i in range(runs):
        t0 = time.perf_counter()
        subprocess.run([kontakt, "solve", deck_path, "-o", os.path.join(work, f"cli{i}"), "--quiet",
                        "--threads", "1"], check=True, timeout=60)
        times.append(time.perf_counter() - t0)
    return times


def daemon_sample(d, deck):
    """(submit-to-done seconds, the daemon's overhead: that minus the solver's own wall time)."""
    t0 = time.perf_counter()
    status, _, job = d.submit(deck)
    assert status == 201, job
    events = d.sse(job["id"])
    total = time.perf_counter() - t0
    assert events[-1][2]["status"] == "succeeded", events[-1]
    solver = [data for _, kind, data in events if kind == "done"][-1]["wall_time"]
    return total, total - solver


def timed_events(d, job_id, on_event=None):
    """[(arrival time, kind, data)] of the job's event stream, read live to its end;
    `on_event(kind, data)` is called as each arrives."""
    conn = http.client.HTTPConnection("127.0.0.1", d.port, timeout=600)
    events = []
    try:
        conn.request("GET", f"/v1/jobs/{job_id}/events", headers={"Accept": "text/event-stream"})
        r = conn.getresponse()
        frame = {}
        while True:
            raw = r.readline()
            if not raw:
                break
            line = raw.decode().rstrip("\n")
            if line.startswith(":"):
                continue
            if line:
                key, _, value = line.partition(": ")
                frame[key] = value
                continue
            if "data" in frame:
                data = json.loads(frame["data"])
                events.append((time.monotonic(), frame["event"], data))
                if on_event:
                    on_event(frame["event"], data)
            frame = {}
    finally:
        conn.close()
    return events


def cancel_latency(d, deck):
    """Cancels the block half way through its factorisation (timed by a run to the end first);
    (factorisation seconds, seconds it still had to go at the cancel, cancel latency, status)."""
    job = d.submit(deck)[2]["id"]
    events = timed_events(d, job)
    step = next(t for t, kind, _ in events if kind == "step")
    done = next(t for t, kind, _ in events if kind == "done")
    factorisation = done - step  # assembly is a small part of a linear block's solve
    # On a loaded machine the timing run may be slower than the next: a job that ends before
    # its cancel is sent is run again with the cancel earlier.
    for share in (0.5, 0.25, 0.1, 0.0):
        job = d.submit(deck)[2]["id"]
        sent = {}
        lock = threading.Lock()

        def cancel(job=job, sent=sent, lock=lock):
            with lock:
                if sent.get("done"):
                    return
                sent["at"] = time.monotonic()
            d.json("POST", f"/v1/jobs/{job}/cancel")

        def cancel_in_factorisation(kind, data, cancel=cancel, share=share):
            if kind == "step":
                threading.Timer(share * factorisation, cancel).start()

        events = timed_events(d, job, cancel_in_factorisation)
        end, _, final = events[-1]
        with lock:
            sent["done"] = True
        if "at" in sent:
            return factorisation, (1 - share) * factorisation, end - sent["at"], final["status"]
    raise RuntimeError("every run of the block ended before its cancel was sent")


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


def sweep_throughput(d, n_rows, max_parallel):
    """(seconds from the POST to the sweep's end, jobs/s) of a sweep of tiny decks."""
    template = decks.load_template(decks.tiny(), -10.0)
    t0 = time.perf_counter()
    status, _, sweep = harness.post_sweep(d, {"template": template, "max_parallel": max_parallel,
                                              "rows": [{"load": -(i + 1)} for i in range(n_rows)]})
    assert status == 201, sweep
    done = harness.wait_sweep(d, sweep["id"], timeout=1800)
    seconds = time.perf_counter() - t0
    assert done["jobs"]["succeeded"] == n_rows, done
    return seconds, n_rows / seconds


def sweep_comparison(d, slurm_d, sizes, slurm_workers):
    """Part 5: sweeps through the local executor, a Slurm array, and separate Slurm jobs."""
    print("5. sweeps of tiny decks, from the POST to the last job's end:")
    for n in sizes:
        seconds, rate = sweep_throughput(d, n, n)
        print(f"   {n:4d} rows, local executor (2 workers):            {seconds:7.2f} s = {rate:5.1f} jobs/s")
        if slurm_d:
            seconds, rate = sweep_throughput(slurm_d, n, slurm_workers)
            print(f"   {n:4d} rows, one Slurm array (%{slurm_workers}, 2 CPUs):        "
                  f"{seconds:7.2f} s = {rate:5.1f} jobs/s")
            count, _, seconds = throughput(slurm_d, decks.tiny(), n)
            print(f"   {count:4d} Slurm jobs submitted one by one ({slurm_workers} in Slurm): "
                  f"{seconds:7.2f} s = {count / seconds:5.1f} jobs/s")


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
    p.add_argument("--baseline-kontaktd", help="another kontaktd build to compare with (e.g. an older commit's)")
    p.add_argument("--cancel-dofs", type=int, default=200000, help="size of the block canceled in part 4")
    p.add_argument("--smoke", action="store_true", help="small sizes, for CI")
    p.add_argument("--executor", choices=("local", "slurm"), default="local",
                   help="slurm: also measure a daemon with --executor slurm on a private Slurm "
                        "(parts 1 and 2), side by side with the local executor")
    p.add_argument("--slurm-workers", type=int, default=4,
                   help="--workers of the slurm daemon: jobs in Slurm at once (default 4)")
    p.add_argument("--sweep", action="store_true",
                   help="only part 5: sweep throughput (local; with --executor slurm a Slurm "
                        "array and separate Slurm jobs too)")
    p.add_argument("--sweep-rows", default="20,100", help="sizes of the sweeps of --sweep")
    args = p.parse_args()
    if args.smoke:
        args.jobs, args.runs, args.wrk_seconds, args.cancel_dofs = 20, 5, 2, 30000
    work = tempfile.mkdtemp(prefix="bench-daemon-")
    deck = decks.tiny()
    deck_path = os.path.join(work, "tiny.inp")
    with open(deck_path, "w") as f:
        f.write(deck)
    daemon_args = ["--workers", "2", "--threads-per-job", "1"]
    d = harness.Daemon(args.kontaktd, args=daemon_args).start()
    baseline = harness.Daemon(args.baseline_kontaktd, args=daemon_args).start() if args.baseline_kontaktd else None
    cluster = slurm_d = None
    try:
        if args.executor == "slurm":
            from slurm_cluster import LocalSlurm
            cluster = LocalSlurm().__enter__()
            slurm_d = harness.Daemon(args.kontaktd, env={"SLURM_CONF": cluster.conf},
                                     args=["--executor", "slurm", "--workers",
                                           str(args.slurm_workers)]).start()
        if args.sweep:
            sweep_comparison(d, slurm_d, [int(n) for n in args.sweep_rows.split(",")],
                             args.slurm_workers)
            return 0
        cli = cli_latency(args.kontakt, deck_path, work, args.runs)
        print(f"1. tiny deck, median of {args.runs}: kontakt solve {1e3 * statistics.median(cli):.1f} ms "
              f"(process wall time)")
        samples = {"kontaktd": [], "baseline": [], "slurm": []}
        for _ in range(args.runs):  # alternating, so both see the same machine
            samples["kontaktd"].append(daemon_sample(d, deck))
            if baseline:
                samples["baseline"].append(daemon_sample(baseline, deck))
            if slurm_d:
                samples["slurm"].append(daemon_sample(slurm_d, deck))
        labels = {"kontaktd": "this build", "baseline": "baseline build",
                  "slurm": "this build, --executor slurm"}
        for name, rows in samples.items():
            if not rows:
                continue
            total = sorted(1e3 * t for t, _ in rows)
            overhead = sorted(1e3 * o for _, o in rows)
            label = labels[name]
            print(f"   daemon, {label}: submit-to-done {statistics.median(total):.1f} ms "
                  f"(p90 {total[int(0.9 * len(total))]:.1f} ms); overhead (all but the solver's own "
                  f"time) {statistics.median(overhead):.1f} ms median, {overhead[-1]:.1f} ms max "
                  f"(goal < 50 ms)")
        n, submitted, total = throughput(d, deck, args.jobs)
        print(f"2. {n} tiny jobs, 2 workers: submitted in {submitted:.2f} s, all done in {total:.2f} s "
              f"= {n / total:.1f} jobs/s")
        if slurm_d:
            n, submitted, total = throughput(slurm_d, deck, args.jobs)
            print(f"   --executor slurm (2 CPUs, {args.slurm_workers} jobs in Slurm at once): submitted in "
                  f"{submitted:.2f} s, all done in {total:.2f} s = {n / total:.1f} jobs/s")
        job_id = d.submit(deck)[2]["id"]
        d.wait(job_id)
        for connections in (4, 16):
            p50, p99, rps, errors = wrk_latency(args.wrk, f"{d.url}/v1/jobs/{job_id}", args.wrk_seconds,
                                                connections)
            print(f"3. GET /v1/jobs/{{id}} under wrk load ({args.wrk_seconds} s, {connections} connections): "
                  f"{rps:.0f} req/s, p50 {p50:.2f} ms, p99 {p99:.2f} ms (goal < 10 ms), non-2xx {errors}")
            if errors:
                return 1
        block = os.path.join(work, "block.inp")
        dofs, _ = make_block.write_block(block, "C3D8", args.cancel_dofs)
        with open(block) as f:
            block_deck = f.read()
        for name, daemon in (("this build", d), ("the baseline build", baseline)):
            if daemon is None:
                continue
            factorisation, remaining, latency, status = cancel_latency(daemon, block_deck)
            print(f"4. cancel during the factorisation of a {dofs}-dof C3D8 block, {name}: "
                  f"{status} {latency:.2f} s after the request, with {remaining:.1f} s of its "
                  f"{factorisation:.1f} s solve to go")
    finally:
        d.stop()
        if baseline:
            baseline.stop()
        if slurm_d:
            slurm_d.stop()
        if cluster:
            cluster.stop()
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
