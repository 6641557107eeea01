#!/usr/bin/python3
"""kontaktd --executor slurm against a real Slurm started here (slurm_cluster.py: munged,
slurmctld, slurmd on this host, torn down at the end, also on failure): submit with progress
over SSE and the HDF5 results, a deck that fails in its run, sbatch refusals, a Slurm job killed
outside kontaktd, cancel of a running job and of one pending in Slurm, kill -9 and SIGTERM
of the daemon with jobs in Slurm (adopted again by the next daemon, nothing lost, no event
twice), and sweeps as one job array: 20 rows with the throttle seen in squeue, cancel with
tasks pending and running, kill -9 of the daemon mid-sweep, an sbatch refusal."""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "server"))

import decks  # noqa: E402
import kontaktd_harness as harness  # noqa: E402
from kontaktd_harness import post_sweep, sweep_jobs, wait_iterating, wait_sweep  # noqa: E402
from openapi_check import validate  # noqa: E402
from slurm_cluster import LocalSlurm  # noqa: E402

KONTAKTD = None
SLURM = None


def setUpModule():
    global SLURM
    SLURM = LocalSlurm().__enter__()


def tearDownModule():
    if SLURM:
        SLURM.stop()


def slurm_daemon(data_dir=None, args=()):
    return harness.Daemon(KONTAKTD, data_dir=data_dir, env={"SLURM_CONF": SLURM.conf},
                          args=["--executor", "slurm", "--workers", "4", "--kill-grace", "3"] +
                          list(args))


def slurm_id(d, job_id):
    with open(os.path.join(d.data_dir, "jobs", job_id, "slurm", "slurm_job_id")) as f:
        return f.read().strip()


def squeue_state(sid):
    out = subprocess.run(["squeue", "-h", "--states=all", "-j", sid, "-o", "%T"],
                         env=SLURM.env, capture_output=True, text=True)
    return out.stdout.strip()


def slurm_end_state(sid, timeout=15):
    """The Slurm job's state once it has left RUNNING: the worker writes its outcome (which
    ends the job in the store) a moment before the batch script exits."""
    deadline = time.monotonic() + timeout
    while (state := squeue_state(sid)) == "RUNNING" and time.monotonic() < deadline:
        time.sleep(0.1)
    return state


def solver_pid(d, job_id):
    """The solver's process: it works in the job's work folder."""
    suffix = f"/jobs/{job_id}/work"
    for entry in filter(str.isdigit, os.listdir("/proc")):
        try:
            if os.readlink(f"/proc/{entry}/cwd").endswith(suffix):
                return int(entry)
        except OSError:
            continue
    raise AssertionError("no solver process for job " + job_id)


def assert_no_event_twice(test, d, job_id):
    """The run's solver events in the store are the lines of its events file, each once."""
    _, _, page = d.json("GET", f"/v1/jobs/{job_id}/iterations?limit=10000")
    with open(os.path.join(d.data_dir, "jobs", job_id, "slurm", "events.ndjson")) as f:
        in_file = [e for e in map(json.loads, f) if e["event"] == "iteration"]
    test.assertEqual(len(page["iterations"]), len(in_file))
    test.assertGreater(len(in_file), 0)


class SlurmExecutorTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.d = slurm_daemon().start()

    @classmethod
    def tearDownClass(cls):
        cls.d.stop()

    def test_submit_progress_over_sse_and_results(self):
        d = self.d
        status, _, job = d.submit(decks.beam(4, nlgeom=True, increments=5, load=-200.0))
        self.assertEqual(status, 201)
        events = d.sse(job["id"], timeout=60)
        kinds = [k for _, k, _ in events]
        self.assertIn("iteration", kinds)
        self.assertEqual(kinds[-2:], ["done", "status"])
        self.assertEqual(events[-1][2]["status"], "succeeded")
        final = d.wait(job["id"])
        validate(final, "Job")
        self.assertEqual(final["status"], "succeeded")
        self.assertIsNotNone(final["started"])
        self.assertIn(slurm_end_state(slurm_id(d, job["id"])), ("COMPLETING", "COMPLETED"))
        status, _, results = d.json("GET", f"/v1/jobs/{job['id']}/results")
        names = [a["name"] for a in results["artifacts"]]
        self.assertIn("deck.hdf", names)
        status, _, body = d.request("GET", f"/v1/jobs/{job['id']}/results/deck.hdf")
        self.assertEqual(status, 200)
        with tempfile.NamedTemporaryFile(suffix=".hdf") as f:
            f.write(body)
            f.flush()
            import h5py
            with h5py.File(f.name, "r") as h5:
                self.assertGreater(len(list(h5.keys())), 0)

    def test_a_deck_that_fails_in_its_run_says_why(self):
        d = self.d
        _, _, job = d.submit(decks.beam(4, nlgeom=True, increments=1, load=-5e6))
        final = d.wait(job["id"], timeout=60)
        self.assertEqual((final["status"], final["reason"]["code"]), ("failed", "not_converged"))
        self.assertIn("inverted", final["reason"]["message"])

    def test_resources_are_validated_and_sbatch_refusals_fail_the_job(self):
        d = self.d
        status, _, problem = d.json("POST", "/v1/jobs", json.dumps(
            {"deck": decks.tiny(), "resources": {"cpus": 0}}).encode(),
            {"Content-Type": "application/json"})
        self.assertEqual(status, 400)
        self.assertIn("resources.cpus", json.dumps(problem))
        for resources, said in (({"partition": "nosuchpartition"}, "invalid partition"),
                                ({"memory": "900G"}, "Memory specification")):
            status, _, job = d.json("POST", "/v1/jobs", json.dumps(
                {"deck": decks.tiny(), "resources": resources}).encode(),
                {"Content-Type": "application/json"})
            self.assertEqual(status, 201, job)
            self.assertEqual(job["resources"], resources)
            final = d.wait(job["id"], timeout=30)
            self.assertEqual((final["status"], final["reason"]["code"]),
                             ("failed", "executor_refused"))
            self.assertIn(said, final["reason"]["message"])

    def test_a_run_killed_on_its_node_fails_with_slurms_word(self):
        """SIGKILL to the solver on the node (the OOM killer, say): no outcome file, Slurm's
        state and exit signal are the verdict."""
        d = self.d
        _, _, job = d.submit(decks.long_running(increments=1000))
        wait_iterating(d, job["id"], timeout=60)
        sid = slurm_id(d, job["id"])
        os.kill(solver_pid(d, job["id"]), 9)
        final = d.wait(job["id"], timeout=60)
        self.assertEqual((final["status"], final["reason"]["code"]), ("failed", "solver_crashed"))
        self.assertIn(f"Slurm job {sid} ended FAILED", final["reason"]["message"])
        self.assertIn("SIGKILL", final["reason"]["message"])

    def test_a_job_canceled_in_slurm_by_someone_else_fails(self):
        """An scancel outside kontaktd: the solver stops at an iteration (SIGTERM) and the job
        fails, saying so; it is not taken for the daemon's cancel."""
        d = self.d
        _, _, job = d.submit(decks.long_running(increments=1000))
        wait_iterating(d, job["id"], timeout=60)
        subprocess.run(["scancel", slurm_id(d, job["id"])], env=SLURM.env, check=True)
        final = d.wait(job["id"], timeout=60)
        self.assertEqual(final["status"], "failed")
        self.assertIn("SIGTERM from outside kontaktd", final["reason"]["message"])

    def test_cancel_a_running_job(self):
        d = self.d
        _, _, job = d.submit(decks.long_running(increments=1000))
        wait_iterating(d, job["id"], timeout=60)
        status, _, _ = d.json("POST", f"/v1/jobs/{job['id']}/cancel")
        self.assertIn(status, (200, 202))
        final = d.wait(job["id"], timeout=60)
        self.assertEqual(final["status"], "canceled")
        # The solver stopped at an iteration (--signal TERM to the batch shell: the solver) and
        # wrote its outcome; the converged increments' results are published.
        with open(os.path.join(d.data_dir, "jobs", job["id"], "slurm", "outcome.json")) as f:
            self.assertEqual(json.load(f)["exit_code"], 5)
        _, _, results = d.json("GET", f"/v1/jobs/{job['id']}/results")
        self.assertIn("deck.hdf", [a["name"] for a in results["artifacts"]])
        deadline = time.monotonic() + 20
        while squeue_state(slurm_id(d, job["id"])) not in ("COMPLETED", "CANCELLED", "FAILED"):
            self.assertLess(time.monotonic(), deadline)
            time.sleep(0.2)

    def test_cancel_a_job_still_pending_in_slurm(self):
        """Both CPUs taken: the third job pends in Slurm. Its cancel is a plain scancel (there
        is no batch shell to signal yet), and it ends canceled without ever running."""
        d = self.d
        # Long enough to outlast the test (canceled at its end).
        busy = [d.submit(decks.long_running(increments=5000))[2] for _ in range(2)]
        for job in busy:
            wait_iterating(d, job["id"], timeout=60)
        _, _, pending = d.submit(decks.tiny())
        deadline = time.monotonic() + 20
        while not os.path.exists(os.path.join(d.data_dir, "jobs", pending["id"], "slurm",
                                              "slurm_job_id")):
            self.assertLess(time.monotonic(), deadline)
            time.sleep(0.05)
        self.assertEqual(squeue_state(slurm_id(d, pending["id"])), "PENDING")
        d.json("POST", f"/v1/jobs/{pending['id']}/cancel")
        final = d.wait(pending["id"], timeout=30)
        self.assertEqual(final["status"], "canceled")
        self.assertEqual(squeue_state(slurm_id(d, pending["id"])), "CANCELLED")
        self.assertFalse(os.path.exists(os.path.join(d.data_dir, "jobs", pending["id"], "slurm",
                                                     "events.ndjson")))
        for job in busy:
            d.json("POST", f"/v1/jobs/{job['id']}/cancel")
        for job in busy:
            self.assertEqual(d.wait(job["id"], timeout=30)["status"], "canceled")


