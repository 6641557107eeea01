"""Running ccx 2.20 and `kontakt solve --scheme NAME` on a generated contact deck, the same
way for both: one child process (under `nice -n 10`, which execs it: the same process) in its
own process group (killed with its children on timeout); wall time and peak resident memory
of that child (`ru_maxrss` from wait4, the figure /usr/bin/time -v reports), converged or
not, and the Newton iterations read from the solver's .sta file.

Counting (identical for both solvers): `iterations` is the sum of the ITRS column over every
attempt in the .sta, cut-back attempts (marked U) included; `increments` counts the converged
ones (tests/peer/run_peer.py's sta_counts).
Converged: ccx exit code 0 and "Job finished" in its output; kontakt exit code 0 (3 means
not converged, 2 input error, 4 numerical or internal error).
"""
import json
import os
import signal
import subprocess
import sys
import threading
import time
from dataclasses import dataclass

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "peer"))
import run_peer  # noqa: E402

# kontakt's contact discretisations (issue 4; l = linear variant, gcN = Gauss-Cut with N
# points per triangle); ccx's two pair types are the reference columns
SCHEMES = ("nts", "gauss", "lgauss", "gc1", "gc3", "gc7", "gc12", "lgc1", "lgc3", "lgc7", "lgc12")
CCX_TYPES = ("NODE TO SURFACE", "SURFACE TO SURFACE")
DEFAULT_TIMEOUT = 600
NICENESS = 10  # the machine is shared: both solvers run at the same lowered priority


@dataclass
class Run:
    converged: bool
    status: str          # "converged", "not converged", "timeout", "exit N"
    iterations: int      # over every attempt (0 when there is no .sta)
    increments: int      # converged increments
    wall: float          # seconds
    peak_mib: float
    result_dir: str      # folder holding NAME.dat / .sta (and .frd or .hdf)
    message: str = ""    # when not converged: the solver's first error line (or its last line)
    cpu: float = 0.0     # user + system seconds of the child: less sensitive to a loaded machine


def contact_type_for(scheme):
    """The *CONTACT PAIR TYPE a deck solved with --scheme SCHEME is written with: node to
    surface for nts, surface to surface for every segment scheme."""
    return "NODE TO SURFACE" if scheme == "nts" else "SURFACE TO SURFACE"


def deck_suffix(contact_type):
    return "nts" if contact_type == "NODE TO SURFACE" else "sts"


def timed_run(cmd, cwd, log_path, timeout, env=None):
    """(wall seconds, peak RSS MiB, return code or None on timeout, CPU seconds) of one child
    process."""
    start = time.perf_counter()
    with open(log_path, "w") as log:
        proc = subprocess.Popen(["nice", "-n", str(NICENESS)] + cmd, cwd=cwd, env=env,
                                stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
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
    return (wall, usage.ru_maxrss / 1024.0, None if expired.is_set() else proc.returncode,
            usage.ru_utime + usage.ru_stime)


def _message(log_path):
    """The first line of a solver log that mentions an error, else its last non-empty line."""
    with open(log_path, errors="replace") as f:
        lines = [ln.strip() for ln in f if ln.strip()]
    return next((ln for ln in lines if "error" in ln.lower()), lines[-1] if lines else "")


def done_summary(result_dir, name):
    """The summary of kontakt's `done` event in RESULT_DIR/NAME.log.jsonl ({} without one)."""
    path = os.path.join(result_dir, name + ".log.jsonl")
    if not os.path.exists(path):
        return {}
    with open(path) as f:
        done = [json.loads(line) for line in f if '"event":"done"' in line.replace(" ", "")]
    return done[-1].get("summary", {}) if done else {}


def _counts(sta_path):
    return run_peer.sta_counts(sta_path) or (0, 0)


def run_ccx(deck_path, timeout=DEFAULT_TIMEOUT, threads=1):
    """ccx -i NAME in the deck's folder."""
    folder, name = os.path.split(os.path.abspath(deck_path))
    name = name[:-4]
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), CCX_NPROC_EQUATION_SOLVER=str(threads))
    log = os.path.join(folder, name + ".ccx.log")
    wall, peak, rc, cpu = timed_run(["ccx", "-i", name], folder, log, timeout, env)
    with open(log, errors="replace") as f:
        finished = "Job finished" in f.read()
    converged = rc == 0 and finished
    status = ("timeout" if rc is None else "converged" if converged
              else "not converged" if rc == 0 or not finished else f"exit {rc}")
    increments, iterations = _counts(os.path.join(folder, name + ".sta"))
    return Run(converged, status, iterations, increments, wall, peak, folder,
               "" if converged else _message(log), cpu)


