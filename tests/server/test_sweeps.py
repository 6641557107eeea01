#!/usr/bin/python3
"""End-to-end sweeps (POST /v1/sweeps) with the local executor: a template and a parameter
table expanded to one job per row (the values reach the decks), the 400s and the 422 of a
refused row (nothing stored), Idempotency-Key, the max_parallel throttle (never more rows of
the sweep running at once, other jobs not starved), cancel of a sweep, and kill -9 of the
daemon with a sweep half done (every row ends succeeded after the restart)."""
import os
import time
import unittest

import decks
import kontaktd_harness as harness
from kontaktd_harness import post_sweep, sweep_jobs, wait_sweep
from openapi_check import validate

KONTAKTD = None


TINY = decks.load_template(decks.tiny(), -10.0)


def long_rows(increments):
    return decks.load_template(decks.long_running(increments=increments), -2000.0)


class ExpansionTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.d = harness.Daemon(KONTAKTD, args=["--workers", "2"]).start()

    @classmethod
    def tearDownClass(cls):
        cls.d.stop()

    def test_rows_become_labelled_jobs_with_their_values(self):
        loads = [-1.0, -2.0, -4.0]
        status, hdrs, doc = post_sweep(self.d, {
            "template": TINY, "rows": [{"load": v} for v in loads], "name": "tip",
            "labels": {"study": "e2e"}})
        self.assertEqual(status, 201, doc)
        validate(doc, "SweepRecord")
        self.assertEqual(hdrs["location"], f"/v1/sweeps/id/{doc['id']}")
        self.assertEqual((doc["rows"], doc["max_parallel"], doc["slurm_array_id"]), (3, 3, None))
        done = wait_sweep(self.d, doc["id"])
        self.assertEqual(done["jobs"]["succeeded"], 3, done)
        jobs = sweep_jobs(self.d, doc["id"])
        self.assertEqual([j["row"] for j in jobs], [0, 1, 2])
        self.assertEqual([j["name"] for j in jobs], ["tip-0", "tip-1", "tip-2"])
        for job, load in zip(jobs, loads):
            self.assertEqual(job["labels"], {"sweep": doc["id"], "study": "e2e", "load": str(load)})
        # Linear: the tip displacement follows the row's load, so each deck got its own value.
        u = [j["max_displacement"] for j in jobs]
        self.assertAlmostEqual(u[1] / u[0], 2.0, places=6)
        self.assertAlmostEqual(u[2] / u[0], 4.0, places=6)
        # The label views show the sweep: by its id and by its parameter.
        _, _, view = self.d.json("GET", f"/v1/sweeps/load?label=sweep={doc['id']}")
        validate(view, "Sweep")
        self.assertEqual(sorted(float(r["value"]) for r in view["jobs"]), sorted(loads))
        _, _, keys = self.d.json("GET", "/v1/sweeps")
        self.assertIn("sweep", [k["key"] for k in keys["sweeps"]])

    def test_list_of_decks(self):
        status, _, doc = post_sweep(self.d, {"decks": [decks.tiny(), decks.beam(2)]})
        self.assertEqual(status, 201, doc)
        self.assertEqual(wait_sweep(self.d, doc["id"])["jobs"]["succeeded"], 2)
        self.assertEqual([j["labels"] for j in sweep_jobs(self.d, doc["id"])],
                         [{"sweep": doc["id"]}] * 2)

    def test_bad_requests_name_the_field_and_store_nothing(self):
        _, _, before = self.d.json("GET", "/v1/jobs?limit=200")
        rows = [{"load": -1}]
        cases = [
            ({"template": TINY.replace("<load>", "<lod>"), "rows": rows}, "rows"),  # column unused
            ({"template": TINY + "** <extra>\n", "rows": rows}, "template"),  # no column
            ({"template": TINY, "rows": []}, "rows"),
            ({"template": TINY, "rows": [{"load": i} for i in range(1001)]}, "rows"),
            ({"template": TINY, "rows": [{"load": -1}, {}]}, "rows"),
            ({"template": TINY, "rows": [{"load": "1\n*STEP"}]}, "rows"),
            ({"template": TINY, "rows": [{"load": [1]}]}, "rows"),
            ({"template": TINY}, "rows"),
            ({"template": TINY, "rows": rows, "max_parallel": 0}, "max_parallel"),
            ({"template": TINY, "rows": rows, "max_parallel": "2"}, "max_parallel"),
            ({"template": TINY, "rows": rows, "max_parallel": 1001}, "max_parallel"),
            ({"template": TINY, "rows": rows, "decks": [TINY]}, "decks"),
            ({"template": TINY, "rows": rows, "labels": {"sweep": "x"}}, "labels"),
            ({"template": TINY, "rows": rows, "labels": {"load": "x"}}, "rows"),
            ({"template": TINY, "rows": rows, "scheme": "nope"}, "scheme"),
            ({"template": TINY, "rows": rows, "resources": {"cpus": 0}}, "resources.cpus"),
            ({"template": TINY, "rows": rows, "speed": 1}, "speed"),
            ({"decks": []}, "decks"),
            ({"decks": [""]}, "decks"),
            ({}, "template"),
        ]
        for body, field in cases:
            status, _, doc = post_sweep(self.d, body)
            self.assertEqual((status, doc.get("field")), (400, field), (str(body)[:120], doc))
        status, _, doc = self.d.json("POST", "/v1/sweeps", b"x", {"Content-Type": "text/plain"})
        self.assertEqual(status, 415)
        # A row whose deck the reader refuses: 422 naming the row, and no job of the sweep.
        bad = {"template": TINY, "rows": [{"load": -1}, {"load": "abc"}, {"load": -3}]}
        status, _, doc = post_sweep(self.d, bad)
        self.assertEqual(status, 422, doc)
        self.assertEqual(doc["row"], 1)
        self.assertTrue(doc["detail"].startswith("row 1: "), doc["detail"])
        self.assertEqual(doc["errors"][0]["file"], "row-1.inp")
        self.assertGreater(doc["errors"][0]["line"], 0)
        _, _, after = self.d.json("GET", "/v1/jobs?limit=200")
        self.assertEqual(len(after["jobs"]), len(before["jobs"]))
        folders = os.listdir(os.path.join(self.d.data_dir, "jobs"))
        self.assertEqual(len(folders), len(after["jobs"]))
        self.assertEqual(self.d.json("GET", "/v1/sweeps/id/" + "0" * 32)[0], 404)

    def test_idempotency_key(self):
        body = {"template": TINY, "rows": [{"load": -1}, {"load": -2}]}
        key = {"Idempotency-Key": "sweep-key-1"}
        s1, _, first = post_sweep(self.d, body, key)
        s2, hdrs, again = post_sweep(self.d, body, key)
        self.assertEqual((s1, s2, again["id"]), (201, 201, first["id"]))
        self.assertEqual(hdrs.get("idempotent-replayed"), "true")
        self.assertEqual(len(sweep_jobs(self.d, first["id"])), 2)
        status, _, doc = post_sweep(self.d, dict(body, max_parallel=1), key)
        self.assertEqual((status, doc["type"].rsplit(":", 1)[-1]), (422, "idempotency_key_reused"))


