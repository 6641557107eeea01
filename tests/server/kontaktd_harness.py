"""Starts kontaktd on a free loopback port with a temporary data folder, and small HTTP
helpers the end-to-end tests share (standard library only)."""
import argparse
import contextlib
import http.client
import json
import os
import shutil
import signal
import subprocess
import tempfile
import time
import unittest
import urllib.parse

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
START_TIMEOUT = 20.0


class Daemon:
    """One kontaktd process. `data_dir` survives restart() so crash tests can reuse it."""

    def __init__(self, exe, data_dir=None, args=(), env=None):
        self.exe = exe
        self.own_dir = data_dir is None
        self.data_dir = data_dir or tempfile.mkdtemp(prefix="kontaktd-test-")
        self.args = list(args)
        self.env = env
        self.proc = None
        self.port = None
        self.log_path = os.path.join(self.data_dir, "daemon.log")

    def start(self):
        log = self._log = open(self.log_path, "a")
        env = dict(os.environ, **(self.env or {}))
        self.proc = subprocess.Popen(
            [self.exe, "--port", "0", "--data-dir", self.data_dir] + self.args,
            stdout=subprocess.PIPE, stderr=log, text=True, env=env, start_new_session=True)
        deadline = time.monotonic() + START_TIMEOUT
        while time.monotonic() < deadline:
            line = self.proc.stdout.readline()
            if not line:
                raise RuntimeError("kontaktd exited early; log:\n" + self.log())
            log.write(line)
            log.flush()
            if "listening on http://" in line:
                self.port = int(line.split("http://")[1].split()[0].rsplit(":", 1)[1])
                break
        else:
            raise RuntimeError("kontaktd did not start in time")
        # Keep draining stdout so the daemon never blocks on a full pipe.
        self._pump = subprocess.Popen(["cat"], stdin=self.proc.stdout, stdout=log)
        self.proc.stdout.close()
        return self

    def _reap(self):
        self._pump.wait(timeout=10)
        self._log.close()

    def log(self):
        with open(self.log_path) as f:
            return f.read()

    def kill9(self):
        os.killpg(self.proc.pid, signal.SIGKILL)
        self.proc.wait(timeout=10)
        self._reap()

    def terminate(self, timeout=30):
        """SIGTERM and wait; returns the exit code."""
        self.proc.send_signal(signal.SIGTERM)
        code = self.proc.wait(timeout=timeout)
        self._reap()
        return code

    def stop(self):
        if self.proc and self.proc.poll() is None:
            try:
                self.terminate(timeout=15)
            except subprocess.TimeoutExpired:
                self.kill9()
        if self.own_dir:
            shutil.rmtree(self.data_dir, ignore_errors=True)

    @property
    def url(self):
        return f"http://127.0.0.1:{self.port}"

    def request(self, method, path, body=None, headers=None, timeout=30):
        """(status, headers dict lower-case, body bytes)."""
        conn = http.client.HTTPConnection("127.0.0.1", self.port, timeout=timeout)
        try:
            conn.request(method, path, body=body, headers=headers or {})
            r = conn.getresponse()
            return r.status, {k.lower(): v for k, v in r.getheaders()}, r.read()
        finally:
            conn.close()

    def json(self, method, path, body=None, headers=None, timeout=30):
        status, hdrs, data = self.request(method, path, body, headers, timeout)
        return status, hdrs, (json.loads(data) if data else None)

    def submit(self, deck, query="", headers=None):
        h = {"Content-Type": "text/plain"}
        h.update(headers or {})
        return self.json("POST", "/v1/jobs" + (("?" + query) if query else ""), deck.encode(), h)

    def wait(self, job_id, until=("succeeded", "failed", "canceled"), timeout=60, headers=None):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            status, _, job = self.json("GET", f"/v1/jobs/{job_id}", headers=headers)
            if status == 200 and job["status"] in until:
                return job
            time.sleep(0.05)
        raise TimeoutError(f"job {job_id} not in {until} after {timeout} s")

    def sse(self, job_id, last_event_id=None, query="", timeout=30, stop_after=None):
        """Reads the event stream to its end (or `stop_after` events): [(id, kind, data)]."""
        headers = {"Accept": "text/event-stream"}
        if last_event_id is not None:
            headers["Last-Event-ID"] = str(last_event_id)
        conn = http.client.HTTPConnection("127.0.0.1", self.port, timeout=timeout)
        events = []
        try:
            conn.request("GET", f"/v1/jobs/{job_id}/events" + query, headers=headers)
            r = conn.getresponse()
            if r.status != 200:
                raise RuntimeError(f"SSE status {r.status}: {r.read()!r}")
            frame = {}
            for raw in r:
                line = raw.decode().rstrip("\n")
                if not line:
                    if "data" in frame:
                        events.append((int(frame["id"]), frame["event"], json.loads(frame["data"])))
                        if stop_after and len(events) >= stop_after:
                            break
                    frame = {}
                elif not line.startswith(":"):
                    key, _, value = line.partition(": ")
                    frame[key] = value
        finally:
            conn.close()
        return events


