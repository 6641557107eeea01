#!/usr/bin/python3
"""Linear benchmark: the same cantilever block (make_block.py) solved by ccx 2.20 and by
`kontakt solve` in one run, one after the other on this machine. Reports wall time and peak
memory of each and their ratios, and checks that the tip displacements agree.
Both solvers get the same thread budget (--threads, default 2)."""
import argparse
import os
import resource
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_block  # noqa: E402


def timed_run(cmd, cwd, env):
    """(wall seconds, peak RSS in MiB, return code) of one child process."""
    start = time.perf_counter()
    proc = subprocess.Popen(cmd, cwd=cwd, env=env, stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode != 0:
        sys.stderr.write(proc.stderr.read().decode(errors="replace"))
    return wall, usage.ru_maxrss / 1024.0, proc.returncode


def tip_deflection(dat_path):
    """Mean u_z over the printed tip line of a .dat file."""
    values = []
    with open(dat_path) as f:
        for line in f:
            fields = line.split()
            if len(fields) == 4 and fields[0].isdigit():
                values.append(float(fields[3]))
    return sum(values) / len(values)


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--kontakt", required=True)
    p.add_argument("--dofs", type=int, default=300000)
    p.add_argument("--elements", nargs="+", default=["C3D8", "C3D20"])
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--work", default="bench_work")
    p.add_argument("--smoke", action="store_true", help="tiny size, for CI (seconds)")
    a = p.parse_args()
    dofs = 6000 if a.smoke else a.dofs
    os.makedirs(a.work, exist_ok=True)
    env = dict(os.environ, OMP_NUM_THREADS=str(a.threads),
               CCX_NPROC_EQUATION_SOLVER=str(a.threads), OPENBLAS_NUM_THREADS=str(a.threads))
    print(f"threads: {a.threads} for both (OMP_NUM_THREADS, CCX_NPROC_EQUATION_SOLVER, --threads)")
    print(f"{'element':8s} {'dofs':>8s} {'ccx s':>8s} {'kontakt s':>10s} {'time ratio':>10s} "
          f"{'ccx MiB':>8s} {'kontakt MiB':>11s} {'mem ratio':>9s} {'tip rel diff':>12s}")
    ok = True
    for element in a.elements:
        name = f"block_{element.lower()}"
        deck = os.path.join(a.work, name + ".inp")
        n_dofs, _ = make_block.write_block(deck, element, dofs)
        t_ccx, m_ccx, rc_ccx = timed_run(["ccx", "-i", name], a.work, env)
        t_k, m_k, rc_k = timed_run([os.path.abspath(a.kontakt), "solve", name + ".inp", "-o",
                                    "kontakt_out", "--quiet", "--threads", str(a.threads)],
                                   a.work, env)
        if rc_ccx or rc_k:
            print(f"{element}: ccx exit {rc_ccx}, kontakt exit {rc_k}")
            ok = False
            continue
        d_ccx = tip_deflection(os.path.join(a.work, name + ".dat"))
        d_k = tip_deflection(os.path.join(a.work, "kontakt_out", name + ".dat"))
        diff = abs(d_k - d_ccx) / abs(d_ccx)
        ok &= diff < 1e-5
        print(f"{element:8s} {n_dofs:8d} {t_ccx:8.2f} {t_k:10.2f} {t_k / t_ccx:10.3f} "
              f"{m_ccx:8.0f} {m_k:11.0f} {m_k / m_ccx:9.3f} {diff:12.2e}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
