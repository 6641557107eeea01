#!/usr/bin/python3
"""Writes the seed corpora of the fuzz harnesses from the project's own decks (never the ccx
example decks, which are GPL): the .inp files of this repository, the decks the daemon tests and
the mutation probe generate, a generated contact deck. One folder per harness under OUT:

  deck_text/   decks, and decks with include files (parts separated by NUL bytes)
  deck_zip/    zip uploads: a deck with its *INCLUDE files, in folders too
  submission/  a media-type byte, a query line, a JSON (or text) body
  router/      raw HTTP requests over the whole API

  make_corpus.py OUT
"""
import io
import json
import os
import subprocess
import sys
import zipfile

sys.dont_write_bytecode = True
HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import mutate_decks  # noqa: E402
from mutate_decks import decks  # noqa: E402

# Decks longer than this are left out (the harnesses run with -max_len 4096; a longer seed
# would only be cut).
MAX_SEED = 4000


def repository_decks():
    files = subprocess.run(["git", "ls-files", "*.inp"], cwd=REPO, capture_output=True, text=True,
                           check=True).stdout.split()
    out = {}
    for name in files:
        with open(os.path.join(REPO, name), encoding="utf-8", errors="replace") as f:
            text = f.read()
        if len(text) <= MAX_SEED:
            out[os.path.basename(name)] = text
    return out


def generated_decks(work):
    out = {name + ".inp": text for name, text in mutate_decks.base_decks(work).items()}
    out["tiny.inp"] = decks.tiny()
    out["nlgeom_many.inp"] = decks.long_running(increments=5, nx=3)
    return {name: text for name, text in out.items() if len(text) <= MAX_SEED}


def split_for_includes(deck):
    """(main, nodes, rest): the *NODE block moved to an include file."""
    start = deck.find("*NODE")
    end = deck.find("*ELEMENT")
    if start < 0 or end < start:
        return None
    return deck[:start] + "*INCLUDE, INPUT=nodes.inp\n" + deck[end:], deck[start:end]


def write(folder, name, data):
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def zip_bytes(files):
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as z:
        for name, text in files.items():
            z.writestr(name, text)
    return buffer.getvalue()


def requests(deck):
    body = deck.encode()
    job = "0123456789abcdef0123456789abcdef"
    lines = [
        b"POST /v1/jobs?name=beam&label=k%3Dv&scheme=lgc7 HTTP/1.1\r\nHost: x\r\n"
        b"Content-Type: text/plain\r\nIdempotency-Key: abc\r\nContent-Length: " +
        str(len(body)).encode() + b"\r\n\r\n" + body,
        b"POST /v1/jobs HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
        b"Transfer-Encoding: chunked\r\n\r\n" +
        hex(len(json.dumps({"deck": deck})))[2:].encode() + b"\r\n" +
        json.dumps({"deck": deck}).encode() + b"\r\n0\r\n\r\n",
        b"GET /v1/jobs?status=queued,running&label=k%3Dv&limit=2&page_token=abc HTTP/1.1\r\n"
        b"Host: x\r\nAuthorization: Bearer secret-token\r\n\r\n",
        f"GET /v1/jobs/{job} HTTP/1.1\r\nHost: x\r\n\r\n".encode(),
        f"POST /v1/jobs/{job}/cancel HTTP/1.1\r\nHost: x\r\nContent-Length: 0\r\n\r\n".encode(),
        f"DELETE /v1/jobs/{job} HTTP/1.1\r\nHost: x\r\n\r\n".encode(),
        f"GET /v1/jobs/{job}/events?since=3&follow=false HTTP/1.1\r\nHost: x\r\n"
        f"Last-Event-ID: 2\r\n\r\n".encode(),
        f"GET /v1/jobs/{job}/iterations?since=0&limit=10 HTTP/1.1\r\nHost: x\r\n\r\n".encode(),
        f"GET /v1/jobs/{job}/increments HTTP/1.1\r\nHost: x\r\n\r\n".encode(),
        f"GET /v1/jobs/{job}/results HTTP/1.1\r\nHost: x\r\n\r\n".encode(),
        f"GET /v1/jobs/{job}/results/deck.hdf HTTP/1.1\r\nHost: x\r\nRange: bytes=0-99\r\n"
        f"If-None-Match: \"x\"\r\n\r\n".encode(),
        f"GET /v1/jobs/{job}/summary?access_token=secret-token HTTP/1.1\r\nHost: x\r\n\r\n".encode(),
        b"GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n",
        b"GET /metrics HTTP/1.1\r\nHost: x\r\n\r\n",
        b"GET /v1/openapi.json HTTP/1.1\r\nHost: x\r\n\r\n",
        b"GET / HTTP/1.1\r\nHost: x\r\n\r\n",
    ]
    return lines


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 1
    out = sys.argv[1]
    work = os.path.join(out, ".work")
    os.makedirs(work, exist_ok=True)
    all_decks = {**repository_decks(), **generated_decks(work)}
    for name, text in all_decks.items():
        write(os.path.join(out, "deck_text"), name, text)
        split = split_for_includes(text)
        if split:
            main_deck, nodes = split
            write(os.path.join(out, "deck_text"), "incl_" + name,
                  main_deck.replace("INPUT=nodes.inp", "INPUT=1.inp") + "\0" + nodes)
            write(os.path.join(out, "deck_zip"), name + ".zip",
                  zip_bytes({"deck.inp": main_deck, "nodes.inp": nodes}))
            write(os.path.join(out, "deck_zip"), "sub_" + name + ".zip",
                  zip_bytes({"deck.inp": main_deck.replace("INPUT=nodes.inp", "INPUT=mesh/nodes.inp"),
                             "mesh/nodes.inp": nodes}))
        else:
            write(os.path.join(out, "deck_zip"), name + ".zip", zip_bytes({"deck.inp": text}))
    tiny = decks.tiny()
    for i, (media, query, body) in enumerate([
            (0, "name=a&label=k%3Dv", {"deck": tiny, "name": "x", "labels": {"a": "b"}}),
            (0, "", {"deck": tiny, "scheme": "lgc7", "main": "m.inp", "labels": {}}),
            (0, "scheme=nts", {"deck": tiny, "name": None}),
            (2, "name=plain", tiny)]):
        text = body if isinstance(body, str) else json.dumps(body)
        write(os.path.join(out, "submission"), f"seed{i}", bytes([media]) + f"{query}\n{text}".encode())
    for i, raw in enumerate(requests(tiny)):
        for tokens in (0, 1):
            write(os.path.join(out, "router"), f"seed{i}_{tokens}", bytes([tokens]) + raw)
    subprocess.run(["rm", "-rf", work], check=True)
    print(f"{out}: " + ", ".join(f"{d} {len(os.listdir(os.path.join(out, d)))}"
                                  for d in ("deck_text", "deck_zip", "submission", "router")))
    return 0


if __name__ == "__main__":
    sys.exit(main())
