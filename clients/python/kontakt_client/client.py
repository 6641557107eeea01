"""Client and Job: submit, follow, cancel, list and download kontaktd jobs (stdlib only)."""
import hashlib
import http.client
import json
import os
import random
import time
import urllib.parse
import uuid

from .sse import parse_sse

TERMINAL = ("succeeded", "failed", "canceled")


class TransportError(Exception):
    """The daemon could not be reached (after the retries)."""


class ApiError(Exception):
    """The daemon refused the request; carries the problem details."""

    def __init__(self, status, problem):
        self.status = status
        self.problem = problem if isinstance(problem, dict) else {"detail": str(problem)}
        self.code = self.problem.get("code")
        self.errors = self.problem.get("errors", [])
        super().__init__(f"HTTP {status}: {self.problem.get('detail', '')}")


class Client:
    """A kontaktd at `base_url` (http://HOST:PORT). Requests that fail to connect or get a 5xx
    or 429 are retried with exponential backoff; a retried submission reuses its
    Idempotency-Key, so it never creates a second job."""

    def __init__(self, base_url="http://127.0.0.1:8080", token=None, timeout=30.0, retries=4,
                 backoff=0.25):
        parsed = urllib.parse.urlsplit(base_url)
        if parsed.scheme != "http" or not parsed.hostname:
            raise ValueError("base_url must be http://HOST[:PORT]")
        self.host, self.port = parsed.hostname, parsed.port or 80
        self.token, self.timeout, self.retries, self.backoff = token, timeout, retries, backoff

    # -- transport ---------------------------------------------------------------------------
    def _headers(self, extra=None):
        h = {"User-Agent": "kontakt-client-python"}
        if self.token:
            h["Authorization"] = "Bearer " + self.token
        h.update(extra or {})
        return h

    def _open(self, method, path, body=None, headers=None, timeout=None):
        """The response object of one attempt (the caller reads and closes it)."""
        conn = http.client.HTTPConnection(self.host, self.port, timeout=timeout or self.timeout)
        conn.request(method, path, body=body, headers=self._headers(headers))
        return conn, conn.getresponse()

    def request(self, method, path, body=None, headers=None):
        """(status, headers, parsed JSON or bytes) with retries; raises ApiError for 4xx/5xx."""
        for attempt in range(self.retries + 1):
            try:
                conn, r = self._open(method, path, body, headers)
                try:
                    data = r.read()
                finally:
                    conn.close()
            except (OSError, http.client.HTTPException) as e:
                if attempt == self.retries:
                    raise TransportError(f"{method} {path}: {e}") from e
                self._sleep(attempt)
                continue
            if (r.status >= 500 or r.status == 429) and attempt < self.retries:
                self._sleep(attempt)
                continue
            ctype = r.getheader("Content-Type", "")
            payload = json.loads(data) if data and "json" in ctype else data
            if r.status >= 400:
                raise ApiError(r.status, payload if isinstance(payload, dict) else data.decode(errors="replace"))
            return r.status, {k.lower(): v for k, v in r.getheaders()}, payload
        raise AssertionError("unreachable")

    def _sleep(self, attempt):
        time.sleep(self.backoff * (2 ** attempt) * (0.5 + random.random() / 2))

    # -- jobs ----------------------------------------------------------------------------------
    def submit(self, deck, name=None, scheme=None, labels=None, main=None, zip_archive=False,
               idempotency_key=None):
        """Submits deck bytes or text (a raw .inp, or a zip with zip_archive=True); returns a Job.

        A bad deck raises ApiError with status 422 and `.errors` naming file, line, keyword."""
        query = [(k, v) for k, v in (("name", name), ("scheme", scheme), ("main", main)) if v]
        query += [("label", f"{k}={v}") for k, v in (labels or {}).items()]
        body = deck.encode() if isinstance(deck, str) else deck
        headers = {"Content-Type": "application/zip" if zip_archive else "text/plain",
                   "Idempotency-Key": idempotency_key or str(uuid.uuid4())}
        path = "/v1/jobs" + ("?" + urllib.parse.urlencode(query) if query else "")
        _, _, doc = self.request("POST", path, body, headers)
        return Job(self, doc)

    def submit_file(self, path, **options):
        """Submits a .inp or .zip file (the deck's file name becomes `main` for a raw deck)."""
        with open(path, "rb") as f:
            data = f.read()
        is_zip = path.endswith(".zip")
        if not is_zip:
            options.setdefault("main", os.path.basename(path))
        return self.submit(data, zip_archive=is_zip, **options)

    def job(self, job_id):
        return Job(self, self.request("GET", f"/v1/jobs/{job_id}")[2])

    def submit_sweep(self, template, rows, name=None, scheme=None, labels=None, resources=None,
                     max_parallel=None, idempotency_key=None):
        """Submits a parametric sweep: `template` is a deck (text) with <name> placeholders,
        `rows` a list of dicts (name -> value, str or number), one job each; or `template=None`
        and `rows` a list of complete decks. At most `max_parallel` rows run at once (on Slurm:
        one job array, --array=...%max_parallel). Returns a Sweep.

        A bad table raises ApiError 400 naming the field (`.problem["row"]` for a row); a row
        whose deck the reader refuses, ApiError 422 with `.problem["row"]` and `.errors`."""
        body = {"decks": list(rows)} if template is None else {"template": template,
                                                                "rows": list(rows)}
        for key, value in (("name", name), ("scheme", scheme), ("labels", labels),
                           ("resources", resources), ("max_parallel", max_parallel)):
            if value is not None:
                body[key] = value
        headers = {"Content-Type": "application/json",
                   "Idempotency-Key": idempotency_key or str(uuid.uuid4())}
        _, _, doc = self.request("POST", "/v1/sweeps", json.dumps(body).encode(), headers)
        return Sweep(self, doc)

    def sweep(self, sweep_id):
        return Sweep(self, self.request("GET", f"/v1/sweeps/id/{sweep_id}")[2])

    def list_jobs(self, status=None, labels=None, page_size=50):
        """Yields every matching job document, newest first, following next_page_token."""
        token = None
        while True:
            query = [("limit", str(page_size))]
            if status:
                query.append(("status", status if isinstance(status, str) else ",".join(status)))
            query += [("label", f"{k}={v}") for k, v in (labels or {}).items()]
            if token:
                query.append(("page_token", token))
            page = self.request("GET", "/v1/jobs?" + urllib.parse.urlencode(query))[2]
            yield from page["jobs"]
            token = page["next_page_token"]
            if not token:
                return


