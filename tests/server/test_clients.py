#!/usr/bin/python3
"""End-to-end: the Python client (clients/python), the `kontakt` daemon commands and the
design-loop example against a live kontaktd."""
import csv
import hashlib
import http.client
import http.server
import json
import os
import subprocess
import sys
import tempfile
import threading
import unittest

import decks
import kontaktd_harness as harness

sys.path.insert(0, os.path.join(harness.REPO, "clients", "python"))
from kontakt_client import ApiError, Client, TransportError, parse_sse  # noqa: E402

KONTAKTD = KONTAKT = None


def not_converging():
    """Needs more increments than *STEP, INC= allows: fails as not converged."""
    return decks.beam(2, nlgeom=True, increments=4).replace("INC=14", "INC=2")


class LosingProxy(http.server.ThreadingHTTPServer):
    """Forwards requests to the daemon, but drops the connection instead of answering the
    first POST (after the daemon has processed it): a response lost on the way back."""

    def __init__(self, daemon_port):
        self.daemon_port, self.dropped = daemon_port, []
        super().__init__(("127.0.0.1", 0), LosingProxy.Handler)
        threading.Thread(target=self.serve_forever, daemon=True).start()

    class Handler(http.server.BaseHTTPRequestHandler):
        def forward(self):
            body = self.rfile.read(int(self.headers.get("Content-Length", 0)))
            conn = http.client.HTTPConnection("127.0.0.1", self.server.daemon_port, timeout=10)
            conn.request(self.command, self.path, body=body,
                         headers={k: v for k, v in self.headers.items() if k.lower() != "host"})
            r = conn.getresponse()
            data = r.read()
            conn.close()
            if self.command == "POST" and not self.server.dropped:
                self.server.dropped.append(json.loads(data)["id"])
                self.close_connection = True
                return
            self.send_response(r.status)
            for k, v in r.getheaders():
                if k.lower() not in ("connection", "transfer-encoding", "content-length"):
                    self.send_header(k, v)
            self.send_header("Content-Length", str(len(data)))
            self.end_headers()
            self.wfile.write(data)

        do_GET = do_POST = forward

        def log_message(self, *args):
            pass


class ClientTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.d = harness.Daemon(KONTAKTD, args=["--workers", "2"]).start()
        cls.client = Client(cls.d.url, timeout=10)
        cls.tmp = tempfile.mkdtemp(prefix="kontakt-client-test-")

    @classmethod
    def tearDownClass(cls):
        cls.d.stop()

    def cli(self, *args, timeout=60):
        env = dict(os.environ, KONTAKT_SERVER=self.d.url)
        return subprocess.run([KONTAKT, *args], capture_output=True, text=True, timeout=timeout, env=env)

    # -- Python client ---------------------------------------------------------------------
    def test_submit_string_wait_by_polling_and_download(self):
        job = self.client.submit(decks.beam(3), name="py-poll", labels={"via": "python"})
        final = job.wait(timeout=60)
        self.assertEqual(final["status"], "succeeded")
        path = job.download("deck.hdf", self.tmp)
        with open(path, "rb") as f:
            sha = hashlib.sha256(f.read()).hexdigest()
        self.assertEqual(sha, {a["name"]: a for a in job.results()}["deck.hdf"]["sha256"])
        self.assertGreater(job.summary()["max_displacement"], 0)

    def test_submit_file_wait_by_stream(self):
        deck = os.path.join(self.tmp, "streamed.inp")
        with open(deck, "w") as f:
            f.write(decks.beam(2, nlgeom=True, increments=10))
        job = self.client.submit_file(deck)
        seen = []
        final = job.wait(stream=True, timeout=60, on_progress=lambda e: seen.append(e["event"]))
        self.assertEqual(final["status"], "succeeded")
        self.assertEqual(final["main"], "streamed.inp")
        self.assertEqual(seen.count("increment"), 10)
        replay = list(job.events(since=0, follow=False))
        self.assertEqual([s for s, _, _ in replay], list(range(1, len(replay) + 1)))

    def test_bad_deck_raises_with_the_line(self):
        with self.assertRaises(ApiError) as ctx:
            self.client.submit(decks.tiny().replace("*ELASTIC", "*ELASTIK"), main="bad.inp")
        self.assertEqual(ctx.exception.status, 422)
        self.assertEqual(ctx.exception.errors[0]["file"], "bad.inp")
        self.assertGreater(ctx.exception.errors[0]["line"], 0)

    def test_cancel_and_list(self):
        job = self.client.submit(decks.long_running(), labels={"case": "cancel-list"})
        job.cancel()
        self.assertEqual(job.wait(timeout=30)["status"], "canceled")
        listed = list(self.client.list_jobs(labels={"case": "cancel-list"}, page_size=1))
        self.assertEqual([j["id"] for j in listed], [job.id])
        self.assertTrue(any(j["id"] == job.id for j in self.client.list_jobs(status="canceled")))

    def test_same_idempotency_key_is_one_job_and_unreachable_daemon_raises(self):
        a = self.client.submit(decks.tiny(), idempotency_key="py-retry-1")
        b = self.client.submit(decks.tiny(), idempotency_key="py-retry-1")
        self.assertEqual(a.id, b.id)
        dead = Client("http://127.0.0.1:9", retries=2, backoff=0.01, timeout=2)
        with self.assertRaises(TransportError):
            dead.submit(decks.tiny())

    def test_retry_after_a_lost_response_reuses_the_idempotency_key(self):
        proxy = LosingProxy(self.d.port)
        try:
            client = Client(f"http://127.0.0.1:{proxy.server_address[1]}", retries=3, backoff=0.01,
                            timeout=10)
            job = client.submit(decks.tiny(), labels={"retry": "lost-response"})
            self.assertEqual(len(proxy.dropped), 1, "the first answer was dropped")
            self.assertEqual(job.id, proxy.dropped[0], "the retry got the job the first POST created")
            same = list(self.client.list_jobs(labels={"retry": "lost-response"}))
            self.assertEqual([j["id"] for j in same], [job.id], "one job, not two")
        finally:
            proxy.shutdown()
            proxy.server_close()

    def test_sse_parser(self):
        frames = list(parse_sse(["id: 3\n", "event: step\n", "data: {}\n", "\n", ": ping\n", "\n",
                                 "data: a\n", "data: b\n", "\n"]))
        self.assertEqual(frames, [(3, "step", "{}"), (3, "message", "a\nb")])

    # -- kontakt CLI -----------------------------------------------------------------------
    def test_cli_submit_wait_status_logs_fetch_list(self):
        deck = os.path.join(self.tmp, "cli.inp")
        with open(deck, "w") as f:
            f.write(decks.beam(3))
        r = self.cli("submit", deck, "--name", "cli-job", "--label", "via=cli")
        self.assertEqual(r.returncode, 0, r.stderr)
        job_id = r.stdout.strip()
        self.assertEqual(len(job_id), 32)
        r = self.cli("wait", job_id, "--timeout", "60")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("succeeded", r.stdout)
        r = self.cli("status", job_id, "--json")
        self.assertEqual(r.returncode, 0)
        self.assertIn('"status":"succeeded"', r.stdout)
        r = self.cli("logs", job_id)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn('"event":"done"', r.stdout)
        out = os.path.join(self.tmp, "fetched")
        r = self.cli("fetch", job_id, "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertTrue(os.path.exists(os.path.join(out, "cli.hdf")))
        r = self.cli("list", "--label", "via=cli")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn(job_id, r.stdout)

    def test_cli_exit_codes_tell_outcomes_apart(self):
        deck = os.path.join(self.tmp, "codes.inp")
        def submit_wait(text, *extra):
            with open(deck, "w") as f:
                f.write(text)
            return self.cli("submit", deck, "--wait", "--timeout", "60", *extra)
        self.assertEqual(submit_wait(decks.tiny()).returncode, 0)
        bad = submit_wait(decks.tiny().replace("*ELASTIC", "*ELASTIK"))
        self.assertEqual(bad.returncode, 2, bad.stderr)
        self.assertIn("codes.inp:", bad.stderr)
        self.assertEqual(submit_wait(not_converging()).returncode, 3)
        job = self.client.submit(decks.long_running())
        job.cancel()
        self.assertEqual(self.cli("wait", job.id).returncode, 5)
        self.assertEqual(self.cli("status", "0" * 32).returncode, 6)
        self.assertEqual(self.cli("status", "x", "--server", "http://127.0.0.1:9").returncode, 6)
        self.assertEqual(self.cli("wait").returncode, 1)
        slow = self.client.submit(decks.long_running())
        self.assertEqual(self.cli("wait", slow.id, "--timeout", "0.3").returncode, 7)
        self.assertEqual(self.cli("cancel", slow.id).returncode, 0)

    # -- sweeps ----------------------------------------------------------------------------
    def test_submit_sweep_wait_and_cancel(self):
        template = decks.load_template(decks.tiny(), -10.0)
        sweep = self.client.submit_sweep(template, [{"load": -1}, {"load": "-3"}], name="py",
                                         max_parallel=1, labels={"via": "python"})
        self.assertEqual((sweep.doc["rows"], sweep.doc["max_parallel"]), (2, 1))
        rows = sweep.wait(timeout=60)
        self.assertEqual([r["status"] for r in rows], ["succeeded"] * 2)
        self.assertEqual([r["labels"]["load"] for r in rows], ["-1", "-3"])
        self.assertAlmostEqual(rows[1]["max_displacement"] / rows[0]["max_displacement"], 3.0)
        self.assertEqual(sweep.job(1).status, "succeeded")
        with self.assertRaises(ApiError) as bad:
            self.client.submit_sweep(template, [{"lod": 1}])
        self.assertEqual((bad.exception.status, bad.exception.problem["field"]), (400, "rows"))
        with self.assertRaises(ApiError) as refused:
            self.client.submit_sweep(template, [{"load": 1}, {"load": "x"}])
        self.assertEqual((refused.exception.status, refused.exception.problem["row"]), (422, 1))
        long_sweep = self.client.submit_sweep(None, [decks.long_running()] * 3, max_parallel=1)
        long_sweep.cancel()
        self.assertEqual([r["status"] for r in long_sweep.wait(timeout=60)], ["canceled"] * 3)

    def test_cli_sweep_from_a_csv(self):
        template = os.path.join(self.tmp, "param.inp")
        with open(template, "w") as f:
            f.write(decks.load_template(decks.tiny(), -10.0))
        table = os.path.join(self.tmp, "params.csv")
        with open(table, "w") as f:
            f.write("load\n-1\n-2\n\n-4\n")
        r = self.cli("sweep", template, table, "--max-parallel", "2", "--name", "cli-sweep",
                     "--wait", "--timeout", "60")
        self.assertEqual(r.returncode, 0, r.stderr)
        lines = r.stdout.splitlines()
        self.assertEqual(len(lines), 3, r.stdout)
        self.assertTrue(all("succeeded" in line for line in lines), r.stdout)
        sweep_id = r.stderr.split("sweep ")[1].split(":")[0]
        doc = self.client.sweep(sweep_id).doc
        self.assertEqual((doc["name"], doc["max_parallel"], doc["jobs"]["succeeded"]),
                         ("cli-sweep", 2, 3))
        # The table's and the daemon's errors, with their exit codes.
        with open(table, "w") as f:
            f.write("load\n-1\n-2,3\n")
        r = self.cli("sweep", template, table)
        self.assertEqual(r.returncode, 1)
        self.assertIn("params.csv: line 3: 2 fields, the header has 1", r.stderr)
        with open(table, "w") as f:
            f.write("load,mu\n-1,0.2\n")
        r = self.cli("sweep", template, table)
        self.assertEqual(r.returncode, 6)
        self.assertIn("column 'mu' is used by no <mu> placeholder", r.stderr)
        with open(table, "w") as f:
            f.write("load\n-1\nabc\n")
        r = self.cli("sweep", template, table)
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("row 1: ", r.stderr)
        self.assertEqual(self.cli("sweep", template, table, "--max-parallel", "0").returncode, 1)
        self.assertEqual(self.cli("sweep", template).returncode, 1)

    # -- design loop -----------------------------------------------------------------------
    def test_design_loop_example_writes_the_csv(self):
        out = os.path.join(self.tmp, "sweep.csv")
        r = subprocess.run([sys.executable, os.path.join(harness.REPO, "clients", "examples", "design_loop.py"),
                            "--server", self.d.url, "--values=-100,-200,-400", "--csv", out],
                           capture_output=True, text=True, timeout=120)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        with open(out) as f:
            rows = list(csv.DictReader(f))
        self.assertEqual([float(r["value"]) for r in rows], [-100, -200, -400])
        self.assertTrue(all(r["status"] == "succeeded" for r in rows))
        u = [float(r["max_displacement"]) for r in rows]
        self.assertTrue(u[0] < u[1] < u[2], u)


if __name__ == "__main__":
    harness.run_tests(globals(), "kontaktd", "kontakt")