def array_tasks(array_id, state):
    """The array's tasks in `state` now, one line each (squeue --array)."""
    out = subprocess.run(["squeue", "-h", "--array", "--states=" + state, "-j", array_id,
                          "-o", "%i"], env=SLURM.env, capture_output=True, text=True)
    return out.stdout.split()


def array_id_of(d, sweep_id, timeout=30):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        _, _, doc = d.json("GET", f"/v1/sweeps/id/{sweep_id}")
        if doc["slurm_array_id"]:
            return doc["slurm_array_id"]
        time.sleep(0.05)
    raise TimeoutError("the sweep's array was not submitted")


class SweepArrayTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.d = slurm_daemon().start()

    @classmethod
    def tearDownClass(cls):
        cls.d.stop()

    def test_a_20_row_sweep_is_one_throttled_array(self):
        d = self.d
        loads = [-(i + 1.0) for i in range(20)]
        status, _, sweep = post_sweep(d, {"template": decks.load_template(decks.tiny(), -10.0),
                                          "rows": [{"load": v} for v in loads],
                                          "max_parallel": 2, "name": "array"})
        self.assertEqual(status, 201, sweep)
        array = array_id_of(d, sweep["id"])
        most_running = 0
        deadline = time.monotonic() + 80
        while True:
            most_running = max(most_running, len(array_tasks(array, "RUNNING")))
            _, _, doc = d.json("GET", f"/v1/sweeps/id/{sweep['id']}")
            if doc["status"] == "finished":
                break
            self.assertLess(time.monotonic(), deadline, doc)
            time.sleep(0.05)
        validate(doc, "SweepRecord")
        self.assertEqual(doc["jobs"]["succeeded"], 20, doc)
        self.assertLessEqual(most_running, 2, "--array=...%2: at most 2 tasks at once")
        self.assertGreaterEqual(most_running, 1)
        jobs = sweep_jobs(d, sweep["id"])
        u0 = jobs[0]["max_displacement"]
        for i, job in enumerate(jobs):
            # One array: each row ran as its task, with its own load (linear: u follows it).
            self.assertEqual(slurm_id(d, job["id"]), f"{array}_{i}")
            self.assertAlmostEqual(job["max_displacement"] / u0, loads[i] / loads[0], places=6)
            _, _, results = d.json("GET", f"/v1/jobs/{job['id']}/results")
            self.assertIn(f"row-{i}.hdf", [a["name"] for a in results["artifacts"]])
        self.assertEqual(os.listdir(os.path.join(d.data_dir, "sweeps")).count(sweep["id"]), 1)

    def test_cancel_of_a_sweep_with_tasks_running_and_pending(self):
        d = self.d
        _, _, sweep = post_sweep(d, {
            "template": decks.load_template(decks.long_running(increments=5000), -2000.0),
            "rows": [{"load": -10.0 * (i + 1)} for i in range(4)], "max_parallel": 2})
        array = array_id_of(d, sweep["id"])
        jobs = sweep_jobs(d, sweep["id"])
        for job in jobs[:2]:
            wait_iterating(d, job["id"], timeout=60)
        self.assertEqual([j["status"] for j in sweep_jobs(d, sweep["id"])][2:], ["queued"] * 2)
        self.assertEqual(sorted(array_tasks(array, "PENDING")), [f"{array}_2", f"{array}_3"])
        status, _, doc = d.json("POST", f"/v1/sweeps/id/{sweep['id']}/cancel")
        self.assertEqual(status, 202, doc)
        done = wait_sweep(d, sweep["id"], timeout=60)
        self.assertEqual(done["jobs"]["canceled"], 4, done)
        for i, job in enumerate(jobs):
            folder = os.path.join(d.data_dir, "jobs", job["id"], "slurm")
            if i < 2:  # stopped at an iteration: its outcome says canceled
                with open(os.path.join(folder, "outcome.json")) as f:
                    self.assertEqual(json.load(f)["exit_code"], 5)
            else:  # pending: scancelled (Slurm drops a pending task), never ran
                self.assertNotIn(f"{array}_{i}", array_tasks(array, "PENDING"))
                self.assertFalse(os.path.exists(os.path.join(folder, "events.ndjson")))
        deadline = time.monotonic() + 20
        while array_tasks(array, "PENDING,RUNNING,COMPLETING"):
            self.assertLess(time.monotonic(), deadline)
            time.sleep(0.2)

    def test_an_sbatch_refusal_fails_every_row(self):
        d = self.d
        _, _, sweep = post_sweep(d, {"decks": [decks.tiny()] * 3,
                                     "resources": {"partition": "nosuchpartition"}})
        done = wait_sweep(d, sweep["id"], timeout=30)
        self.assertEqual(done["jobs"]["failed"], 3, done)
        self.assertIsNone(done["slurm_array_id"])
        for job in sweep_jobs(d, sweep["id"]):
            _, _, full = d.json("GET", f"/v1/jobs/{job['id']}")
            self.assertEqual(full["reason"]["code"], "executor_refused")
            self.assertIn("invalid partition", full["reason"]["message"])