def wait_iterating(d, job_id, timeout=30):
    """The job's document once it runs and has reported an iteration (an AssertionError when
    it ends first)."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        _, _, job = d.json("GET", f"/v1/jobs/{job_id}")
        if job["status"] == "running" and job["progress"]["iteration"] > 0:
            return job
        if job["status"] not in ("queued", "running"):
            raise AssertionError(f"job ended early: {job}")
        time.sleep(0.02)
    raise TimeoutError(f"job {job_id} did not start iterating within {timeout} s")


def post_sweep(d, body, headers=None):
    """POST /v1/sweeps with `body` as JSON."""
    h = {"Content-Type": "application/json"}
    h.update(headers or {})
    return d.json("POST", "/v1/sweeps", json.dumps(body).encode(), h)


def wait_sweep(d, sweep_id, timeout=120):
    """The sweep's document once every job of it has finished."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        _, _, doc = d.json("GET", f"/v1/sweeps/id/{sweep_id}")
        if doc["status"] == "finished":
            return doc
        time.sleep(0.1)
    raise TimeoutError(f"sweep {sweep_id} not finished after {timeout} s")


def sweep_jobs(d, sweep_id):
    """GET /v1/sweeps/id/{id}/jobs, checked against the API description: the rows' jobs."""
    from openapi_check import validate
    status, _, doc = d.json("GET", f"/v1/sweeps/id/{sweep_id}/jobs")
    assert status == 200, doc
    validate(doc, "SweepJobs")
    return doc["jobs"]


def children(pid):
    """Processes whose parent is `pid`: a daemon's worker processes, waiting or working."""
    out = []
    for entry in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open(f"/proc/{entry}/stat") as f:
                if int(f.read().rsplit(")", 1)[1].split()[1]) == pid:
                    out.append(int(entry))
        except (OSError, IndexError, ValueError):
            continue
    return out


def job_process(daemon, job_id):
    """The pid of the process running the job (it works in the job's work folder), or None."""
    for pid in children(daemon.proc.pid):
        try:
            if os.readlink(f"/proc/{pid}/cwd").endswith(f"/jobs/{job_id}/work"):
                return pid
        except OSError:
            continue
    return None


def quote(s):
    return urllib.parse.quote(s, safe="")


@contextlib.contextmanager
def restartable(exe, args=()):
    """A started daemon whose data folder outlives kill9()/terminate() + start(), removed at
    the end."""
    d = Daemon(exe, args=args)
    d.own_dir = False
    d.start()
    try:
        yield d
    finally:
        d.stop()
        shutil.rmtree(d.data_dir, ignore_errors=True)


def run_tests(module_globals, *programs):
    """Runs the calling script's unittest cases; `--NAME PATH` for each program sets the
    module global NAME.upper() (e.g. --kontaktd -> KONTAKTD)."""
    p = argparse.ArgumentParser()
    for name in programs:
        p.add_argument("--" + name, required=True)
    args, rest = p.parse_known_args()
    for name in programs:
        module_globals[name.upper()] = getattr(args, name)
    unittest.main(argv=[module_globals["__file__"]] + rest, verbosity=2)