class _Resource:
    """A job or sweep of the API with `doc`, its latest document, at `path`."""

    def __init__(self, client, doc):
        self.client, self.doc = client, doc
        self.id = doc["id"]

    @property
    def path(self):
        raise NotImplementedError

    @property
    def status(self):
        return self.doc["status"]

    def refresh(self):
        self.doc = self.client.request("GET", self.path)[2]
        return self.doc

    def cancel(self):
        """Cancels the job, or every unfinished job of the sweep."""
        self.doc = self.client.request("POST", f"{self.path}/cancel")[2]
        return self.doc


class Sweep(_Resource):
    """One sweep made by submit_sweep; `doc` is its latest document (status, job counts by
    status, rows, max_parallel, slurm_array_id)."""

    @property
    def path(self):
        return f"/v1/sweeps/id/{self.id}"

    def jobs(self):
        """One summary per row, in row order: row, id, status, labels (the row's parameter
        values), max_displacement, max_mises, ..."""
        return self.client.request("GET", f"{self.path}/jobs")[2]["jobs"]

    def job(self, row):
        return self.client.job(self.jobs()[row]["id"])

    def wait(self, timeout=None, poll_interval=0.5):
        """Blocks until every job of the sweep has ended; returns jobs()."""
        deadline = None if timeout is None else time.monotonic() + timeout
        while self.refresh()["status"] != "finished":
            if deadline and time.monotonic() > deadline:
                raise TimeoutError(f"sweep {self.id} still {self.status} after {timeout} s")
            time.sleep(poll_interval)
        return self.jobs()


