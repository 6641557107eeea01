#!/usr/bin/python3
"""Crash campaign of kontaktd (issue 10), loopback only, bounded in time:

1. daemon kills: CYCLES times, start the daemon on the same data folder, submit a batch of
   jobs (tiny, multi-increment, NLGEOM), wait a random moment (jobs queued, running, being
   published), kill -9 the daemon. After each kill: none of its job processes (waiting or
   working) outlives it, and
   `PRAGMA integrity_check` is ok. At the end every accepted job (201) must succeed - none lost,
   none stuck - with every published file matching its listed size and sha256.
2. job process kills: kill -9 of one job's process is retried (--max-attempts) while the job
   beside it succeeds; a second kill -9 past the attempts fails it as solver_crashed; a SIGSEGV
   fails its job at once, naming the signal, with its events kept.
3. concurrent submissions: N at once from 32 threads; every 201 is a job that succeeds and is
   listed by GET /v1/jobs.

  crash_campaign.py --kontaktd build/server/kontaktd [--cycles 50] [--concurrent 1000] [--seed 1]
  crash_campaign.py --kontaktd ... --smoke      # CI: 6 cycles, 100 concurrent submissions
"""
import argparse
import concurrent.futures
import hashlib
import os
import random
import signal
import sqlite3
import sys
import time
import urllib.parse

sys.dont_write_bytecode = True
import decks  # noqa: E402
import kontaktd_harness as harness  # noqa: E402

TERMINAL = ("succeeded", "failed", "canceled")


def alive(pids):
    return [p for p in pids if os.path.exists(f"/proc/{p}")]


def integrity(data_dir):
    db = sqlite3.connect(os.path.join(data_dir, "kontakt.db"))
    try:
        return db.execute("PRAGMA integrity_check").fetchone()[0]
    finally:
        db.close()


def wait_until(predicate, timeout, what):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        value = predicate()
        if value:
            return value
        time.sleep(0.05)
    raise AssertionError(f"timed out after {timeout} s waiting for {what}")


def check_results(d, job_id):
    """Every listed artifact downloads with its listed size and sha256."""
    _, _, listing = d.json("GET", f"/v1/jobs/{job_id}/results")
    for a in listing["artifacts"]:
        status, _, body = d.request("GET", f"/v1/jobs/{job_id}/results/{urllib.parse.quote(a['name'])}")
        assert status == 200, (job_id, a, status)
        assert len(body) == a["size"] and hashlib.sha256(body).hexdigest() == a["sha256"], (job_id, a)
    return len(listing["artifacts"])


def daemon_kills(exe, cycles, rng):
    batch = [decks.tiny(), decks.beam(4), decks.beam(3, nlgeom=True, increments=6),
             decks.long_running(increments=40, nx=6)]
    accepted = []
    with harness.restartable(exe, ["--workers", "2", "--max-attempts", "100"]) as d:
        for cycle in range(cycles):
            if cycle:
                d.start()
            for deck in rng.sample(batch, k=len(batch)):
                status, _, job = d.submit(deck, f"label=cycle%3D{cycle}")
                assert status == 201, job
                accepted.append(job["id"])
            time.sleep(rng.uniform(0.0, 1.5))
            workers = harness.children(d.proc.pid)
            d.kill9()
            wait_until(lambda: not alive(workers), 10, "job processes to die with the daemon")
            verdict = integrity(d.data_dir)
            assert verdict == "ok", f"cycle {cycle}: integrity_check: {verdict}"
        d.start()
        jobs = {}
        for job_id in accepted:
            jobs[job_id] = d.wait(job_id, timeout=300)
        bad = {j: doc["status"] for j, doc in jobs.items() if doc["status"] != "succeeded"}
        assert not bad, f"jobs not succeeded: {bad}"
        files = sum(check_results(d, j) for j in accepted)
        runs = sum(doc["attempts"] for doc in jobs.values())
        verdict = integrity(d.data_dir)
    print(f"1. {cycles} kill -9 cycles of the daemon: {len(accepted)} jobs accepted, "
          f"{len(accepted)} succeeded, 0 lost, 0 stuck; {runs} runs in all "
          f"({runs - len(accepted)} interrupted and run again); {files} published files "
          f"match size and sha256; integrity_check ok after every kill and at the end ({verdict})",
          flush=True)