class ThrottleAndCancelTest(unittest.TestCase):
    def test_max_parallel_is_respected_and_other_jobs_run(self):
        d = harness.Daemon(KONTAKTD, args=["--workers", "3"]).start()
        try:
            _, _, sweep = post_sweep(d, {"template": long_rows(60),
                                         "rows": [{"load": -100 * (i + 1)} for i in range(5)],
                                         "max_parallel": 2})
            _, _, other = d.submit(decks.long_running(increments=20))
            most, other_ran_during_sweep = 0, False
            deadline = time.monotonic() + 150
            while time.monotonic() < deadline:
                jobs = sweep_jobs(d, sweep["id"])
                running = sum(j["status"] == "running" for j in jobs)
                most = max(most, running)
                _, _, o = d.json("GET", f"/v1/jobs/{other['id']}")
                if o["status"] != "queued" and any(j["status"] == "queued" for j in jobs):
                    other_ran_during_sweep = True
                if all(j["status"] == "succeeded" for j in jobs):
                    break
                time.sleep(0.02)
            self.assertEqual([j["status"] for j in sweep_jobs(d, sweep["id"])], ["succeeded"] * 5)
            self.assertEqual(most, 2, "max_parallel 2: at most (and, with 3 workers, exactly) 2")
            self.assertTrue(other_ran_during_sweep, "a job behind the sweep waited for all of it")
            self.assertEqual(d.wait(other["id"])["status"], "succeeded")
        finally:
            d.stop()

    def test_cancel_of_a_sweep(self):
        d = harness.Daemon(KONTAKTD, args=["--workers", "2"]).start()
        try:
            _, _, sweep = post_sweep(d, {"template": long_rows(400),
                                         "rows": [{"load": -10 * (i + 1)} for i in range(4)],
                                         "max_parallel": 1})
            deadline = time.monotonic() + 30
            while sweep_jobs(d, sweep["id"])[0]["status"] != "running":
                self.assertLess(time.monotonic(), deadline)
                time.sleep(0.02)
            status, _, doc = d.json("POST", f"/v1/sweeps/id/{sweep['id']}/cancel")
            self.assertEqual(status, 202, doc)
            validate(doc, "SweepRecord")
            done = wait_sweep(d, sweep["id"], timeout=30)
            self.assertEqual(done["jobs"]["canceled"], 4, done)
            jobs = sweep_jobs(d, sweep["id"])
            self.assertEqual([j["status"] for j in jobs], ["canceled"] * 4)
            for j in jobs[1:]:  # canceled while queued: never started
                _, _, full = d.json("GET", f"/v1/jobs/{j['id']}")
                self.assertIsNone(full["started"])
            status, _, doc = d.json("POST", f"/v1/sweeps/id/{sweep['id']}/cancel")
            self.assertEqual(status, 200)
        finally:
            d.stop()


class RestartTest(unittest.TestCase):
    def test_kill9_with_a_sweep_half_done_loses_nothing(self):
        with harness.restartable(KONTAKTD, args=["--workers", "2"]) as d:
            _, _, sweep = post_sweep(d, {"template": long_rows(30),
                                         "rows": [{"load": -100 * (i + 1)} for i in range(6)],
                                         "max_parallel": 2})
            deadline = time.monotonic() + 120
            while True:
                statuses = [j["status"] for j in sweep_jobs(d, sweep["id"])]
                if statuses.count("succeeded") >= 2 and "running" in statuses:
                    break
                self.assertLess(time.monotonic(), deadline, statuses)
                time.sleep(0.02)
            d.kill9()
            d.start()
            done = wait_sweep(d, sweep["id"], timeout=150)
            self.assertEqual(done["jobs"]["succeeded"], 6, done)
            self.assertEqual(done["rows"], 6)


if __name__ == "__main__":
    harness.run_tests(globals(), "kontaktd")
