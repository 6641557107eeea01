"""Running ccx 2.20 and `kontakt solve --scheme NAME` on a generated contact deck, the same
way for both: one child process in its own process group (killed with its children on
timeout), wall time and peak resident memory of that child (`ru_maxrss` from wait4, the figure
/usr/bin/time -v reports), converged or not, and the Newton iterations read from the
solver's .sta file.

Counting (identical for both solvers): `iterations` is the sum of the ITRS column over every
attempt in the .sta, cut-back attempts (marked U) included; `increments` counts the converged
ones (tests/peer/run_peer.py's sta_counts).
Converged: ccx exit code 0 and "Job finished" in its output; kontakt exit code 0 (3 means
not converged, 2 input error, 4 numerical or internal error).
"""
import os
import signal
import subprocess
import sys
import threading
import time
from dataclasses import dataclass

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "peer"))
import run_peer  # noqa: E402

DEFAULT_TIMEOUT = 600


@dataclass
class Run:
    solver: str          # "ccx" or "kontakt --scheme NAME"
    converged: bool
    status: str          # "converged", "not converged", "timeout", "exit N"
    iterations: int      # over every attempt (0 when there is no .sta)
    increments: int      # converged increments
    wall: float          # seconds
    peak_mib: float
    result_dir: str      # folder holding NAME.dat / .sta (and .frd or .hdf)


def timed_run(cmd, cwd, log_path, timeout, env=None):
    """(wall seconds, peak RSS MiB, return code or None on timeout) of one child process."""
    start = time.perf_counter()
    with open(log_path, "w") as log:
        proc = subprocess.Popen(cmd, cwd=cwd, env=env, stdout=log, stderr=subprocess.STDOUT,
                                start_new_session=True)
        expired = threading.Event()

        def kill():
            expired.set()
            os.killpg(proc.pid, signal.SIGKILL)
        timer = threading.Timer(timeout, kill)
        timer.start()
        _, status, usage = os.wait4(proc.pid, 0)
        timer.cancel()
        proc.returncode = os.waitstatus_to_exitcode(status)
    wall = time.perf_counter() - start
    return wall, usage.ru_maxrss / 1024.0, None if expired.is_set() else proc.returncode


def _counts(sta_path):
    return run_peer.sta_counts(sta_path) or (0, 0)


def run_ccx(deck_path, timeout=DEFAULT_TIMEOUT, threads=1):
    """ccx -i NAME in the deck's folder."""
    folder, name = os.path.split(os.path.abspath(deck_path))
    name = name[:-4]
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), CCX_NPROC_EQUATION_SOLVER=str(threads))
    log = os.path.join(folder, name + ".ccx.log")
    wall, peak, rc = timed_run(["ccx", "-i", name], folder, log, timeout, env)
    with open(log, errors="replace") as f:
        finished = "Job finished" in f.read()
    converged = rc == 0 and finished
    status = ("timeout" if rc is None else "converged" if converged
              else "not converged" if rc == 0 or not finished else f"exit {rc}")
    increments, iterations = _counts(os.path.join(folder, name + ".sta"))
    return Run("ccx", converged, status, iterations, increments, wall, peak, folder)


def run_kontakt(exe, deck_path, scheme, out_dir, timeout=DEFAULT_TIMEOUT, threads=1):
    """kontakt solve DECK -o OUT_DIR --scheme SCHEME --threads N --quiet."""
    deck_path = os.path.abspath(deck_path)
    name = os.path.basename(deck_path)[:-4]
    os.makedirs(out_dir, exist_ok=True)
    cmd = [os.path.abspath(exe), "solve", deck_path, "-o", out_dir, "--quiet",
           "--threads", str(threads)]
    if scheme:
        cmd += ["--scheme", scheme]
    env = dict(os.environ, OPENBLAS_NUM_THREADS=str(threads))
    wall, peak, rc = timed_run(cmd, out_dir, os.path.join(out_dir, name + ".kontakt.log"),
                               timeout, env)
    status = {None: "timeout", 0: "converged", 3: "not converged"}.get(rc, f"exit {rc}")
    increments, iterations = _counts(os.path.join(out_dir, name + ".sta"))
    return Run(f"kontakt --scheme {scheme}" if scheme else "kontakt", rc == 0, status,
               iterations, increments, wall, peak, out_dir)
