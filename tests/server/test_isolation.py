#!/usr/bin/python3
"""End-to-end: kontaktd survives every deck and every job (issue 10). The deck that crashed the
daemon gets a 422 naming its line; jobs run in processes whose crash, memory limit, file size
limit or full disk fail only their own job - with a clear reason, nothing half-published, the
store intact - while the daemon keeps serving."""
import os
import shutil
import signal
import sqlite3
import subprocess
import sys
import tempfile
import time
import unittest

import decks
import kontaktd_harness as harness
from openapi_check import validate

sys.path.insert(0, os.path.join(harness.REPO, "tests", "bench"))
import make_block  # noqa: E402

KONTAKTD = None

ISSUE_DECK = "*HEADING\n*\n*NODE\n1,0,0,0\n"


def integrity(db_path):
    db = sqlite3.connect(db_path)
    try:
        return db.execute("PRAGMA integrity_check").fetchone()[0]
    finally:
        db.close()


def big_print_deck(nx=40, increments=20):
    """An NLGEOM beam printing U and RF of every node at every increment: a .dat of ~1 MB."""
    return decks.beam(nx, nlgeom=True, increments=increments, load=-200.0,
                      extra_step_lines="*NODE PRINT, NSET=NALL\nU, RF\n")


def still_serving(d):
    """The daemon answers and runs a job to the end."""
    status, _, health = d.json("GET", "/healthz")
    assert status == 200 and health["status"] == "ok", health
    job = d.submit(decks.tiny())[2]
    assert d.wait(job["id"], timeout=60)["status"] == "succeeded"


class DeckTest(unittest.TestCase):
    def test_the_deck_that_crashed_the_daemon_is_a_422_naming_line_2(self):
        d = harness.Daemon(KONTAKTD).start()
        try:
            status, _, problem = d.submit(ISSUE_DECK, "main=model.inp")
            self.assertEqual(status, 422, problem)
            validate(problem, "Problem")
            self.assertEqual(problem["code"], "input_error")
            self.assertEqual(problem["errors"][0]["file"], "model.inp")
            self.assertEqual(problem["errors"][0]["line"], 2)
            self.assertEqual(problem["errors"][0]["keyword"], "*")
            still_serving(d)
        finally:
            d.stop()

    def test_a_deck_check_past_the_memory_limit_is_a_422_not_a_dead_daemon(self):
        d = harness.Daemon(KONTAKTD, args=["--job-memory-limit", "256M"]).start()
        try:
            # A million nodes: 13 MB of deck, about 330 MB to read.
            deck = "*NODE\n" + "".join(f"{n},0,0,0\n" for n in range(1, 1_000_001))
            status, _, problem = d.submit(deck)
            self.assertEqual(status, 422, problem)
            self.assertEqual(problem["code"], "deck_check_failed")
            self.assertIn("memory limit of 256 MiB", problem["detail"])
            still_serving(d)
        finally:
            d.stop()


