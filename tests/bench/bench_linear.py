#!/usr/bin/python3
"""Linear benchmark: the same cantilever block (make_block.py), meshed with C3D8 and with
C3D20, solved by ccx 2.20 and by `kontakt solve` in one run, one after the other on this
machine. Reports the wall time and peak resident memory of each run and the kontakt/ccx
ratios, and checks that the printed tip displacements agree (max |kontakt - ccx| / max |ccx|
over the tip line's displacement components, at most 1e-5).

Both solvers get the same thread budget (--threads, default 2): OMP_NUM_THREADS and
CCX_NPROC_EQUATION_SOLVER (ccx/SPOOLES), OPENBLAS_NUM_THREADS, and kontakt's --threads.
Peak memory is the child's ru_maxrss from wait4(2), i.e. the figure `/usr/bin/time -v`
reports as "Maximum resident set size", taken for each child separately.
Exit code 0 when every run succeeded and every tip agreed."""
import argparse
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_block  # noqa: E402

SMOKE_DOFS = 6000
TIP_TOLERANCE = 1e-5


def timed_run(cmd, cwd, env, log_name=None):
    """(wall seconds, peak RSS in MiB, return code) of one child process; its output goes to
    cwd/LOG_NAME (default: the program's name + .log)."""
    start = time.perf_counter()
    log_name = log_name or os.path.basename(cmd[0]) + ".log"
    with open(os.path.join(cwd, log_name), "w") as log:
        proc = subprocess.Popen(cmd, cwd=cwd, env=env, stdout=log, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    proc.returncode = os.waitstatus_to_exitcode(status)
    return wall, usage.ru_maxrss / 1024.0, proc.returncode


def tip_displacements(dat_path):
    """[(ux, uy, uz)] of the printed tip line (the only *NODE PRINT of the deck)."""
    rows = []
    with open(dat_path) as f:
        for line in f:
            fields = line.split()
            if len(fields) == 4 and fields[0].isdigit():
                rows.append(tuple(float(v) for v in fields[1:]))
    if not rows:
        raise ValueError(f"no displacement rows in {dat_path}")
    return rows


def tip_deflection(dat_path):
    """Mean u_z over the printed tip line of a .dat file."""
    rows = tip_displacements(dat_path)
    return sum(r[2] for r in rows) / len(rows)


def relative_difference(ours, ref):
    """max |ours - ref| / max |ref| over every component of the tip line."""
    if len(ours) != len(ref):
        return float("inf")
    scale = max(abs(v) for row in ref for v in row)
    diff = max(abs(a - b) for ra, rb in zip(ours, ref) for a, b in zip(ra, rb))
    return diff / scale if scale > 0 else diff


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--kontakt", required=True, help="path of the kontakt executable")
    p.add_argument("--dofs", type=int, default=300000, help="size target (default %(default)s)")
    p.add_argument("--elements", nargs="+", default=["C3D8", "C3D20"], choices=["C3D8", "C3D20"])
    p.add_argument("--load", choices=["cload", "pressure"], default="cload",
                   help="end load: shear *CLOAD (default) or end pressure *DLOAD")
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--work", help="scratch folder (default: a new temporary folder)")
    p.add_argument("--smoke", action="store_true",
                   help=f"tiny size ({SMOKE_DOFS} dofs), for CI (seconds)")
    a = p.parse_args()
    dofs = SMOKE_DOFS if a.smoke else a.dofs
    work = os.path.abspath(a.work or tempfile.mkdtemp(prefix="kontakt_bench_"))
    os.makedirs(work, exist_ok=True)
    kontakt = os.path.abspath(a.kontakt)
    env = dict(os.environ, OMP_NUM_THREADS=str(a.threads),
               CCX_NPROC_EQUATION_SOLVER=str(a.threads), OPENBLAS_NUM_THREADS=str(a.threads))
    print(f"threads: {a.threads} for both (ccx: OMP_NUM_THREADS={a.threads}, "
          f"CCX_NPROC_EQUATION_SOLVER={a.threads}; kontakt: --threads {a.threads}); "
          f"runs one after the other; peak RSS per child from wait4; work folder {work}")
    print(f"{'element':8s} {'dofs':>8s} {'ccx s':>8s} {'kontakt s':>10s} {'time ratio':>10s} "
          f"{'ccx MiB':>8s} {'kontakt MiB':>11s} {'mem ratio':>9s} {'tip rel diff':>12s}")
    ok = True
    for element in a.elements:
        name = f"block_{element.lower()}"
        n_dofs, _ = make_block.write_block(os.path.join(work, name + ".inp"), element, dofs,
                                           load_type=a.load)
        t_ccx, m_ccx, rc_ccx = timed_run(["ccx", "-i", name], work, env, name + ".ccx.log")
        t_k, m_k, rc_k = timed_run([kontakt, "solve", name + ".inp", "-o", "kontakt_out",
                                    "--quiet", "--threads", str(a.threads)], work, env,
                                   name + ".kontakt.log")
        if rc_ccx or rc_k:
            print(f"{element:8s} {n_dofs:8d}  ccx exit {rc_ccx}, kontakt exit {rc_k} "
                  f"(logs: {work}/{name}.ccx.log, {name}.kontakt.log)")
            ok = False
            continue
        try:
            tip_c = tip_displacements(os.path.join(work, name + ".dat"))
            tip_k = tip_displacements(os.path.join(work, "kontakt_out", name + ".dat"))
            diff = relative_difference(tip_k, tip_c)
        except (OSError, ValueError) as e:
            print(f"{element:8s} {n_dofs:8d}  no tip displacements: {e}")
            ok = False
            continue
        ok &= diff <= TIP_TOLERANCE
        print(f"{element:8s} {n_dofs:8d} {t_ccx:8.2f} {t_k:10.2f} {t_k / t_ccx:10.3f} "
              f"{m_ccx:8.0f} {m_k:11.0f} {m_k / m_ccx:9.3f} {diff:12.2e}", flush=True)
    print(f"ratios are kontakt/ccx; tip rel diff = max|u_kontakt - u_ccx| / max|u_ccx| over the "
          f"tip line (must be <= {TIP_TOLERANCE:g}): {'ok' if ok else 'FAILED'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