def run_kontakt(exe, deck_path, scheme, out_dir, timeout=DEFAULT_TIMEOUT, threads=1,
                extra_args=()):
    """kontakt solve DECK -o OUT_DIR --scheme SCHEME --threads N --quiet EXTRA_ARGS."""
    deck_path = os.path.abspath(deck_path)
    name = os.path.basename(deck_path)[:-4]
    os.makedirs(out_dir, exist_ok=True)
    cmd = [os.path.abspath(exe), "solve", deck_path, "-o", out_dir, "--quiet",
           "--threads", str(threads)]
    if scheme:
        cmd += ["--scheme", scheme]
    cmd += list(extra_args)
    env = dict(os.environ, OPENBLAS_NUM_THREADS=str(threads))
    log = os.path.join(out_dir, name + ".kontakt.log")
    wall, peak, rc, cpu = timed_run(cmd, out_dir, log, timeout, env)
    status = {None: "timeout", 0: "converged", 3: "not converged"}.get(rc, f"exit {rc}")
    increments, iterations = _counts(os.path.join(out_dir, name + ".sta"))
    return Run(rc == 0, status, iterations, increments, wall, peak, out_dir,
               "" if rc == 0 else _message(log), cpu)


def write_deck(model, folder, contact_type, name="model"):
    """Writes the TwoBodyModel with the given pair type to FOLDER/nts|sts/NAME.inp."""
    deck_dir = os.path.join(folder, deck_suffix(contact_type))
    os.makedirs(deck_dir, exist_ok=True)
    return model.with_contact_type(contact_type).write(os.path.join(deck_dir, name + ".inp"))


def solve(deck_for, folder, column, kontakt=None, timeout=DEFAULT_TIMEOUT, kontakt_args=()):
    """Run of one column: `column` is a kontakt scheme (needs `kontakt`, the executable, run
    with the options `kontakt_args`) or a ccx pair type (CCX_TYPES); `deck_for` maps a pair
    type to its deck (write_deck). ccx solves in the deck's folder; kontakt writes into
    FOLDER/kontakt_SCHEME/."""
    if column in CCX_TYPES:
        return run_ccx(deck_for[column], timeout)
    return run_kontakt(kontakt, deck_for[contact_type_for(column)], column,
                       os.path.join(folder, "kontakt_" + column), timeout,
                       extra_args=kontakt_args)


def runs_per_slave(model_for, name, args):
    """Yields (slave side, column label, Run) for every side in args.slave and every column:
    kontakt's args.schemes, and ccx's two pair types with args.ccx. `model_for(slave,
    contact_type)` builds the model; the decks go to ARGS.WORK/slave_SIDE/."""
    for slave in args.slave:
        folder = os.path.join(os.path.abspath(args.work), "slave_" + slave)
        decks = {t: write_deck(model_for(slave, t), folder, t, name) for t in CCX_TYPES}
        for label, column in columns(args.schemes, args.kontakt, CCX_TYPES if args.ccx else ()):
            yield slave, label, solve(decks, folder, column, args.kontakt)


def columns(schemes, kontakt, ccx_types=CCX_TYPES):
    """[(label, column)]: kontakt's schemes (when an executable is given), then ccx's types."""
    return ([(f"kontakt {s}", s) for s in (schemes if kontakt else [])]
            + [(f"ccx {t.lower()}", t) for t in ccx_types])


def add_solver_options(parser, default_schemes):
    """--kontakt EXE (without it only ccx's columns run) and --schemes NAME ... of a script."""
    parser.add_argument("--kontakt", help="kontakt executable (without it: the ccx columns only)")
    parser.add_argument("--schemes", nargs="+", default=list(default_schemes), choices=SCHEMES,
                        help="kontakt's schemes (default: %(default)s)")