class Job(_Resource):
    """One job; `doc` is its latest status document."""

    @property
    def path(self):
        return f"/v1/jobs/{self.id}"

    def summary(self):
        return self.client.request("GET", f"/v1/jobs/{self.id}/summary")[2]

    def results(self):
        return self.client.request("GET", f"/v1/jobs/{self.id}/results")[2]["artifacts"]

    def events(self, since=0, follow=True):
        """Yields (seq, kind, event dict) from the SSE stream, resuming after `since`; with
        follow, until the job ends (reconnecting with Last-Event-ID if the stream breaks)."""
        last = since
        for attempt in range(self.client.retries + 1):
            try:
                conn, r = self.client._open(
                    "GET", f"/v1/jobs/{self.id}/events?follow={'true' if follow else 'false'}",
                    headers={"Last-Event-ID": str(last), "Accept": "text/event-stream"},
                    timeout=max(60.0, self.client.timeout))
                try:
                    if r.status != 200:
                        raise ApiError(r.status, json.loads(r.read() or b"{}"))
                    lines = (raw.decode("utf-8") for raw in r)
                    for seq, kind, data in parse_sse(lines):
                        last = seq
                        yield seq, kind, json.loads(data)
                finally:
                    conn.close()
                return  # the server closed the stream: the job ended (or caught up)
            except (OSError, http.client.HTTPException):
                if attempt == self.client.retries:
                    raise
                self.client._sleep(attempt)

    def wait(self, timeout=None, stream=False, poll_interval=0.25, on_progress=None):
        """Blocks until the job ends; returns the final status document.

        stream=False polls the status document; stream=True follows the event stream and then
        reads the document once. `on_progress(doc_or_event)` is called along the way."""
        deadline = None if timeout is None else time.monotonic() + timeout
        if stream:
            for _, kind, event in self.events(follow=True):
                if on_progress:
                    on_progress(event)
                if deadline and time.monotonic() > deadline:
                    raise TimeoutError(f"job {self.id} still running after {timeout} s")
            return self.refresh()
        while True:
            doc = self.refresh()
            if on_progress:
                on_progress(doc)
            if doc["status"] in TERMINAL:
                return doc
            if deadline and time.monotonic() > deadline:
                raise TimeoutError(f"job {self.id} still {doc['status']} after {timeout} s")
            time.sleep(poll_interval)

    def download(self, name, dest_dir="."):
        """Downloads one result into dest_dir, checks its sha256 against the listing (resuming
        a partial download with Range); returns the path."""
        listing = {a["name"]: a for a in self.results()}
        if name not in listing:
            raise ApiError(404, {"detail": f"job {self.id} has no result {name}"})
        expected = listing[name]["sha256"]
        os.makedirs(dest_dir, exist_ok=True)
        final = os.path.join(dest_dir, os.path.basename(name))
        partial = final + ".download"
        for attempt in range(self.client.retries + 1):
            have = os.path.getsize(partial) if os.path.exists(partial) else 0
            headers = {"Range": f"bytes={have}-", "If-Range": f'"{expected}"'} if have else {}
            try:
                conn, r = self.client._open("GET", f"/v1/jobs/{self.id}/results/{urllib.parse.quote(name)}",
                                            headers=headers)
                try:
                    if r.status not in (200, 206):
                        raise ApiError(r.status, json.loads(r.read() or b"{}"))
                    with open(partial, "ab" if r.status == 206 else "wb") as out:
                        while chunk := r.read(1 << 16):
                            out.write(chunk)
                finally:
                    conn.close()
                break
            except (OSError, http.client.HTTPException):
                if attempt == self.client.retries:
                    raise
                self.client._sleep(attempt)
        digest = hashlib.sha256()
        with open(partial, "rb") as f:
            while chunk := f.read(1 << 16):
                digest.update(chunk)
        if digest.hexdigest() != expected:
            os.remove(partial)
            raise TransportError(f"{name}: checksum mismatch")
        os.replace(partial, final)
        return final