def job_process_kills(exe):
    with harness.restartable(exe, ["--workers", "2", "--max-attempts", "2"]) as d:
        victim = d.submit(decks.long_running(increments=300))[2]["id"]
        bystander = d.submit(decks.long_running(increments=120))[2]["id"]
        pid = wait_until(lambda: harness.job_process(d, victim), 30, "the victim's process")
        wait_until(lambda: d.json("GET", f"/v1/jobs/{victim}")[2]["progress"]["iteration"] > 0, 30,
                   "the victim's first iteration")
        os.kill(pid, signal.SIGKILL)
        again = wait_until(lambda: (p := harness.job_process(d, victim)) and p != pid and p, 30,
                           "the victim's second run")
        assert d.json("GET", f"/v1/jobs/{victim}")[2]["attempts"] == 2
        os.kill(again, signal.SIGKILL)
        job = d.wait(victim, timeout=30)
        assert (job["status"], job["reason"]["code"]) == ("failed", "solver_crashed"), job
        assert "SIGKILL" in job["reason"]["message"], job
        assert d.wait(bystander, timeout=120)["status"] == "succeeded"
        crasher = d.submit(decks.long_running(increments=300))[2]["id"]
        pid = wait_until(lambda: harness.job_process(d, crasher), 30, "the crasher's process")
        wait_until(lambda: d.json("GET", f"/v1/jobs/{crasher}")[2]["progress"]["iteration"] > 0, 30,
                   "the crasher's first iteration")
        os.kill(pid, signal.SIGSEGV)
        job = d.wait(crasher, timeout=30)
        assert (job["status"], job["reason"]["code"]) == ("failed", "solver_crashed"), job
        assert "SIGSEGV" in job["reason"]["message"] and job["attempts"] == 1, job
        events = d.sse(crasher)
        assert any(kind == "iteration" for _, kind, _ in events), "the events before the crash are kept"
        _, _, health = d.json("GET", "/healthz")
        assert health["status"] == "ok"
    print("2. job processes killed: kill -9 -> run again (attempt 2), kill -9 again -> failed "
          "solver_crashed (SIGKILL named), the job beside it succeeded; SIGSEGV -> failed "
          f"solver_crashed at once (SIGSEGV named, {len(events)} events kept); the daemon kept serving",
          flush=True)


def concurrent_submissions(exe, n):
    deck = decks.tiny()
    d = harness.Daemon(exe, args=["--workers", "2", "--handler-threads", "8"]).start()
    try:
        def submit(i):
            status, _, job = d.submit(deck, f"label=burst%3D1&name=burst{i}", )
            return status, job.get("id") if isinstance(job, dict) else None

        t0 = time.monotonic()
        with concurrent.futures.ThreadPoolExecutor(32) as pool:
            answers = list(pool.map(submit, range(n)))
        submitted = time.monotonic() - t0
        codes = {}
        for status, _ in answers:
            codes[status] = codes.get(status, 0) + 1
        ids = {job_id for status, job_id in answers if status == 201}
        assert codes == {201: n}, codes
        for job_id in ids:
            assert d.wait(job_id, timeout=600)["status"] == "succeeded", job_id
        listed, token = set(), None
        while True:
            q = "label=burst%3D1&limit=200" + (f"&page_token={urllib.parse.quote(token)}" if token else "")
            _, _, page = d.json("GET", f"/v1/jobs?{q}")
            listed |= {j["id"] for j in page["jobs"]}
            token = page["next_page_token"]
            if not token:
                break
        assert listed == ids, (len(listed), len(ids))
        total = time.monotonic() - t0
    finally:
        d.stop()
    print(f"3. {n} concurrent submissions (32 threads): {n} x 201 in {submitted:.1f} s, all "
          f"{n} succeeded and listed, {total:.1f} s to the last result", flush=True)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--kontaktd", required=True)
    p.add_argument("--cycles", type=int, default=50)
    p.add_argument("--concurrent", type=int, default=1000)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--smoke", action="store_true", help="CI size: 6 cycles, 100 submissions")
    args = p.parse_args()
    if args.smoke:
        args.cycles, args.concurrent = 6, 100
    exe = os.path.abspath(args.kontaktd)
    t0 = time.monotonic()
    daemon_kills(exe, args.cycles, random.Random(args.seed))
    job_process_kills(exe)
    concurrent_submissions(exe, args.concurrent)
    print(f"crash campaign passed in {time.monotonic() - t0:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
