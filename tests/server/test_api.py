#!/usr/bin/python3
"""End-to-end: kontaktd on a free loopback port with a temporary data folder.

Submit -> poll -> download and open the HDF5; SSE replay and resume; bad decks (422 naming
the line); oversized bodies (413); unknown jobs (404); auth on and off; 50 concurrent
submissions; the dashboard's endpoints (queue, sweeps, resubmit, pages); every JSON response
checked against proto/openapi.yaml."""
import hashlib
import io
import json
import socket
import threading
import time
import unittest
import zipfile

import h5py

import decks
import kontaktd_harness as harness
from openapi_check import validate, validate_inline

KONTAKTD = None


class ApiTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.d = harness.Daemon(KONTAKTD, args=["--workers", "2", "--max-body", "256K"]).start()

    @classmethod
    def tearDownClass(cls):
        cls.d.stop()

    def submit_ok(self, deck, query=""):
        status, headers, job = self.d.submit(deck, query)
        self.assertEqual(status, 201, job)
        validate(job, "Job")
        self.assertEqual(headers["location"], "/v1/jobs/" + job["id"])
        return job

    def test_submit_poll_download_and_open_the_hdf5(self):
        job = self.submit_ok(decks.beam(4), "name=beam4&label=case%3De2e")
        done = self.d.wait(job["id"])
        validate(done, "Job")
        self.assertEqual(done["status"], "succeeded", done)
        self.assertEqual(done["progress"]["fraction"], 1.0)
        self.assertTrue(done["results_available"])
        status, _, listing = self.d.json("GET", f"/v1/jobs/{job['id']}/results")
        validate(listing, "ArtifactList")
        names = {a["name"]: a for a in listing["artifacts"]}
        self.assertTrue({"deck.hdf", "deck.xdmf", "deck.dat", "deck.sta", "deck.cvg", "deck.log.jsonl"} <= set(names), names)
        # The deck asks for file output (*NODE FILE, *EL FILE): cgx's .frd is published too.
        self.assertEqual(names["deck.frd"]["media_type"], "text/plain; charset=utf-8")
        status, _, frd = self.d.request("GET", f"/v1/jobs/{job['id']}/results/deck.frd")
        self.assertEqual(status, 200)
        self.assertTrue(frd.startswith(b"    1C\n") and frd.endswith(b" 9999\n"), frd[-40:])
        status, headers, data = self.d.request("GET", f"/v1/jobs/{job['id']}/results/deck.hdf")
        self.assertEqual(status, 200)
        self.assertEqual(hashlib.sha256(data).hexdigest(), names["deck.hdf"]["sha256"])
        self.assertEqual(headers["etag"], '"' + names["deck.hdf"]["sha256"] + '"')
        with h5py.File(io.BytesIO(data), "r") as f:
            self.assertIn("VTKHDF", f)
            self.assertEqual(f["VTKHDF"]["NumberOfPoints"][0], 20)
        status, headers, part = self.d.request("GET", f"/v1/jobs/{job['id']}/results/deck.hdf",
                                               headers={"Range": "bytes=0-7"})
        self.assertEqual(status, 206)
        self.assertEqual(part, data[:8])
        self.assertEqual(headers["content-range"], f"bytes 0-7/{len(data)}")
        status, _, summary = self.d.json("GET", f"/v1/jobs/{job['id']}/summary")
        validate(summary, "Summary")
        self.assertGreater(summary["max_displacement"], 0)
        self.assertIsNone(summary["max_contact_pressure"])
        for table in ("iterations", "increments"):
            status, _, rows = self.d.json("GET", f"/v1/jobs/{job['id']}/{table}")
            validate_inline(rows, "/v1/jobs/{id}/" + table, "get", 200)
        status, _, page = self.d.json("GET", "/v1/jobs?label=case%3De2e")
        validate(page, "JobList")
        self.assertEqual([j["id"] for j in page["jobs"]], [job["id"]])

    def test_sse_replays_everything_and_resumes_after_last_event_id(self):
        job = self.submit_ok(decks.beam(2, nlgeom=True, increments=20))
        events = self.d.sse(job["id"])  # live until the job ends, then closed by the server
        ids = [e[0] for e in events]
        self.assertEqual(ids, list(range(1, len(ids) + 1)))
        kinds = [e[1] for e in events]
        self.assertEqual(kinds[0], "status")
        self.assertEqual(events[-1][2]["status"], "succeeded")
        self.assertEqual(kinds.count("increment"), 20)
        for _, _, data in events:
            validate(data, "Event")
        resumed = self.d.sse(job["id"], last_event_id=ids[9])
        self.assertEqual([e[0] for e in resumed], ids[10:])
        self.assertEqual(self.d.sse(job["id"], query="?since=5")[0][0], 6)
        # A stream opened before the job ends follows it live.
        job2 = self.submit_ok(decks.beam(2, nlgeom=True, increments=40))
        first = self.d.sse(job2["id"], stop_after=3)
        rest = self.d.sse(job2["id"], last_event_id=first[-1][0])
        self.assertEqual(rest[0][0], first[-1][0] + 1)
        self.assertEqual(rest[-1][2]["status"], "succeeded")

    def test_sse_replays_a_long_history_at_once(self):
        # More events than one write batch (500): the replay must not wait for new commits.
        job = self.submit_ok(decks.beam(1, nlgeom=True, increments=400))
        self.assertEqual(self.d.wait(job["id"], timeout=120)["status"], "succeeded")
        start = time.monotonic()
        events = self.d.sse(job["id"], timeout=60)
        elapsed = time.monotonic() - start
        self.assertGreater(len(events), 800)
        self.assertEqual([e[0] for e in events], list(range(1, len(events) + 1)))
        self.assertLess(elapsed, 3.0, f"replay of {len(events)} events took {elapsed:.1f} s")

    def test_queue_sweeps_and_resubmit(self):
        status, _, queue = self.d.json("GET", "/v1/queue")
        self.assertEqual(status, 200)
        validate(queue, "Queue")
        self.assertEqual(queue["workers"], 2)
        ids = [self.submit_ok(decks.beam(2, load=-10.0 * k), f"label=e2eload%3D{k}&label=case%3Dq")["id"]
               for k in (1, 2, 4)]
        for job_id in ids:
            self.assertEqual(self.d.wait(job_id)["status"], "succeeded")
        status, _, sweeps = self.d.json("GET", "/v1/sweeps")
        validate(sweeps, "SweepList")
        self.assertIn({"key": "e2eload", "jobs": 3},
                      [{k: s[k] for k in ("key", "jobs")} for s in sweeps["sweeps"]])
        status, _, sweep = self.d.json("GET", "/v1/sweeps/e2eload")
        self.assertEqual(status, 200)
        validate(sweep, "Sweep")
        rows = {r["value"]: r for r in sweep["jobs"]}
        self.assertEqual(set(rows), {"1", "2", "4"})
        # Linear: the tip displacement scales with the load.
        self.assertAlmostEqual(rows["4"]["max_displacement"] / rows["1"]["max_displacement"], 4.0, places=6)
        status, _, page = self.d.json("GET", "/v1/sweeps/e2eload?limit=2")
        validate(page, "Sweep")
        self.assertIsNotNone(page["next_page_token"])
        status, _, problem = self.d.json("GET", "/v1/sweeps/no%20such")
        self.assertEqual(status, 400)
        validate(problem, "Problem")

        status, headers, again = self.d.json("POST", f"/v1/jobs/{ids[0]}/resubmit",
                                             json.dumps({"scheme": "gc3", "name": "again"}).encode(),
                                             {"Content-Type": "application/json"})
        self.assertEqual(status, 201, again)
        validate(again, "Job")
        self.assertEqual((again["scheme"], again["name"], again["labels"]["e2eload"]), ("gc3", "again", "1"))
        self.assertEqual(headers["location"], "/v1/jobs/" + again["id"])
        done = self.d.wait(again["id"])
        self.assertEqual(done["status"], "succeeded")
        _, _, s0 = self.d.json("GET", f"/v1/jobs/{ids[0]}/summary")
        _, _, s1 = self.d.json("GET", f"/v1/jobs/{again['id']}/summary")
        self.assertEqual(s0["max_displacement"], s1["max_displacement"])
        status, _, problem = self.d.json("POST", f"/v1/jobs/{ids[0]}/resubmit", b'{"scheme": "gc5"}',
                                         {"Content-Type": "application/json"})
        self.assertEqual(status, 400)
        validate(problem, "Problem")

    def test_bad_decks_are_422_naming_the_line(self):
        good = decks.tiny().splitlines()
        node_line = good.index("*NODE, NSET=NALL") + 2
        cases = {
            "unknown keyword": (good[:3] + ["*FROBNICATE"] + good[3:], 4, "*FROBNICATE"),
            "bad number": (good[:node_line - 1] + ["1, 0.0, x, 0.0"] + good[node_line:], node_line, "*NODE"),
            "unknown element type": ([l.replace("C3D8,", "C3D9,") for l in good],
                                     next(i for i, l in enumerate(good) if l.startswith("*ELEMENT")) + 1, "*ELEMENT"),
            "unknown set": ([l.replace("FIX, 1, 3", "NOPE, 1, 3") for l in good],
                            good.index("FIX, 1, 3") + 1, "*BOUNDARY"),
        }
        for what, (lines, line, keyword) in cases.items():
            with self.subTest(what):
                status, headers, problem = self.d.submit("\n".join(lines) + "\n", "main=case.inp")
                self.assertEqual(status, 422, problem)
                self.assertEqual(headers["content-type"], "application/problem+json")
                validate(problem, "Problem")
                self.assertEqual(problem["errors"][0]["file"], "case.inp")
                self.assertEqual(problem["errors"][0]["line"], line, problem)
                self.assertEqual(problem["errors"][0]["keyword"], keyword, problem)
                self.assertIn(f"case.inp:{line}", problem["detail"])

    def test_zip_upload_with_include(self):
        deck = decks.tiny()
        start, end = deck.index("*NODE"), deck.index("*ELEMENT")
        main = deck[:start] + "*INCLUDE, INPUT=parts/nodes.inp\n" + deck[end:]
        buf = io.BytesIO()
        with zipfile.ZipFile(buf, "w") as z:
            z.writestr("model.inp", main)
            z.writestr("parts/nodes.inp", deck[start:end])
        status, _, job = self.d.json("POST", "/v1/jobs", buf.getvalue(), {"Content-Type": "application/zip"})
        self.assertEqual(status, 201, job)
        self.assertEqual(self.d.wait(job["id"])["status"], "succeeded")
        evil = io.BytesIO()
        with zipfile.ZipFile(evil, "w") as z:
            z.writestr("../../escape.inp", deck)
        status, _, problem = self.d.json("POST", "/v1/jobs?main=x.inp", evil.getvalue(), {"Content-Type": "application/zip"})
        self.assertEqual(status, 400)
        validate(problem, "Problem")

    def test_oversized_body_is_413(self):
        # Declared too large: refused from the header, before the body is read.
        with socket.create_connection(("127.0.0.1", self.d.port), timeout=10) as s:
            s.sendall(b"POST /v1/jobs HTTP/1.1\r\nHost: x\r\nContent-Type: text/plain\r\n"
                      b"Content-Length: 10000000\r\n\r\n" + b"*" * 1000)
            reply = s.recv(65536).decode(errors="replace")
        self.assertTrue(reply.startswith("HTTP/1.1 413"), reply[:200])
        self.assertIn("application/problem+json", reply)
        # Chunked, no length: refused once the body passes the limit.
        with socket.create_connection(("127.0.0.1", self.d.port), timeout=10) as s:
            s.sendall(b"POST /v1/jobs HTTP/1.1\r\nHost: x\r\nContent-Type: text/plain\r\n"
                      b"Transfer-Encoding: chunked\r\n\r\n")
            chunk = b"*" * 65536
            reply = b""
            try:
                for _ in range(8):
                    s.sendall(b"%x\r\n%s\r\n" % (len(chunk), chunk))
            except (BrokenPipeError, ConnectionResetError):
                pass
            s.settimeout(10)
            reply = s.recv(65536).decode(errors="replace")
        self.assertTrue(reply.startswith("HTTP/1.1 413"), reply[:200])
        # A body under the limit is still fine on a new connection.
        self.submit_ok(decks.tiny())

    def test_unknown_job_is_404(self):
        for path in ("/v1/jobs/" + "0" * 32, "/v1/jobs/nope/summary", "/v1/jobs/" + "0" * 32 + "/results/x"):
            status, headers, problem = self.d.json("GET", path)
            self.assertEqual(status, 404, path)
            validate(problem, "Problem")
        status, _, _ = self.d.json("POST", "/v1/jobs/" + "0" * 32 + "/cancel")
        self.assertEqual(status, 404)

    def test_idempotency_key(self):
        h = {"Idempotency-Key": "e2e-key-1"}
        s1, _, j1 = self.d.submit(decks.tiny(), headers=h)
        s2, h2, j2 = self.d.submit(decks.tiny(), headers=h)
        self.assertEqual((s1, s2), (201, 201))
        self.assertEqual(j1["id"], j2["id"])
        self.assertEqual(h2.get("idempotent-replayed"), "true")
        s3, _, p3 = self.d.submit(decks.beam(2), headers=h)
        self.assertEqual(s3, 422)
        self.assertEqual(p3["code"], "idempotency_key_reused")

    def test_fifty_concurrent_submissions_from_several_threads(self):
        ids, errors = [], []
        lock = threading.Lock()

        def worker(n):
            for i in range(10):
                try:
                    status, _, job = self.d.submit(decks.tiny(), f"label=batch%3Dc50&name=t{n}-{i}")
                    with lock:
                        (ids if status == 201 else errors).append(job["id"] if status == 201 else status)
                except Exception as e:  # noqa: BLE001 - any failure is a finding
                    with lock:
                        errors.append(repr(e))

        threads = [threading.Thread(target=worker, args=(n,)) for n in range(5)]
        for t in threads:
            t.start()
        for t in threads:
            t.join(timeout=120)
        self.assertEqual(errors, [])
        self.assertEqual(len(set(ids)), 50)
        for job_id in ids:
            self.assertEqual(self.d.wait(job_id, timeout=120)["status"], "succeeded")
        listed, token = set(), None
        while True:
            q = "/v1/jobs?label=batch%3Dc50&limit=7" + (f"&page_token={harness.quote(token)}" if token else "")
            status, _, page = self.d.json("GET", q)
            validate(page, "JobList")
            listed |= {j["id"] for j in page["jobs"]}
            token = page["next_page_token"]
            if not token:
                break
        self.assertEqual(listed, set(ids))
        _, _, metrics = self.d.request("GET", "/metrics")
        self.assertIn("kontakt_jobs_finished_total{status=\"succeeded\"}", metrics.decode())

    def test_service_endpoints(self):
        status, _, health = self.d.json("GET", "/healthz")
        validate(health, "Health")
        status, _, spec = self.d.json("GET", "/v1/openapi.json")
        self.assertEqual(spec["openapi"], "3.1.0")
        self.assertEqual(set(spec["paths"]), set(__import__("openapi_check").SPEC["paths"]))
        for path, script in (("/", b"job_list.js"), ("/jobs/" + "0" * 32, b"job_page.js"),
                             ("/sweeps?label=x", b"sweeps_page.js")):
            status, headers, page = self.d.request("GET", path)
            self.assertEqual(status, 200, path)
            self.assertTrue(headers["content-type"].startswith("text/html"), path)
            self.assertIn("default-src 'self'", headers["content-security-policy"])
            self.assertIn(script, page)
        status, headers, module = self.d.request("GET", "/assets/uPlot.esm.js")
        self.assertEqual(status, 200)
        self.assertTrue(headers["content-type"].startswith("text/javascript"))
        self.assertEqual(self.d.request("GET", "/assets/uPlot.esm.js",
                                        headers={"If-None-Match": headers["etag"]})[0], 304)