class RestartTest(unittest.TestCase):
    def test_kill9_during_a_sweep_then_restart_adopts_its_tasks(self):
        data = tempfile.mkdtemp(prefix="kontaktd-slurm-sweep-")
        d = slurm_daemon(data_dir=data).start()
        try:
            _, _, sweep = post_sweep(d, {
                "template": decks.load_template(decks.long_running(increments=150, nx=4), -2000.0),
                "rows": [{"load": -100.0 * (i + 1)} for i in range(6)], "max_parallel": 2})
            array = array_id_of(d, sweep["id"])
            jobs = sweep_jobs(d, sweep["id"])
            wait_iterating(d, jobs[0]["id"], timeout=60)
            d.kill9()
            # Slurm goes on without the daemon: tasks end and others start.
            deadline = time.monotonic() + 40
            while not os.path.exists(os.path.join(data, "jobs", jobs[2]["id"], "slurm",
                                                  "events.ndjson")):
                self.assertLess(time.monotonic(), deadline)
                time.sleep(0.2)
            d.start()
            done = wait_sweep(d, sweep["id"], timeout=90)
            self.assertEqual(done["jobs"]["succeeded"], 6, done)
            self.assertEqual(done["slurm_array_id"], array)
            for i, job in enumerate(sweep_jobs(d, sweep["id"])):
                self.assertEqual(slurm_id(d, job["id"]), f"{array}_{i}")
                _, _, full = d.json("GET", f"/v1/jobs/{job['id']}")
                self.assertEqual(full["attempts"], 1)  # adopted or found done, not run again
                assert_no_event_twice(self, d, job["id"])
        finally:
            d.stop()
            shutil.rmtree(data, ignore_errors=True)


    def test_kill9_with_jobs_in_slurm_then_restart(self):
        data = tempfile.mkdtemp(prefix="kontaktd-slurm-restart-")
        d = slurm_daemon(data_dir=data).start()
        try:
            _, _, long_job = d.submit(decks.long_running(increments=1200))
            _, _, short_job = d.submit(decks.long_running(increments=150, nx=4))
            wait_iterating(d, long_job["id"], timeout=60)
            d.kill9()
            # The short job ends while no daemon watches; the long one is still running.
            deadline = time.monotonic() + 30
            while not os.path.exists(os.path.join(data, "jobs", short_job["id"], "slurm",
                                                  "outcome.json")):
                self.assertLess(time.monotonic(), deadline)
                time.sleep(0.2)
            self.assertEqual(squeue_state(slurm_id(d, long_job["id"])), "RUNNING")
            d.start()
            self.assertIn("watched again", d.log())
            for j in (short_job, long_job):
                final = d.wait(j["id"], timeout=90)
                self.assertEqual(final["status"], "succeeded", final)
                self.assertEqual(final["attempts"], 1)  # adopted, not run again
                assert_no_event_twice(self, d, j["id"])
                _, _, results = d.json("GET", f"/v1/jobs/{j['id']}/results")
                self.assertIn("deck.hdf", [a["name"] for a in results["artifacts"]])
        finally:
            d.stop()
            shutil.rmtree(data, ignore_errors=True)

    def test_sigterm_leaves_slurm_jobs_running_for_the_next_daemon(self):
        """A drain does not wait for or stop Slurm jobs: the daemon is gone at once, the job
        runs on, and the next daemon finishes it."""
        data = tempfile.mkdtemp(prefix="kontaktd-slurm-drain-")
        d = slurm_daemon(data_dir=data, args=["--drain-timeout", "60"])
        d.start()
        try:
            _, _, job = d.submit(decks.long_running(increments=800))
            wait_iterating(d, job["id"], timeout=60)
            t0 = time.monotonic()
            self.assertEqual(d.terminate(timeout=20), 0)
            self.assertLess(time.monotonic() - t0, 10)  # not the 60 s drain timeout
            self.assertEqual(squeue_state(slurm_id(d, job["id"])), "RUNNING")
            d.start()
            final = d.wait(job["id"], timeout=90)
            self.assertEqual((final["status"], final["attempts"]), ("succeeded", 1))
            assert_no_event_twice(self, d, job["id"])
        finally:
            d.stop()
            shutil.rmtree(data, ignore_errors=True)


if __name__ == "__main__":
    harness.run_tests(globals(), "kontaktd")
