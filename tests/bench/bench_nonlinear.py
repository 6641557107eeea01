#!/usr/bin/python3
"""Nonlinear benchmark: the cantilever block of make_block.py under NLGEOM, solved by ccx 2.20
and by `kontakt solve` in one run. By default the steel is elastic-plastic (*PLASTIC 250 /
300 at 0.02 / 330 at 0.1) and the tip load 6 (first yield at 4.2, plastic collapse of the
root section at 6.25 without hardening): a plastic zone spreads from the clamped end. With
--elastic the old elastic variant (tip load 500, tip deflection about 0.3 of the length).
Reports wall time, peak memory, increments and Newton iterations of both (from their .sta
files), and the tip deflections."""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench_linear  # noqa: E402
import make_block  # noqa: E402


PLASTIC_CURVE = ((250.0, 0.0), (300.0, 0.02), (330.0, 0.1))


def increments_and_iterations(sta_path):
    """(converged increments, iterations of converged and cut-back attempts) from a .sta."""
    increments = iterations = 0
    with open(sta_path) as f:
        for line in f:
            fields = line.split()
            if len(fields) >= 7 and fields[0].isdigit():
                attempt = fields[2]
                iterations += int(fields[3])
                increments += not attempt.endswith("U")
    return increments, iterations


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--kontakt", required=True)
    p.add_argument("--dofs", type=int, default=100000)
    p.add_argument("--element", default="C3D20", choices=["C3D8", "C3D20"])
    p.add_argument("--elastic", action="store_true",
                   help="no *PLASTIC (the elastic NLGEOM benchmark)")
    p.add_argument("--load", type=float, default=None,
                   help="total tip load (default 6 plastic, 500 elastic)")
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--work", default="bench_nl_work")
    p.add_argument("--smoke", action="store_true", help="tiny size, for CI (seconds)")
    a = p.parse_args()
    dofs = 3000 if a.smoke else a.dofs
    os.makedirs(a.work, exist_ok=True)
    env = dict(os.environ, OMP_NUM_THREADS=str(a.threads),
               CCX_NPROC_EQUATION_SOLVER=str(a.threads), OPENBLAS_NUM_THREADS=str(a.threads))
    load = a.load if a.load is not None else (500.0 if a.elastic else 6.0)
    plastic = () if a.elastic else PLASTIC_CURVE
    name = f"nlblock_{a.element.lower()}" + ("" if a.elastic else "_plastic")
    n_dofs, _ = make_block.write_block(os.path.join(a.work, name + ".inp"), a.element, dofs,
                                       nlgeom=True, load=load, plastic=plastic)
    t_ccx, m_ccx, rc_ccx = bench_linear.timed_run(["ccx", "-i", name], a.work, env)
    t_k, m_k, rc_k = bench_linear.timed_run(
        [os.path.abspath(a.kontakt), "solve", name + ".inp", "-o", "kontakt_out", "--quiet",
         "--threads", str(a.threads)], a.work, env)
    if rc_ccx or rc_k:
        print(f"ccx exit {rc_ccx}, kontakt exit {rc_k}")
        return 1
    inc_c, it_c = increments_and_iterations(os.path.join(a.work, name + ".sta"))
    inc_k, it_k = increments_and_iterations(os.path.join(a.work, "kontakt_out", name + ".sta"))
    d_c = bench_linear.tip_deflection(os.path.join(a.work, name + ".dat"))
    d_k = bench_linear.tip_deflection(os.path.join(a.work, "kontakt_out", name + ".dat"))
    kind = "elastic" if a.elastic else "elastic-plastic (*PLASTIC)"
    print(f"threads: {a.threads} for both; {a.element}, {n_dofs} dofs, NLGEOM, {kind}, "
          f"tip load {load:g}")
    print(f"{'':8s} {'wall s':>8s} {'peak MiB':>9s} {'increments':>10s} {'iterations':>10s} "
          f"{'tip u_z':>12s}")
    print(f"{'ccx':8s} {t_ccx:8.2f} {m_ccx:9.0f} {inc_c:10d} {it_c:10d} {d_c:12.6g}")
    print(f"{'kontakt':8s} {t_k:8.2f} {m_k:9.0f} {inc_k:10d} {it_k:10d} {d_k:12.6g}")
    print(f"ratios kontakt/ccx: wall {t_k / t_ccx:.3f}, memory {m_k / m_ccx:.3f}, "
          f"iterations {it_k / max(it_c, 1):.3f}; tip difference {abs(d_k - d_c) / abs(d_c):.2e}")
    return 0 if abs(d_k - d_c) <= 1e-3 * abs(d_c) else 1


if __name__ == "__main__":
    sys.exit(main())