class AuthTest(unittest.TestCase):
    def test_tokens_on(self):
        d = harness.Daemon(KONTAKTD)
        token_file = d.data_dir + "/tokens"
        with open(token_file, "w") as f:
            f.write("# tokens\nalpha-token\n")
        d.args = ["--token-file", token_file]
        d.start()
        try:
            status, headers, problem = d.json("GET", "/v1/jobs")
            self.assertEqual(status, 401)
            validate(problem, "Problem")
            self.assertIn("bearer", headers["www-authenticate"].lower())
            self.assertEqual(d.json("GET", "/v1/jobs", headers={"Authorization": "Bearer wrong"})[0], 401)
            auth = {"Authorization": "Bearer alpha-token"}
            self.assertEqual(d.json("GET", "/v1/jobs", headers=auth)[0], 200)
            status, _, job = d.submit(decks.tiny(), headers=auth)
            self.assertEqual(status, 201)
            self.assertEqual(d.submit(decks.tiny())[0], 401)
            self.assertEqual(d.wait(job["id"], headers=auth)["status"], "succeeded")
            self.assertEqual(d.json("GET", "/healthz")[0], 200)  # liveness stays open
            # The token is taken from the header only, never from the URL.
            self.assertEqual(d.json("GET", "/v1/jobs?access_token=alpha-token")[0], 401)
            self.assertEqual(d.request("GET", f"/v1/jobs/{job['id']}/events?access_token=alpha-token")[0], 401)
            # The dashboard's pages and assets hold no data and load without it; its API calls
            # carry the header.
            for path in ("/", f"/jobs/{job['id']}", "/sweeps", "/assets/job_page.js"):
                self.assertEqual(d.request("GET", path)[0], 200, path)
            for path in ("/v1/queue", "/v1/sweeps", f"/v1/jobs/{job['id']}/summary"):
                self.assertEqual(d.json("GET", path)[0], 401, path)
                self.assertEqual(d.json("GET", path, headers=auth)[0], 200, path)
        finally:
            d.stop()

    def test_tokens_off_and_loopback_default(self):
        d = harness.Daemon(KONTAKTD).start()
        try:
            self.assertEqual(d.json("GET", "/v1/jobs")[0], 200)
            self.assertIn("listening on http://127.0.0.1:", d.log())
        finally:
            d.stop()


if __name__ == "__main__":
    harness.run_tests(globals(), "kontaktd")