class JobLimitTest(unittest.TestCase):
    def test_a_crashing_job_fails_alone_with_the_signal_named(self):
        d = harness.Daemon(KONTAKTD, args=["--workers", "2"]).start()
        try:
            crasher = d.submit(decks.long_running(increments=300))[2]["id"]
            other = d.submit(decks.long_running(increments=60))[2]["id"]
            deadline = time.monotonic() + 30
            while d.json("GET", f"/v1/jobs/{crasher}")[2]["progress"]["iteration"] == 0:
                self.assertLess(time.monotonic(), deadline)
                time.sleep(0.02)
            pid = harness.job_process(d, crasher)
            self.assertIsNotNone(pid, "the job runs in a process of its own")
            os.kill(pid, signal.SIGABRT)
            job = d.wait(crasher, timeout=30)
            validate(job, "Job")
            self.assertEqual((job["status"], job["reason"]["code"]), ("failed", "solver_crashed"))
            self.assertIn("SIGABRT", job["reason"]["message"])
            kinds = [k for _, k, _ in d.sse(crasher)]
            self.assertIn("iteration", kinds, "the events before the crash are kept")
            self.assertEqual(d.wait(other, timeout=120)["status"], "succeeded")
            still_serving(d)
        finally:
            d.stop()

    def test_a_job_past_the_memory_limit_fails_as_memory_limit(self):
        # The deck reads in a few MiB; assembling and factoring its 200k dofs needs far more.
        d = harness.Daemon(KONTAKTD, args=["--job-memory-limit", "400M"]).start()
        try:
            work = tempfile.mkdtemp()
            try:
                make_block.write_block(os.path.join(work, "b.inp"), "C3D8", 200000)
                with open(os.path.join(work, "b.inp")) as f:
                    block = f.read()
            finally:
                shutil.rmtree(work)
            status, _, job = d.submit(block)
            self.assertEqual(status, 201, job)
            job = d.wait(job["id"], timeout=120)
            self.assertEqual((job["status"], job["reason"]["code"]), ("failed", "memory_limit"), job)
            self.assertIn("400 MiB", job["reason"]["message"])
            still_serving(d)
        finally:
            d.stop()

    def test_a_result_file_past_the_size_limit_fails_cleanly(self):
        with harness.restartable(KONTAKTD, ["--job-file-size-limit", "256K"]) as d:
            job = d.submit(big_print_deck())[2]
            done = d.wait(job["id"], timeout=120)
            validate(done, "Job")
            self.assertEqual((done["status"], done["reason"]["code"]), ("failed", "file_size_limit"), done)
            self.assertIn("256 KiB", done["reason"]["message"])
            _, _, listing = d.json("GET", f"/v1/jobs/{job['id']}/results")
            self.assertEqual(listing["artifacts"], [], "nothing half-written is published")
            self.assertFalse(os.path.exists(os.path.join(d.data_dir, "jobs", job["id"], "work")))
            self.assertEqual(integrity(os.path.join(d.data_dir, "kontakt.db")), "ok")
            still_serving(d)


def can_mount_tmpfs():
    if shutil.which("unshare") is None:
        return False
    r = subprocess.run(["unshare", "-m", "sh", "-c", "mount -t tmpfs -o size=1m none /mnt"],
                       capture_output=True)
    return r.returncode == 0


class DiskFullTest(unittest.TestCase):
    @unittest.skipUnless(can_mount_tmpfs(), "needs a mount namespace (root or user namespaces)")
    def test_a_full_disk_fails_the_job_and_keeps_the_store_and_the_daemon(self):
        # The daemon runs in a mount namespace of its own with its data folder on a 4 MiB tmpfs.
        wrapper_dir = tempfile.mkdtemp()
        wrapper = os.path.join(wrapper_dir, "kontaktd-on-tmpfs")
        with open(wrapper, "w") as f:
            f.write('#!/bin/sh\n# argv: --port 0 --data-dir DIR ...\n'
                    f'exec unshare -m sh -c \'mount -t tmpfs -o size=4m tmpfs "$4" && exec {KONTAKTD} "$@"\' '
                    'kontaktd "$@"\n')
        os.chmod(wrapper, 0o755)
        d = harness.Daemon(wrapper).start()
        try:
            root = f"/proc/{d.proc.pid}/root"  # the daemon's view: its tmpfs (wrapper, unshare, sh exec it)
            job = d.submit(big_print_deck(nx=60, increments=40))[2]
            done = d.wait(job["id"], timeout=120)
            validate(done, "Job")
            self.assertEqual((done["status"], done["reason"]["code"]), ("failed", "disk_full"), done)
            _, _, listing = d.json("GET", f"/v1/jobs/{job['id']}/results")
            self.assertEqual(listing["artifacts"], [])
            self.assertEqual(integrity(root + os.path.join(d.data_dir, "kontakt.db")), "ok")
            still_serving(d)
        finally:
            d.stop()
            shutil.rmtree(wrapper_dir)


if __name__ == "__main__":
    harness.run_tests(globals(), "kontaktd")
